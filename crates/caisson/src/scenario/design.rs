//! `[design]`: the lifetime Monte Carlo of performance-based design (docs/model.md §6.4), read
//! into [`DesignParams`] (the life model and the run controls), whose constructors hold the rules
//! of the values ([`DesignParams::checked`], and those of its parts: `StormDistribution::weibull`,
//! `ErrorModel::new`, the climate's); this file reads the keys (missing, together or not, names of
//! choices, whole numbers) and names a refusal's key. Every key is documented in
//! `docs/design.md`; the defaults are the values docs/model.md §6.4 cites (Goda & Takagi 2000;
//! Takayama & Ikeda 1992 via Shimosako & Takahashi 1999; Kim & Takayama 2003 for the truncation).

use super::waves::{self, seed_of};
use super::{ScenarioError, ScenarioFile};
use crate::analysis::climate::{
    Climate, SeaLevelError, SeaLevelRise, StormDuration, StormModel, WaveDirection, WavePeriods, MAX_SEA_LEVEL_POINTS,
};
use crate::analysis::lifetime::Sampling;
use crate::analysis::lifetime::{
    AutoLives, DesignParams, ErrorModel, ErrorScope, Errors, LifeParams, StormDistribution, DEFAULT_AUTO_MAX_LIVES,
    DEFAULT_TARGET_RELATIVE_ERROR, MAX_LIFE_YEARS,
};
use crate::analysis::limits::ROCKING_LIMIT_RAD;
use crate::waves::periods::DEFAULT_SPECTRAL_WIDTH;
use serde::Deserialize;

pub use crate::analysis::lifetime::{MAX_FAILURE_ROTATION_RAD, MAX_LIVES, STANDARD_THRESHOLDS_M};

type R<T> = Result<T, ScenarioError>;

/// `[design]` as written.
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct DesignTable {
    pub life_years: Option<i64>,
    /// A whole number, or `"auto"` (lives to `target_relative_error`, at most `max_lives`).
    pub lives: Option<LivesKey>,
    /// `lives = "auto"`: the target relative standard error of E|S| and of P(failure).
    pub target_relative_error: Option<f64>,
    /// `lives = "auto"`: the most lives the run may take.
    pub max_lives: Option<i64>,
    pub seed: Option<i64>,
    /// `"weibull"` or `"gumbel"`.
    pub storm_distribution: Option<String>,
    pub storm_scale_m: Option<f64>,
    pub storm_shape: Option<f64>,
    pub storm_location_m: Option<f64>,
    pub period_coefficient: Option<f64>,
    pub period_exponent: Option<f64>,
    pub storm_duration_h: Option<f64>,
    pub tidal_range_m: Option<f64>,
    pub deep_water_height_bias: Option<f64>,
    pub deep_water_height_cov: Option<f64>,
    pub transformation_bias: Option<f64>,
    pub transformation_cov: Option<f64>,
    pub wave_force_bias: Option<f64>,
    pub wave_force_cov: Option<f64>,
    pub friction_bias: Option<f64>,
    pub friction_cov: Option<f64>,
    pub error_truncation_sigmas: Option<f64>,
    /// Extra sliding thresholds, m (0.03, 0.1, 0.3, 1 and 3 m are always reported).
    pub thresholds_m: Option<Vec<f64>>,
    pub screen: Option<bool>,
    /// `"plain"` (default: every life simulated) or `"stratified"` (docs/design.md).
    pub sampling: Option<String>,
    /// The failure limit on the caisson's distance from its place, m (default B/4).
    pub failure_sliding_m: Option<f64>,
    /// The failure limit on the caisson's rotation, rad (default 0.01).
    pub failure_rotation_rad: Option<f64>,
    /// Refused with a note: every life runs to its end, its failure recorded (docs/design.md).
    pub continue_after_failure: Option<bool>,
    /// The allowable heel pressure, kPa (default 500, as `[size] allowable_heel_pressure_kpa`).
    pub allowable_heel_pressure_kpa: Option<f64>,
    /// The heel pressure beyond which a life fails, kPa (default: no such failure mode).
    pub failure_heel_pressure_kpa: Option<f64>,
    /// `"annual-maxima"` (default) or `"peaks-over-threshold"`.
    pub storm_model: Option<String>,
    /// Peaks over threshold: the mean number of storms a year.
    pub storm_rate_per_year: Option<f64>,
    /// Peaks over threshold: the threshold of the deep-water H1/3, m.
    pub storm_threshold_m: Option<f64>,
    /// `"storm"` (default: errors drawn for every storm) or `"life"` (once per life).
    pub error_scope: Option<String>,
    /// Whether the errors are truncated at ±`error_truncation_sigmas` (default true).
    pub error_truncated: Option<bool>,
    /// The impulsive component's own error (default: the wave force's).
    pub impact_force_bias: Option<f64>,
    pub impact_force_cov: Option<f64>,
    /// The rise of the still-water level at the end of the life, m (linear from 0).
    pub sea_level_rise_m: Option<f64>,
    /// The rise as a table of [years from the start of the life, m] points.
    pub sea_level_rise_table: Option<Vec<Vec<f64>>>,
    /// `"head-on"` (default), `"normal"` or `"uniform"`: the storms' angle to the normal.
    pub wave_direction: Option<String>,
    /// The mean angle to the breakwater's normal, degrees.
    pub wave_direction_mean_deg: Option<f64>,
    /// The standard deviation (normal) or half-width (uniform) of the angle, degrees.
    pub wave_direction_spread_deg: Option<f64>,
    /// `"fixed"` (default) or `"lognormal"` (mean `storm_duration_h`).
    pub storm_duration_model: Option<String>,
    /// Lognormal durations: the coefficient of variation.
    pub storm_duration_cov: Option<f64>,
    /// `"significant"` (default: every wave at T1/3) or `"longuet-higgins"` (each wave's period
    /// given its height).
    pub wave_periods: Option<String>,
    /// Longuet-Higgins periods: the spectral width ν.
    pub period_spectral_width: Option<f64>,
}

