//! The statistics of the lives: capped and plain sliding statistics, the counts the warnings read,
//! the impulsive share and the heel pressure's exceedance.

use super::outcome::StormOutcome;
use super::params::FailureLimits;
use crate::analysis::limits::SEAWARD_REPORT_M;

/// Statistics of the life totals.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct LifeStatistics {
    pub lives: usize,
    pub mean_m: f64,
    /// (percent, value m) for 5, 50, 95, 99 %.
    pub percentiles_m: Vec<(f64, f64)>,
    /// (threshold m, probability of exceeding it).
    pub exceedance: Vec<(f64, f64)>,
}

/// The headline statistics of a model's lives (module docs, "Failure"): mean, percentiles and
/// exceedances of the magnitudes |S| with each failed life at the sliding limit `limit_m` (a
/// surviving life's |S| never exceeds it, so the mean is bounded by it), and a failed life
/// counted as exceeding every threshold (at and beyond the limit too: P(|S| > s) ≥ P(failure)).
pub fn capped_statistics(magnitudes: &[f64], failed: &[bool], limit_m: f64, thresholds_m: &[f64]) -> LifeStatistics {
    let capped: Vec<f64> = magnitudes.iter().zip(failed).map(|(&m, &f)| if f { limit_m } else { m }).collect();
    let mut s = life_statistics(&capped, &[]);
    let n = magnitudes.len().max(1) as f64;
    s.exceedance = thresholds_m
        .iter()
        .map(|&t| (t, magnitudes.iter().zip(failed).filter(|(&m, &f)| f || m > t).count() as f64 / n))
        .collect();
    s
}

/// Mean, percentiles (nearest-rank) and exceedance probabilities of `values`.
pub fn life_statistics(values: &[f64], thresholds_m: &[f64]) -> LifeStatistics {
    let n = values.len();
    let mut sorted = values.to_vec();
    sorted.sort_by(f64::total_cmp);
    let pct = |p: f64| if n == 0 { 0.0 } else { sorted[((p / 100.0 * n as f64).ceil() as usize).clamp(1, n) - 1] };
    LifeStatistics {
        lives: n,
        mean_m: if n == 0 { 0.0 } else { values.iter().sum::<f64>() / n as f64 },
        percentiles_m: [5.0, 50.0, 95.0, 99.0].iter().map(|&p| (p, pct(p))).collect(),
        exceedance: thresholds_m
            .iter()
            .map(|&t| (t, values.iter().filter(|&&v| v > t).count() as f64 / n.max(1) as f64))
            .collect(),
    }
}

/// What the life warnings need of a model's lives: a design run's lives reduce to it, and a
/// sizing candidate keeps it ([`crate::analysis::sizing::Candidate::life_counts`]).
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct LifeCounts {
    pub lives: usize,
    /// Lives that failed (any mode), and by each mode of their failing wave (a life may count
    /// in several).
    pub failed_lives: usize,
    pub failed_by_sliding_lives: usize,
    pub failed_by_rotation_lives: usize,
    pub failed_by_heel_pressure_lives: usize,
    /// Lives with a wave that rotated the caisson beyond [`ROCKING_LIMIT_RAD`].
    pub large_rotation_lives: usize,
    /// Lives that ended more than [`SEAWARD_REPORT_M`] seaward of their place.
    pub seaward_lives: usize,
    /// The largest of those seaward distances, m (0 without such lives).
    pub largest_seaward_sliding_m: f64,
    /// E|S| of the lives as simulated (every life to its end, not capped at the failure
    /// limit), m.
    pub expected_sliding_uncapped_m: f64,
    /// E|S| of the rigid block (over the whole lives), m.
    pub rigid_block_expected_sliding_m: f64,
    /// The largest net sliding of a single storm, m.
    pub max_storm_sliding_m: f64,
    /// Failed lives whose dynamic model stopped running on at a wave that did not converge.
    pub run_on_stopped_lives: usize,
    /// What the impulsive waves make of each model's lives.
    pub impulsive: ImpulsiveShare,
    pub rigid_block_impulsive: ImpulsiveShare,
}

