//! `caisson fragility`: `fragility.json` (keys in docs/fragility.md).

use super::{ModelReport, Provenance};
use crate::analysis::checks::{impulsive_warnings, storm_warnings, structure_warnings, wave_load_warnings, Warning};
use crate::analysis::climate::{StormDuration, WaveDirection, WavePeriods};
use crate::analysis::conventional::{DesignWave, DesignWaveRule, StaticCheck};
use crate::analysis::fragility::{FitFailure, FragilityParams, FragilityResult, LevelResult, LognormalFit, HMAX_RATIO};
use crate::analysis::lifetime::{ErrorModel, FailureLimits, ImpulsiveShare};
use crate::analysis::site::WaveSetup;
use crate::analysis::Structure;
use serde::Serialize;

/// Goda's static sliding safety factor (μ_s) under the design wave of a sea of significant height
/// `h13_m` at the toe (H_max, docs/model.md §1.3: 1.8 H1/3, or Goda's breaking-limited H_max
/// inside the surf zone), if defined.
pub fn goda_sliding_safety(structure: &Structure, waves: &WaveSetup, h13_m: f64, period_s: f64) -> Option<f64> {
    goda_design_check(structure, waves, h13_m, period_s).and_then(|c| c.safety.sliding)
}

/// Goda's static checks under the design wave of a sea of significant height `h13_m` at the toe.
pub fn goda_design_check(structure: &Structure, waves: &WaveSetup, h13_m: f64, period_s: f64) -> Option<StaticCheck> {
    let (w, mu) = (structure.caisson.weight_in_water_n, structure.foundation.mu_static);
    StaticCheck::new(waves, DesignWave::irregular(&waves.model, h13_m, period_s), w, mu, waves.regime()).ok()
}

/// A lognormal fit, or why there is none.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum FitReport {
    Fitted {
        fitted: bool,
        median_m: f64,
        beta: f64,
        ln_median_se: f64,
        beta_se: f64,
        log_likelihood: f64,
        /// 95 % profile-likelihood intervals ([low, high]; `null` for an end beyond the search
        /// bounds).
        median_ci95_m: [Option<f64>; 2],
        beta_ci95: [Option<f64>; 2],
    },
    Refused {
        fitted: bool,
        reason: FitFailure,
        message: String,
    },
}

impl From<&Result<LognormalFit, FitFailure>> for FitReport {
    fn from(f: &Result<LognormalFit, FitFailure>) -> Self {
        match f {
            Ok(f) => FitReport::Fitted {
                fitted: true,
                median_m: f.median,
                beta: f.beta,
                ln_median_se: f.ln_median_se,
                beta_se: f.beta_se,
                log_likelihood: f.log_likelihood,
                median_ci95_m: f.median_ci95,
                beta_ci95: f.beta_ci95,
            },
            Err(e) => FitReport::Refused { fitted: false, reason: *e, message: e.to_string() },
        }
    }
}

/// The counts of one limit at one height.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LevelExceedance {
    pub limit_m: f64,
    pub dynamic_count: u64,
    pub dynamic_probability: f64,
    pub rigid_block_count: u64,
    pub rigid_block_probability: f64,
}

/// The storms of one height.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LevelReport {
    pub significant_height_m: f64,
    pub hmax_m: f64,
    pub storms: usize,
    pub mean_sliding_m: f64,
    pub max_sliding_m: f64,
    pub mean_rigid_block_sliding_m: f64,
    pub max_rigid_block_sliding_m: f64,
    pub screened_share: f64,
    pub simulated_waves: u64,
    /// Storms that rotated the caisson beyond `failure_rotation_rad`: counted as exceeding
    /// every limit (dynamic model).
    pub rotation_failures: u64,
    pub exceedance: Vec<LevelExceedance>,
    pub storm_sliding_m: Vec<f64>,
    pub storm_rigid_block_sliding_m: Vec<f64>,
    /// The largest rotation of each storm, rad.
    pub storm_max_rotation_rad: Vec<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub goda_sliding_safety_factor: Option<f64>,
}

