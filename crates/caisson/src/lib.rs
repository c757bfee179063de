//! # caisson
//!
//! Dynamic sliding of caisson breakwaters under breaking and non-breaking waves: the model of
//! Cuomo, Lupoi, Shimosako & Takahashi (the "seed" paper), with every formula it leaves out taken
//! from docs/model.md.
//!
//! A rigid caisson (sliding u_x, heave u_y, rocking θ) rests on a bed of nonlinear interface
//! springs (no tension; elastic-Coulomb friction with static and dynamic coefficients) and is
//! integrated by Newmark + Newton-Raphson under a wave-force time history.
//!
//! Sign conventions (used everywhere): x positive shoreward, y positive upward (uplift positive),
//! moments and θ about the centre of the base, positive clockwise looking alongshore with the sea
//! on the left (the sense in which a shoreward force overturns the caisson). SI units inside.
//!
//! Layers, each knowing only those below it: [`waves`] → [`loads`] → [`structure`],
//! [`foundation`] → [`dynamics`] → [`analysis`] (the drivers) → [`report`] (the JSON contracts)
//! and [`scenario`] (the input file, the only module that knows TOML). Each module owns its
//! parameter types and validates them when they are built ([`ParamError`]).
//!
//! The library never prints and never touches files, except [`scenario`], which reads the
//! scenario file and the force series it names.
//!
//! ```
//! // Goda's pressures on the seed's PARI caisson (docs/model.md §11, first row).
//! use caisson::loads::goda::{goda, GodaInput};
//! let g = goda(&GodaInput {
//!     height_m: 0.428, wavelength_m: 9.3214, depth_m: 1.14, depth_5h_seaward_m: 1.14,
//!     wall_depth_m: 0.8, base_depth_m: 0.8, crest_freeboard_m: 0.32, width_m: 0.78,
//!     angle_rad: 0.0, berm_width_m: None, lambda: [1.0; 3], rho_w: 1000.0,
//! });
//! assert!((g.horizontal_force_n_per_m / 1e3 - 3.552).abs() < 1e-3);
//! ```

pub mod analysis;
pub mod drive;
pub mod dynamics;
pub mod foundation;
pub mod loads;
pub mod report;
pub mod scenario;
pub mod structure;
pub mod waves;

/// Gravitational acceleration used throughout, m/s² (docs/model.md §0).
pub const G_M_PER_S2: f64 = 9.81;

/// The version of this library (and of the `caisson` tool built on it).
pub const VERSION: &str = env!("CARGO_PKG_VERSION");

/// The version of the results: raised whenever a change moves any number the tool reports for
/// the same input (a model, a default, a random stream). Outputs and checkpoints record it, so
/// results of different versions are never mixed.
pub const RESULTS_VERSION: u32 = 28;

/// The largest magnitude of a number in a scenario file or a force series: beyond it a value in
/// kN or kPa overflows to infinity once converted to SI, and the messages could only say `inf`.
pub const MAX_MAGNITUDE: f64 = 1e300;

/// Most worker threads a parallel driver may be given (the CLI's `--threads`, the Python
/// `threads=`; 0 means one per core): more only costs memory and start-up time.
pub const MAX_THREADS: usize = 256;

/// Which reading of the seed paper sets the defaults of the model's choices (docs/model.md §10,
/// "Profiles"). A profile only sets defaults: every key given in a scenario overrides it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize)]
pub enum Profile {
    /// Physically consistent defaults: the foundation dashpot in series with the friction
    /// slider (`damping_mode = "elastic"`, §10 item 30), the vertical and rotational dashpots
    /// beside the springs (`vertical_damping = "springs"`, item 10 option B), the exact coupled
    /// mass matrix (item 9) and one friction coefficient, μ_d = μ_s, as in the rigid-plastic design
    /// method (Shimosako & Takahashi 1999).
    #[default]
    #[serde(rename = "consistent")]
    Consistent,
    /// Every literal reading of the seed: the dashpot on the total velocity (Eq. 15), global 10 C
    /// on u_y and on θ (Eqs. 24-25), the diagonal mass matrix (Eq. 24) and the seed's friction
    /// pair μ_s = 0.6, μ_d = 0.4 (μ_d = min(0.4, μ_s)).
    #[serde(rename = "seed-2011")]
    Seed2011,
}

