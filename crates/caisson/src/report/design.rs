//! `caisson design`: `design.json` (keys in docs/design.md).

use super::{fingerprint, ModelReport, Provenance};
use crate::analysis::checks::{counts_warnings, impulsive_warnings, structure_warnings, wave_load_warnings, Warning};
use crate::analysis::climate::{SeaLevelRise, StormDuration, StormModel, WaveDirection, WavePeriods};
use crate::analysis::estimate::{normal_ci95, percentile_ci95, Estimate};
use crate::analysis::lifetime::sampling::{Pool, Strata, STRATA};
use crate::analysis::lifetime::{
    capped_statistics, life_statistics, AutoLives, AutoPrecision, DesignParams, ErrorModel, ErrorScope, FailureLimits,
    HeelPressureExceedance, ImpulsiveShare, LifeCounts, LifeParams, LifeStatistics, Sampling, StormCase, StormOutcome,
    WaveDraws,
};
use crate::analysis::site::WaveSetup;
use crate::analysis::sizing::failure_modes;
use crate::analysis::stratified::TwoPhase;
use crate::analysis::Structure;
use crate::loads::model::WaveLoadModel;
use serde::Serialize;

/// Everything a life's outcome depends on besides its index.
#[derive(Serialize)]
struct LifeInputs<'a> {
    structure: &'a Structure,
    waves: &'a WaveLoadModel,
    rigid_block_mu: f64,
    screen: bool,
    draws: WaveDraws,
    failure: Option<FailureLimits>,
    heel_screen_pa: f64,
    life: &'a LifeParams,
    seed: u64,
}

/// The fingerprint of a design run's lives: two runs with the same fingerprint (and results
/// version) give every life the same outcome, so their lives may be merged or resumed. The number
/// of lives and the thresholds are not part of it (they do not change any life).
pub fn design_fingerprint(case: &StormCase<'_>, p: &DesignParams) -> String {
    fingerprint(&LifeInputs {
        structure: case.structure,
        waves: case.model,
        rigid_block_mu: case.rigid_block_mu,
        screen: case.screen,
        draws: case.draws,
        failure: case.failure,
        heel_screen_pa: case.heel_screen_pa,
        life: &p.life,
        seed: p.seed,
    })
}

/// Nearest-rank percentiles of the life totals, m.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Percentiles {
    pub p5: f64,
    pub p50: f64,
    pub p95: f64,
    pub p99: f64,
}

/// The 95 % intervals of [`Percentiles`] ([low, high] order statistics of the lives, an end
/// `None` where the lives are too few for it: [`crate::analysis::estimate::percentile_ci95`]), m.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PercentileIntervals {
    pub p5: [Option<f64>; 2],
    pub p50: [Option<f64>; 2],
    pub p95: [Option<f64>; 2],
    pub p99: [Option<f64>; 2],
}

impl PercentileIntervals {
    /// Of the life totals `values` (in any order).
    fn of(values: &[f64]) -> Self {
        let mut sorted = values.to_vec();
        sorted.sort_by(f64::total_cmp);
        let ci = |q: f64| percentile_ci95(&sorted, q);
        PercentileIntervals { p5: ci(0.05), p50: ci(0.50), p95: ci(0.95), p99: ci(0.99) }
    }
}

/// The probability that a life's sliding exceeds a threshold, with its Wilson 95 % interval.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Exceedance {
    pub threshold_m: f64,
    pub probability: f64,
    pub ci95: [f64; 2],
}

/// The lives that failed: moved beyond the sliding limit from their place at some time, or
/// rotated beyond the rotation limit.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Failure {
    /// The share of lives that failed, and its Wilson 95 % interval.
    pub probability: f64,
    pub probability_ci95: [f64; 2],
    pub lives: usize,
    /// The lives that failed by sliding (beyond `failure_sliding_m`).
    pub by_sliding: FailureMode,
    /// The lives that failed by rotation (beyond `failure_rotation_rad`; never the rigid
    /// block's). A life whose failing wave did both counts in both modes.
    pub by_rotation: FailureMode,
    /// The lives that failed by heel pressure (beyond `failure_heel_pressure_kpa`, if given;
    /// never the rigid block's).
    pub by_heel_pressure: FailureMode,
}

/// The lives that failed by one mode.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FailureMode {
    pub probability: f64,
    /// Its Wilson 95 % interval.
    pub probability_ci95: [f64; 2],
    pub lives: usize,
}

impl FailureMode {
    /// `lives` of `n`.
    fn of(lives: usize, n: usize) -> Self {
        let e = proportion(lives, n);
        FailureMode { probability: e.value, probability_ci95: e.ci95, lives }
    }
}

/// The proportion `k` of `n` lives with its Wilson interval ([`Estimate::proportion`]).
fn proportion(k: usize, n: usize) -> Estimate {
    Estimate::proportion(k as u64, n as u64)
}

/// The statistics of the lives that did not fail.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Surviving {
    pub lives: usize,
    /// Mean |S| of the surviving lives, m (0 when none survived), its standard error and 95 %
    /// interval.
    pub expected_sliding_m: f64,
    pub expected_sliding_standard_error_m: f64,
    pub expected_sliding_ci95_m: [f64; 2],
    pub percentiles_m: Percentiles,
    pub percentiles_ci95_m: PercentileIntervals,
}

