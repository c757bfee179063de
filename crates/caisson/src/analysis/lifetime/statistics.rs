//! The statistics of the lives: capped and plain sliding statistics, the counts the warnings read,
//! the impulsive share and the heel pressure's exceedance.

use super::outcome::StormOutcome;
use super::params::FailureLimits;
use crate::analysis::estimate::{wilson_ci95, Z95};
use crate::analysis::limits::SEAWARD_REPORT_M;
use crate::analysis::stratified::TwoPhase;

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
    /// A stratified run's estimate of P(failure) (its lives weighted): the counts above are of
    /// its simulated lives, which hold the severe storms more often than the climate does, so the
    /// warnings say so and give this; `None` when every life was simulated.
    #[serde(default)]
    pub weighted_failure_probability: Option<f64>,
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
            weighted_failure_probability: None,
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
    /// Its 95 % interval (module docs, "Impulsive waves"): R ± 1.96 SE with the ratio
    /// estimator's linearised standard error; [0, 0] when E|S| = 0.
    pub share_of_expected_sliding_ci95: [f64; 2],
    /// The failed lives whose failing wave was impulsive, over the failed lives (0 when none
    /// failed).
    pub share_of_failures: f64,
    /// Its Wilson 95 % interval over the failed lives; [0, 1] when none failed.
    pub share_of_failures_ci95: [f64; 2],
    /// The failed lives.
    pub failures: usize,
}

impl ImpulsiveShare {
    /// From each life's (S, S_imp, failed, failing wave impulsive), with the intervals of simple
    /// random sampling (module docs, "Impulsive waves"): the share of E|S| R = Σ x_i / Σ y_i (x_i
    /// = sign(S_i) S_imp,i, y_i = |S_i|) with SE² = Σ (x_i − R y_i)² / (n (n − 1) ȳ²) (Cochran
    /// 1977, Eq. 6.13), and Wilson's interval of the k impulsive failures among the failed ones.
    pub(super) fn of(waves: u64, lives: impl Iterator<Item = (f64, f64, bool, bool)>) -> Self {
        let lives: Vec<_> = lives.collect();
        let mut share = Self::weighted(waves, lives.iter().map(|&l| (1.0, l)));
        let n = lives.len() as f64;
        let total: f64 = lives.iter().map(|l| l.0.abs()).sum();
        if total > 0.0 && lives.len() > 1 {
            let r = share.share_of_expected_sliding;
            let d2: f64 = lives.iter().map(|&(s, s_imp, _, _)| (signed_part(s, s_imp) - r * s.abs()).powi(2)).sum();
            let se = (d2 / (n * (n - 1.0))).sqrt() / (total / n);
            share.share_of_expected_sliding_ci95 = [r - Z95 * se, r + Z95 * se];
        } else {
            share.share_of_expected_sliding_ci95 = [share.share_of_expected_sliding; 2];
        }
        let impulsive_failures = lives.iter().filter(|l| l.2 && l.3).count() as u64;
        share.share_of_failures_ci95 =
            if share.failures > 0 { wilson_ci95(impulsive_failures, share.failures as u64) } else { [0.0, 1.0] };
        share
    }

    /// [`Self::weighted`] of a stratified run's simulated lives weighted by `est` (in its order),
    /// with the two-phase intervals ([`TwoPhase`]): the share of E|S| linearised, z_i = (x_i − R
    /// y_i)/ȳ, its variance that of the mean of z (Särndal, Swensson & Wretman 1992, §5.6); the
    /// share of the failures a domain proportion, Wilson's interval at its effective size
    /// (p̂(1 − p̂)/V, or Kish's over the failed lives at p̂ = 0 or 1).
    fn two_phase(waves: u64, est: &TwoPhase, lives: &[(f64, f64, bool, bool)]) -> Self {
        let w = est.weights();
        let mut share = Self::weighted(waves, w.iter().zip(lives).map(|(&w, &l)| (w, l)));
        let mean_y: f64 = w.iter().zip(lives).map(|(w, l)| w * l.0.abs()).sum();
        if mean_y > 0.0 {
            let r = share.share_of_expected_sliding;
            let z: Vec<f64> =
                lives.iter().map(|&(s, s_imp, _, _)| (signed_part(s, s_imp) - r * s.abs()) / mean_y).collect();
            let se = est.mean(&z).standard_error;
            share.share_of_expected_sliding_ci95 = [r - Z95 * se, r + Z95 * se];
        } else {
            share.share_of_expected_sliding_ci95 = [0.0, 0.0];
        }
        let (failed, impulsive): (Vec<bool>, Vec<bool>) = lives.iter().map(|l| (l.2, l.3)).unzip();
        share.share_of_failures_ci95 = est.domain_proportion(&impulsive, &failed).ci95;
        share
    }

    /// From each life's weight and (S, S_imp, failed, failing wave impulsive): the sums of the
    /// module docs weighted (a stratified run's lives, [`super::sampling`]); `failures` counts the
    /// lives. Weights of 1 give [`Self::of`]'s values to the bit. The intervals are left at 0:
    /// [`Self::of`] and [`Self::two_phase`] set them.
    fn weighted(waves: u64, lives: impl Iterator<Item = (f64, (f64, f64, bool, bool))>) -> Self {
        let (mut n, mut imp, mut part, mut total) = (0.0, 0.0, 0.0, 0.0);
        let (mut failures, mut failed_weight, mut impulsive_weight) = (0, 0.0, 0.0);
        for (w, (s, s_imp, failed, impulsive)) in lives {
            n += w;
            imp += w * s_imp;
            part += w * signed_part(s, s_imp);
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
            ..Self::default()
        }
    }

