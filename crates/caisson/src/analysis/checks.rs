//! Plausibility checks: results and inputs that are valid but that an engineer should not accept
//! without a second look. Each is a [`Warning`] (never an error): a code, a message that says
//! what to check, and the numbers behind it. The CLI prints them as `Warning:` lines and every
//! JSON output lists them under `warnings`.
//!
//! | code | fires when | why |
//! |---|---|---|
//! | `implausible-settlement` | W'/K_y > 0.2 m | a caisson on a rubble mound settles by millimetres to centimetres; 24.7 m is E100 given in MPa |
//! | `implausible-natural-period` | T0 outside 2 ms to 3 s | flume caissons sway at about 0.02 s, prototypes at 0.1-1 s |
//! | `implausible-base-pressure` | W'/(B l) outside 1 to 1000 kPa | flume caissons bear about 10 kPa, prototypes 100-400 kPa; a weight in MN or N gives 1000 × less or more |
//! | `coarse-time-step` | fixed steps `dt_s` > T0/10 | Newmark's average acceleration stays stable at any step but lengthens the period of the response, T̄/T = Ω/(2 atan(Ω/2)), Ω = 2π dt/T0 (Chopra 2012, §5.5): 3 % at T0/10, 56 % at T0/2; a short impulse falls between steps (docs/model.md §9.1 recommends T0/20); steps over T0 are refused by the scenario |
//! | `implausible-load` | a peak wave force (or uplift) above 100 W' | no wave load on a caisson exceeds a few times its weight in water; a force in N written as kN gives 1000 × more (beyond 10³ W' the scenario refuses it) |
//! | `undamped-adaptive` | C = 0 with adaptive steps | the stepper's error estimate assumes damped transients; without damping an independent check found −1.90 mm adaptive against −0.094 mm fixed |
//! | `dashpot-exceeds-friction` | C u̇_x > μ N while sliding (`damping_mode = "total"`) | a Coulomb interface carries no more than μN; the dashpot then limits the slide (docs/model.md §10 item 30) |
//! | `rotational-dashpot-moment` | with `vertical_damping = "seed"`, the dashpots' moment > ½ the largest wave moment | they, not the springs, hold the caisson upright (the seed's 10C as N·m·s/rad, item 10) |
//! | `rocking-without-slip` | a displacement above 1 µm with no slip event | it comes from rocking: lifted springs re-contact at a displaced base |
//! | `rocking` | rotation above 0.01 rad | the seaward heel lifts by θB/2; beyond small rotations the model's kinematics and foundation do not hold, and the landing can slide the caisson seaward (docs/design.md) |
//! | `beyond-failure` | \|sliding\| above 0.25 B | a quarter of the base has left the bedding the model describes |
//! | `sliding-beyond-width` | \|sliding\| above B (a run, a realization; a design's E\|S\| as simulated; a fragility storm) | a caisson cannot slide beyond its mound: the model is far outside its validity and the number is no prediction (the design example at W' = 500 kN slid 52 km in a life); usually an input error (the weight, the loads) |
//! | `overturning-under-design-wave` | Goda's overturning safety factor under the design wave below 1 ([`super::conventional`]) | the caisson would tip about its heel, which the dynamic model (small rotations, an elastic foundation) does not follow |
//! | `failed-lives` | a design life (or a sizing candidate's) moved beyond `failure_sliding_m` or rotated beyond `failure_rotation_rad` | what the model computes after failure lies outside its validity: a failed life enters E\|S\| at the sliding limit; read P(failure) and the surviving lives' statistics |
//! | `large-rotation-lives` | a wave of a design life rotated the caisson beyond 0.01 rad | as `rocking`: the model does not follow overturning |
//! | `seaward-lives` | a design life ends more than 1 cm seaward of its place | rocking landings, not the wave's push, moved it (docs/design.md) |
//! | `impulsive-share` | impulsive waves make more than half of E\|S\| (as simulated) or of the failures, of either model (a design, a sizing candidate, a fragility) | the answer rests on the breaking-wave load rule, whose impact coefficient is unconfirmed (docs/model.md §5.1): check it against the site's breaking conditions |
//! | `impulsive-share-outside-goda-conditions` | the same at a site outside Goda's (2000) conditions of a danger of impulsive breaking (docs/model.md §1.4) under the design sea of `[waves]` | the impacts that make the answer are ones Goda's practice does not expect there |

use super::conventional::static_check;
use super::lifetime::{AutoPrecision, FailureLimits, ImpulsiveShare, LifeCounts, StormOutcome};
use super::limits::{FAILURE_FRACTION_OF_WIDTH, ROCKING_LIMIT_RAD, SEAWARD_REPORT_M};
use super::run::Response;
use super::site::WaveSetup;
use super::sizing::Candidate;
use super::train::{RealizationResult, TrainCase};
use super::Structure;
use crate::dynamics::Stepping;
use crate::foundation::VerticalDamping;
use crate::loads::breaking_load::BreakingLoad;
use crate::loads::generator::{HeightVariability, TrainKind};
use crate::loads::model::WaveLoadModel;
use crate::loads::regime::RegimeChoice;
use crate::loads::{LoadSpec, WaveForce};
use crate::waves::dispersion::{deep_water_wavelength_m, wavenumber};
use crate::waves::surf_zone::equivalent_deep_water_height_m;
use std::collections::BTreeMap;