/// The statistics of one model's life totals. "Sliding" is the magnitude |S| of the life's net
/// displacement S (shoreward +): the distance from its place at the end of the life, whichever
/// the direction (docs/design.md).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ModelStatistics {
    /// E|S| with each failed life at the sliding limit (bounded by it), m, its standard error
    /// and 95 % interval (the normal interval, ± 1.96 standard errors).
    pub expected_sliding_m: f64,
    pub expected_sliding_standard_error_m: f64,
    pub expected_sliding_ci95_m: [f64; 2],
    /// E|S| / life years, m, with its standard error and interval (those of E|S| over the years).
    pub expected_sliding_per_year_m: f64,
    pub expected_sliding_per_year_standard_error_m: f64,
    pub expected_sliding_per_year_ci95_m: [f64; 2],
    /// E|S| of the lives as simulated (every life run to its end, failed or not: the expected
    /// sliding distance of Shimosako & Takahashi 1999), m, its standard error and interval.
    pub expected_sliding_uncapped_m: f64,
    pub expected_sliding_uncapped_standard_error_m: f64,
    pub expected_sliding_uncapped_ci95_m: [f64; 2],
    /// Of |S| with each failed life at the sliding limit, and their 95 % intervals.
    pub percentiles_m: Percentiles,
    pub percentiles_ci95_m: PercentileIntervals,
    /// P(|S| > threshold), a failed life exceeding every threshold.
    pub exceedance_probability: Vec<Exceedance>,
    pub failure: Failure,
    pub surviving: Surviving,
    /// What the impulsive waves make of the lives (docs/design.md, "Impulsive waves").
    pub impulsive: ImpulsiveShare,
}

fn percentiles(s: &LifeStatistics) -> Percentiles {
    let pct = |p: f64| s.percentiles_m.iter().find(|(q, _)| *q == p).map_or(0.0, |(_, v)| *v);
    Percentiles { p5: pct(5.0), p50: pct(50.0), p95: pct(95.0), p99: pct(99.0) }
}

impl ModelStatistics {
    /// `magnitudes`: |S| of every life; `modes`: the modes of each life's failing wave
    /// (sliding, rotation, heel pressure); `limit_m`: the sliding limit.
    fn new(
        magnitudes: &[f64],
        modes: &[[bool; 3]],
        limit_m: f64,
        thresholds_m: &[f64],
        years: usize,
        impulsive: ImpulsiveShare,
    ) -> Self {
        let failed: Vec<bool> = modes.iter().map(|m| m.iter().any(|&f| f)).collect();
        let s = capped_statistics(magnitudes, &failed, limit_m, thresholds_m);
        let capped: Vec<f64> = magnitudes.iter().zip(&failed).map(|(&m, &f)| if f { limit_m } else { m }).collect();
        let (_, se) = crate::analysis::sizing::mean_and_se(capped.iter().copied());
        let (uncapped, uncapped_se) = crate::analysis::sizing::mean_and_se(magnitudes.iter().copied());
        let surviving: Vec<f64> = magnitudes.iter().zip(&failed).filter(|(_, &f)| !f).map(|(&m, _)| m).collect();
        let sv = life_statistics(&surviving, &[]);
        let (_, sv_se) = crate::analysis::sizing::mean_and_se(surviving.iter().copied());
        let (n, failures) = (magnitudes.len(), magnitudes.len() - surviving.len());
        let mode = |k: usize| FailureMode::of(modes.iter().filter(|m| m[k]).count(), n);
        let per_year = (s.mean_m / years as f64, se / years as f64);
        ModelStatistics {
            expected_sliding_m: s.mean_m,
            expected_sliding_standard_error_m: se,
            expected_sliding_ci95_m: normal_ci95(s.mean_m, se),
            expected_sliding_per_year_m: per_year.0,
            expected_sliding_per_year_standard_error_m: per_year.1,
            expected_sliding_per_year_ci95_m: normal_ci95(per_year.0, per_year.1),
            expected_sliding_uncapped_m: uncapped,
            expected_sliding_uncapped_standard_error_m: uncapped_se,
            expected_sliding_uncapped_ci95_m: normal_ci95(uncapped, uncapped_se),
            percentiles_m: percentiles(&s),
            percentiles_ci95_m: PercentileIntervals::of(&capped),
            exceedance_probability: s
                .exceedance
                .iter()
                .map(|&(threshold_m, probability)| {
                    let k = magnitudes.iter().zip(&failed).filter(|(&m, &f)| f || m > threshold_m).count();
                    Exceedance { threshold_m, probability, ci95: proportion(k, n).ci95 }
                })
                .collect(),
            failure: Failure {
                probability: proportion(failures, n).value,
                probability_ci95: proportion(failures, n).ci95,
                lives: failures,
                by_sliding: mode(0),
                by_rotation: mode(1),
                by_heel_pressure: mode(2),
            },
            surviving: Surviving {
                lives: sv.lives,
                expected_sliding_m: sv.mean_m,
                expected_sliding_standard_error_m: sv_se,
                expected_sliding_ci95_m: normal_ci95(sv.mean_m, sv_se),
                percentiles_m: percentiles(&sv),
                percentiles_ci95_m: PercentileIntervals::of(&surviving),
            },
            impulsive,
        }
    }
}

