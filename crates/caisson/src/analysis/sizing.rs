//! Sizing (docs/size.md): the smallest caisson width whose lifetime sliding meets a performance
//! criterion, found with the lifetime Monte Carlo of [`super::lifetime`] run at candidate widths.
//!
//! **Criteria** (any combination; all must hold), on the life's sliding magnitude |S| and the
//! failure (by sliding or rotation) of [`super::lifetime::StormOutcome::failed`], with the
//! statistics of a design run ([`super::lifetime::capped_statistics`]: a failed life at the
//! sliding limit, and exceeding every threshold):
//!
//! * expected sliding E|S| ≤ S_a (Shimosako & Takahashi 1999: 0.3 m; Goda & Takagi 2000: 0.1 m),
//!   E|S| with each failed life at the failure limit (`[size] expected_sliding = "capped"`, the
//!   default), or as simulated, the plain mean of |S| with every life run to its end, failed or
//!   not (`"as-simulated"`: the expected sliding distance of Shimosako & Takahashi 1999 and Goda
//!   & Takagi 2000); both are reported with their standard errors whatever the criterion;
//! * P(|S| > S_lim) ≤ p;
//! * P(failure) ≤ p_f.
//!
//! **Common random numbers.** Every candidate runs lives 0 … N − 1 of the same seed: life i sees
//! the same storms, tides, estimation errors and wave heights at every width (the per-life
//! streams do not depend on the caisson, and the screen draws every wave whether it simulates it
//! or not), so the difference between two candidates is the width's, not the sampling's, and the
//! curve of E|S| against width is smooth and monotone within the noise of the few lives that
//! change their fate.
//!
//! **Search.** The criterion is evaluated on a grid of `curve_points` widths over the range (the
//! design curve); the smallest grid width that meets it and the one below bracket the answer,
//! which is then bisected until the bracket is narrower than `tolerance_m`; the required width is
//! the bracket's upper end (it meets the criterion). The rigid block (Shimosako model, computed
//! in the same lives) gets its own bracket and bisection from the same evaluations. Every
//! evaluated width is kept (a width is never run twice).
//!
//! **Confidence.** With n lives, the standard error of E|S| is s/√n (s the sample standard
//! deviation of |S|) and that of a probability p̂ is √(p̂(1 − p̂)/n). A criterion is *met with
//! confidence* at a width if it holds at the upper 95 % bound (estimate + 1.645 SE, one-sided),
//! and *possibly met* if it holds at the lower bound (estimate − 1.645 SE). The widths where the
//! evaluated candidates change from not met to met under each bound give the 90 % (two-sided)
//! Monte Carlo interval of the required width; the report also gives, at the required width,
//! Φ(margin / SE) of the tightest criterion, the normal-approximation probability that the
//! criterion is met.

use super::estimate::{normal_ci95, Estimate};
use super::fragility::normal_cdf;
use super::lifetime::{
    capped_statistics, FailureLimits, HeelPressureExceedance, ImpulsiveShare, LifeCounts, StormOutcome,
};
use super::stratified::TwoPhase;
use crate::check::{count, interval};
use serde::Serialize;

/// One-sided 95 % normal quantile.
pub const Z95: f64 = 1.644_853_626_951_472_2;

/// The performance criteria (all given ones must hold).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct Criteria {
    /// E|S| ≤ this, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub expected_sliding_m: Option<f64>,
    /// Which E|S| the criterion reads (module docs).
    #[serde(skip_serializing_if = "ExpectedSliding::is_capped")]
    pub expected_sliding: ExpectedSliding,
    /// P(|S| > `sliding_m`) ≤ `probability`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub exceedance: Option<ExceedanceCriterion>,
    /// P(failure) ≤ this.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub failure_probability: Option<f64>,
}

/// Which expected sliding an E|S| criterion reads (`[size] expected_sliding`, module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum ExpectedSliding {
    /// Each failed life at the sliding failure limit (the default).
    #[default]
    Capped,
    /// The plain mean of the lives as simulated, each run to its end (Shimosako & Takahashi 1999).
    AsSimulated,
}

impl ExpectedSliding {
    fn is_capped(&self) -> bool {
        *self == ExpectedSliding::Capped
    }
}

/// P(|S| > sliding_m) ≤ probability.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ExceedanceCriterion {
    pub sliding_m: f64,
    pub probability: f64,
}