/// A result or input to check (module docs).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Warning {
    pub code: &'static str,
    pub message: String,
    /// The numbers behind it, named with their unit.
    pub numbers: BTreeMap<&'static str, f64>,
}

impl Warning {
    fn new(code: &'static str, message: String, numbers: &[(&'static str, f64)]) -> Self {
        Warning { code, message, numbers: numbers.iter().copied().collect() }
    }
}

/// Largest plausible static settlement W'/K_y, m.
pub const MAX_SETTLEMENT_M: f64 = 0.2;
/// Plausible natural periods T0 of the horizontal mode, s.
pub const NATURAL_PERIOD_RANGE_S: (f64, f64) = (2e-3, 3.0);
/// Plausible mean base pressures W'/(B l), Pa.
pub const BASE_PRESSURE_RANGE_PA: (f64, f64) = (1e3, 1e6);
/// Fixed steps longer than this fraction of T0 are coarse (`coarse-time-step`).
pub const COARSE_STEP_FRACTION_OF_T0: f64 = 0.1;
/// Peak wave forces above this multiple of W' are implausible (`implausible-load`).
pub const PLAUSIBLE_LOAD_OVER_WEIGHT: f64 = 100.0;
/// Peak wave forces above this multiple of W' are input errors (refused by the scenario): pushed
/// by a thousand times its weight in water a caisson slides hundreds of metres per wave, and the
/// Newton-Raphson tolerance (relative to W') falls below the round-off of its spring forces
/// (K (u − s) with u and s of hundreds of metres): the PARI non-breaking campaign with `length_m
/// = 3000` (its waves 1100 times its weight in water) failed to converge, and so did its caisson
/// with a weight in water 10⁴ times smaller (3600 W').
pub const MAX_LOAD_OVER_WEIGHT: f64 = 1e3;
/// H_max / H1/3 of the largest wave of an irregular train (Goda's design ratio, as the storms of
/// [`super::fragility`]).
const NOMINAL_HMAX_RATIO: f64 = super::conventional::HMAX_OVER_H13;
/// Sliding beyond this multiple of the base width is absurd (`sliding-beyond-width`).
pub const ABSURD_SLIDING_OVER_WIDTH: f64 = 1.0;

/// What every `sliding-beyond-width` message ends with.
const BEYOND_WIDTH: &str = "a caisson cannot slide beyond its mound, so the model (a caisson sliding on its bedding) is far outside its validity and this number is no prediction: check the input, above all `[caisson] weight_in_water_kn` (in kN, the total over `length_m`) and the loads (`caisson loads` gives the design wave's and Goda's sliding safety factor)";

/// Checks of the structure itself (before any run).
pub fn structure_warnings(s: &Structure) -> Vec<Warning> {
    let mut out = Vec::new();
    let model = s.model();
    let settlement = model.static_settlement_m();
    if settlement > MAX_SETTLEMENT_M {
        out.push(Warning::new(
            "implausible-settlement",
            format!(
                "the static settlement W'/K_y is {settlement:.3} m, where a caisson on a rubble mound settles by millimetres to centimetres: is `[foundation] e100_kpa` (or `ky_kn_per_m`) in kPa (kN/m)?"
            ),
            &[("static_settlement_m", settlement), ("limit_m", MAX_SETTLEMENT_M)],
        ));
    }
    let t0 = model.natural_period_s();
    let (lo, hi) = NATURAL_PERIOD_RANGE_S;
    if !(lo..=hi).contains(&t0) {
        out.push(Warning::new(
            "implausible-natural-period",
            format!(
                "the natural period T0 = 2π √(m/K_x) is {t0:.4} s, outside the {lo} to {hi} s of caissons from flume models to prototypes: are `[foundation] e100_kpa` (or `kx_kn_per_m`) and `[caisson] weight_in_water_kn` in kPa and kN?"
            ),
            &[("natural_period_s", t0), ("low_s", lo), ("high_s", hi)],
        ));
    }
    let c = &s.caisson;
    let q = c.weight_in_water_n / (c.width_m * c.length_m);
    let (lo, hi) = BASE_PRESSURE_RANGE_PA;
    if !(lo..=hi).contains(&q) {
        out.push(Warning::new(
            "implausible-base-pressure",
            format!(
                "the mean base pressure W'/(B l) is {:.4} kPa, outside the {} to {} kPa of caissons from flume models to prototypes: is `[caisson] weight_in_water_kn` in kN (not MN or N)?",
                q / 1e3,
                lo / 1e3,
                hi / 1e3
            ),
            &[("base_pressure_kpa", q / 1e3), ("low_kpa", lo / 1e3), ("high_kpa", hi / 1e3)],
        ));
    }
    if s.solver.stepping == Stepping::Fixed && s.solver.dt_s > COARSE_STEP_FRACTION_OF_T0 * t0 {
        let dt = s.solver.dt_s;
        let ratio = newmark_period_ratio(dt / t0);
        out.push(Warning::new(
            "coarse-time-step",
            format!(
                "the fixed time step dt_s = {dt} s is {:.2} of the natural period T0 = {t0:.4} s: the response's period comes out {:.1} % too long (Newmark's average acceleration) and an impulse shorter than a few steps is missed; lower `[solver] dt_s` to T0/20 = {:.2e} s or use stepping = \"adaptive\"",
                dt / t0,
                100.0 * (ratio - 1.0),
                t0 / 20.0
            ),
            &[("dt_s", dt), ("natural_period_s", t0), ("period_ratio", ratio)],
        ));
    }
    if s.foundation.stiffness.damping_ns_per_m == 0.0 && matches!(s.solver.stepping, Stepping::Adaptive(_)) {
        out.push(Warning::new(
            "undamped-adaptive",
            "the foundation is undamped (`damping_kns_per_m = 0`) and the steps are adaptive: the stepper's error control does not hold without damping (an undamped check moved by millimetres); use `[solver] stepping = \"fixed\"`".to_string(),
            &[],
        ));
    }
    out
}