impl ModelStatistics {
    /// [`Self::new`] of the simulated lives of a stratified run, weighted by `est` (one value per
    /// simulated life; [`crate::analysis::stratified`]): every mean, proportion and percentile its
    /// two-phase estimate and interval; the counts are of the simulated lives.
    fn stratified(
        est: &TwoPhase,
        magnitudes: &[f64],
        modes: &[[bool; 3]],
        limit_m: f64,
        thresholds_m: &[f64],
        years: usize,
        impulsive: ImpulsiveShare,
    ) -> Self {
        let failed: Vec<bool> = modes.iter().map(|m| m.iter().any(|&f| f)).collect();
        let survived: Vec<bool> = failed.iter().map(|f| !f).collect();
        let capped: Vec<f64> = magnitudes.iter().zip(&failed).map(|(&m, &f)| if f { limit_m } else { m }).collect();
        let mean = est.mean(&capped);
        let uncapped = est.mean(magnitudes);
        let percentile =
            |inside: Option<&[bool]>, q: f64| est.quantile(&capped, inside, q).unwrap_or((0.0, [None, None]));
        let table = |inside: Option<&[bool]>| {
            let [a, b, c, d] = [0.05, 0.5, 0.95, 0.99].map(|q| percentile(inside, q));
            (
                Percentiles { p5: a.0, p50: b.0, p95: c.0, p99: d.0 },
                PercentileIntervals { p5: a.1, p50: b.1, p95: c.1, p99: d.1 },
            )
        };
        let (percentiles_m, percentiles_ci95_m) = table(None);
        let (surviving_percentiles, surviving_ci) = table(Some(&survived));
        let surviving = est.domain_mean(magnitudes, &survived);
        let fail = est.proportion(&failed);
        let mode = |k: usize| {
            let flags: Vec<bool> = modes.iter().map(|m| m[k]).collect();
            let e = est.proportion(&flags);
            FailureMode { probability: e.value, probability_ci95: e.ci95, lives: flags.iter().filter(|&&f| f).count() }
        };
        let per_year = (mean.value / years as f64, mean.standard_error / years as f64);
        ModelStatistics {
            expected_sliding_m: mean.value,
            expected_sliding_standard_error_m: mean.standard_error,
            expected_sliding_ci95_m: mean.ci95,
            expected_sliding_per_year_m: per_year.0,
            expected_sliding_per_year_standard_error_m: per_year.1,
            expected_sliding_per_year_ci95_m: normal_ci95(per_year.0, per_year.1),
            expected_sliding_uncapped_m: uncapped.value,
            expected_sliding_uncapped_standard_error_m: uncapped.standard_error,
            expected_sliding_uncapped_ci95_m: uncapped.ci95,
            percentiles_m,
            percentiles_ci95_m,
            exceedance_probability: thresholds_m
                .iter()
                .map(|&threshold_m| {
                    let beyond: Vec<bool> =
                        magnitudes.iter().zip(&failed).map(|(&m, &f)| f || m > threshold_m).collect();
                    let e = est.proportion(&beyond);
                    Exceedance { threshold_m, probability: e.value, ci95: e.ci95 }
                })
                .collect(),
            failure: Failure {
                probability: fail.value,
                probability_ci95: fail.ci95,
                lives: failed.iter().filter(|&&f| f).count(),
                by_sliding: mode(0),
                by_rotation: mode(1),
                by_heel_pressure: mode(2),
            },
            surviving: Surviving {
                lives: survived.iter().filter(|&&s| s).count(),
                expected_sliding_m: surviving.value,
                expected_sliding_standard_error_m: surviving.standard_error,
                expected_sliding_ci95_m: surviving.ci95,
                percentiles_m: surviving_percentiles,
                percentiles_ci95_m: surviving_ci,
            },
            impulsive,
        }
    }
}

/// How a stratified run sampled its lives (docs/design.md, "Stratified sampling"): the
/// `sampling` object of `design.json`, absent from a plain run's.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SamplingReport {
    pub method: Sampling,
    /// The lives ranked by severity (the run's lives), and those simulated.
    pub pool_lives: usize,
    pub simulated_lives: usize,
    /// The strata, lowest severity first.
    pub strata: Vec<StratumReport>,
}

/// One stratum of a stratified run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StratumReport {
    /// Its upper severity bound max H_max² F, m² (absent for the last).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub severity_up_to_m2: Option<f64>,
    /// The share of its lives simulated.
    pub fraction: f64,
    pub pool_lives: usize,
    pub simulated_lives: usize,
}

impl SamplingReport {
    /// Of a pool and its strata.
    pub fn new(strata: &Strata, pool: &Pool) -> Self {
        let mut simulated = [0_usize; STRATA];
        for &(_, h) in &pool.selected {
            simulated[h] += 1;
        }
        SamplingReport {
            method: Sampling::Stratified,
            pool_lives: pool.counts.iter().sum(),
            simulated_lives: pool.selected.len(),
            strata: (0..STRATA)
                .map(|h| StratumReport {
                    severity_up_to_m2: strata.upper_m2.get(h).copied(),
                    fraction: strata.fractions[h],
                    pool_lives: pool.counts[h],
                    simulated_lives: simulated[h],
                })
                .collect(),
        }
    }
}