/// What sizing needs of one model at one width: the estimates and their standard errors.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, serde::Deserialize)]
pub struct ModelPoint {
    /// E|S| with each failed life at the sliding limit, m.
    pub expected_sliding_m: f64,
    /// Its standard error and 95 % interval ([low, high], the normal interval ± 1.96 standard
    /// errors: [`crate::analysis::estimate`]), m.
    pub expected_sliding_standard_error_m: f64,
    pub expected_sliding_ci95_m: [f64; 2],
    /// E|S| of the lives as simulated (every life run to its end, not capped), m, its standard
    /// error and 95 % interval.
    pub expected_sliding_uncapped_m: f64,
    pub expected_sliding_uncapped_standard_error_m: f64,
    pub expected_sliding_uncapped_ci95_m: [f64; 2],
    /// Median and 95 % value of |S| with each failed life at the limit (nearest rank), m.
    pub p50_m: f64,
    pub p95_m: f64,
    /// P(|S| > the criterion's S_lim), a failed life exceeding it (0 without an exceedance
    /// criterion).
    pub exceedance_probability: f64,
    /// Its Wilson 95 % interval ([0, 0] without an exceedance criterion).
    pub exceedance_probability_ci95: [f64; 2],
    pub failure_probability: f64,
    /// Its Wilson 95 % interval.
    pub failure_probability_ci95: [f64; 2],
    /// P(failure by sliding), by rotation and by heel pressure (of the failing wave: a life may
    /// count in several).
    pub failure_by_sliding_probability: f64,
    pub failure_by_rotation_probability: f64,
    pub failure_by_heel_pressure_probability: f64,
    /// What the impulsive waves make of the lives.
    pub impulsive: ImpulsiveShare,
    /// A stratified run's standard errors of P(failure) and of the exceedance (the criteria's
    /// margins read them); absent: the binomial √(p(1 − p)/n) of the lives.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub failure_probability_standard_error: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub exceedance_probability_standard_error: Option<f64>,
}

/// Which model a search is for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SizedModel {
    Dynamic,
    RigidBlock,
}

/// One evaluated width.
#[derive(Debug, Clone, PartialEq, Serialize, serde::Deserialize)]
pub struct Candidate {
    pub width_m: f64,
    /// W' of the caisson at this width, N.
    pub weight_in_water_n: f64,
    pub lives: usize,
    pub dynamic: ModelPoint,
    pub rigid_block: ModelPoint,
    /// The exceedance of the allowable heel pressure by the lives' largest heel pressure (the
    /// dynamic model's).
    pub heel_pressure_exceedance: HeelPressureExceedance,
    /// What the life warnings of the dynamic model's lives need
    /// ([`super::checks::candidate_warnings`]).
    pub life_counts: LifeCounts,
    /// `[size] lives = "auto"`: the rule's verdict on this candidate's lives (how many it took,
    /// the relative errors, met or not); absent with a fixed number of lives.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub precision: Option<crate::analysis::lifetime::AutoPrecision>,
}

impl Candidate {
    /// The rule of `lives = "auto"` ([`crate::analysis::lifetime::AutoLives::judge`]) on this
    /// candidate's statistics: the dynamic model's capped E|S| with its standard error and its
    /// P(failure), as the candidate reports them — the one place the sizing reads them for the
    /// rule. P(failure) is the binomial proportion of the failed lives of a plain run, or a
    /// stratified run's weighted proportion with its two-phase standard error and Wilson interval
    /// ([`crate::analysis::lifetime::AutoLives::judge_estimates`]); `lives` is the pool's then.
    /// `max_lives`: the budget, reported beside.
    pub fn judge(
        &self,
        auto: &crate::analysis::lifetime::AutoLives,
        max_lives: usize,
    ) -> crate::analysis::lifetime::AutoPrecision {
        let d = &self.dynamic;
        let es = (d.expected_sliding_m, d.expected_sliding_standard_error_m);
        match d.failure_probability_standard_error {
            Some(standard_error) => {
                let failure = crate::analysis::estimate::Estimate {
                    value: d.failure_probability,
                    standard_error,
                    ci95: d.failure_probability_ci95,
                };
                auto.judge_estimates(es, &failure, self.lives, max_lives)
            }
            None => auto.judge(es, self.life_counts.failed_lives, self.lives, max_lives),
        }
    }

    pub fn point(&self, m: SizedModel) -> &ModelPoint {
        match m {
            SizedModel::Dynamic => &self.dynamic,
            SizedModel::RigidBlock => &self.rigid_block,
        }
    }
}

/// The mean of `values` and its standard error s/√n (0 with fewer than two values).
pub fn mean_and_se(values: impl Iterator<Item = f64> + Clone) -> (f64, f64) {
    let n = values.clone().count();
    let mean = values.clone().sum::<f64>() / n.max(1) as f64;
    let var = if n > 1 { values.map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1) as f64 } else { 0.0 };
    (mean, (var / n.max(1) as f64).sqrt())
}