/// A `lives` key as written: a whole number or a word (`"auto"`); any other type is refused
/// with the words of what is allowed.
#[derive(Debug, Clone)]
pub enum LivesKey {
    Count(i64),
    Word(String),
}

impl<'de> Deserialize<'de> for LivesKey {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl serde::de::Visitor<'_> for V {
            type Value = LivesKey;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a whole number (or \"auto\": lives to `target_relative_error`)")
            }
            fn visit_i64<E: serde::de::Error>(self, v: i64) -> Result<LivesKey, E> {
                Ok(LivesKey::Count(v))
            }
            fn visit_u64<E: serde::de::Error>(self, v: u64) -> Result<LivesKey, E> {
                Ok(LivesKey::Count(i64::try_from(v).unwrap_or(i64::MAX)))
            }
            fn visit_str<E: serde::de::Error>(self, v: &str) -> Result<LivesKey, E> {
                Ok(LivesKey::Word(v.to_string()))
            }
        }
        d.deserialize_any(V)
    }
}

/// The lives of `table`'s `lives`, `target_relative_error` and `max_lives` keys: a fixed count
/// (`default` when absent, refused outside 1..=`hi`), or with `lives = "auto"` the budget
/// (`max_lives`, default [`DEFAULT_AUTO_MAX_LIVES`] capped at `hi`) and the target (default
/// [`DEFAULT_TARGET_RELATIVE_ERROR`]); the two keys of "auto" are refused beside a count.
pub(super) fn lives_keys(
    table: &str,
    (lives, target, max_lives): (&Option<LivesKey>, Option<f64>, Option<i64>),
    default: (usize, Option<AutoLives>),
    hi: usize,
) -> R<(usize, Option<AutoLives>)> {
    let whole = |key: &str, n: i64| -> R<usize> {
        if (1..=hi as i64).contains(&n) {
            Ok(n as usize)
        } else {
            Err(ScenarioError::range(&format!("{table} {key}"), n, format!("must be a whole number from 1 to {hi}")))
        }
    };
    match lives {
        Some(LivesKey::Word(w)) if w == "auto" => {
            let target_relative_error = target.unwrap_or(DEFAULT_TARGET_RELATIVE_ERROR);
            let auto = AutoLives { target_relative_error }.checked().map_err(|e| {
                ScenarioError::range(
                    &format!("{table} target_relative_error"),
                    super::fmt_value(target_relative_error),
                    e.allowed.describe(1.0, "the relative standard error of E|S| and of P(failure), e.g. 0.05"),
                )
            })?;
            let budget = max_lives.map_or(Ok(DEFAULT_AUTO_MAX_LIVES.min(hi)), |n| whole("max_lives", n))?;
            Ok((budget, Some(auto)))
        }
        Some(LivesKey::Word(w)) => Err(ScenarioError::range(
            &format!("{table} lives"),
            format!("\"{w}\""),
            format!("must be a whole number from 1 to {hi}, or \"auto\" (lives to `target_relative_error`)"),
        )),
        other => {
            for (key, given) in [("target_relative_error", target.is_some()), ("max_lives", max_lives.is_some())] {
                if given {
                    return Err(ScenarioError::Conflict {
                        message: format!(
                            "`{table} {key}` is used only with lives = \"auto\" (lives to a target precision); set `{table} lives = \"auto\"` or remove it"
                        ),
                    });
                }
            }
            match other {
                Some(LivesKey::Count(n)) => Ok((whole("lives", *n)?, None)),
                _ => Ok(default),
            }
        }
    }
}