/// What only the dynamic model tells: the direction of sliding, the largest excursion and
/// rocking.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DynamicStatistics {
    #[serde(flatten)]
    pub sliding: ModelStatistics,
    /// E[S], signed (shoreward +), m.
    pub expected_net_sliding_m: f64,
    /// E[sum of the shoreward wave slides], m.
    pub expected_shoreward_sliding_m: f64,
    /// E[sum of the seaward wave slides] (a magnitude), m.
    pub expected_seaward_sliding_m: f64,
    /// Lives that ended seaward of their place (S < 0).
    pub seaward_lives: usize,
    /// E[the largest distance from the place during the life], m.
    pub expected_max_excursion_m: f64,
    /// Waves (all lives) during which part of the base lifted off.
    pub rocking_waves: u64,
    /// Waves (all lives) that rotated the caisson beyond 0.01 rad ([`crate::analysis::limits::ROCKING_LIMIT_RAD`]).
    pub large_rotation_waves: u64,
    /// Lives with a large-rotation wave: outside the model's validity (it does not follow
    /// overturning).
    pub large_rotation_lives: usize,
    /// The lives' largest heel pressure against the allowable one (docs/design.md, "Heel
    /// pressure"; the rigid block has no foundation pressure).
    pub heel_pressure_exceedance: HeelPressureExceedance,
}

/// The climate choices of a run that differ from today's model (docs/design.md, "Climate"): the
/// `climate` object of `design.json` and `size.json`, absent when every choice is the default.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ClimateChoices {
    pub storms: StormModel,
    pub storm_duration: StormDuration,
    pub wave_direction: WaveDirection,
    pub sea_level_rise: SeaLevelRise,
    /// The waves' periods when each wave has its own; absent when every wave is at T1/3.
    #[serde(skip_serializing_if = "WavePeriods::is_significant")]
    pub wave_periods: WavePeriods,
    pub error_scope: ErrorScope,
    pub errors_truncated: bool,
    /// The impulsive component's own error (bias, cov); absent: the wave force's.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub impact_force_error: Option<ErrorModel>,
}

impl ClimateChoices {
    /// The choices of `life`, or `None` if all are today's.
    pub fn of(life: &LifeParams) -> Option<Self> {
        let e = &life.errors;
        let truncated = e.wave_force.truncation_sigmas.is_some();
        let default =
            life.climate.is_default() && e.scope == ErrorScope::Storm && truncated && e.impact_force.is_none();
        (!default).then(|| ClimateChoices {
            storms: life.climate.storms,
            storm_duration: life.climate.duration,
            wave_direction: life.climate.direction,
            sea_level_rise: life.climate.sea_level.clone(),
            wave_periods: life.climate.periods,
            error_scope: e.scope,
            errors_truncated: truncated,
            impact_force_error: e.impact_force,
        })
    }

    /// One line for a run's text output: each choice that is not today's.
    pub fn describe(&self) -> String {
        let mut parts = Vec::new();
        if let StormModel::PeaksOverThreshold { rate_per_year, threshold_m } = self.storms {
            parts.push(format!(
                "peaks over threshold, {rate_per_year} storms a year (Poisson) above H0 = {threshold_m} m"
            ));
        }
        parts.extend(duration_text(&self.storm_duration));
        parts.extend(direction_text(&self.wave_direction));
        parts.extend(periods_text(&self.wave_periods));
        match &self.sea_level_rise {
            SeaLevelRise::None => {}
            SeaLevelRise::Linear { rise_m, life_years } => {
                parts.push(format!("sea level rising {rise_m} m over {life_years} years"))
            }
            SeaLevelRise::Table { points } => parts.push(format!(
                "sea level rising by a table of {} points (to {} m)",
                points.len(),
                points.iter().map(|p| p.1).fold(0.0, f64::max)
            )),
        }
        if self.error_scope == ErrorScope::Life {
            parts.push("errors drawn once per life".into());
        }
        if !self.errors_truncated {
            parts.push("errors not truncated".into());
        }
        if let Some(m) = self.impact_force_error {
            parts.push(format!("impact error bias {} COV {}", m.bias, m.cov));
        }
        format!("climate: {}", parts.join("; "))
    }
}

/// The storm durations in words, if drawn.
pub fn duration_text(d: &StormDuration) -> Option<String> {
    match d {
        StormDuration::Fixed => None,
        StormDuration::Lognormal { cov } => Some(format!("lognormal storm durations (COV {cov})")),
    }
}

/// The waves' periods in words, if not every wave at T1/3.
pub fn periods_text(p: &WavePeriods) -> Option<String> {
    match p {
        WavePeriods::Significant => None,
        WavePeriods::LonguetHiggins { spectral_width } => Some(format!(
            "wave-by-wave periods given the heights (Longuet-Higgins 1983, spectral width ν = {spectral_width})"
        )),
    }
}

/// The wave directions in words, if not head-on.
pub fn direction_text(d: &WaveDirection) -> Option<String> {
    let deg = 180.0 / std::f64::consts::PI;
    match *d {
        WaveDirection::HeadOn => None,
        WaveDirection::Normal { mean_rad, sd_rad } => {
            Some(format!("wave angle normal {:.1}° ± {:.1}° (σ)", mean_rad * deg, sd_rad * deg))
        }
        WaveDirection::Uniform { mean_rad, half_width_rad } => {
            Some(format!("wave angle uniform {:.1}° ± {:.1}°", mean_rad * deg, half_width_rad * deg))
        }
    }
}