/// The statistics of one model over `n` lives: magnitudes |S|, the modes of each life's failing
/// wave (sliding, rotation, heel pressure; none: it did not fail), the sliding limit `limit_m`
/// (module docs, "Criteria") and what the impulsive waves made of the lives.
pub fn model_point(
    magnitudes: &[f64],
    modes: &[[bool; 3]],
    limit_m: f64,
    criteria: &Criteria,
    impulsive: ImpulsiveShare,
) -> ModelPoint {
    let n = magnitudes.len().max(1) as f64;
    let failed: Vec<bool> = modes.iter().map(|m| m.iter().any(|&f| f)).collect();
    // Mean and nearest-rank percentiles as the design report computes them.
    let thresholds = criteria.exceedance.map(|e| vec![e.sliding_m]).unwrap_or_default();
    let s = capped_statistics(magnitudes, &failed, limit_m, &thresholds);
    let pct = |p: f64| s.percentiles_m.iter().find(|(q, _)| *q == p).map_or(0.0, |(_, v)| *v);
    let capped = magnitudes.iter().zip(&failed).map(|(&m, &f)| if f { limit_m } else { m });
    let (mean, se) = mean_and_se(capped);
    let (uncapped, uncapped_se) = mean_and_se(magnitudes.iter().copied());
    let share = |k: Option<usize>| modes.iter().filter(|m| k.map_or(m.iter().any(|&f| f), |k| m[k])).count() as f64 / n;
    let lives = magnitudes.len() as u64;
    let failures = modes.iter().filter(|m| m.iter().any(|&f| f)).count() as u64;
    // The lives beyond the exceedance criterion's S_lim, a failed life beyond it.
    let beyond = |t: f64| magnitudes.iter().zip(&failed).filter(|(&m, &f)| f || m > t).count() as u64;
    let exceedance = criteria.exceedance.map(|e| Estimate::proportion(beyond(e.sliding_m), lives));
    let exceedance_probability = s.exceedance.first().map_or(0.0, |(_, p)| *p);
    ModelPoint {
        expected_sliding_m: mean,
        expected_sliding_standard_error_m: se,
        expected_sliding_ci95_m: normal_ci95(mean, se),
        expected_sliding_uncapped_m: uncapped,
        expected_sliding_uncapped_standard_error_m: uncapped_se,
        expected_sliding_uncapped_ci95_m: normal_ci95(uncapped, uncapped_se),
        p50_m: pct(50.0),
        p95_m: pct(95.0),
        exceedance_probability,
        exceedance_probability_ci95: exceedance.map_or([0.0, 0.0], |e| e.ci95),
        failure_probability: share(None),
        failure_probability_ci95: Estimate::proportion(failures, lives).ci95,
        failure_by_sliding_probability: share(Some(0)),
        failure_by_rotation_probability: share(Some(1)),
        failure_by_heel_pressure_probability: share(Some(2)),
        impulsive,
        failure_probability_standard_error: None,
        exceedance_probability_standard_error: None,
    }
}

/// [`model_point`] of a stratified run's simulated lives, weighted by `est`
/// ([`crate::analysis::stratified`]): every estimate and interval the two-phase one.
pub fn model_point_weighted(
    est: &TwoPhase,
    magnitudes: &[f64],
    modes: &[[bool; 3]],
    limit_m: f64,
    criteria: &Criteria,
    impulsive: ImpulsiveShare,
) -> ModelPoint {
    let failed: Vec<bool> = modes.iter().map(|m| m.iter().any(|&f| f)).collect();
    let capped: Vec<f64> = magnitudes.iter().zip(&failed).map(|(&m, &f)| if f { limit_m } else { m }).collect();
    let mean = est.mean(&capped);
    let uncapped = est.mean(magnitudes);
    let pct = |q: f64| est.quantile(&capped, None, q).map_or(0.0, |(v, _)| v);
    let mode = |k: usize| est.proportion(&modes.iter().map(|m| m[k]).collect::<Vec<bool>>()).value;
    let failure = est.proportion(&failed);
    let exceedance = criteria.exceedance.map(|e| {
        est.proportion(&magnitudes.iter().zip(&failed).map(|(&m, &f)| f || m > e.sliding_m).collect::<Vec<bool>>())
    });
    ModelPoint {
        expected_sliding_m: mean.value,
        expected_sliding_standard_error_m: mean.standard_error,
        expected_sliding_ci95_m: mean.ci95,
        expected_sliding_uncapped_m: uncapped.value,
        expected_sliding_uncapped_standard_error_m: uncapped.standard_error,
        expected_sliding_uncapped_ci95_m: uncapped.ci95,
        p50_m: pct(0.5),
        p95_m: pct(0.95),
        exceedance_probability: exceedance.map_or(0.0, |e| e.value),
        exceedance_probability_ci95: exceedance.map_or([0.0, 0.0], |e| e.ci95),
        failure_probability: failure.value,
        failure_probability_ci95: failure.ci95,
        failure_by_sliding_probability: mode(0),
        failure_by_rotation_probability: mode(1),
        failure_by_heel_pressure_probability: mode(2),
        impulsive,
        failure_probability_standard_error: Some(failure.standard_error),
        exceedance_probability_standard_error: exceedance.map(|e| e.standard_error),
    }
}