/// How a value of a key is shown in its refusal: as the key's value is read
/// ([`super::fmt_value`]), or as Rust writes the number.
#[derive(Clone, Copy)]
enum Shown {
    AsRead,
    Plain,
}

/// The keys of the quantities of the life model's types (named as in their types), without
/// their table, and their units.
const LIFE_KEYS: &[(&str, &str, &str, Shown)] = &[
    ("scale_m", "storm_scale_m", "m", Shown::AsRead),
    ("shape", "storm_shape", "-", Shown::AsRead),
    ("location_m", "storm_location_m", "m", Shown::AsRead),
    ("rate_per_year", "storm_rate_per_year", "storms a year", Shown::AsRead),
    ("threshold_m", "storm_threshold_m", "m", Shown::AsRead),
    ("duration_cov", "storm_duration_cov", "fraction", Shown::AsRead),
    ("rise_m", "sea_level_rise_m", RISE_UNIT, Shown::AsRead),
    ("mean_deg", "wave_direction_mean_deg", "degrees from the breakwater's normal", Shown::AsRead),
    ("sd_deg", "wave_direction_spread_deg", "degrees", Shown::AsRead),
    ("half_width_deg", "wave_direction_spread_deg", "degrees", Shown::AsRead),
    ("spectral_width", "period_spectral_width", "", Shown::Plain),
    ("truncation_sigmas", "error_truncation_sigmas", "standard deviations", Shown::AsRead),
    ("life_years", "life_years", "", Shown::AsRead),
    ("period_coefficient", "period_coefficient", "s·m^−b", Shown::AsRead),
    ("period_exponent", "period_exponent", "-", Shown::AsRead),
    ("tidal_range_m", "tidal_range_m", "m", Shown::AsRead),
    ("lives", "lives", "", Shown::AsRead),
    ("failure_sliding_m", "failure_sliding_m", "m", Shown::AsRead),
    ("failure_rotation_rad", "failure_rotation_rad", "rad", Shown::AsRead),
];

/// The heel pressure keys of `[design]`, read in kPa, and the quantities of [`DesignParams`]
/// (in Pa) they give.
const HEEL_KEYS: [(&str, &str); 2] = [
    ("allowable_heel_pressure_pa", "allowable_heel_pressure_kpa"),
    ("failure_heel_pressure_pa", "failure_heel_pressure_kpa"),
];

/// The unit of the sea-level rise keys.
const RISE_UNIT: &str = "m; the still-water level's rise, at most 5 m";