/// The period of Newmark's average-acceleration scheme (γ = ½, β = ¼) over the true period, for a
/// step of `dt_over_t` periods: Ω/(2 atan(Ω/2)), Ω = 2π dt/T (the scheme's amplification
/// matrix has eigenvalues of modulus 1 and phase 2 atan(Ω/2) per step; Chopra 2012, §5.5).
pub fn newmark_period_ratio(dt_over_t: f64) -> f64 {
    let omega = 2.0 * std::f64::consts::PI * dt_over_t;
    if omega == 0.0 {
        1.0
    } else {
        omega / (2.0 * (0.5 * omega).atan())
    }
}

/// The peak |horizontal force| and |uplift| of the largest wave of `waves` (regular waves: the
/// nominal height at the top of its variability, H (1 + cov k) or H (1 + δ); irregular waves:
/// H_max = 1.8 H1/3) at the wall, totals over the caisson's length (the larger of the
/// quasi-static and the impact components), N; `None` if the wave's loads cannot be evaluated.
pub fn nominal_wave_peak(waves: &WaveSetup) -> Option<WaveForce> {
    let h = match waves.train.kind {
        TrainKind::Regular { height_m, variability } => match variability {
            HeightVariability::Normal { cov, truncation_sigmas } => height_m * (1.0 + cov * truncation_sigmas),
            HeightVariability::Uniform { half_width } => height_m * (1.0 + half_width),
            HeightVariability::None => height_m,
        },
        TrainKind::Irregular { significant_height_m } => NOMINAL_HMAX_RATIO * significant_height_m,
    };
    let m = &waves.model;
    // A forced regime the wave contradicts (non-breaking above the limit): the criterion decides.
    let loads = m
        .evaluate_with(h, waves.period_s(), m.options.regime)
        .or_else(|_| m.evaluate_with(h, waves.period_s(), RegimeChoice::Auto))
        .ok()?;
    let e = m.event(&loads, None, 0.0);
    Some(WaveForce {
        fx_n: e.impact.x.fx_n.abs().max(e.quasi.x.fx_n.abs()),
        fy_n: e.impact.y.fy_n.abs().max(e.quasi.y.fy_n.abs()),
        m_nm: 0.0,
    })
}

/// A load's peak above [`MAX_LOAD_OVER_WEIGHT`] × W' (refused by the scenario): the first of the
/// peak |horizontal force| and |uplift| beyond it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OverWeight {
    /// The uplift (else the horizontal force).
    pub uplift: bool,
    /// Its magnitude, N.
    pub force_n: f64,
    /// force / W'.
    pub ratio: f64,
}

/// The peak |F_x| or |F_y| of `peak` above [`MAX_LOAD_OVER_WEIGHT`] times the weight in water
/// `weight_in_water_n`, if any (the horizontal force first).
pub fn over_weight(weight_in_water_n: f64, peak: WaveForce) -> Option<OverWeight> {
    let w = weight_in_water_n;
    [peak.fx_n.abs(), peak.fy_n.abs()]
        .into_iter()
        .enumerate()
        .find(|&(_, f)| f > MAX_LOAD_OVER_WEIGHT * w)
        .map(|(i, f)| OverWeight { uplift: i == 1, force_n: f, ratio: f / w })
}

/// What a load's peak is checked against: the scenario's keys to name in a message.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LoadSource {
    /// A `[load]` table (a pulse or a force series): its forces are totals in kN.
    Load,
    /// The wave loads of `[waves]`: per metre × `[caisson] length_m`.
    Waves,
}

impl LoadSource {
    /// What to check when a load is far above the weight.
    pub fn likely_slip(self) -> &'static str {
        match self {
            LoadSource::Load => "are `[load] peak_horizontal_kn` and `peak_uplift_kn` (or the series file's fx_kn, fy_kn) in kN, not N, and is `[caisson] weight_in_water_kn` in kN, not MN?",
            LoadSource::Waves => "is `[caisson] weight_in_water_kn` in kN (not MN) and the total over `[caisson] length_m`, and `length_m` in m (not mm)?",
        }
    }
}

