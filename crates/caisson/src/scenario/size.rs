//! `[size]`: the search of `caisson size` (docs/size.md), validated into [`SizeParams`]. The rest
//! of the file is a design scenario (`[design]` gives the life model and the seed; `[size] lives`
//! the lives per candidate).

use super::waves::number;
use super::{ScenarioError, ScenarioFile};
use crate::analysis::conventional::{
    ConventionalCriteria, DEFAULT_ALLOWABLE_HEEL_PRESSURE_PA, DEFAULT_OVERTURNING_SAFETY_FACTOR,
    DEFAULT_SLIDING_SAFETY_FACTOR,
};
use crate::analysis::sizing::{Criteria, ExceedanceCriterion, SizeParams};
use serde::Deserialize;

type R<T> = Result<T, ScenarioError>;

/// `[size]` as written.
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct SizeTable {
    /// The variable sized: `"width_m"` (the only one so far).
    pub variable: Option<String>,
    /// [smallest, largest] width searched, m.
    pub range_m: Option<Vec<f64>>,
    /// Criterion: E|S| ≤ this, m.
    pub expected_sliding_m: Option<f64>,
    /// Criterion: P(|S| > exceedance_sliding_m) ≤ exceedance_probability.
    pub exceedance_sliding_m: Option<f64>,
    pub exceedance_probability: Option<f64>,
    /// Criterion: P(failure) ≤ this.
    pub failure_probability: Option<f64>,
    /// Lives per candidate width (default `[design] lives`).
    pub lives: Option<i64>,
    /// Width tolerance, m (default 0.25).
    pub tolerance_m: Option<f64>,
    /// Widths of the design curve's grid (default 8).
    pub curve_points: Option<i64>,
    /// Goda's conventional width: required sliding safety factor (default 1.2).
    pub sliding_safety_factor: Option<f64>,
    /// Goda's conventional width: required overturning safety factor (default 1.2).
    pub overturning_safety_factor: Option<f64>,
    /// The allowable heel pressure on the mound, kPa (default 500).
    pub allowable_heel_pressure_kpa: Option<f64>,
    /// Whether the heel pressure limits the conventional width (default false: reported, warned).
    pub heel_pressure_governs: Option<bool>,
}

/// Default width tolerance, m.
pub const DEFAULT_TOLERANCE_M: f64 = 0.25;
/// Default grid of the design curve.
pub const DEFAULT_CURVE_POINTS: usize = 8;

/// Validate `[size]` (`design_lives`: `[design] lives`, the default lives per candidate).
pub(super) fn validate_size(file: &ScenarioFile, design_lives: usize) -> R<SizeParams> {
    let t = file.size.as_ref().ok_or_else(|| ScenarioError::missing("[size]", "add a [size] table"))?;
    match t.variable.as_deref() {
        None | Some("width_m") => {}
        Some(other) => {
            return Err(ScenarioError::range("[size] variable", format!("\"{other}\""), "must be \"width_m\""))
        }
    }
    let range = t.range_m.as_deref().ok_or_else(|| {
        ScenarioError::missing("[size] range_m", "the smallest and largest width searched, m, e.g. [12.0, 30.0]")
    })?;
    let (lo, hi) = match range {
        [lo, hi] => (
            number("[size] range_m[0]", *lo, 0.0, 1000.0, true, "m")?,
            number("[size] range_m[1]", *hi, 0.0, 1000.0, true, "m")?,
        ),
        _ => {
            return Err(ScenarioError::range(
                "[size] range_m",
                format!("{range:?}"),
                "must be two widths [smallest, largest], m",
            ))
        }
    };
    if lo >= hi {
        return Err(ScenarioError::range(
            "[size] range_m",
            format!("[{lo}, {hi}]"),
            "the smallest width must be below the largest",
        ));
    }
    let probability = |key: &str, v: f64| number(&format!("[size] {key}"), v, 0.0, 1.0, false, "probability, 0 to 1");
    let exceedance = match (t.exceedance_sliding_m, t.exceedance_probability) {
        (None, None) => None,
        (Some(s), Some(p)) => Some(ExceedanceCriterion {
            sliding_m: number("[size] exceedance_sliding_m", s, 0.0, 1000.0, true, "m")?,
            probability: probability("exceedance_probability", p)?,
        }),
        (Some(_), None) => {
            return Err(ScenarioError::missing(
                "[size] exceedance_probability",
                "the largest allowed P(|S| > exceedance_sliding_m)",
            ))
        }
        (None, Some(_)) => {
            return Err(ScenarioError::missing("[size] exceedance_sliding_m", "the sliding S_lim of P(|S| > S_lim), m"))
        }
    };
    let criteria = Criteria {
        expected_sliding_m: t
            .expected_sliding_m
            .map(|v| number("[size] expected_sliding_m", v, 0.0, 1000.0, true, "m"))
            .transpose()?,
        exceedance,
        failure_probability: t.failure_probability.map(|v| probability("failure_probability", v)).transpose()?,
    };
    if !criteria.any() {
        return Err(ScenarioError::missing(
            "[size] expected_sliding_m",
            "a criterion: expected_sliding_m, and/or exceedance_sliding_m with exceedance_probability, and/or failure_probability",
        ));
    }
    let lives = match t.lives {
        None => design_lives,
        Some(n) if (1..=1_000_000).contains(&n) => n as usize,
        Some(n) => return Err(ScenarioError::range("[size] lives", n, "must be a whole number from 1 to 1000000")),
    };
    let curve_points = match t.curve_points {
        None => DEFAULT_CURVE_POINTS,
        Some(n) if (2..=100).contains(&n) => n as usize,
        Some(n) => return Err(ScenarioError::range("[size] curve_points", n, "must be a whole number from 2 to 100")),
    };
    let tolerance_m = match t.tolerance_m {
        None => DEFAULT_TOLERANCE_M,
        Some(v) => {
            number("[size] tolerance_m", v, (hi - lo) * 1e-6, hi - lo, true, "m, above a millionth of the range")?
        }
    };
    let factor = |key: &str, v: Option<f64>, default: f64| {
        v.map_or(Ok(default), |v| number(&format!("[size] {key}"), v, 1.0, 10.0, false, "a safety factor from 1 to 10"))
    };
    let conventional = ConventionalCriteria {
        sliding_safety_factor: factor("sliding_safety_factor", t.sliding_safety_factor, DEFAULT_SLIDING_SAFETY_FACTOR)?,
        overturning_safety_factor: factor(
            "overturning_safety_factor",
            t.overturning_safety_factor,
            DEFAULT_OVERTURNING_SAFETY_FACTOR,
        )?,
        allowable_heel_pressure_pa: 1e3
            * t.allowable_heel_pressure_kpa.map_or(Ok(DEFAULT_ALLOWABLE_HEEL_PRESSURE_PA / 1e3), |v| {
                number("[size] allowable_heel_pressure_kpa", v, 10.0, 1e4, true, "kPa, from 10 to 10000")
            })?,
        heel_pressure_governs: t.heel_pressure_governs.unwrap_or(false),
    };
    Ok(SizeParams { range_m: (lo, hi), criteria, lives, tolerance_m, curve_points, conventional })
}