impl LevelReport {
    fn new(l: &LevelResult, limits_m: &[f64], goda: Option<f64>) -> Self {
        let n = l.storms.len() as f64;
        LevelReport {
            significant_height_m: l.h13_m,
            hmax_m: l.hmax_m,
            storms: l.storms.len(),
            mean_sliding_m: l.mean_sliding_m(),
            max_sliding_m: l.storms.iter().map(|o| o.sliding_m.abs()).fold(0.0, f64::max),
            mean_rigid_block_sliding_m: l.mean_rigid_block_sliding_m(),
            max_rigid_block_sliding_m: l.storms.iter().map(|o| o.rigid_block_sliding_m).fold(0.0, f64::max),
            screened_share: l.screened_share(),
            simulated_waves: l.storms.iter().map(|o| o.simulated_waves).sum(),
            rotation_failures: l.rotation_failures,
            exceedance: limits_m
                .iter()
                .enumerate()
                .map(|(j, &limit_m)| LevelExceedance {
                    limit_m,
                    dynamic_count: l.dynamic_exceedances[j],
                    dynamic_probability: l.dynamic_exceedances[j] as f64 / n,
                    rigid_block_count: l.rigid_block_exceedances[j],
                    rigid_block_probability: l.rigid_block_exceedances[j] as f64 / n,
                })
                .collect(),
            storm_sliding_m: l.storms.iter().map(|o| o.sliding_m).collect(),
            storm_rigid_block_sliding_m: l.storms.iter().map(|o| o.rigid_block_sliding_m).collect(),
            storm_max_rotation_rad: l.storms.iter().map(|o| o.max_rotation_rad).collect(),
            goda_sliding_safety_factor: goda,
        }
    }
}

/// The design wave of a fragility file.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DesignWaveReport {
    pub significant_height_m: f64,
    /// Goda's design wave H_max (docs/model.md §1.3), m.
    pub hmax_m: f64,
    /// How H_max was found (`1.8-significant-height` or `goda-breaking-limited`).
    pub rule: DesignWaveRule,
    pub period_s: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub goda_sliding_safety_factor: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub goda_overturning_safety_factor: Option<f64>,
}

/// The fits of one limit.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LimitFitReport {
    pub limit_m: f64,
    pub dynamic: FitReport,
    pub rigid_block: FitReport,
}

/// The results of a fragility analysis.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FragilityReport {
    #[serde(flatten)]
    pub provenance: Provenance,
    /// The profile and model choices of the run ([`ModelReport`]).
    pub model: ModelReport,
    pub scenario: String,
    pub period_s: f64,
    pub storm_duration_h: f64,
    /// The storms' durations when drawn (storm_duration_h their mean; waves_per_storm that of
    /// the mean); absent when fixed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub storm_duration: Option<StormDuration>,
    /// The storms' wave directions when not head-on; absent when head-on.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub wave_direction: Option<WaveDirection>,
    /// The waves' periods when each wave has its own (`period_s` their T1/3); absent when every
    /// wave is at T1/3.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub wave_periods: Option<WavePeriods>,
    pub waves_per_storm: usize,
    pub hmax_ratio: f64,
    pub storms: usize,
    pub seed: u64,
    pub limits_m: Vec<f64>,
    /// `[fragility] failure_rotation_rad`, rad.
    pub failure_rotation_rad: f64,
    /// The load-model errors drawn per storm (docs/fragility.md); `null` with `errors = false`.
    pub errors: Option<LoadErrors>,
    /// What the impulsive waves make of the storms of every height, per model (a storm "fails"
    /// when a wave takes it beyond the largest limit or, the dynamic model, rotates it beyond
    /// `failure_rotation_rad`; docs/fragility.md).
    pub impulsive: ImpulsiveGroup,
    pub rigid_block_mu: f64,
    pub design_wave: DesignWaveReport,
    pub levels: Vec<LevelReport>,
    pub fits: Vec<LimitFitReport>,
    /// Plausibility warnings of the structure.
    pub warnings: Vec<Warning>,
}