/// The check of a load's peak forces against the caisson's weight in water (module docs).
pub fn load_warnings(s: &Structure, peak: WaveForce, source: LoadSource) -> Vec<Warning> {
    let w = s.caisson.weight_in_water_n;
    let mut out = Vec::new();
    for (what, force) in [("horizontal force", peak.fx_n.abs()), ("uplift", peak.fy_n.abs())] {
        if force > PLAUSIBLE_LOAD_OVER_WEIGHT * w {
            out.push(Warning::new(
                "implausible-load",
                format!(
                    "the peak wave {what} is {:.4e} kN, {:.0} times the weight in water W' = {:.4} kN, where wave loads on a caisson reach a few times W': {}",
                    force / 1e3,
                    force / w,
                    w / 1e3,
                    source.likely_slip()
                ),
                &[("peak_kn", force / 1e3), ("weight_in_water_kn", w / 1e3), ("limit_over_weight", PLAUSIBLE_LOAD_OVER_WEIGHT)],
            ));
            break;
        }
    }
    out
}

/// [`load_warnings`] of a `[load]`.
pub fn run_load_warnings(s: &Structure, load: &LoadSpec) -> Vec<Warning> {
    load_warnings(s, load.peak_abs(), LoadSource::Load)
}

/// [`load_warnings`] of the largest wave of `waves` ([`nominal_wave_peak`]).
pub fn wave_load_warnings(s: &Structure, waves: &WaveSetup) -> Vec<Warning> {
    let mut out = nominal_wave_peak(waves).map_or_else(Vec::new, |p| load_warnings(s, p, LoadSource::Waves));
    out.extend(design_wave_warnings(s, waves));
    out
}

/// Warnings of the static checks: an overturning safety factor below 1 under the design wave;
/// and the breaking-wave load `goda-takahashi` taken without a berm width (B_M = 0, the profile's
/// default) where the design wave breaks at the wall and a berm of 0.12 L, the most impulsive of
/// Takahashi's coefficient, would make α_I exceed α2 (docs/model.md §5.5).
pub fn design_wave_warnings(structure: &Structure, waves: &WaveSetup) -> Vec<Warning> {
    let Ok(c) = static_check(structure, waves) else { return Vec::new() };
    let mut out = without_berm_warning(waves, &c.loads).into_iter().collect::<Vec<_>>();
    out.extend(overturning_warning(&c));
    out
}

/// The warning of the breaking-wave load's coefficients under the design wave,
/// `impulsive-coefficient-without-berm`, alone: for reports whose width varies (a sizing), where
/// the rest of [`design_wave_warnings`] reads the starting caisson.
pub fn breaking_load_warnings(structure: &Structure, waves: &WaveSetup) -> Vec<Warning> {
    let Ok(c) = static_check(structure, waves) else { return Vec::new() };
    without_berm_warning(waves, &c.loads).into_iter().collect()
}

/// `impulsive-coefficient-without-berm` ([`design_wave_warnings`]).
fn without_berm_warning(waves: &WaveSetup, l: &crate::loads::model::WaveLoads) -> Option<Warning> {
    use crate::loads::breaking_load::BreakingLoad;
    use crate::loads::goda::takahashi_alpha_i;
    let site = &waves.model.site;
    let breaking = l.regime.regime == crate::loads::regime::Regime::Breaking;
    if waves.model.options.breaking_load != BreakingLoad::GodaTakahashi || site.berm_width_m.is_some() || !breaking {
        return None;
    }
    let berm_m = 0.12 * l.toe_wavelength_m;
    let (h, d) = (l.height_m, site.depth_at_wall_m);
    let with_berm = takahashi_alpha_i(h, l.toe_wavelength_m, site.depth_at_toe_m, d, berm_m);
    let without = l.impulsive_goda.and_then(|g| g.alpha_i).unwrap_or(f64::NAN);
    let alpha2 = l.pulsating.alpha2;
    (with_berm > alpha2).then(|| Warning {
        code: "impulsive-coefficient-without-berm",
        message: format!(
            "the breaking-wave load (`[waves] breaking_load = \"goda-takahashi\"`, the profile's default) takes Takahashi's impulsive coefficient with no berm, B_M = 0, as no `[water] berm_width_m` is given: α_I = {without:.3} under the design wave (H_D = {h:.2} m, α2 = {alpha2:.3}); a berm of 0.12 L = {berm_m:.1} m would give α_I = {with_berm:.3} and an impulsive peak above Goda's pulsating load: give the mound's `berm_width_m`"
        ),
        numbers: [
            ("alpha_i_without_berm", without),
            ("alpha_i_with_berm_of_0_12_l", with_berm),
            ("alpha2", alpha2),
            ("berm_width_0_12_l_m", berm_m),
            ("design_height_m", h),
        ]
        .into_iter()
        .collect(),
    })
}

/// `overturning-under-design-wave` ([`design_wave_warnings`]).
fn overturning_warning(c: &crate::analysis::conventional::StaticCheck) -> Option<Warning> {
    match c.safety.overturning {
        Some(sf) if sf < 1.0 => Some(Warning {
            code: "overturning-under-design-wave",
            message: format!(
                "Goda's overturning safety factor under the design wave (H_D = {:.2} m) is {sf:.2}: the caisson would tip about its heel, and the dynamic model does not follow overturning (its rotations are small, its foundation elastic); widen the caisson (Goda requires 1.2) before reading its sliding",
                c.design_wave.design_height_m
            ),
            numbers: [("overturning_safety_factor", sf), ("design_height_m", c.design_wave.design_height_m)]
                .into_iter()
                .collect(),
        }),
        _ => None,
    }
}