impl Profile {
    /// Every profile with its scenario name.
    pub const ALL: [(&'static str, Profile); 2] =
        [("consistent", Profile::Consistent), ("seed-2011", Profile::Seed2011)];

    /// The scenario name (`[model] profile`).
    pub fn name(self) -> &'static str {
        match self {
            Profile::Consistent => "consistent",
            Profile::Seed2011 => "seed-2011",
        }
    }
}

/// A value as a message shows it: its shortest decimal from 10⁻⁴ to 10⁶ (where that is at most
/// 16 characters), and from 10⁶ to 10¹⁵ where that is no longer than its scientific notation;
/// else in scientific notation (1e-9, 1e9, 5e-324 and 8.24e200, not rows of zeros or hundreds of
/// digits). Every digit of the value is kept. `inf` and `NaN` as Rust writes them.
pub fn fmt_value(v: f64) -> String {
    let (s, e) = (v.to_string(), format!("{v:e}"));
    let a = v.abs();
    let decimal = !v.is_finite()
        || v == 0.0
        || ((1e-4..1e6).contains(&a) && s.len() <= 16)
        || ((1e6..1e15).contains(&a) && s.len() <= e.len());
    if decimal {
        s
    } else {
        e
    }
}

/// A number a message computes (a bound from other values, a product of units) as it prints
/// it: [`fmt_value`] of the number rounded to 12 significant digits, so that the rounding of the
/// computation does not show (3.071000000000001e-6 is 3.071e-6, 0.30000000000000004 is 0.3).
pub fn fmt_number(v: f64) -> String {
    if !v.is_finite() || v == 0.0 {
        return v.to_string();
    }
    fmt_value(format!("{v:.11e}").parse().unwrap_or(v))
}

/// The decimals that a figure known to ± `half_width` (a standard error, or half the width of an
/// interval) supports: down to the first significant digit of `half_width` (0.35 ± 0.04 m: two;
/// 10.9 m, 10.6-11.3 m: one), none from a half-width of 1 up; 4 where the half-width is 0 or
/// not finite, at most 6.
pub fn supported_decimals(half_width: f64) -> usize {
    if !(half_width.is_finite() && half_width > 0.0) {
        return 4;
    }
    (-half_width.log10().floor()).clamp(0.0, 6.0) as usize
}

/// A share in per cent with its 95 % interval, to the decimals half its width supports: "15 %
/// (9-22 %)" (a negative end with a minus sign: "(−3 to 20 %)"); a share of nothing (no life slid:
/// [0, 0]; no life failed: [0, 1]) "0 %".
pub fn share_text(value: f64, ci: [f64; 2]) -> String {
    let half = 50.0 * (ci[1] - ci[0]);
    if half <= 0.0 || (value == 0.0 && ci == [0.0, 1.0]) {
        return format!("{:.0} %", 100.0 * value);
    }
    let d = supported_decimals(half);
    let f = |v: f64| format!("{:.d$}", 100.0 * v).replace('-', "−");
    let sep = if ci[0] < 0.0 { " to " } else { "-" };
    format!("{} % ({}{sep}{} %)", f(value), f(ci[0]), f(ci[1]))
}

/// A parameter outside what the model allows: the quantity (as named in its parameter type, SI
/// units), its value and what is allowed. The [`scenario`] module reports it under the name of
/// the file key, in the key's unit.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{quantity} = {}: {}", fmt_value(*value), allowed.describe(1.0, ""))]
pub struct ParamError {
    pub quantity: &'static str,
    pub value: f64,
    pub allowed: Allowed,
}

/// What a parameter may be (bounds in the quantity's SI unit).
#[derive(Debug, Clone, PartialEq)]
pub enum Allowed {
    /// A finite number.
    Finite,
    /// A finite number > 0.
    Positive,
    /// A finite number ≥ 0.
    NonNegative,
    /// A finite number from `lo` to `hi`, both included.
    Between { lo: f64, hi: f64 },
    /// A finite number > 0 and at most `hi`.
    PositiveUpTo { hi: f64 },
    /// A finite number above `lo` (or at least `lo`, when `lo_open` is false) and at most `hi`.
    Interval { lo: f64, hi: f64, lo_open: bool },
    /// A finite number from `lo` · `per` to `hi` · `per`, both included: from `lo` to `hi` per
    /// unit of `of` (a total of a caisson `per` metres long, say).
    Per { lo: f64, hi: f64, per: f64, of: &'static str },
    /// A whole number from `lo` to `hi`.
    Count { lo: u64, hi: u64 },
    /// A rule in words (its numbers in SI units).
    Rule(String),
}

impl Allowed {
    /// The rule in words, with bounds multiplied by `scale` and followed by `unit` (the unit of a
    /// file key, e.g. kN for a force given in N here).
    pub fn describe(&self, scale: f64, unit: &str) -> String {
        let u = if unit.is_empty() { String::new() } else { format!(" ({unit})") };
        let n = |v: f64| fmt_number(v * scale);
        match self {
            Allowed::Finite => "must be a finite number".to_string(),
            Allowed::Positive => format!("must be a finite number > 0{u}"),
            Allowed::NonNegative => format!("must be a finite number ≥ 0{u}"),
            Allowed::Between { lo, hi } => format!("must be between {} and {}{u}", n(*lo), n(*hi)),
            Allowed::PositiveUpTo { hi } => format!("must be a finite number > 0 and at most {}{u}", n(*hi)),
            Allowed::Interval { lo, hi, lo_open } => {
                let low = if *lo_open { ">" } else { "≥" };
                format!("must be a finite number {low} {} and ≤ {}{u}", n(*lo), n(*hi))
            }
            Allowed::Per { lo, hi, per, of } => {
                format!("must be between {} and {}{u}: {} to {} per {of}", n(lo * per), n(hi * per), n(*lo), n(*hi))
            }
            Allowed::Count { lo, hi } => format!("must be a whole number from {lo} to {hi}"),
            Allowed::Rule(s) => s.clone(),
        }
    }
}

/// Range checks shared by the parameter types' validating constructors.
pub(crate) mod check {
    use super::{Allowed, ParamError};