/// The failing wave's modes of each life of the dynamic model (sliding, rotation, heel pressure),
/// and the rigid block's (sliding beyond the limit only).
pub fn failure_modes(lives: &[StormOutcome], failure: &FailureLimits) -> (Vec<[bool; 3]>, Vec<[bool; 3]>) {
    let dynamic =
        lives.iter().map(|l| [l.failed_by_sliding, l.failed_by_rotation, l.failed_by_heel_pressure].map(|f| f != 0));
    let rigid = lives.iter().map(|l| [l.rigid_block_failed(failure), false, false]);
    (dynamic.collect(), rigid.collect())
}

/// The candidate of `lives` (their outcomes, in index order) at `width_m` with the failure limits
/// `failure` (at this width); `heel_pa`: the allowable heel pressure and the heel pressure from
/// which the lives' values are exact (`DesignParams::heel_screen_pa`).
pub fn candidate(
    width_m: f64,
    weight_in_water_n: f64,
    lives: &[StormOutcome],
    failure: &FailureLimits,
    criteria: &Criteria,
    heel_pa: (f64, f64),
) -> Candidate {
    let dynamic: Vec<f64> = lives.iter().map(|l| l.sliding_m.abs()).collect();
    let rigid: Vec<f64> = lives.iter().map(|l| l.rigid_block_sliding_m.abs()).collect();
    let (modes, rigid_modes) = failure_modes(lives, failure);
    let counts = LifeCounts::of(lives, failure);
    Candidate {
        width_m,
        weight_in_water_n,
        lives: lives.len(),
        dynamic: model_point(&dynamic, &modes, failure.sliding_m, criteria, counts.impulsive),
        rigid_block: model_point(&rigid, &rigid_modes, failure.sliding_m, criteria, counts.rigid_block_impulsive),
        heel_pressure_exceedance: HeelPressureExceedance::of(lives, heel_pa.0, heel_pa.1),
        life_counts: counts,
        precision: None,
    }
}

/// [`candidate`] of a stratified run: `lives` the simulated lives of its pool (in the pool's
/// order), weighted by `est`; `lives` of the candidate is the pool's.
pub fn candidate_sampled(
    width_m: f64,
    weight_in_water_n: f64,
    lives: &[StormOutcome],
    failure: &FailureLimits,
    criteria: &Criteria,
    heel_pa: (f64, f64),
    est: &TwoPhase,
) -> Candidate {
    let dynamic: Vec<f64> = lives.iter().map(|l| l.sliding_m.abs()).collect();
    let rigid: Vec<f64> = lives.iter().map(|l| l.rigid_block_sliding_m.abs()).collect();
    let (modes, rigid_modes) = failure_modes(lives, failure);
    let counts = LifeCounts::of(lives, failure);
    let dynamic_share = ImpulsiveShare::dynamic_sampled(est, lives);
    let rigid_share = ImpulsiveShare::rigid_block_sampled(est, lives, failure);
    let mut heel = HeelPressureExceedance::of(lives, heel_pa.0, heel_pa.1);
    let beyond: Vec<bool> = lives.iter().map(|l| l.max_heel_pressure_kpa > heel.allowable_kpa).collect();
    let e = est.proportion(&beyond);
    (heel.probability, heel.standard_error, heel.ci95) = (e.value, e.standard_error, e.ci95);
    let dynamic = model_point_weighted(est, &dynamic, &modes, failure.sliding_m, criteria, dynamic_share);
    Candidate {
        width_m,
        weight_in_water_n,
        lives: est.pool(),
        rigid_block: model_point_weighted(est, &rigid, &rigid_modes, failure.sliding_m, criteria, rigid_share),
        heel_pressure_exceedance: heel,
        // The warnings count the simulated lives and give the weighted P(failure) beside them.
        life_counts: LifeCounts { weighted_failure_probability: Some(dynamic.failure_probability), ..counts },
        dynamic,
        precision: None,
    }
}

impl Criteria {
    /// Whether any criterion is given.
    pub fn any(&self) -> bool {
        self.expected_sliding_m.is_some() || self.exceedance.is_some() || self.failure_probability.is_some()
    }