/// A refused quantity of the life model under its key of `table` (`[design]` or `[fragility]`):
/// a range with the value shown as [`LIFE_KEYS`] says, a rule with the value as Rust writes it.
pub(super) fn keyed(table: &str, e: crate::ParamError) -> ScenarioError {
    let found = LIFE_KEYS.iter().find(|(q, ..)| *q == e.quantity);
    let (key, unit, shown) = found.map_or((e.quantity, "", Shown::Plain), |&(_, k, u, s)| (k, u, s));
    shown_under(&format!("{table} {key}"), e, unit, shown)
}

/// `e` under `key`, its bounds in `unit`.
fn shown_under(key: &str, e: crate::ParamError, unit: &str, shown: Shown) -> ScenarioError {
    let value = match (&e.allowed, shown) {
        (crate::Allowed::Rule(_), _) | (_, Shown::Plain) => e.value.to_string(),
        (_, Shown::AsRead) => super::fmt_value(e.value),
    };
    ScenarioError::range(key, value, e.allowed.describe(1.0, unit))
}

fn count(key: &str, v: Option<i64>, default: usize, hi: usize) -> R<usize> {
    match v {
        None => Ok(default),
        Some(n) if (1..=hi as i64).contains(&n) => Ok(n as usize),
        Some(n) => {
            Err(ScenarioError::range(&format!("[design] {key}"), n, format!("must be a whole number from 1 to {hi}")))
        }
    }
}

fn required(key: &str, v: Option<f64>, hint: &str) -> R<f64> {
    waves::required(&format!("[design] {key}"), v, hint)
}

/// Read `[design]` into [`DesignParams`], whose constructors check the values
/// ([`DesignParams::checked`] and those of its parts).
pub(super) fn validate_design(file: &ScenarioFile) -> R<DesignParams> {
    let t = file.design.as_ref().ok_or_else(|| {
        ScenarioError::missing(
            "[design]",
            "add a [design] table: storm_distribution, its parameters, life_years, lives",
        )
    })?;
    if let Some(v) = t.continue_after_failure {
        return Err(ScenarioError::range(
            "[design] continue_after_failure",
            v,
            "is not a key any more: every life runs to its end and records the wave that failed it, so both the capped and the as-simulated expected sliding are reported (docs/design.md, \"Direction, magnitude and failure\"); remove it",
        ));
    }
    let heel_kpa = |v: Option<f64>, key: &str| -> R<Option<f64>> {
        match v {
            Some(q) if q.is_nan() || q <= 0.0 || q.is_infinite() => Err(ScenarioError::range(
                &format!("[design] {key}"),
                super::fmt_value(q),
                "must be a pressure from 10 to 10000 kPa",
            )),
            v => Ok(v.map(|q| q * 1e3)),
        }
    };
    let allowable_heel_pressure_pa = heel_kpa(t.allowable_heel_pressure_kpa, "allowable_heel_pressure_kpa")?
        .unwrap_or(crate::analysis::lifetime::DEFAULT_ALLOWABLE_HEEL_PRESSURE_PA);
    let failure_heel_pressure_pa = heel_kpa(t.failure_heel_pressure_kpa, "failure_heel_pressure_kpa")?;
    let storms = distribution(t)?;
    let life_years = count("life_years", t.life_years, 50, MAX_LIFE_YEARS)?;
    let climate = Climate {
        storms: storm_model(t, &storms)?,
        duration: duration_model("[design]", &t.storm_duration_model, t.storm_duration_cov)?,
        sea_level: sea_level(t, life_years)?,
        direction: direction("[design]", &t.wave_direction, t.wave_direction_mean_deg, t.wave_direction_spread_deg)?,
        periods: wave_periods("[design]", &t.wave_periods, t.period_spectral_width)?,
    };
    let errors = errors("[design]", t)?;
    let extra = t.thresholds_m.as_deref().unwrap_or_default();
    let thresholds_m = DesignParams::thresholds_m(extra)
        .map_err(|(i, e)| shown_under(&format!("[design] thresholds_m[{i}]"), e, "m", Shown::Plain))?;
    let seed = seed_of("[design] seed", t.seed)?;
    let (lives, auto) =
        lives_keys("[design]", (&t.lives, t.target_relative_error, t.max_lives), (5000, None), MAX_LIVES)?;
    let params = DesignParams {
        life: LifeParams {
            life_years,
            storms,
            period_coefficient: t.period_coefficient.unwrap_or(3.3),
            period_exponent: t.period_exponent.unwrap_or(0.63),
            storm_duration_s: t.storm_duration_h.unwrap_or(2.0) * 3600.0,
            tidal_range_m: t.tidal_range_m.unwrap_or(0.0),
            errors,
            climate,
        },
        lives,
        seed,
        thresholds_m,
        screen: t.screen.unwrap_or(true),
        failure_sliding_m: t.failure_sliding_m,
        failure_rotation_rad: t.failure_rotation_rad.unwrap_or(ROCKING_LIMIT_RAD),
        allowable_heel_pressure_pa,
        failure_heel_pressure_pa,
        sampling: super::validate::choice(
            "[design] sampling",
            t.sampling.as_deref().unwrap_or("plain"),
            &[("plain", Sampling::Plain), ("stratified", Sampling::Stratified)],
        )?,
        auto,
    };
    params.checked().map_err(|e| match e.quantity {
        // Shown in hours, as read (the rule's bounds in seconds, shown in hours).
        "storm_duration_s" => ScenarioError::range(
            "[design] storm_duration_h",
            super::fmt_value(t.storm_duration_h.unwrap_or(2.0)),
            e.allowed.describe(1.0 / 3600.0, "h"),
        ),
        q => match HEEL_KEYS.iter().find(|(quantity, _)| *quantity == q) {
            Some((_, key)) => ScenarioError::range(
                &format!("[design] {key}"),
                super::fmt_value(e.value / 1e3),
                e.allowed.describe(1e-3, "kPa"),
            ),
            None => keyed("[design]", e),
        },
    })
}