/// Checks of a run's response on `s` (module docs).
pub fn response_warnings(s: &Structure, r: &Response) -> Vec<Warning> {
    let mut out = Vec::new();
    if r.max_dashpot_over_friction > 1.0 {
        out.push(Warning::new(
            "dashpot-exceeds-friction",
            format!(
                "while the caisson slid, the foundation dashpot on its total velocity carried up to {:.2} times the friction force: the dashpot, not friction, limits the slide (`damping_mode = \"total\"`, the seed's literal Eq. 15); the consistent placement is `damping_mode = \"elastic\"`, the default profile's",
                r.max_dashpot_over_friction
            ),
            &[("max_dashpot_over_friction", r.max_dashpot_over_friction)],
        ));
    }
    let global_rotational = s.foundation.vertical_damping == VerticalDamping::Seed;
    if global_rotational && r.max_wave_moment_nm > 0.0 && r.max_dashpot_moment_nm > 0.5 * r.max_wave_moment_nm {
        out.push(Warning::new(
            "rotational-dashpot-moment",
            format!(
                "the vertical and rotational dashpots carried up to {:.4} kN·m, {:.0} % of the largest wave moment {:.4} kN·m: they, not the springs, hold the caisson against overturning (with `vertical_damping = \"seed\"` the seed's 10 C is used as N·m·s/rad); the consistent form is `vertical_damping = \"springs\"`, the default profile's",
                r.max_dashpot_moment_nm / 1e3,
                100.0 * r.max_dashpot_moment_nm / r.max_wave_moment_nm,
                r.max_wave_moment_nm / 1e3
            ),
            &[("max_dashpot_moment_kn_m", r.max_dashpot_moment_nm / 1e3), ("max_wave_moment_kn_m", r.max_wave_moment_nm / 1e3)],
        ));
    }
    if r.slip_events == 0 && r.sliding_m.abs() > 1e-6 {
        out.push(Warning::new(
            "rocking-without-slip",
            format!(
                "the caisson ends {:.3} mm from where it started although no spring slipped: the displacement comes from rocking (lifted springs re-contact at a displaced base), not from sliding",
                r.sliding_m * 1e3
            ),
            &[("sliding_m", r.sliding_m)],
        ));
    }
    let b = s.caisson.width_m;
    if r.max_rotation_rad > ROCKING_LIMIT_RAD {
        out.push(Warning::new(
            "rocking",
            format!(
                "the caisson rocked up to {:.4} rad (its heel lifted {:.3} m): beyond small rotations the model's kinematics and its foundation (the weight on part of the base) do not hold, and the landing can slide it seaward (docs/design.md): the model does not follow overturning, so check overturning and the bearing capacity of the mound under the heel for this wave otherwise",
                r.max_rotation_rad,
                r.max_rotation_rad * b
            ),
            &[("max_rotation_rad", r.max_rotation_rad), ("limit_rad", ROCKING_LIMIT_RAD)],
        ));
    }
    let limit = FAILURE_FRACTION_OF_WIDTH * b;
    if r.sliding_m.abs() > limit {
        out.push(Warning::new(
            "beyond-failure",
            format!(
                "the caisson slid {:.3} m, beyond the failure limit of a quarter of its base width ({limit:.3} m): it has left the bedding the model describes, and the model no longer holds",
                r.sliding_m
            ),
            &[("sliding_m", r.sliding_m), ("limit_m", limit)],
        ));
    }
    if r.sliding_m.abs() > ABSURD_SLIDING_OVER_WIDTH * b {
        out.push(Warning::new(
            "sliding-beyond-width",
            format!(
                "the caisson slid {:.4} m, {:.1} times its base width B = {b} m: {BEYOND_WIDTH}",
                r.sliding_m,
                r.sliding_m.abs() / b
            ),
            &[("sliding_m", r.sliding_m), ("width_m", b)],
        ));
    }
    out
}

/// The plausibility warnings of realizations `rs` of `case`: each code once, from the first
/// realization that raises it, with the count of realizations that do.
pub fn realization_warnings(case: &TrainCase<'_>, rs: &[RealizationResult]) -> Vec<Warning> {
    let mut out: Vec<(Warning, usize)> = Vec::new();
    for r in rs {
        for w in response_warnings(case.structure, &r.response) {
            match out.iter_mut().find(|(x, _)| x.code == w.code) {
                Some((_, n)) => *n += 1,
                None => {
                    let mut w = w;
                    w.message = format!("realization {}: {}", r.index, w.message);
                    out.push((w, 1));
                }
            }
        }
    }
    out.into_iter()
        .map(|(mut w, n)| {
            w.message.push_str(&format!(" ({n} of {} realizations)", rs.len()));
            w.numbers.insert("realizations", n as f64);
            w
        })
        .collect()
}