    /// The margins (allowed − estimate) and standard errors of the given criteria at `p` with
    /// `n` lives.
    fn margins(&self, p: &ModelPoint, n: usize) -> Vec<(f64, f64)> {
        let n = n.max(1) as f64;
        let prob_se = |q: f64| (q * (1.0 - q) / n).sqrt();
        let mut out = Vec::with_capacity(3);
        if let Some(s) = self.expected_sliding_m {
            out.push(match self.expected_sliding {
                ExpectedSliding::Capped => (s - p.expected_sliding_m, p.expected_sliding_standard_error_m),
                ExpectedSliding::AsSimulated => {
                    (s - p.expected_sliding_uncapped_m, p.expected_sliding_uncapped_standard_error_m)
                }
            });
        }
        if let Some(e) = self.exceedance {
            let se = p.exceedance_probability_standard_error.unwrap_or_else(|| prob_se(p.exceedance_probability));
            out.push((e.probability - p.exceedance_probability, se));
        }
        if let Some(f) = self.failure_probability {
            let se = p.failure_probability_standard_error.unwrap_or_else(|| prob_se(p.failure_probability));
            out.push((f - p.failure_probability, se));
        }
        out
    }

    /// Whether every criterion holds at the estimate shifted by `z` standard errors (z = 0: the
    /// estimate; z = Z95: the upper bound, met with confidence; z = −Z95: possibly met).
    pub fn met(&self, p: &ModelPoint, n: usize, z: f64) -> bool {
        self.margins(p, n).iter().all(|&(margin, se)| margin - z * se >= 0.0)
    }

    /// Φ(margin/SE) of the tightest criterion: the normal-approximation probability that the
    /// criterion is met, given the Monte Carlo noise (1 or 0 when the SE is 0).
    pub fn confidence(&self, p: &ModelPoint, n: usize) -> f64 {
        self.margins(p, n)
            .iter()
            .map(|&(margin, se)| {
                if se > 0.0 {
                    normal_cdf(margin / se)
                } else if margin >= 0.0 {
                    1.0
                } else {
                    0.0
                }
            })
            .fold(1.0, f64::min)
    }
}

/// The search's controls.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SizeParams {
    /// The widths searched, m (lo < hi).
    pub range_m: (f64, f64),
    pub criteria: Criteria,
    /// Lives per candidate (with `auto`, the most a candidate may take).
    pub lives: usize,
    /// `[size] lives = "auto"`: each candidate's lives to this target precision
    /// ([`crate::analysis::lifetime::AutoLives`]); absent from the fingerprint when `None`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub auto: Option<crate::analysis::lifetime::AutoLives>,
    /// Width tolerance of the bisection, m.
    pub tolerance_m: f64,
    /// Widths of the design curve's grid (≥ 2, ends included).
    pub curve_points: usize,
    /// Goda's conventional design beside the search (it changes no life: left out of the
    /// checkpoint's fingerprint).
    #[serde(skip)]
    pub conventional: super::conventional::ConventionalCriteria,
}

/// Why a sizing's controls were refused: one quantity out of its range, or a range of widths
/// that holds none.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SizeParamError {
    #[error(transparent)]
    Param(#[from] crate::ParamError),
    #[error("range_m = [{lo_m}, {hi_m}]: the smallest width must be below the largest")]
    EmptyRange { lo_m: f64, hi_m: f64 },
}

impl SizeParams {
    /// The controls if in range: the widths above 0 and at most 1 km, the smallest below the
    /// largest; the criteria ([`Criteria::checked`]); 1 to 10⁶ lives; 2 to 100 widths on the
    /// design curve; the tolerance above a millionth of the range and at most the range; Goda's
    /// criteria ([`super::conventional::ConventionalCriteria::checked`]).
    pub fn checked(self) -> Result<Self, SizeParamError> {
        let (lo, hi) = self.range_m;
        interval("range_lo_m", lo, 0.0, 1000.0, true)?;
        interval("range_hi_m", hi, 0.0, 1000.0, true)?;
        if lo >= hi {
            return Err(SizeParamError::EmptyRange { lo_m: lo, hi_m: hi });
        }
        self.criteria.checked()?;
        count("lives", self.lives, 1, 1_000_000)?;
        if let Some(a) = self.auto {
            a.checked()?;
        }
        count("curve_points", self.curve_points, 2, 100)?;
        interval("tolerance_m", self.tolerance_m, (hi - lo) * 1e-6, hi - lo, true)?;
        self.conventional.checked()?;
        Ok(self)
    }
}