impl LifeCounts {
    /// The counts of `lives` with the failure limits `failure` (the rigid block's failure: its
    /// sliding beyond the sliding limit).
    pub fn of(lives: &[StormOutcome], failure: &FailureLimits) -> Self {
        let count = |f: &dyn Fn(&StormOutcome) -> bool| lives.iter().filter(|l| f(l)).count();
        let seaward = |l: &StormOutcome| l.sliding_m < -SEAWARD_REPORT_M;
        LifeCounts {
            lives: lives.len(),
            failed_lives: count(&|l| l.failed()),
            failed_by_sliding_lives: count(&|l| l.failed_by_sliding != 0),
            failed_by_rotation_lives: count(&|l| l.failed_by_rotation != 0),
            failed_by_heel_pressure_lives: count(&|l| l.failed_by_heel_pressure != 0),
            large_rotation_lives: count(&|l| l.large_rotation_waves > 0),
            seaward_lives: count(&seaward),
            largest_seaward_sliding_m: lives.iter().filter(|l| seaward(l)).map(|l| -l.sliding_m).fold(0.0, f64::max),
            expected_sliding_uncapped_m: lives.iter().map(|l| l.sliding_m.abs()).sum::<f64>()
                / lives.len().max(1) as f64,
            rigid_block_expected_sliding_m: lives.iter().map(|l| l.rigid_block_sliding_m.abs()).sum::<f64>()
                / lives.len().max(1) as f64,
            max_storm_sliding_m: lives.iter().map(|l| l.max_storm_sliding_m).fold(0.0, f64::max),
            run_on_stopped_lives: count(&|l| l.run_on_stopped != 0),
            impulsive: ImpulsiveShare::dynamic(lives),
            rigid_block_impulsive: ImpulsiveShare::rigid_block(lives, failure),
        }
    }
}

/// What the impulsive waves make of one model's lives (or storms; module docs, "Impulsive
/// waves"): the `impulsive` group of `design.json`, `size.json` and `fragility.json`.
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct ImpulsiveShare {
    /// The impulsive waves of all lives ([`StormOutcome::impulsive_waves`]).
    pub waves: u64,
    /// The mean over the lives of the sliding those waves caused, m (signed for the dynamic
    /// model, shoreward +).
    pub sliding_m: f64,
    /// Their share of E|S| as simulated: Σ sign(S) S_imp / Σ |S| over the lives, S a life's
    /// sliding and S_imp its impulsive waves' (the part of |S| they made; above 1 where other
    /// waves slid the caisson back); 0 when E|S| = 0.
    pub share_of_expected_sliding: f64,
    /// The failed lives whose failing wave was impulsive, over the failed lives (0 when none
    /// failed).
    pub share_of_failures: f64,
    /// The failed lives.
    pub failures: usize,
}

impl ImpulsiveShare {
    /// From each life's (S, S_imp, failed, failing wave impulsive).
    pub(super) fn of(waves: u64, lives: impl Iterator<Item = (f64, f64, bool, bool)>) -> Self {
        Self::weighted(waves, lives.map(|l| (1.0, l)))
    }

    /// From each life's weight and (S, S_imp, failed, failing wave impulsive): the sums of the
    /// module docs weighted (a stratified run's lives, [`super::sampling`]); `failures` counts the
    /// lives. Weights of 1 give [`Self::of`] to the bit.
    pub fn weighted(waves: u64, lives: impl Iterator<Item = (f64, (f64, f64, bool, bool))>) -> Self {
        let (mut n, mut imp, mut part, mut total) = (0.0, 0.0, 0.0, 0.0);
        let (mut failures, mut failed_weight, mut impulsive_weight) = (0, 0.0, 0.0);
        for (w, (s, s_imp, failed, impulsive)) in lives {
            n += w;
            imp += w * s_imp;
            part += w * if s < 0.0 { -s_imp } else { s_imp };
            total += w * s.abs();
            failures += usize::from(failed);
            if failed {
                failed_weight += w;
                if impulsive {
                    impulsive_weight += w;
                }
            }
        }
        ImpulsiveShare {
            waves,
            sliding_m: if n > 0.0 { imp / n } else { 0.0 },
            share_of_expected_sliding: if total > 0.0 { part / total } else { 0.0 },
            share_of_failures: if failed_weight > 0.0 { impulsive_weight / failed_weight } else { 0.0 },
            failures,
        }
    }