/// The share above which the impulsive waves are said to make an answer (module docs,
/// `impulsive-share`).
pub const IMPULSIVE_SHARE_WARNED: f64 = 0.5;

/// Goda's (2000) conditions that signal a danger of impulsive breaking pressure (docs/model.md
/// §1.4) at a site, under a sea of H1/3 and T1/3: the ratios they read and whether either set
/// holds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpulsiveBreakingDanger {
    /// β, the angle of incidence after Goda's 15° rotation, degrees.
    pub angle_deg: f64,
    /// B_M/L: the berm width over the wavelength at the toe depth h.
    pub berm_over_wavelength: f64,
    /// tan θ of the seabed.
    pub seabed_slope: f64,
    /// H0'/L0: the equivalent deep-water height over the deep-water wavelength.
    pub deep_water_steepness: f64,
    /// h_c/H1/3 and d/h.
    pub crest_over_height: f64,
    pub mound_depth_ratio: f64,
    /// β < 20°, B_M/L < 0.02, seabed steeper than 1/50, H0'/L0 < 0.03 and h_c/H1/3 > 0.3; or
    /// β < 20°, 0.02 < B_M/L < 0.3, d/h < 0.6 and h_c/H1/3 > 0.3.
    pub danger: bool,
}

/// [`ImpulsiveBreakingDanger`] of the site of `model` under the sea `h13_m`, `period_s` (a site
/// without `berm_width_m` taken as a mound without a berm, B_M = 0); `None` where it cannot be
/// assessed (no equivalent deep-water height).
pub fn impulsive_breaking_danger(model: &WaveLoadModel, h13_m: f64, period_s: f64) -> Option<ImpulsiveBreakingDanger> {
    let s = &model.site;
    let berm_m = s.berm_width_m.unwrap_or(0.0);
    let h0 = equivalent_deep_water_height_m(h13_m, period_s, s.depth_at_toe_m, s.seabed_slope)?;
    let l = 2.0 * std::f64::consts::PI / wavenumber(period_s, s.depth_at_toe_m);
    let beta = (model.options.angle_rad.abs().to_degrees() - 15.0).max(0.0);
    let d = ImpulsiveBreakingDanger {
        angle_deg: beta,
        berm_over_wavelength: berm_m / l,
        seabed_slope: s.seabed_slope,
        deep_water_steepness: h0 / deep_water_wavelength_m(period_s),
        crest_over_height: s.crest_freeboard_m / h13_m,
        mound_depth_ratio: s.depth_at_wall_m / s.depth_at_toe_m,
        danger: false,
    };
    let first = d.berm_over_wavelength < 0.02 && d.seabed_slope > 1.0 / 50.0 && d.deep_water_steepness < 0.03;
    let second = d.berm_over_wavelength > 0.02 && d.berm_over_wavelength < 0.3 && d.mound_depth_ratio < 0.6;
    Some(ImpulsiveBreakingDanger { danger: beta < 20.0 && d.crest_over_height > 0.3 && (first || second), ..d })
}

/// The breaking-wave load rule of `model` in words, with its uncertainty.
pub fn breaking_load_rule(model: &WaveLoadModel) -> String {
    let o = &model.options;
    match o.breaking_load {
        BreakingLoad::Cuomo2010 => format!(
            "`breaking_load = \"cuomo-2010\"`, the seed's impact force of Cuomo et al. (2010, seed Eq. 30) with a_imp = {} and α_max = {:.4}, whose coefficient could not be confirmed (docs/model.md §5.1: M-low)",
            o.a_imp, o.alpha_max
        ),
        BreakingLoad::GodaTakahashi => "`breaking_load = \"goda-takahashi\"`, Goda's force with Takahashi's impulsive coefficient α* = max(α2, α_I) (Takahashi, Tanimoto & Shimosako 1994; docs/model.md §5.5)".to_string(),
        BreakingLoad::None => "`breaking_load = \"none\"`, which gives no impulsive peak".to_string(),
    }
}