impl Criteria {
    /// The criteria if in range: slidings above 0 and at most 1 km, probabilities from 0 to 1.
    pub fn checked(self) -> Result<Self, crate::ParamError> {
        if let Some(e) = self.exceedance {
            interval("exceedance_sliding_m", e.sliding_m, 0.0, 1000.0, true)?;
            interval("exceedance_probability", e.probability, 0.0, 1.0, false)?;
        }
        if let Some(s) = self.expected_sliding_m {
            interval("expected_sliding_m", s, 0.0, 1000.0, true)?;
        }
        if let Some(p) = self.failure_probability {
            interval("failure_probability", p, 0.0, 1.0, false)?;
        }
        Ok(self)
    }
}

/// The answer for one model.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "status", rename_all = "snake_case")]
pub enum Required {
    /// The smallest width meeting the criterion, within the tolerance (the bracket's upper end),
    /// with the Monte Carlo interval (where the candidates' lower and upper 95 % bounds change
    /// from not met to met; `None` where the range holds no such change) and the confidence at
    /// the required width.
    Found { width_m: f64, bracket_m: (f64, f64), interval_m: (Option<f64>, Option<f64>), confidence: f64 },
    /// Already the smallest width of the range meets it: widen the range downwards.
    AtLowerBound { width_m: f64 },
    /// No width of the range meets it: widen the range upwards.
    NotInRange { largest_m: f64 },
}

impl Required {
    pub fn width_m(&self) -> Option<f64> {
        match self {
            Required::Found { width_m, .. } | Required::AtLowerBound { width_m } => Some(*width_m),
            Required::NotInRange { .. } => None,
        }
    }
}

/// The result of a search: every evaluated candidate (sorted by width) and the answers.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Sizing {
    pub candidates: Vec<Candidate>,
    pub dynamic: Required,
    pub rigid_block: Required,
}

/// The grid widths of the design curve.
pub fn curve_widths(p: &SizeParams) -> Vec<f64> {
    let k = p.curve_points.max(2);
    let (lo, hi) = p.range_m;
    (0..k).map(|i| if i + 1 == k { hi } else { lo + (hi - lo) * i as f64 / (k - 1) as f64 }).collect()
}

/// How many bisection steps narrow a bracket of `width_m` to the tolerance.
pub fn bisection_steps(p: &SizeParams, width_m: f64) -> usize {
    if width_m <= p.tolerance_m {
        0
    } else {
        (width_m / p.tolerance_m).log2().ceil() as usize
    }
}

/// Search the width (module docs). `evaluate(width)` runs the lives at that width; it is called
/// once per width, never twice for the same one.
pub fn size<E>(p: &SizeParams, evaluate: &mut dyn FnMut(f64) -> Result<Candidate, E>) -> Result<Sizing, E> {
    let mut done: Vec<Candidate> = Vec::new();
    let mut eval = |w: f64, done: &mut Vec<Candidate>| -> Result<usize, E> {
        if let Some(i) = done.iter().position(|c| c.width_m == w) {
            return Ok(i);
        }
        done.push(evaluate(w)?);
        Ok(done.len() - 1)
    };
    for w in curve_widths(p) {
        eval(w, &mut done)?;
    }
    let mut answers = Vec::with_capacity(2);
    for model in [SizedModel::Dynamic, SizedModel::RigidBlock] {
        let meets = |c: &Candidate| p.criteria.met(c.point(model), c.lives, 0.0);
        let mut grid: Vec<&Candidate> = done.iter().collect();
        grid.sort_by(|a, b| a.width_m.total_cmp(&b.width_m));
        let first = grid.iter().position(|c| meets(c));
        let answer = match first {
            None => Required::NotInRange { largest_m: p.range_m.1 },
            Some(0) => Required::AtLowerBound { width_m: grid[0].width_m },
            Some(k) => {
                let (mut a, mut b) = (grid[k - 1].width_m, grid[k].width_m);
                while b - a > p.tolerance_m {
                    let mid = 0.5 * (a + b);
                    let i = eval(mid, &mut done)?;
                    if meets(&done[i]) {
                        b = mid;
                    } else {
                        a = mid;
                    }
                }
                let at = done.iter().find(|c| c.width_m == b).expect("the bracket's end was evaluated");
                let mut sorted: Vec<&Candidate> = done.iter().collect();
                sorted.sort_by(|x, y| x.width_m.total_cmp(&y.width_m));
                Required::Found {
                    width_m: b,
                    bracket_m: (a, b),
                    interval_m: (crossing(&sorted, model, p, -Z95), crossing(&sorted, model, p, Z95)),
                    confidence: p.criteria.confidence(at.point(model), at.lives),
                }
            }
        };
        answers.push(answer);
    }
    done.sort_by(|a, b| a.width_m.total_cmp(&b.width_m));
    Ok(Sizing { candidates: done, dynamic: answers[0], rigid_block: answers[1] })
}