/// `[design] storm_distribution` and its parameters.
fn distribution(t: &DesignTable) -> R<StormDistribution> {
    let dist = t.storm_distribution.as_deref().ok_or_else(|| {
        ScenarioError::missing(
            "[design] storm_distribution",
            "\"weibull\" or \"gumbel\" (annual maxima of the deep-water H1/3)",
        )
    })?;
    let storms = match dist {
        "weibull" => StormDistribution::weibull(
            required("storm_scale_m", t.storm_scale_m, "the Weibull scale A, m")?,
            required("storm_shape", t.storm_shape, "the Weibull shape k (0.75-2 typically)")?,
            t.storm_location_m.unwrap_or(0.0),
        ),
        "gumbel" => {
            if t.storm_shape.is_some() {
                return Err(ScenarioError::Conflict {
                    message: "`[design] storm_shape` is not used with storm_distribution = \"gumbel\"; remove it"
                        .into(),
                });
            }
            StormDistribution::gumbel(
                required("storm_location_m", t.storm_location_m, "the Gumbel location B, m")?,
                required("storm_scale_m", t.storm_scale_m, "the Gumbel scale A, m")?,
            )
        }
        other => {
            return Err(ScenarioError::range(
                "[design] storm_distribution",
                format!("\"{other}\""),
                "must be \"weibull\" or \"gumbel\"",
            ))
        }
    };
    storms.map_err(|e| keyed("[design]", e))
}