/// The warnings of what the impulsive waves make of an answer (module docs, `impulsive-share`):
/// `shares` of the dynamic model and the rigid block, on the site of `model`, with the design
/// sea of `waves` (for Goda's conditions; none: not assessed).
pub fn impulsive_warnings(
    shares: [&ImpulsiveShare; 2],
    model: &WaveLoadModel,
    waves: Option<&WaveSetup>,
) -> Vec<Warning> {
    let names = ["the dynamic model", "the rigid block"];
    let over: Vec<String> = shares
        .iter()
        .zip(names)
        .filter(|(s, _)| s.dominates())
        .map(|(s, name)| {
            format!(
                "{name}: {:.0} % of E|S| (as simulated) and {:.0} % of its {} failures",
                100.0 * s.share_of_expected_sliding,
                100.0 * s.share_of_failures,
                s.failures
            )
        })
        .collect();
    if over.is_empty() {
        return Vec::new();
    }
    let numbers = [
        ("dynamic_share_of_expected_sliding", shares[0].share_of_expected_sliding),
        ("dynamic_share_of_failures", shares[0].share_of_failures),
        ("rigid_block_share_of_expected_sliding", shares[1].share_of_expected_sliding),
        ("rigid_block_share_of_failures", shares[1].share_of_failures),
        ("share_warned", IMPULSIVE_SHARE_WARNED),
    ];
    let rule = breaking_load_rule(model);
    let mut out = vec![Warning::new(
        "impulsive-share",
        format!(
            "impulsive waves make more than half of the answer ({}): it rests on the breaking-wave load rule, {rule}; check the rule against the site's breaking conditions (docs/model.md §1.4 and §5.1)",
            over.join("; ")
        ),
        &numbers,
    )];
    let danger = waves.and_then(|w| impulsive_breaking_danger(model, w.height_m(), w.period_s()));
    if let (Some(d), Some(w)) = (danger, waves) {
        if !d.danger {
            let mut numbers = numbers.to_vec();
            numbers.extend([
                ("berm_over_wavelength", d.berm_over_wavelength),
                ("seabed_slope", d.seabed_slope),
                ("deep_water_steepness", d.deep_water_steepness),
                ("crest_over_height", d.crest_over_height),
                ("mound_depth_ratio", d.mound_depth_ratio),
                ("angle_deg", d.angle_deg),
            ]);
            out.push(Warning::new(
                "impulsive-share-outside-goda-conditions",
                format!(
                    "impulsive waves make more than half of the answer at a site outside Goda's (2000) conditions of a danger of impulsive breaking under the design sea (H1/3 = {} m, T1/3 = {} s: B_M/L = {:.3}, seabed slope {:.4}, H0'/L0 = {:.4}, h_c/H1/3 = {:.2}, d/h = {:.2}, β = {:.0}°; docs/model.md §1.4): Goda's practice expects no impulsive pressure there, the load rule ({rule}) expects it to govern",
                    w.height_m(),
                    w.period_s(),
                    d.berm_over_wavelength,
                    d.seabed_slope,
                    d.deep_water_steepness,
                    d.crest_over_height,
                    d.mound_depth_ratio,
                    d.angle_deg
                ),
                &numbers,
            ));
        }
    }
    out
}

/// Checks of a design run's lives with the failure limits `failure`, of a caisson of base width
/// `width_m`.
pub fn life_warnings(lives: &[StormOutcome], failure: &FailureLimits, width_m: f64) -> Vec<Warning> {
    counts_warnings(&LifeCounts::of(lives, failure), failure, width_m)
}

/// [`life_warnings`] of a sizing candidate (the dynamic model's lives at its width), from the
/// counts it keeps; `failure`: the limits at its width.
pub fn candidate_warnings(c: &Candidate, failure: &FailureLimits) -> Vec<Warning> {
    counts_warnings(&c.life_counts, failure, c.width_m)
}

