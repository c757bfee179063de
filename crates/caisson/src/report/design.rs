//! `caisson design`: `design.json` (keys in docs/design.md).

use super::{fingerprint, Provenance};
use crate::analysis::checks::Warning;
use crate::analysis::lifetime::{life_statistics, DesignParams, LifeParams, LifeStatistics, StormCase, StormOutcome};
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

/// The probability that a life's sliding exceeds a threshold.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Exceedance {
    pub threshold_m: f64,
    pub probability: f64,
}

/// The statistics of one model's life totals.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ModelStatistics {
    pub expected_sliding_m: f64,
    pub expected_sliding_per_year_m: f64,
    pub percentiles_m: Percentiles,
    pub exceedance_probability: Vec<Exceedance>,
}

impl ModelStatistics {
    fn new(s: &LifeStatistics, years: usize) -> Self {
        let pct = |p: f64| s.percentiles_m.iter().find(|(q, _)| *q == p).map_or(0.0, |(_, v)| *v);
        ModelStatistics {
            expected_sliding_m: s.mean_m,
            expected_sliding_per_year_m: s.mean_m / years as f64,
            percentiles_m: Percentiles { p5: pct(5.0), p50: pct(50.0), p95: pct(95.0), p99: pct(99.0) },
            exceedance_probability: s
                .exceedance
                .iter()
                .map(|&(threshold_m, probability)| Exceedance { threshold_m, probability })
                .collect(),
        }
    }
}

/// The results of a design run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DesignReport {
    #[serde(flatten)]
    pub provenance: Provenance,
    pub lives: usize,
    pub life_years: usize,
    pub seed: u64,
    pub screen: bool,
    pub dynamic: ModelStatistics,
    pub rigid_block: ModelStatistics,
    pub rigid_block_mu: f64,
    pub waves: u64,
    pub simulated_waves: u64,
    pub screened_waves: u64,
    pub screened_share: f64,
    /// Plausibility warnings (filled by the caller).
    pub warnings: Vec<Warning>,
}

impl DesignReport {
    /// The statistics of `lives` (every life of the run, in index order) of design `p`.
    pub fn new(p: &DesignParams, rigid_block_mu: f64, lives: &[StormOutcome]) -> Self {
        let dynamic: Vec<f64> = lives.iter().map(|l| l.sliding_m).collect();
        let rigid: Vec<f64> = lives.iter().map(|l| l.rigid_block_sliding_m).collect();
        let years = p.life.life_years;
        let waves: u64 = lives.iter().map(|l| l.waves).sum();
        let screened: u64 = lives.iter().map(|l| l.screened).sum();
        DesignReport {
            provenance: Provenance::CURRENT,
            lives: lives.len(),
            life_years: years,
            seed: p.seed,
            screen: p.screen,
            dynamic: ModelStatistics::new(&life_statistics(&dynamic, &p.thresholds_m), years),
            rigid_block: ModelStatistics::new(&life_statistics(&rigid, &p.thresholds_m), years),
            rigid_block_mu,
            waves,
            simulated_waves: lives.iter().map(|l| l.simulated).sum(),
            screened_waves: screened,
            screened_share: screened as f64 / waves.max(1) as f64,
            warnings: Vec::new(),
        }
    }
}