/// The load-model errors of a fragility's storms: the multipliers 1 + bias + COV z of the wave
/// force, the friction and the impulsive component (absent: the wave force's).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LoadErrors {
    pub wave_force: ErrorModel,
    pub friction: ErrorModel,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub impact_force: Option<ErrorModel>,
}

/// The `impulsive` group of a report: one [`ImpulsiveShare`] per model.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ImpulsiveGroup {
    pub dynamic: ImpulsiveShare,
    pub rigid_block: ImpulsiveShare,
}

impl FragilityReport {
    /// The report of `r`, the fragility `p` of `structure` under `waves` (file `name`).
    pub fn new(name: &str, structure: &Structure, waves: &WaveSetup, p: &FragilityParams, r: &FragilityResult) -> Self {
        let (h, t) = (waves.height_m(), waves.period_s());
        let storms: Vec<_> = r.levels.iter().flat_map(|l| l.storms.iter().copied()).collect();
        let largest = FailureLimits {
            sliding_m: p.limits_m.last().copied().unwrap_or(f64::INFINITY),
            rotation_rad: p.failure_rotation_rad,
            heel_pressure_pa: None,
        };
        let impulsive = ImpulsiveGroup {
            dynamic: ImpulsiveShare::dynamic(&storms),
            rigid_block: ImpulsiveShare::rigid_block(&storms, &largest),
        };
        FragilityReport {
            provenance: Provenance::CURRENT,
            model: ModelReport::new(structure, Some(waves)),
            scenario: name.to_string(),
            period_s: p.period_s,
            storm_duration_h: p.storm_duration_s / 3600.0,
            storm_duration: (p.duration != StormDuration::Fixed).then_some(p.duration),
            wave_direction: (p.direction != WaveDirection::HeadOn).then_some(p.direction),
            wave_periods: (!p.periods.is_significant()).then_some(p.periods),
            waves_per_storm: p.waves_per_storm(),
            hmax_ratio: HMAX_RATIO,
            storms: p.storms,
            seed: p.seed,
            limits_m: p.limits_m.clone(),
            failure_rotation_rad: p.failure_rotation_rad,
            errors: p.errors.map(|e| LoadErrors {
                wave_force: e.wave_force,
                friction: e.friction,
                impact_force: e.impact_force,
            }),
            impulsive,
            rigid_block_mu: waves.rigid_block_mu(&structure.foundation),
            design_wave: {
                let check = goda_design_check(structure, waves, h, t);
                let dw = check.map_or_else(|| DesignWave::irregular(&waves.model, h, t), |c| c.design_wave);
                DesignWaveReport {
                    significant_height_m: h,
                    hmax_m: dw.design_height_m,
                    rule: dw.rule,
                    period_s: t,
                    goda_sliding_safety_factor: check.and_then(|c| c.safety.sliding),
                    goda_overturning_safety_factor: check.and_then(|c| c.safety.overturning),
                }
            },
            levels: r
                .levels
                .iter()
                .map(|l| LevelReport::new(l, &p.limits_m, goda_sliding_safety(structure, waves, l.h13_m, p.period_s)))
                .collect(),
            fits: r
                .fits
                .iter()
                .map(|f| LimitFitReport {
                    limit_m: f.limit_m,
                    dynamic: FitReport::from(&f.dynamic),
                    rigid_block: FitReport::from(&f.rigid_block),
                })
                .collect(),
            warnings: {
                let mut w = structure_warnings(structure);
                w.extend(wave_load_warnings(structure, waves));
                w.extend(storm_warnings(r.levels.iter().flat_map(|l| &l.storms), structure.caisson.width_m));
                w.extend(impulsive_warnings([&impulsive.dynamic, &impulsive.rigid_block], &waves.model, Some(waves)));
                w
            },
        }
    }
}