/// The life warnings of `c` (module docs).
pub fn counts_warnings(c: &LifeCounts, failure: &FailureLimits, width_m: f64) -> Vec<Warning> {
    let mut out = Vec::new();
    let n = c.lives as f64;
    let storm = c.max_storm_sliding_m;
    let b = width_m;
    // The statistics themselves beyond the width (a life or a storm alone beyond it is a failed
    // life, `failed-lives`: rare extreme storms do that to sound designs). The larger mean of
    // the two models tells.
    let (mean, which) = if c.rigid_block_expected_sliding_m > c.expected_sliding_uncapped_m {
        (c.rigid_block_expected_sliding_m, "of the rigid block over the whole lives")
    } else {
        (c.expected_sliding_uncapped_m, "of the dynamic model as simulated")
    };
    if mean > ABSURD_SLIDING_OVER_WIDTH * b {
        out.push(Warning::new(
            "sliding-beyond-width",
            format!(
                "the lives slid {mean:.4} m on average (E|S| {which}, {:.1} times the base width B = {b} m) and a single storm slid the caisson up to {storm:.4} m ({:.1} B): {BEYOND_WIDTH}",
                mean / b,
                storm / b
            ),
            &[
                ("expected_sliding_uncapped_m", c.expected_sliding_uncapped_m),
                ("rigid_block_expected_sliding_m", c.rigid_block_expected_sliding_m),
                ("max_storm_sliding_m", storm),
                ("width_m", b),
            ],
        ));
    }
    let (sliding_m, rotation_rad) = (failure.sliding_m, failure.rotation_rad);
    // "of 903 lives", or of a stratified run's simulated lives, which are not the climate's mix.
    let of = match c.weighted_failure_probability {
        None => format!("{} lives", c.lives),
        Some(_) => format!(
            "{} simulated lives of a stratified sample (the severe storms oversampled; the statistics weight them back)",
            c.lives
        ),
    };
    if c.failed_lives > 0 {
        out.push(Warning::new(
            "failed-lives",
            format!(
                "{} of {of} failed{}: {} moved the caisson more than {sliding_m:.3} m from its place ([design] failure_sliding_m, default a quarter of the base width), {} rotated it beyond {rotation_rad} rad ([design] failure_rotation_rad){}; what the model computes after that is outside its validity, so a failed life enters E|S| at the sliding limit (E|S| as simulated runs it on{}): read the failure probability and the statistics of the surviving lives",
                c.failed_lives,
                c.weighted_failure_probability.map_or(String::new(), |p| format!(" (weighted, P(failure) = {p:.3})")),
                c.failed_by_sliding_lives,
                c.failed_by_rotation_lives,
                failure.heel_pressure_pa.map_or(String::new(), |q| format!(
                    " and {} pressed the heel beyond {:.0} kPa ([design] failure_heel_pressure_kpa)",
                    c.failed_by_heel_pressure_lives,
                    q / 1e3
                )),
                if c.run_on_stopped_lives > 0 {
                    format!(
                        "; in {} of them a later wave did not converge and the dynamic model stopped there, run_on_stopped in lives.csv",
                        c.run_on_stopped_lives
                    )
                } else {
                    String::new()
                }
            ),
            &[
                ("failed_lives", c.failed_lives as f64),
                ("failed_by_sliding_lives", c.failed_by_sliding_lives as f64),
                ("failed_by_rotation_lives", c.failed_by_rotation_lives as f64),
                ("failed_by_heel_pressure_lives", c.failed_by_heel_pressure_lives as f64),
                ("run_on_stopped_lives", c.run_on_stopped_lives as f64),
                ("lives", n),
                ("failure_probability", c.weighted_failure_probability.unwrap_or(c.failed_lives as f64 / n.max(1.0))),
                ("failure_sliding_m", sliding_m),
                ("failure_rotation_rad", rotation_rad),
            ],
        ));
    }
    if c.large_rotation_lives > 0 {
        out.push(Warning::new(
            "large-rotation-lives",
            format!(
                "in {} of {of} a wave rotated the caisson beyond {ROCKING_LIMIT_RAD} rad (the seaward heel lifts by θB/2): the model does not follow overturning (large rotations, the bearing capacity of the mound under the heel), so check overturning and the mound for these waves otherwise (docs/design.md)",
                c.large_rotation_lives
            ),
            &[("large_rotation_lives", c.large_rotation_lives as f64), ("lives", n), ("rotation_limit_rad", ROCKING_LIMIT_RAD)],
        ));
    }
    if c.seaward_lives > 0 {
        out.push(Warning::new(
            "seaward-lives",
            format!(
                "{} of {of} ended more than {SEAWARD_REPORT_M} m seaward of their place (up to {:.3} m): the wave pushes shoreward, so these displacements come from the caisson rocking and landing (docs/design.md); the statistics use the magnitude |S|",
                c.seaward_lives, c.largest_seaward_sliding_m
            ),
            &[
                ("seaward_lives", c.seaward_lives as f64),
                ("lives", n),
                ("largest_seaward_sliding_m", c.largest_seaward_sliding_m),
                ("seaward_threshold_m", SEAWARD_REPORT_M),
            ],
        ));
    }
    out
}

/// Checks of a fragility run's storms on a caisson of base width `width_m`: storms that slid it
/// beyond its width (`sliding-beyond-width`; the exceedance counts of limits below it stand).
pub fn storm_warnings<'a>(storms: impl Iterator<Item = &'a StormOutcome>, width_m: f64) -> Vec<Warning> {
    let (mut n, mut beyond, mut worst) = (0usize, 0usize, 0.0f64);
    for s in storms {
        n += 1;
        let slid = s.sliding_m.abs().max(s.max_storm_sliding_m);
        if slid > ABSURD_SLIDING_OVER_WIDTH * width_m {
            beyond += 1;
        }
        worst = worst.max(slid);
    }
    if beyond == 0 {
        return Vec::new();
    }
    vec![Warning::new(
        "sliding-beyond-width",
        format!(
            "{beyond} of {n} storms slid the caisson beyond its base width B = {width_m} m (up to {worst:.4} m): they count as exceeding every limit, but their sliding is no prediction: {BEYOND_WIDTH}"
        ),
        &[("storms_beyond_width", beyond as f64), ("storms", n as f64), ("max_storm_sliding_m", worst), ("width_m", width_m)],
    )]
}

/// `lives = "auto"` whose budget ran out before the target precision (`precision-not-met`):
/// the statistics are of the budget's lives, less precise than asked; `what` names the run ("the
/// design run", "the candidate at 23.5 m").
pub fn precision_warning(p: &AutoPrecision, what: &str) -> Option<Warning> {
    if p.met {
        return None;
    }
    let failure = p.failure_relative_error.map_or_else(
        || {
            format!(
                "no failure, its 95 % upper bound {:.2e} not below {:.0e}",
                p.failure_probability_upper, p.failure_probability_floor
            )
        },
        |r| format!("{r:.3}"),
    );
    Some(Warning::new(
        "precision-not-met",
        format!(
            "{what} took its whole budget of {} lives (max_lives) without reaching the target relative error {}: E|S| {:.3}, P(failure) {failure}; its statistics are less precise than asked: raise max_lives (and the work budget) or the target",
            p.max_lives, p.target_relative_error, p.expected_sliding_relative_error
        ),
        &[
            ("lives", p.lives as f64),
            ("max_lives", p.max_lives as f64),
            ("target_relative_error", p.target_relative_error),
            ("expected_sliding_relative_error", p.expected_sliding_relative_error),
            ("failure_probability_upper", p.failure_probability_upper),
        ],
    ))
}
