//! `[size]`: the search of `caisson size` (docs/size.md), read into [`SizeParams`], whose
//! [`SizeParams::checked`] holds the rules of the values (the heel pressure, in kPa, is refused
//! in the file's unit before it is converted). The rest of the file is a design scenario (`[design]` gives the life model and the seed; `[size] lives`
//! the lives per candidate).

use super::waves::number;
use super::{ScenarioError, ScenarioFile};
use crate::analysis::conventional::{
    ConventionalCriteria, DEFAULT_ALLOWABLE_HEEL_PRESSURE_PA, DEFAULT_OVERTURNING_SAFETY_FACTOR,
    DEFAULT_SLIDING_SAFETY_FACTOR,
};
use crate::analysis::sizing::{Criteria, ExceedanceCriterion, ExpectedSliding, SizeParamError, SizeParams};
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
    /// Which E|S| the criterion reads: `"capped"` (default) or `"as-simulated"`.
    pub expected_sliding: Option<String>,
    /// Criterion: P(|S| > exceedance_sliding_m) ≤ exceedance_probability.
    pub exceedance_sliding_m: Option<f64>,
    pub exceedance_probability: Option<f64>,
    /// Criterion: P(failure) ≤ this.
    pub failure_probability: Option<f64>,
    /// Lives per candidate width (default `[design] lives`), or `"auto"`.
    pub lives: Option<super::design::LivesKey>,
    /// `lives = "auto"`: the target relative standard error of each candidate's E|S| and
    /// P(failure).
    pub target_relative_error: Option<f64>,
    /// `lives = "auto"`: the most lives of a candidate.
    pub max_lives: Option<i64>,
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

/// Most lives per candidate (`[size] lives` or `max_lives`).
pub const MAX_SIZE_LIVES: usize = 1_000_000;

/// Default width tolerance, m.
pub const DEFAULT_TOLERANCE_M: f64 = 0.25;
/// Default grid of the design curve.
pub const DEFAULT_CURVE_POINTS: usize = 8;

/// The keys of the quantities of [`SizeParams`] (named as in their types) and their units.
const SIZE_KEYS: super::NamedKeys = &[
    ("range_lo_m", "[size] range_m[0]", "m"),
    ("range_hi_m", "[size] range_m[1]", "m"),
    ("exceedance_sliding_m", "[size] exceedance_sliding_m", "m"),
    ("exceedance_probability", "[size] exceedance_probability", "probability, 0 to 1"),
    ("expected_sliding_m", "[size] expected_sliding_m", "m"),
    ("failure_probability", "[size] failure_probability", "probability, 0 to 1"),
    ("lives", "[size] lives", ""),
    ("curve_points", "[size] curve_points", ""),
    ("tolerance_m", "[size] tolerance_m", "m, above a millionth of the range"),
    ("sliding_safety_factor", "[size] sliding_safety_factor", "a safety factor from 1 to 10"),
    ("overturning_safety_factor", "[size] overturning_safety_factor", "a safety factor from 1 to 10"),
];

/// A refused [`SizeParams`] under its `[size]` key, the value as read.
fn keyed_size(e: SizeParamError) -> ScenarioError {
    match e {
        SizeParamError::Param(e) => super::keyed_in(SIZE_KEYS, e),
        SizeParamError::EmptyRange { lo_m, hi_m } => ScenarioError::range(
            "[size] range_m",
            format!("[{lo_m}, {hi_m}]"),
            "the smallest width must be below the largest",
        ),
    }
}

/// Read `[size]` into [`SizeParams`] (`design_lives`: `[design] lives` and its "auto", the
/// default lives per candidate), which checks the values ([`SizeParams::checked`]).
pub(super) fn validate_size(
    file: &ScenarioFile,
    design_lives: (usize, Option<crate::analysis::lifetime::AutoLives>),
) -> R<SizeParams> {
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
    let &[lo, hi] = range else {
        return Err(ScenarioError::range(
            "[size] range_m",
            format!("{range:?}"),
            "must be two widths [smallest, largest], m",
        ));
    };
    let whole = |key: &str, v: Option<i64>, default: usize, lo: i64, hi: i64| match v {
        None => Ok(default),
        Some(n) if (lo..=hi).contains(&n) => Ok(n as usize),
        Some(n) => {
            Err(ScenarioError::range(&format!("[size] {key}"), n, format!("must be a whole number from {lo} to {hi}")))
        }
    };
    let (design_n, design_auto) = design_lives;
    let default = (if design_auto.is_some() { design_n.min(MAX_SIZE_LIVES) } else { design_n }, design_auto);
    let (lives, auto) =
        super::design::lives_keys("[size]", (&t.lives, t.target_relative_error, t.max_lives), default, MAX_SIZE_LIVES)?;
    let curve_points = whole("curve_points", t.curve_points, DEFAULT_CURVE_POINTS, 2, 100)?;
    let params = SizeParams {
        range_m: (lo, hi),
        criteria: criteria(t)?,
        lives,
        auto,
        tolerance_m: t.tolerance_m.unwrap_or(DEFAULT_TOLERANCE_M),
        curve_points,
        conventional: ConventionalCriteria {
            sliding_safety_factor: t.sliding_safety_factor.unwrap_or(DEFAULT_SLIDING_SAFETY_FACTOR),
            overturning_safety_factor: t.overturning_safety_factor.unwrap_or(DEFAULT_OVERTURNING_SAFETY_FACTOR),
            allowable_heel_pressure_pa: 1e3
                * t.allowable_heel_pressure_kpa.map_or(Ok(DEFAULT_ALLOWABLE_HEEL_PRESSURE_PA / 1e3), |v| {
                    number("[size] allowable_heel_pressure_kpa", v, 10.0, 1e4, true, "kPa, from 10 to 10000")
                })?,
            heel_pressure_governs: t.heel_pressure_governs.unwrap_or(false),
        },
    };
    params.checked().map_err(keyed_size)
}

/// The criteria of `[size]`: at least one; the exceedance's sliding and probability together.
fn criteria(t: &SizeTable) -> R<Criteria> {
    let exceedance = match (t.exceedance_sliding_m, t.exceedance_probability) {
        (None, None) => None,
        (Some(sliding_m), Some(probability)) => Some(ExceedanceCriterion { sliding_m, probability }),
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
    let expected_sliding = match t.expected_sliding.as_deref() {
        None | Some("capped") => ExpectedSliding::Capped,
        Some("as-simulated") => ExpectedSliding::AsSimulated,
        Some(other) => {
            return Err(ScenarioError::range(
                "[size] expected_sliding",
                format!("\"{other}\""),
                "must be \"capped\" (a failed life at the sliding limit) or \"as-simulated\" (the plain mean of the lives run to their end, as Shimosako & Takahashi 1999 compute it)",
            ))
        }
    };
    if t.expected_sliding.is_some() && t.expected_sliding_m.is_none() {
        return Err(ScenarioError::missing(
            "[size] expected_sliding_m",
            "the criterion E|S| ≤ S_a that `expected_sliding` chooses the statistic of, m",
        ));
    }
    let criteria = Criteria {
        expected_sliding_m: t.expected_sliding_m,
        expected_sliding,
        exceedance,
        failure_probability: t.failure_probability,
    };
    if !criteria.any() {
        return Err(ScenarioError::missing(
            "[size] expected_sliding_m",
            "a criterion: expected_sliding_m, and/or exceedance_sliding_m with exceedance_probability, and/or failure_probability",
        ));
    }
    Ok(criteria)
}