/// The smallest evaluated width from which on the criterion holds at `z` standard errors (every
/// larger candidate meets it too), or `None` if the largest does not.
fn crossing(sorted: &[&Candidate], model: SizedModel, p: &SizeParams, z: f64) -> Option<f64> {
    let met: Vec<bool> = sorted.iter().map(|c| p.criteria.met(c.point(model), c.lives, z)).collect();
    if !*met.last()? {
        return None;
    }
    let k = met.iter().rposition(|&m| !m).map_or(0, |i| i + 1);
    Some(sorted[k].width_m)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn params() -> SizeParams {
        SizeParams {
            range_m: (12.0, 30.0),
            criteria: Criteria { expected_sliding_m: Some(0.1), ..Criteria::default() },
            lives: 100,
            auto: None,
            tolerance_m: 0.25,
            curve_points: 8,
            conventional: super::super::conventional::ConventionalCriteria::default(),
        }
    }

    #[test]
    fn size_params_refuse_each_control_out_of_range_naming_it() {
        assert_eq!(params().checked(), Ok(params()));
        let named = |p: SizeParams| match p.checked() {
            Err(SizeParamError::Param(e)) => e.quantity,
            other => panic!("{other:?}"),
        };
        assert_eq!(named(SizeParams { range_m: (0.0, 30.0), ..params() }), "range_lo_m");
        assert_eq!(named(SizeParams { range_m: (12.0, 1e4), ..params() }), "range_hi_m");
        assert_eq!(named(SizeParams { lives: 0, ..params() }), "lives");
        assert_eq!(named(SizeParams { curve_points: 1, ..params() }), "curve_points");
        // The tolerance is above a millionth of the range (18 m) and at most the range.
        assert_eq!(named(SizeParams { tolerance_m: 1e-6, ..params() }), "tolerance_m");
        assert_eq!(named(SizeParams { tolerance_m: 18.5, ..params() }), "tolerance_m");
        let criteria = |c: Criteria| named(SizeParams { criteria: c, ..params() });
        assert_eq!(criteria(Criteria { expected_sliding_m: Some(-0.1), ..Criteria::default() }), "expected_sliding_m");
        assert_eq!(criteria(Criteria { failure_probability: Some(1.5), ..Criteria::default() }), "failure_probability");
        let exceedance = |sliding_m, probability| Criteria {
            exceedance: Some(ExceedanceCriterion { sliding_m, probability }),
            ..Criteria::default()
        };
        assert_eq!(criteria(exceedance(0.0, 0.1)), "exceedance_sliding_m");
        assert_eq!(criteria(exceedance(0.5, f64::NAN)), "exceedance_probability");
        let goda = |c| named(SizeParams { conventional: c, ..params() });
        let d = params().conventional;
        assert_eq!(
            goda(super::super::conventional::ConventionalCriteria { sliding_safety_factor: 0.9, ..d }),
            "sliding_safety_factor"
        );
        assert_eq!(
            goda(super::super::conventional::ConventionalCriteria { overturning_safety_factor: 11.0, ..d }),
            "overturning_safety_factor"
        );
        assert_eq!(
            goda(super::super::conventional::ConventionalCriteria { allowable_heel_pressure_pa: 1e4, ..d }),
            "allowable_heel_pressure_pa"
        );
        assert_eq!(
            SizeParams { range_m: (30.0, 12.0), ..params() }.checked(),
            Err(SizeParamError::EmptyRange { lo_m: 30.0, hi_m: 12.0 })
        );
    }

    fn point(mean: f64) -> ModelPoint {
        ModelPoint {
            expected_sliding_m: mean,
            expected_sliding_standard_error_m: 0.0,
            p50_m: mean,
            p95_m: mean,
            expected_sliding_uncapped_m: mean,
            ..ModelPoint::default()
        }
    }

    #[test]
    fn statistics_of_a_sample_by_hand() {
        let c = Criteria {
            exceedance: Some(ExceedanceCriterion { sliding_m: 0.5, probability: 0.1 }),
            ..Criteria::default()
        };
        // Limit 1.5 m: the second life failed by rotation (|S| 0.4 m), the third by sliding
        // (2 m); capped values 0, 1.5, 1.5, 0.2.
        let f = false;
        let modes = [[f, f, f], [f, true, f], [true, f, f], [f, f, f]];
        let p = model_point(&[0.0, 0.4, 2.0, 0.2], &modes, 1.5, &c, ImpulsiveShare::default());
        assert!((p.expected_sliding_m - 0.8).abs() < 1e-15);
        assert!((p.expected_sliding_uncapped_m - 0.65).abs() < 1e-15);
        // s² = (0.64 + 0.49 + 0.49 + 0.36)/3 = 0.66, SE = √(s²/4).
        assert!((p.expected_sliding_standard_error_m - (1.98f64 / 3.0 / 4.0).sqrt()).abs() < 1e-15);
        // As simulated: mean 0.65, s² = (0.4225 + 0.0625 + 1.8225 + 0.2025)/3 = 0.8367, SE = √(s²/4).
        assert!((p.expected_sliding_uncapped_standard_error_m - (2.51f64 / 3.0 / 4.0).sqrt()).abs() < 1e-15);
        // Sorted capped values 0, 0.2, 1.5, 1.5; both failed lives exceed 0.5 m.
        assert_eq!((p.p50_m, p.p95_m, p.exceedance_probability, p.failure_probability), (0.2, 1.5, 0.5, 0.5));
        assert_eq!((p.failure_by_sliding_probability, p.failure_by_rotation_probability), (0.25, 0.25));
        assert_eq!(p.failure_by_heel_pressure_probability, 0.0);
        // The criterion E|S| ≤ 0.7 m: the capped mean (0.8 m) misses it, the as-simulated (0.65 m)
        // meets it.
        let capped = Criteria { expected_sliding_m: Some(0.7), ..Criteria::default() };
        let as_simulated = Criteria { expected_sliding: ExpectedSliding::AsSimulated, ..capped };
        assert_eq!((capped.met(&p, 4, 0.0), as_simulated.met(&p, 4, 0.0)), (false, true));
    }

    /// A smooth decreasing E|S|(B) = 2/B² m with no noise: the search returns the root
    /// B* = √(2/S_a) within the tolerance (upper end of the bracket), evaluates no width twice,
    /// and the required width grows as S_a falls.
    #[test]
    fn the_search_finds_the_root_of_a_smooth_curve_within_its_tolerance() {
        let mut last = 0.0;
        for s_a in [0.05, 0.02, 0.01, 0.005] {
            let p = SizeParams {
                range_m: (5.0, 30.0),
                criteria: Criteria { expected_sliding_m: Some(s_a), ..Criteria::default() },
                lives: 1,
                auto: None,
                tolerance_m: 0.01,
                curve_points: 6,
                conventional: Default::default(),
            };
            let mut widths = Vec::new();
            let r = size::<()>(&p, &mut |b| {
                widths.push(b);
                Ok(Candidate {
                    width_m: b,
                    weight_in_water_n: 0.0,
                    lives: 1,
                    dynamic: point(2.0 / (b * b)),
                    rigid_block: point(3.0 / (b * b)),
                    heel_pressure_exceedance: HeelPressureExceedance::default(),
                    life_counts: LifeCounts::default(),
                    precision: None,
                })
            })
            .unwrap();
            let exact = (2.0 / s_a).sqrt();
            let Required::Found { width_m, bracket_m, .. } = r.dynamic else { panic!("{:?}", r.dynamic) };
            assert!(width_m >= exact && width_m - exact <= 0.01, "S_a {s_a}: {width_m} vs {exact}");
            assert!(bracket_m.1 - bracket_m.0 <= 0.01);
            let rb = r.rigid_block.width_m().unwrap();
            assert!(rb >= (3.0 / s_a).sqrt() && rb - (3.0 / s_a).sqrt() <= 0.01);
            let mut unique = widths.clone();
            unique.sort_by(f64::total_cmp);
            unique.dedup();
            assert_eq!(unique.len(), widths.len(), "no width evaluated twice");
            assert!(width_m > last, "monotone in S_a");
            last = width_m;
        }
    }

    #[test]
    fn a_range_too_narrow_says_which_way_to_widen() {
        let p = SizeParams {
            range_m: (5.0, 6.0),
            criteria: Criteria { expected_sliding_m: Some(0.01), ..Criteria::default() },
            lives: 1,
            auto: None,
            tolerance_m: 0.1,
            curve_points: 3,
            conventional: Default::default(),
        };
        let eval = |k: f64| {
            move |b: f64| -> Result<Candidate, ()> {
                Ok(Candidate {
                    width_m: b,
                    weight_in_water_n: 0.0,
                    lives: 1,
                    dynamic: point(k / (b * b)),
                    rigid_block: point(k / (b * b)),
                    heel_pressure_exceedance: HeelPressureExceedance::default(),
                    life_counts: LifeCounts::default(),
                    precision: None,
                })
            }
        };
        assert_eq!(size(&p, &mut eval(2.0)).unwrap().dynamic, Required::NotInRange { largest_m: 6.0 });
        assert_eq!(size(&p, &mut eval(0.1)).unwrap().dynamic, Required::AtLowerBound { width_m: 5.0 });
    }
}