    /// The dynamic model's.
    pub fn dynamic(lives: &[StormOutcome]) -> Self {
        let waves = lives.iter().map(|l| l.impulsive_waves).sum();
        Self::of(
            waves,
            lives.iter().map(|l| (l.sliding_m, l.impulsive_sliding_m, l.failed(), l.failing_wave_impulsive != 0)),
        )
    }

    /// The rigid block's (it fails by sliding beyond `failure.sliding_m`).
    pub fn rigid_block(lives: &[StormOutcome], failure: &FailureLimits) -> Self {
        let waves = lives.iter().map(|l| l.impulsive_waves).sum();
        Self::of(
            waves,
            lives.iter().map(|l| {
                (
                    l.rigid_block_sliding_m,
                    l.rigid_block_impulsive_sliding_m,
                    l.rigid_block_failed(failure),
                    l.rigid_block_failing_wave_impulsive != 0,
                )
            }),
        )
    }

    /// Whether impulsive waves make more than half of E|S| or of the failures.
    pub fn dominates(&self) -> bool {
        self.share_of_expected_sliding > 0.5 || self.share_of_failures > 0.5
    }
}

/// The exceedance of the allowable heel pressure by the lives' largest heel pressure
/// ([`StormOutcome::max_heel_pressure_kpa`]; module docs, "Heel pressure"): the dynamic model's
/// (the rigid block has no foundation pressure).
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct HeelPressureExceedance {
    /// q_a, kPa.
    pub allowable_kpa: f64,
    /// P(q_heel > q_a): the share of lives whose largest heel pressure exceeds q_a (exact: the
    /// screen runs every wave that may reach q_a).
    pub probability: f64,
    /// Its standard error √(p(1 − p)/n) and Wilson 95 % interval
    /// ([`crate::analysis::estimate::wilson_ci95`]).
    pub standard_error: f64,
    pub ci95: [f64; 2],
    /// The lives beyond q_a.
    pub lives: usize,
    /// The heel pressure at and above which each life's value is exact, kPa (the screen's: q_a,
    /// or the failure heel pressure if lower); below it a life's value is the largest of the
    /// waves run.
    pub exact_from_kpa: f64,
    /// The largest heel pressure of any life, kPa.
    pub largest_kpa: f64,
}

impl HeelPressureExceedance {
    /// Of `lives` against q_a = `allowable_pa`, exact from `exact_from_pa`.
    pub fn of(lives: &[StormOutcome], allowable_pa: f64, exact_from_pa: f64) -> Self {
        let allowable_kpa = allowable_pa / 1e3;
        let beyond = lives.iter().filter(|l| l.max_heel_pressure_kpa > allowable_kpa).count();
        let n = lives.len().max(1) as f64;
        let p = beyond as f64 / n;
        HeelPressureExceedance {
            allowable_kpa,
            probability: p,
            standard_error: (p * (1.0 - p) / n).sqrt(),
            ci95: if lives.is_empty() {
                [0.0, 1.0]
            } else {
                crate::analysis::estimate::wilson_ci95(beyond as u64, lives.len() as u64)
            },
            lives: beyond,
            exact_from_kpa: exact_from_pa / 1e3,
            largest_kpa: lives.iter().map(|l| l.max_heel_pressure_kpa).fold(0.0, f64::max),
        }
    }
}
