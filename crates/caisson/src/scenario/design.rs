//! `[design]`: the lifetime Monte Carlo of performance-based design (docs/model.md §6.4), validated
//! into [`DesignParams`] (the life model and the run controls). Every key is documented in `docs/design.md`; the
//! defaults are the values docs/model.md §6.4 cites (Goda & Takagi 2000; Takayama & Ikeda 1992 via
//! Shimosako & Takahashi 1999; Kim & Takayama 2003 for the truncation).

use super::waves::{self, number, seed_of};
use super::{ScenarioError, ScenarioFile};
use crate::analysis::climate::WavePeriods;
use crate::analysis::climate::{
    Climate, SeaLevelRise, StormDuration, StormModel, WaveDirection, MAX_ANGLE_SPREAD_DEG, MAX_MEAN_ANGLE_DEG,
    MAX_SEA_LEVEL_RISE_M, MAX_STORM_DURATION_COV, MAX_STORM_RATE_PER_YEAR,
};
use crate::analysis::lifetime::{DesignParams, ErrorModel, ErrorScope, Errors, LifeParams, StormDistribution};
use crate::waves::periods::DEFAULT_SPECTRAL_WIDTH;
use serde::Deserialize;

/// Most lives of a design run (`[design] lives`, the CLI's `--lives`, Python's `Design(lives=)`).
pub const MAX_LIVES: usize = 10_000_000;

type R<T> = Result<T, ScenarioError>;