/// The estimation errors of `[design]` (or of the same keys of `table`, `[fragility]`'s): each
/// model's bias and COV, the truncation and the scope.
pub(super) fn errors(table: &str, t: &DesignTable) -> R<Errors> {
    let truncated = t.error_truncated.unwrap_or(true);
    if !truncated && t.error_truncation_sigmas.is_some() {
        return Err(ScenarioError::Conflict {
            message: format!("`{table} error_truncation_sigmas` is not used with error_truncated = false (untruncated normal errors); remove one of them"),
        });
    }
    let k = truncated.then_some(t.error_truncation_sigmas.unwrap_or(2.0));
    let d = Errors::default();
    let err = |name: &str, bias: Option<f64>, cov: Option<f64>, def: ErrorModel| -> R<ErrorModel> {
        ErrorModel::new(bias.unwrap_or(def.bias), cov.unwrap_or(def.cov), k).map_err(|e| match e.quantity {
            "bias" | "cov" => shown_under(&format!("{table} {name}_{}", e.quantity), e, "fraction", Shown::AsRead),
            _ => keyed(table, e),
        })
    };
    let wave_force = err("wave_force", t.wave_force_bias, t.wave_force_cov, d.wave_force)?;
    let impact_force = match (t.impact_force_bias, t.impact_force_cov) {
        (None, None) => None,
        (bias, cov) => Some(err("impact_force", bias, cov, wave_force)?),
    };
    let scope = match t.error_scope.as_deref().unwrap_or("storm") {
        "storm" => ErrorScope::Storm,
        "life" => ErrorScope::Life,
        other => {
            return Err(ScenarioError::range(
                "[design] error_scope",
                format!("\"{other}\""),
                "must be \"storm\" (errors drawn for every storm) or \"life\" (once per life)",
            ))
        }
    };
    Ok(Errors {
        deep_water_height: err(
            "deep_water_height",
            t.deep_water_height_bias,
            t.deep_water_height_cov,
            d.deep_water_height,
        )?,
        transformation: err("transformation", t.transformation_bias, t.transformation_cov, d.transformation)?,
        wave_force,
        friction: err("friction", t.friction_bias, t.friction_cov, d.friction)?,
        impact_force,
        scope,
    })
}

/// `[design] storm_model` and its keys (docs/design.md, "Climate").
fn storm_model(t: &DesignTable, dist: &StormDistribution) -> R<StormModel> {
    match t.storm_model.as_deref().unwrap_or("annual-maxima") {
        "annual-maxima" => {
            for (key, given) in [
                ("storm_rate_per_year", t.storm_rate_per_year.is_some()),
                ("storm_threshold_m", t.storm_threshold_m.is_some()),
            ] {
                if given {
                    return Err(ScenarioError::Conflict {
                        message: format!("`[design] {key}` is used only with storm_model = \"peaks-over-threshold\"; remove it, or set that storm_model"),
                    });
                }
            }
            Ok(StormModel::AnnualMaxima)
        }
        "peaks-over-threshold" => {
            let rate_per_year = required(
                "storm_rate_per_year",
                t.storm_rate_per_year,
                "the mean number of storms a year above the threshold",
            )?;
            let threshold_m = required(
                "storm_threshold_m",
                t.storm_threshold_m,
                "the threshold of the deep-water H1/3 the storms exceed, m",
            )?;
            dist.peaks_over_threshold(rate_per_year, threshold_m).map_err(|e| keyed("[design]", e))
        }
        other => Err(ScenarioError::range(
            "[design] storm_model",
            format!("\"{other}\""),
            "must be \"annual-maxima\" or \"peaks-over-threshold\"",
        )),
    }
}

/// The storm durations of `table` (`[design]` or `[fragility]`): `storm_duration_model` and its
/// COV (docs/design.md, "Climate").
pub(super) fn duration_model(table: &str, model: &Option<String>, cov: Option<f64>) -> R<StormDuration> {
    match model.as_deref().unwrap_or("fixed") {
        "fixed" => match cov {
            Some(_) => Err(ScenarioError::Conflict {
                message: format!("`{table} storm_duration_cov` is used only with storm_duration_model = \"lognormal\"; remove it, or set that model"),
            }),
            None => Ok(StormDuration::Fixed),
        },
        "lognormal" => {
            let key = format!("{table} storm_duration_cov");
            let v = waves::required(&key, cov, "the coefficient of variation of the durations (e.g. 0.5)")?;
            StormDuration::lognormal(v).map_err(|e| keyed(table, e))
        }
        other => Err(ScenarioError::range(
            &format!("{table} storm_duration_model"),
            format!("\"{other}\""),
            "must be \"fixed\" or \"lognormal\"",
        )),
    }
}