/// The results of a design run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DesignReport {
    #[serde(flatten)]
    pub provenance: Provenance,
    /// The profile and model choices of the run ([`ModelReport`]; absent in a table row).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub model: Option<ModelReport>,
    pub lives: usize,
    pub life_years: usize,
    pub seed: u64,
    /// `lives = "auto"`: how many lives it took, the target, the relative errors reached and
    /// whether the target was met ([`AutoLives`]); absent with a fixed number of lives.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub precision: Option<AutoPrecision>,
    pub screen: bool,
    /// The failure limit on the caisson's distance from its place, m (`[design]
    /// failure_sliding_m`, default a quarter of the base width).
    pub failure_sliding_m: f64,
    /// The failure limit on the caisson's rotation, rad (`[design] failure_rotation_rad`).
    pub failure_rotation_rad: f64,
    /// The failure limit on the heel pressure, kPa (`[design] failure_heel_pressure_kpa`);
    /// absent: no failure by heel pressure.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub failure_heel_pressure_kpa: Option<f64>,
    /// The climate choices that are not today's model; absent if none.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub climate: Option<ClimateChoices>,
    pub dynamic: DynamicStatistics,
    pub rigid_block: ModelStatistics,
    pub rigid_block_mu: f64,
    pub waves: u64,
    pub simulated_waves: u64,
    pub screened_waves: u64,
    pub screened_share: f64,
    /// How the lives were sampled (a stratified run's; absent: every life simulated).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sampling: Option<SamplingReport>,
    /// Plausibility warnings of the structure, the lives and the waves ([`DesignReport::new`]).
    pub warnings: Vec<Warning>,
}

impl DesignReport {
    /// The report of `lives` (every life of the run, in index order) of design `p` on the storms
    /// of `case` (and the scenario's `waves`): the statistics with the failure limits of the
    /// caisson's width, and the warnings of the structure, the lives and the waves. What
    /// `caisson design`, `caisson merge` and Python's `Design.statistics` report.
    pub fn new(p: &DesignParams, case: &StormCase<'_>, waves: Option<&WaveSetup>, lives: &[StormOutcome]) -> Self {
        let failure = p.failure_limits(case.structure.caisson.width_m);
        let report = DesignReport::statistics(p, case.rigid_block_mu, failure.sliding_m, lives);
        report.with_warnings(case, waves, &LifeCounts::of(lives, &failure), &failure)
    }

    /// These statistics with the model and the warnings of the structure, of the lives (from
    /// `counts`), of their impulsive shares (as reported) and of the waves.
    fn with_warnings(
        mut self,
        case: &StormCase<'_>,
        waves: Option<&WaveSetup>,
        counts: &LifeCounts,
        failure: &FailureLimits,
    ) -> Self {
        self.model = Some(ModelReport::new(case.structure, waves));
        self.warnings = structure_warnings(case.structure);
        self.warnings.extend(counts_warnings(counts, failure, case.structure.caisson.width_m));
        let shares = [&self.dynamic.sliding.impulsive, &self.rigid_block.impulsive];
        self.warnings.extend(impulsive_warnings(shares, case.model, waves));
        if let Some(ws) = waves {
            self.warnings.extend(wave_load_warnings(case.structure, ws));
        }
        self
    }

    /// The rule of `lives = "auto"` ([`AutoLives::judge`]) on these statistics: the dynamic
    /// model's capped E|S| with its standard error and its failed lives, as reported — the one
    /// place the rule reads the statistics, so it follows any change of their estimators.
    /// `max_lives`: the run's budget, reported beside.
    pub fn judge(&self, auto: &AutoLives, max_lives: usize) -> AutoPrecision {
        let s = &self.dynamic.sliding;
        auto.judge((s.expected_sliding_m, s.expected_sliding_standard_error_m), s.failure.lives, self.lives, max_lives)
    }

    /// The statistics alone (no warnings) of `lives` of design `p`, with the failure limit
    /// `failure_sliding_m` ([`DesignParams::failure_limit_m`]): for a table of many designs
    /// (the validation report) and tests.
    pub fn statistics(p: &DesignParams, rigid_block_mu: f64, failure_sliding_m: f64, lives: &[StormOutcome]) -> Self {
        let years = p.life.life_years;
        let n = lives.len().max(1) as f64;
        let mean = |f: fn(&StormOutcome) -> f64| lives.iter().map(f).sum::<f64>() / n;
        let dynamic: Vec<f64> = lives.iter().map(|l| l.sliding_m.abs()).collect();
        let rigid: Vec<f64> = lives.iter().map(|l| l.rigid_block_sliding_m.abs()).collect();
        let limits = FailureLimits {
            sliding_m: failure_sliding_m,
            rotation_rad: p.failure_rotation_rad,
            heel_pressure_pa: p.failure_heel_pressure_pa,
        };
        let (modes, rigid_modes) = failure_modes(lives, &limits);
        let waves: u64 = lives.iter().map(|l| l.waves).sum();
        let screened: u64 = lives.iter().map(|l| l.screened_waves).sum();
        DesignReport {
            provenance: Provenance::CURRENT,
            model: None,
            lives: lives.len(),
            life_years: years,
            seed: p.seed,
            precision: None,
            screen: p.screen,
            failure_sliding_m,
            failure_rotation_rad: p.failure_rotation_rad,
            failure_heel_pressure_kpa: p.failure_heel_pressure_pa.map(|q| q / 1e3),
            climate: ClimateChoices::of(&p.life),
            dynamic: DynamicStatistics {
                sliding: ModelStatistics::new(
                    &dynamic,
                    &modes,
                    failure_sliding_m,
                    &p.thresholds_m,
                    years,
                    ImpulsiveShare::dynamic(lives),
                ),
                expected_net_sliding_m: mean(|l| l.sliding_m),
                expected_shoreward_sliding_m: mean(|l| l.shoreward_sliding_m),
                expected_seaward_sliding_m: mean(|l| l.seaward_sliding_m),
                seaward_lives: lives.iter().filter(|l| l.sliding_m < 0.0).count(),
                expected_max_excursion_m: mean(|l| l.max_excursion_m),
                rocking_waves: lives.iter().map(|l| l.rocking_waves).sum(),
                large_rotation_waves: lives.iter().map(|l| l.large_rotation_waves).sum(),
                large_rotation_lives: lives.iter().filter(|l| l.large_rotation_waves > 0).count(),
                heel_pressure_exceedance: HeelPressureExceedance::of(
                    lives,
                    p.allowable_heel_pressure_pa,
                    p.heel_screen_pa(),
                ),
            },
            rigid_block: ModelStatistics::new(
                &rigid,
                &rigid_modes,
                failure_sliding_m,
                &p.thresholds_m,
                years,
                ImpulsiveShare::rigid_block(lives, &limits),
            ),
            rigid_block_mu,
            waves,
            simulated_waves: lives.iter().map(|l| l.simulated_waves).sum(),
            screened_waves: screened,
            screened_share: screened as f64 / waves.max(1) as f64,
            sampling: None,
            warnings: Vec::new(),
        }
    }