/// `[design]` as written.
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct DesignTable {
    pub life_years: Option<i64>,
    pub lives: Option<i64>,
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
    /// The failure limit on the caisson's distance from its place, m (default B/4).
    pub failure_sliding_m: Option<f64>,
    /// The failure limit on the caisson's rotation, rad (default 0.01).
    pub failure_rotation_rad: Option<f64>,
    /// Run lives to their end after failure (default false: a life ends at failure).
    pub continue_after_failure: Option<bool>,
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

/// The largest `[design] failure_rotation_rad` (and `[fragility]`'s), rad: 0.1 rad (5.7°) lifts
/// the heel of a 20 m wide caisson by 2 m, far beyond the small rotations the model describes.
pub const MAX_FAILURE_ROTATION_RAD: f64 = 0.1;

/// Takahashi's performance grades (docs/model.md §6.4 step 8), m.
pub const STANDARD_THRESHOLDS_M: [f64; 5] = [0.03, 0.1, 0.3, 1.0, 3.0];

fn num(key: &str, v: Option<f64>, default: f64, lo: f64, hi: f64, lo_open: bool, unit: &str) -> R<f64> {
    v.map_or(Ok(default), |v| number(&format!("[design] {key}"), v, lo, hi, lo_open, unit))
}

fn count(key: &str, v: Option<i64>, default: usize, hi: i64) -> R<usize> {
    match v {
        None => Ok(default),
        Some(n) if (1..=hi).contains(&n) => Ok(n as usize),
        Some(n) => {
            Err(ScenarioError::range(&format!("[design] {key}"), n, format!("must be a whole number from 1 to {hi}")))
        }
    }
}

/// A rule of a parameter type's constructor ([`crate::ParamError`]) under the file's `key`, with
/// its words (the rules' values are in the keys' units).
fn rule(key: &str, e: crate::ParamError) -> ScenarioError {
    ScenarioError::range(key, e.value, e.allowed.describe(1.0, ""))
}

fn required(key: &str, v: Option<f64>, hint: &str) -> R<f64> {
    waves::required(&format!("[design] {key}"), v, hint)
}

/// Validate `[design]`.
pub(super) fn validate_design(file: &ScenarioFile) -> R<DesignParams> {
    let t = file.design.as_ref().ok_or_else(|| {
        ScenarioError::missing(
            "[design]",
            "add a [design] table: storm_distribution, its parameters, life_years, lives",
        )
    })?;
    let dist = t.storm_distribution.as_deref().ok_or_else(|| {
        ScenarioError::missing(
            "[design] storm_distribution",
            "\"weibull\" or \"gumbel\" (annual maxima of the deep-water H1/3)",
        )
    })?;
    let storms = match dist {
        "weibull" => StormDistribution::Weibull {
            scale_m: num(
                "storm_scale_m",
                Some(required("storm_scale_m", t.storm_scale_m, "the Weibull scale A, m")?),
                0.0,
                0.0,
                100.0,
                true,
                "m",
            )?,
            shape: num(
                "storm_shape",
                Some(required("storm_shape", t.storm_shape, "the Weibull shape k (0.75-2 typically)")?),
                0.0,
                0.1,
                20.0,
                false,
                "-",
            )?,
            location_m: num("storm_location_m", t.storm_location_m, 0.0, 0.0, 100.0, false, "m")?,
        },
        "gumbel" => {
            if t.storm_shape.is_some() {
                return Err(ScenarioError::Conflict {
                    message: "`[design] storm_shape` is not used with storm_distribution = \"gumbel\"; remove it"
                        .into(),
                });
            }
            StormDistribution::Gumbel {
                location_m: num(
                    "storm_location_m",
                    Some(required("storm_location_m", t.storm_location_m, "the Gumbel location B, m")?),
                    0.0,
                    0.0,
                    100.0,
                    true,
                    "m",
                )?,
                scale_m: num(
                    "storm_scale_m",
                    Some(required("storm_scale_m", t.storm_scale_m, "the Gumbel scale A, m")?),
                    0.0,
                    0.0,
                    100.0,
                    true,
                    "m",
                )?,
            }
        }
        other => {
            return Err(ScenarioError::range(
                "[design] storm_distribution",
                format!("\"{other}\""),
                "must be \"weibull\" or \"gumbel\"",
            ))
        }
    };
    let life_years = count("life_years", t.life_years, 50, 1000)?;
    let climate = Climate {
        storms: storm_model(t, &storms)?,
        duration: duration_model("[design]", &t.storm_duration_model, t.storm_duration_cov)?,
        sea_level: sea_level(t, life_years)?,
        direction: direction("[design]", &t.wave_direction, t.wave_direction_mean_deg, t.wave_direction_spread_deg)?,
        periods: wave_periods("[design]", &t.wave_periods, t.period_spectral_width)?,
    };
    let truncated = t.error_truncated.unwrap_or(true);
    if !truncated && t.error_truncation_sigmas.is_some() {
        return Err(ScenarioError::Conflict {
            message: "`[design] error_truncation_sigmas` is not used with error_truncated = false (untruncated normal errors); remove one of them".into(),
        });
    }
    let k = num("error_truncation_sigmas", t.error_truncation_sigmas, 2.0, 0.5, 10.0, false, "standard deviations")?;
    let d = Errors::default();
    let err = |name: &str, bias: Option<f64>, cov: Option<f64>, def: ErrorModel| -> R<ErrorModel> {
        let bias = num(&format!("{name}_bias"), bias, def.bias, -0.9, 1.0, false, "fraction")?;
        let cov = num(&format!("{name}_cov"), cov, def.cov, 0.0, 1.0, false, "fraction")?;
        ErrorModel::new(bias, cov, truncated.then_some(k)).map_err(|e| rule(&format!("[design] {name}_cov"), e))
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
    let errors = Errors {
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
    };
    let mut thresholds_m = STANDARD_THRESHOLDS_M.to_vec();
    for (i, v) in t.thresholds_m.iter().flatten().enumerate() {
        if !(v.is_finite() && *v > 0.0) {
            return Err(ScenarioError::range(
                &format!("[design] thresholds_m[{i}]"),
                v,
                "must be a finite number > 0 (m)",
            ));
        }
        thresholds_m.push(*v);
    }
    thresholds_m.sort_by(f64::total_cmp);
    thresholds_m.dedup();
    let seed = seed_of("[design] seed", t.seed)?;
    Ok(DesignParams {
        life: LifeParams {
            life_years,
            storms,
            period_coefficient: num("period_coefficient", t.period_coefficient, 3.3, 0.0, 100.0, true, "s·m^−b")?,
            period_exponent: num("period_exponent", t.period_exponent, 0.63, 0.0, 2.0, false, "-")?,
            storm_duration_s: num("storm_duration_h", t.storm_duration_h, 2.0, 0.0, 72.0, true, "h")? * 3600.0,
            tidal_range_m: num("tidal_range_m", t.tidal_range_m, 0.0, 0.0, 20.0, false, "m")?,
            errors,
            climate,
        },
        lives: count("lives", t.lives, 5000, MAX_LIVES as i64)?,
        seed,
        thresholds_m,
        screen: t.screen.unwrap_or(true),
        failure_sliding_m: t
            .failure_sliding_m
            .map(|v| number("[design] failure_sliding_m", v, 0.0, 1000.0, true, "m"))
            .transpose()?,
        failure_rotation_rad: failure_rotation("[design] failure_rotation_rad", t.failure_rotation_rad)?,
        continue_after_failure: t.continue_after_failure.unwrap_or(false),
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
            let rate_per_year = num(
                "storm_rate_per_year",
                Some(required(
                    "storm_rate_per_year",
                    t.storm_rate_per_year,
                    "the mean number of storms a year above the threshold",
                )?),
                0.0,
                0.0,
                MAX_STORM_RATE_PER_YEAR,
                true,
                "storms a year",
            )?;
            let threshold_m = num(
                "storm_threshold_m",
                Some(required(
                    "storm_threshold_m",
                    t.storm_threshold_m,
                    "the threshold of the deep-water H1/3 the storms exceed, m",
                )?),
                0.0,
                0.0,
                100.0,
                false,
                "m",
            )?;
            dist.peaks_over_threshold(rate_per_year, threshold_m).map_err(|e| rule("[design] storm_threshold_m", e))
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
            Ok(StormDuration::Lognormal { cov: number(&key, v, 0.0, MAX_STORM_DURATION_COV, true, "fraction")? })
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
        "longuet-higgins" => WavePeriods::longuet_higgins(width.unwrap_or(DEFAULT_SPECTRAL_WIDTH))
            .map_err(|e| rule(&format!("{table} period_spectral_width"), e)),
        other => Err(ScenarioError::range(
            &format!("{table} wave_periods"),
            format!("\"{other}\""),
            "must be \"significant\" (every wave at T1/3) or \"longuet-higgins\" (each wave's period given its height)",
        )),
    }
}

/// `[design] sea_level_rise_m` or `sea_level_rise_table` (docs/design.md, "Climate").
fn sea_level(t: &DesignTable, life_years: usize) -> R<SeaLevelRise> {
    let unit = "m; the still-water level's rise, at most 5 m";
    match (t.sea_level_rise_m, &t.sea_level_rise_table) {
        (Some(_), Some(_)) => Err(ScenarioError::Conflict {
            message: "give `[design] sea_level_rise_m` (a linear rise) or `sea_level_rise_table` (years and metres), not both".into(),
        }),
        (None, None) => Ok(SeaLevelRise::None),
        (Some(r), None) => Ok(SeaLevelRise::Linear {
            rise_m: num("sea_level_rise_m", Some(r), 0.0, 0.0, MAX_SEA_LEVEL_RISE_M, false, unit)?,
            life_years: life_years as f64,
        }),
        (None, Some(rows)) => {
            let key = "[design] sea_level_rise_table";
            if rows.is_empty() || rows.len() > 1000 {
                return Err(ScenarioError::range(key, format!("{} rows", rows.len()), "must list 1 to 1000 [years, m] pairs"));
            }
            let mut points = Vec::with_capacity(rows.len());
            for (i, row) in rows.iter().enumerate() {
                let &[y, r] = row.as_slice() else {
                    return Err(ScenarioError::range(
                        &format!("{key}[{i}]"),
                        format!("{row:?}"),
                        "must be a pair [years from the start of the life, rise m]",
                    ));
                };
                let y = number(&format!("{key}[{i}][0]"), y, 0.0, 1000.0, false, "years from the start of the life")?;
                let r = number(&format!("{key}[{i}][1]"), r, 0.0, MAX_SEA_LEVEL_RISE_M, false, unit)?;
                if let Some(&(y0, _)) = points.last() {
                    if y <= y0 {
                        return Err(ScenarioError::range(
                            &format!("{key}[{i}][0]"),
                            y,
                            format!("must be larger than the year before it ({y0}): the years must increase"),
                        ));
                    }
                }
                points.push((y, r));
            }
            Ok(SeaLevelRise::Table { points })
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
    let deg = std::f64::consts::PI / 180.0;
    let mean_rad = || -> R<f64> {
        Ok(mean.map_or(Ok(0.0), |v| {
            number(
                &format!("{table} wave_direction_mean_deg"),
                v,
                -MAX_MEAN_ANGLE_DEG,
                MAX_MEAN_ANGLE_DEG,
                false,
                "degrees from the breakwater's normal",
            )
        })? * deg)
    };
    let spread_rad = |what: &str| -> R<f64> {
        let key = format!("{table} wave_direction_spread_deg");
        let v = waves::required(&key, spread, what)?;
        Ok(number(&key, v, 0.0, MAX_ANGLE_SPREAD_DEG, true, "degrees")? * deg)
    };
    match kind.as_deref().unwrap_or("head-on") {
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
        "normal" => Ok(WaveDirection::Normal {
            mean_rad: mean_rad()?,
            sd_rad: spread_rad("the standard deviation of the angle, degrees (e.g. 15)")?,
        }),
        "uniform" => Ok(WaveDirection::Uniform {
            mean_rad: mean_rad()?,
            half_width_rad: spread_rad("the half-width of the angles about the mean, degrees (e.g. 20)")?,
        }),
        other => Err(ScenarioError::range(
            &format!("{table} wave_direction"),
            format!("\"{other}\""),
            "must be \"head-on\", \"normal\" or \"uniform\"",
        )),
    }
}

/// A failure rotation limit (`key`), rad: in (0, [`MAX_FAILURE_ROTATION_RAD`]], default
/// [`crate::analysis::limits::ROCKING_LIMIT_RAD`].
pub(super) fn failure_rotation(key: &str, v: Option<f64>) -> R<f64> {
    v.map_or(Ok(crate::analysis::limits::ROCKING_LIMIT_RAD), |v| {
        number(key, v, 0.0, MAX_FAILURE_ROTATION_RAD, true, "rad")
    })
}