/// The waves' periods of `table` (`[design]` or `[fragility]`): `wave_periods` and its spectral
/// width (docs/design.md, "Climate").
pub(super) fn wave_periods(table: &str, kind: &Option<String>, width: Option<f64>) -> R<WavePeriods> {
    match kind.as_deref().unwrap_or("significant") {
        "significant" => match width {
            Some(_) => Err(ScenarioError::Conflict {
                message: format!("`{table} period_spectral_width` is used only with wave_periods = \"longuet-higgins\"; remove it, or set wave_periods"),
            }),
            None => Ok(WavePeriods::Significant),
        },
        "longuet-higgins" => {
            WavePeriods::longuet_higgins(width.unwrap_or(DEFAULT_SPECTRAL_WIDTH)).map_err(|e| keyed(table, e))
        }
        other => Err(ScenarioError::range(
            &format!("{table} wave_periods"),
            format!("\"{other}\""),
            "must be \"significant\" (every wave at T1/3) or \"longuet-higgins\" (each wave's period given its height)",
        )),
    }
}

/// `[design] sea_level_rise_m` or `sea_level_rise_table` (docs/design.md, "Climate").
fn sea_level(t: &DesignTable, life_years: usize) -> R<SeaLevelRise> {
    let key = "[design] sea_level_rise_table";
    match (t.sea_level_rise_m, &t.sea_level_rise_table) {
        (Some(_), Some(_)) => Err(ScenarioError::Conflict {
            message: "give `[design] sea_level_rise_m` (a linear rise) or `sea_level_rise_table` (years and metres), not both".into(),
        }),
        (None, None) => Ok(SeaLevelRise::None),
        (Some(r), None) => SeaLevelRise::linear(r, life_years).map_err(|e| keyed("[design]", e)),
        (None, Some(rows)) => {
            let mut points = Vec::with_capacity(rows.len());
            for (i, row) in rows.iter().enumerate() {
                let &[y, r] = row.as_slice() else {
                    return Err(ScenarioError::range(
                        &format!("{key}[{i}]"),
                        format!("{row:?}"),
                        "must be a pair [years from the start of the life, rise m]",
                    ));
                };
                points.push((y, r));
            }
            SeaLevelRise::table(points).map_err(|e| match e {
                SeaLevelError::Points { count } => {
                    let allowed = format!("must list 1 to {MAX_SEA_LEVEL_POINTS} [years, m] pairs");
                    ScenarioError::range(key, format!("{count} rows"), allowed)
                }
                SeaLevelError::Point { index, error } => {
                    let (column, unit) =
                        if error.quantity == "years" { (0, "years from the start of the life") } else { (1, RISE_UNIT) };
                    shown_under(&format!("{key}[{index}][{column}]"), error, unit, Shown::AsRead)
                }
            })
        }
    }
}

/// The storms' wave direction of `table` (`[design]` or `[fragility]`): `wave_direction` and its
/// mean and spread (docs/design.md, "Climate").
pub(super) fn direction(
    table: &str,
    kind: &Option<String>,
    mean: Option<f64>,
    spread: Option<f64>,
) -> R<WaveDirection> {
    let spread_deg = |what: &str| waves::required(&format!("{table} wave_direction_spread_deg"), spread, what);
    let mean_deg = mean.unwrap_or(0.0);
    let direction = match kind.as_deref().unwrap_or("head-on") {
        "head-on" => {
            for (key, given) in
                [("wave_direction_mean_deg", mean.is_some()), ("wave_direction_spread_deg", spread.is_some())]
            {
                if given {
                    return Err(ScenarioError::Conflict {
                        message: format!("`{table} {key}` is not used with wave_direction = \"head-on\" (the default); remove it, or set wave_direction = \"normal\" or \"uniform\""),
                    });
                }
            }
            Ok(WaveDirection::HeadOn)
        }
        "normal" => {
            WaveDirection::normal_deg(mean_deg, spread_deg("the standard deviation of the angle, degrees (e.g. 15)")?)
        }
        "uniform" => WaveDirection::uniform_deg(
            mean_deg,
            spread_deg("the half-width of the angles about the mean, degrees (e.g. 20)")?,
        ),
        other => {
            return Err(ScenarioError::range(
                &format!("{table} wave_direction"),
                format!("\"{other}\""),
                "must be \"head-on\", \"normal\" or \"uniform\"",
            ))
        }
    };
    direction.map_err(|e| keyed(table, e))
}