    pub(crate) fn fail(quantity: &'static str, value: f64, allowed: Allowed) -> ParamError {
        ParamError { quantity, value, allowed }
    }
    pub(crate) fn rule(quantity: &'static str, value: f64, rule: impl Into<String>) -> ParamError {
        ParamError { quantity, value, allowed: Allowed::Rule(rule.into()) }
    }
    pub(crate) fn finite(quantity: &'static str, v: f64) -> Result<f64, ParamError> {
        if v.is_finite() {
            Ok(v)
        } else {
            Err(fail(quantity, v, Allowed::Finite))
        }
    }
    pub(crate) fn positive(quantity: &'static str, v: f64) -> Result<f64, ParamError> {
        if v.is_finite() && v > 0.0 {
            Ok(v)
        } else {
            Err(fail(quantity, v, Allowed::Positive))
        }
    }
    pub(crate) fn non_negative(quantity: &'static str, v: f64) -> Result<f64, ParamError> {
        if v.is_finite() && v >= 0.0 {
            Ok(v)
        } else {
            Err(fail(quantity, v, Allowed::NonNegative))
        }
    }
    pub(crate) fn between(quantity: &'static str, v: f64, lo: f64, hi: f64) -> Result<f64, ParamError> {
        if v.is_finite() && v >= lo && v <= hi {
            Ok(v)
        } else {
            Err(fail(quantity, v, Allowed::Between { lo, hi }))
        }
    }
    /// A finite number from `lo` · `per` to `hi` · `per` ([`Allowed::Per`]).
    pub(crate) fn between_per(
        quantity: &'static str,
        v: f64,
        (lo, hi): (f64, f64),
        per: f64,
        of: &'static str,
    ) -> Result<f64, ParamError> {
        if v.is_finite() && v >= lo * per && v <= hi * per {
            Ok(v)
        } else {
            Err(fail(quantity, v, Allowed::Per { lo, hi, per, of }))
        }
    }
    pub(crate) fn positive_up_to(quantity: &'static str, v: f64, hi: f64) -> Result<f64, ParamError> {
        if v.is_finite() && v > 0.0 && v <= hi {
            Ok(v)
        } else {
            Err(fail(quantity, v, Allowed::PositiveUpTo { hi }))
        }
    }
    /// A finite number in (lo, hi] (`lo_open`) or [lo, hi].
    pub(crate) fn interval(quantity: &'static str, v: f64, lo: f64, hi: f64, lo_open: bool) -> Result<f64, ParamError> {
        let above = if lo_open { v > lo } else { v >= lo };
        if v.is_finite() && above && v <= hi {
            Ok(v)
        } else {
            Err(fail(quantity, v, Allowed::Interval { lo, hi, lo_open }))
        }
    }
    pub(crate) fn count(quantity: &'static str, v: usize, lo: u64, hi: u64) -> Result<usize, ParamError> {
        if (lo..=hi).contains(&(v as u64)) {
            Ok(v)
        } else {
            Err(fail(quantity, v as f64, Allowed::Count { lo, hi }))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::share_text;

    /// The digits follow half the interval's width in per cent (4.5 -> 0 decimals, 0.3 -> 1),
    /// a negative end reads "to", and a point without spread prints alone.
    #[test]
    fn a_share_prints_with_the_digits_its_interval_supports() {
        assert_eq!(share_text(0.154, [0.109, 0.199]), "15 % (11-20 %)");
        assert_eq!(share_text(0.004, [0.001, 0.007]), "0.4 % (0.1-0.7 %)");
        assert_eq!(share_text(0.003, [-0.003, 0.008]), "0.3 % (−0.3 to 0.8 %)");
        assert_eq!(share_text(0.0, [0.0, 0.0]), "0 %");
        assert_eq!(share_text(0.0, [0.0, 1.0]), "0 %");
        assert_eq!(share_text(0.0, [0.0, 0.011]), "0.0 % (0.0-1.1 %)");
    }
    use super::supported_decimals;

    /// The decimals of a figure end at the first significant digit of its uncertainty, by hand:
    /// 0.04 → 2 (0.35 ± 0.04), 0.35 → 1 (10.9 ± 0.35), 0.0099 → 3, 2.5 → 0; no uncertainty → 4.
    #[test]
    fn a_figure_shows_the_digits_its_uncertainty_supports() {
        let cases =
            [(0.04, 2), (0.35, 1), (0.0099, 3), (2.5, 0), (1.0, 0), (0.1, 1), (1e-9, 6), (0.0, 4), (f64::NAN, 4)];
        for (hw, d) in cases {
            assert_eq!(supported_decimals(hw), d, "half-width {hw}");
        }
        assert_eq!(cases.len(), 9);
    }
}