    /// The dynamic model's.
    pub fn dynamic(lives: &[StormOutcome]) -> Self {
        Self::of(impulsive_waves(lives), lives.iter().map(dynamic_life))
    }

    /// The rigid block's (it fails by sliding beyond `failure.sliding_m`).
    pub fn rigid_block(lives: &[StormOutcome], failure: &FailureLimits) -> Self {
        Self::of(impulsive_waves(lives), lives.iter().map(|l| rigid_block_life(l, failure)))
    }

    /// [`Self::dynamic`] of a stratified run's simulated lives weighted by `est`.
    pub fn dynamic_sampled(est: &TwoPhase, lives: &[StormOutcome]) -> Self {
        Self::two_phase(impulsive_waves(lives), est, &lives.iter().map(dynamic_life).collect::<Vec<_>>())
    }

    /// [`Self::rigid_block`] of a stratified run's simulated lives weighted by `est`.
    pub fn rigid_block_sampled(est: &TwoPhase, lives: &[StormOutcome], failure: &FailureLimits) -> Self {
        let of: Vec<_> = lives.iter().map(|l| rigid_block_life(l, failure)).collect();
        Self::two_phase(impulsive_waves(lives), est, &of)
    }

    /// Whether impulsive waves make more than half of E|S| or of the failures.
    pub fn dominates(&self) -> bool {
        self.share_of_expected_sliding > 0.5 || self.share_of_failures > 0.5
    }
}

/// The impulsive waves of all lives.
fn impulsive_waves(lives: &[StormOutcome]) -> u64 {
    lives.iter().map(|l| l.impulsive_waves).sum()
}

/// A life's (S, S_imp, failed, failing wave impulsive) in the dynamic model.
fn dynamic_life(l: &StormOutcome) -> (f64, f64, bool, bool) {
    (l.sliding_m, l.impulsive_sliding_m, l.failed(), l.failing_wave_impulsive != 0)
}

/// A life's (S, S_imp, failed, failing wave impulsive) in the rigid block.
fn rigid_block_life(l: &StormOutcome, failure: &FailureLimits) -> (f64, f64, bool, bool) {
    (
        l.rigid_block_sliding_m,
        l.rigid_block_impulsive_sliding_m,
        l.rigid_block_failed(failure),
        l.rigid_block_failing_wave_impulsive != 0,
    )
}

/// The part of a life's |S| its impulsive waves made: sign(S) S_imp.
fn signed_part(s: f64, s_imp: f64) -> f64 {
    if s < 0.0 {
        -s_imp
    } else {
        s_imp
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::stratified::wilson_ci95_at;

    /// A two-phase sample of one stratum kept whole is simple random sampling: the share of E|S|
    /// and its interval are [`ImpulsiveShare::of`]'s (the linearised z has mean 0, so its
    /// variance s_z²/n is Σ (x − R y)²/(n (n − 1) ȳ²)), and the share of the failures has Wilson's
    /// interval at n_eff = n_D (n − 1)/n (V = p̂(1 − p̂) n/(n_D (n − 1)) for a domain of n_D lives).
    #[test]
    fn one_stratum_kept_whole_gives_the_plain_intervals() {
        // 8 lives: (S, S_imp, failed, failing wave impulsive).
        let lives = [
            (0.2, 0.1, false, false),
            (-1.5, -0.5, true, true),
            (0.7, 0.0, false, false),
            (2.5, 1.0, true, false),
            (0.0, 0.0, false, false),
            (3.1, 2.0, true, true),
            (0.05, 0.05, false, false),
            (2.2, 0.3, true, false),
        ];
        let plain = ImpulsiveShare::of(5, lives.iter().copied());
        let est = TwoPhase::new(&[8], &[(0, 1.0); 8]);
        let sampled = ImpulsiveShare::two_phase(5, &est, &lives);
        assert_eq!(
            (plain.share_of_expected_sliding, plain.share_of_failures),
            (sampled.share_of_expected_sliding, 0.5)
        );
        assert_eq!(sampled.share_of_failures, 0.5);
        for k in 0..2 {
            let (a, b) = (plain.share_of_expected_sliding_ci95[k], sampled.share_of_expected_sliding_ci95[k]);
            assert!((a - b).abs() < 1e-12, "end {k}: {a} against {b}");
        }
        // 2 impulsive failures of n_D = 4: Wilson at 4 for the plain run, at 4·7/8 = 3.5 for the
        // two-phase estimator.
        assert_eq!(plain.share_of_failures_ci95, wilson_ci95(2, 4));
        let at = wilson_ci95_at(0.5, 3.5);
        for k in 0..2 {
            assert!(
                (sampled.share_of_failures_ci95[k] - at[k]).abs() < 1e-12,
                "{:?} against {at:?}",
                sampled.share_of_failures_ci95
            );
        }
        // The plain interval of the share of E|S| is wider than a point and holds it.
        let [lo, hi] = plain.share_of_expected_sliding_ci95;
        assert!(lo < plain.share_of_expected_sliding && plain.share_of_expected_sliding < hi && hi - lo > 0.05);
    }
}