    /// [`Self::new`] of a stratified run: `lives` are the simulated lives of `pool` in its order
    /// (module [`crate::analysis::lifetime::sampling`]), every statistic their weighted estimate.
    pub fn stratified(
        p: &DesignParams,
        case: &StormCase<'_>,
        waves: Option<&WaveSetup>,
        lives: &[StormOutcome],
        strata: &Strata,
        pool: &Pool,
    ) -> Self {
        let failure = p.failure_limits(case.structure.caisson.width_m);
        let report =
            DesignReport::stratified_statistics(p, case.rigid_block_mu, failure.sliding_m, lives, strata, pool);
        // The warnings count the simulated lives and give the weighted P(failure) beside them; the
        // impulsive warnings read the weighted shares.
        let counts = LifeCounts {
            weighted_failure_probability: Some(report.dynamic.sliding.failure.probability),
            ..LifeCounts::of(lives, &failure)
        };
        report.with_warnings(case, waves, &counts, &failure)
    }

    /// [`Self::statistics`] of a stratified run's simulated `lives` (in `pool`'s order).
    pub fn stratified_statistics(
        p: &DesignParams,
        rigid_block_mu: f64,
        failure_sliding_m: f64,
        lives: &[StormOutcome],
        strata: &Strata,
        pool: &Pool,
    ) -> Self {
        assert_eq!(lives.len(), pool.selected.len(), "one life per simulated life of the pool");
        let est = pool.estimator(strata);
        let mut report = DesignReport::statistics(p, rigid_block_mu, failure_sliding_m, lives);
        let years = p.life.life_years;
        let mean = |f: fn(&StormOutcome) -> f64| est.mean(&lives.iter().map(f).collect::<Vec<f64>>()).value;
        let dynamic: Vec<f64> = lives.iter().map(|l| l.sliding_m.abs()).collect();
        let rigid: Vec<f64> = lives.iter().map(|l| l.rigid_block_sliding_m.abs()).collect();
        let limits = FailureLimits {
            sliding_m: failure_sliding_m,
            rotation_rad: p.failure_rotation_rad,
            heel_pressure_pa: p.failure_heel_pressure_pa,
        };
        let (modes, rigid_modes) = failure_modes(lives, &limits);
        let d = &mut report.dynamic;
        d.sliding = ModelStatistics::stratified(
            &est,
            &dynamic,
            &modes,
            failure_sliding_m,
            &p.thresholds_m,
            years,
            ImpulsiveShare::dynamic_sampled(&est, lives),
        );
        d.expected_net_sliding_m = mean(|l| l.sliding_m);
        d.expected_shoreward_sliding_m = mean(|l| l.shoreward_sliding_m);
        d.expected_seaward_sliding_m = mean(|l| l.seaward_sliding_m);
        d.expected_max_excursion_m = mean(|l| l.max_excursion_m);
        let heel = &mut d.heel_pressure_exceedance;
        let beyond: Vec<bool> = lives.iter().map(|l| l.max_heel_pressure_kpa > heel.allowable_kpa).collect();
        let e = est.proportion(&beyond);
        (heel.probability, heel.standard_error, heel.ci95) = (e.value, e.standard_error, e.ci95);
        report.rigid_block = ModelStatistics::stratified(
            &est,
            &rigid,
            &rigid_modes,
            failure_sliding_m,
            &p.thresholds_m,
            years,
            ImpulsiveShare::rigid_block_sampled(&est, lives, &limits),
        );
        report.lives = est.pool();
        report.sampling = Some(SamplingReport::new(strata, pool));
        report
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::checks::{candidate_warnings, life_warnings};
    use crate::analysis::sizing::{candidate, Criteria};

    fn life(sliding_m: f64, shoreward: f64, seaward: f64, excursion_m: f64, rigid_m: f64) -> StormOutcome {
        StormOutcome {
            sliding_m,
            shoreward_sliding_m: shoreward,
            seaward_sliding_m: seaward,
            max_excursion_m: excursion_m,
            rigid_block_sliding_m: rigid_m,
            waves: 100,
            ..StormOutcome::default()
        }
    }

    /// Six lives, failure limits 5 m and 0.01 rad: one seaward (−3 m) that rotated 0.02 rad
    /// (fails by rotation), one beyond the limit at the end (6 m), one that went 5.5 m out and
    /// came back (fails by sliding, |S| = 0), one that slid 8 m and rotated (both modes). Every
    /// number by hand: the capped values are 0.2, 5, 5, 5, 0.001, 5.
    #[test]
    fn failures_surviving_lives_and_direction_are_counted_by_hand() {
        let sc = crate::scenario::load(
            &std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/design_breakwater.toml"),
        )
        .unwrap();
        let mut p = sc.design.clone().unwrap();
        p.thresholds_m = vec![0.1, 1.0, 7.0];
        assert_eq!(p.failure_rotation_rad, 0.01, "the default rotation limit");
        let mut seaward = life(-3.0, 1.0, 4.0, 3.5, 1.0);
        seaward.large_rotation_waves = 2;
        seaward.max_rotation_rad = 0.02;
        seaward.failed_by_rotation = 1;
        // Its failing wave and 2.5 m of the seaward slide were impulsive.
        seaward.failing_wave_impulsive = 1;
        seaward.impulsive_sliding_m = -2.5;
        let mut both = life(8.0, 8.0, 0.0, 8.0, 0.5);
        both.max_rotation_rad = 0.011;
        both.large_rotation_waves = 1;
        (both.failed_by_sliding, both.failed_by_rotation) = (1, 1);
        let mut beyond = life(6.0, 6.0, 0.0, 6.0, 7.0);
        beyond.failed_by_sliding = 1;
        // The rigid block's 7 m: 4 m of it impulsive, and its failing wave.
        (beyond.rigid_block_impulsive_sliding_m, beyond.rigid_block_failing_wave_impulsive) = (4.0, 1);
        let mut back = life(0.0, 5.5, 5.5, 5.5, 0.0);
        back.failed_by_sliding = 1;
        let mut first = life(0.2, 0.2, 0.0, 0.2, 0.25);
        (first.impulsive_waves, first.impulsive_sliding_m, first.max_heel_pressure_kpa) = (3, 0.15, 620.0);
        let lives = [first, seaward, beyond, back, life(1e-3, 1e-3, 0.0, 1e-3, 0.0), both];
        let r = DesignReport::statistics(&p, 0.6, 5.0, &lives);
        let d = &r.dynamic;
        let f = &d.sliding.failure;
        assert_eq!((r.failure_sliding_m, r.failure_rotation_rad, r.failure_heel_pressure_kpa), (5.0, 0.01, None));
        assert_eq!((f.lives, f.probability), (4, 4.0 / 6.0));
        assert_eq!((f.by_sliding.lives, f.by_sliding.probability), (3, 0.5));
        assert_eq!((f.by_rotation.lives, f.by_rotation.probability), (2, 2.0 / 6.0));
        // Capped: the failed lives at 5 m; uncapped: as simulated.
        assert!((d.sliding.expected_sliding_m - (0.2 + 5.0 + 5.0 + 5.0 + 1e-3 + 5.0) / 6.0).abs() < 1e-12);
        assert!((d.sliding.expected_sliding_uncapped_m - (0.2 + 3.0 + 6.0 + 0.0 + 1e-3 + 8.0) / 6.0).abs() < 1e-12);
        assert!((d.sliding.expected_sliding_per_year_m - d.sliding.expected_sliding_m / 50.0).abs() < 1e-15);
        assert!((d.expected_net_sliding_m - (0.2 - 3.0 + 6.0 + 1e-3 + 8.0) / 6.0).abs() < 1e-12);
        // Sorted capped values 0.001, 0.2, 5, 5, 5, 5: ranks ⌈0.05·6⌉ = 1, ⌈0.5·6⌉ = 3.
        let pc = d.sliding.percentiles_m;
        assert_eq!((pc.p5, pc.p50, pc.p95, pc.p99), (1e-3, 5.0, 5.0, 5.0));
        // |S| > 0.1: 0.2 and the four failed lives; > 1: the failed ones; > 7 m (beyond the
        // limit): the failed lives still.
        let e: Vec<f64> = d.sliding.exceedance_probability.iter().map(|e| e.probability).collect();
        assert_eq!(e, vec![5.0 / 6.0, 4.0 / 6.0, 4.0 / 6.0]);
        assert_eq!(d.sliding.surviving.lives, 2);
        assert!((d.sliding.surviving.expected_sliding_m - (0.2 + 1e-3) / 2.0).abs() < 1e-12);
        assert_eq!(d.sliding.surviving.percentiles_m.p99, 0.2);
        assert_eq!(d.seaward_lives, 1);
        assert!((d.expected_shoreward_sliding_m - (0.2 + 1.0 + 6.0 + 5.5 + 1e-3 + 8.0) / 6.0).abs() < 1e-12);
        assert!((d.expected_seaward_sliding_m - (4.0 + 5.5) / 6.0).abs() < 1e-12);
        assert_eq!((d.large_rotation_lives, d.large_rotation_waves), (2, 3));
        // The rigid block fails by its slide alone (7 m), never by rotation; capped at 5 m.
        let rb = &r.rigid_block;
        assert_eq!((rb.failure.lives, rb.failure.by_rotation.lives, rb.surviving.lives), (1, 0, 5));
        assert!((rb.expected_sliding_m - (0.25 + 1.0 + 5.0 + 0.0 + 0.0 + 0.5) / 6.0).abs() < 1e-12);
        assert!((rb.expected_sliding_uncapped_m - (0.25 + 1.0 + 7.0 + 0.5) / 6.0).abs() < 1e-12);
        assert!((rb.surviving.expected_sliding_m - (0.25 + 1.0 + 0.5) / 5.0).abs() < 1e-12);
        let limits = FailureLimits { sliding_m: 5.0, rotation_rad: 0.01, heel_pressure_pa: None };
        // Impulsive shares by hand: the dynamic model's impulsive sliding 0.15 and −2.5 m in lives
        // ending +0.2 and −3 m: their part of Σ|S| = 0.2 + 3 + 6 + 0 + 0.001 + 8 = 17.201 m is
        // 0.15 + 2.5 (a seaward life's seaward impulsive slide adds to its |S|); the failing
        // wave of 1 of the 4 failed lives was impulsive. The rigid block: 4 m of Σ = 8.75 m, and
        // its one failure (7 m > 5 m) impulsive.
        let (id, ir) = (&d.sliding.impulsive, &r.rigid_block.impulsive);
        assert_eq!((id.waves, id.failures, ir.failures), (3, 4, 1));
        assert!((id.sliding_m - (0.15 - 2.5) / 6.0).abs() < 1e-15);
        assert!((id.share_of_expected_sliding - 2.65 / 17.201).abs() < 1e-12);
        assert_eq!((id.share_of_failures, ir.share_of_failures), (0.25, 1.0));
        assert!((ir.share_of_expected_sliding - 4.0 / 8.75).abs() < 1e-12);
        // Their intervals by hand. The share of E|S|, a ratio R = Σx/Σy of x = (0.15, 2.5, 0, 0,
        // 0, 0) to y = |S| = (0.2, 3, 6, 0, 0.001, 8): SE = √(Σ (x − R y)² / (6·5)) / (17.201/6).
        let r = 2.65 / 17.201;
        let d2 = (0.15 - r * 0.2f64).powi(2)
            + (2.5 - r * 3.0f64).powi(2)
            + (r * 6.0f64).powi(2)
            + (r * 0.001f64).powi(2)
            + (r * 8.0f64).powi(2);
        let se = (d2 / 30.0).sqrt() / (17.201 / 6.0);
        let [lo, hi] = id.share_of_expected_sliding_ci95;
        assert!((lo - (r - 1.959964 * se)).abs() < 1e-6 && (hi - (r + 1.959964 * se)).abs() < 1e-6, "{lo} {hi}");
        // Wilson, 1 impulsive failure of 4: centre (p + z²/2n)/(1 + z²/n), half-width
        // z √(p(1 − p)/n + z²/4n²)/(1 + z²/n); 1 of 1: [1/(1 + z²), 1].
        let z2 = 1.959964f64.powi(2);
        let (centre, half) = (
            (0.25 + z2 / 8.0) / (1.0 + z2 / 4.0),
            1.959964 * (0.25 * 0.75 / 4.0 + z2 / 64.0).sqrt() / (1.0 + z2 / 4.0),
        );
        let [lo, hi] = id.share_of_failures_ci95;
        assert!((lo - (centre - half)).abs() < 1e-6 && (hi - (centre + half)).abs() < 1e-6, "{lo} {hi}");
        let [lo, hi] = ir.share_of_failures_ci95;
        assert!((lo - 1.0 / (1.0 + z2)).abs() < 1e-6 && hi == 1.0, "{lo} {hi}");
        // One life of six above 500 kPa: P = 1/6, SE = √(p(1 − p)/6).
        let h = &d.heel_pressure_exceedance;
        assert_eq!((h.lives, h.probability, h.allowable_kpa, h.largest_kpa), (1, 1.0 / 6.0, 500.0, 620.0));
        assert!((h.standard_error - (1.0f64 / 6.0 * 5.0 / 6.0 / 6.0).sqrt()).abs() < 1e-15);
        let warnings = life_warnings(&lives, &limits, 20.0);
        let codes: Vec<&str> = warnings.iter().map(|w| w.code).collect();
        assert_eq!(codes, vec!["failed-lives", "large-rotation-lives", "seaward-lives"]);
        let failed = &warnings[0].numbers;
        assert_eq!(
            (failed["failed_lives"], failed["failed_by_sliding_lives"], failed["failed_by_rotation_lives"]),
            (4.0, 3.0, 2.0)
        );
        // A sizing candidate of the same lives keeps what gives the same warnings.
        let c = candidate(20.0, 1.0, &lives, &limits, &Criteria::default(), (500e3, 500e3));
        assert_eq!(c.heel_pressure_exceedance, d.heel_pressure_exceedance);
        assert_eq!((c.dynamic.impulsive, c.rigid_block.impulsive), (*id, *ir));
        assert_eq!(candidate_warnings(&c, &limits), warnings);
        let calm = [life(0.2, 0.2, 0.0, 0.2, 0.25), life(-0.005, 0.0, 0.005, 0.005, 0.0)];
        assert!(life_warnings(&calm, &limits, 20.0).is_empty(), "5 mm seaward is below the 1 cm reported");
    }
}
