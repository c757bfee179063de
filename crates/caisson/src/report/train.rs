//! `caisson run` on a `[waves]` scenario: the wave-train `summary.json` (keys in docs/cli.md).

use super::{kn, FoundationReport, ModelReport, Provenance, SpreadReport};
use crate::analysis::checks::realization_warnings;
use crate::analysis::checks::{structure_warnings, wave_load_warnings, Warning};
use crate::analysis::run::FoundationSummary;
use crate::analysis::site::WaveSetup;
use crate::analysis::train::{RealizationResult, TrainCase, TrainSummary};
use crate::analysis::Structure;
use crate::loads::generator::{HeightVariability, TrainKind, TrainSpec};
use crate::loads::regime::{Regime, RegimeChoice};
use serde::Serialize;

/// One wave of a realization.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct WaveReport {
    pub start_s: f64,
    pub height_m: f64,
    pub regime: Regime,
    pub sliding_m: f64,
    pub rigid_block_sliding_m: f64,
    pub max_horizontal_reaction_kn: f64,
    /// Impulsive waves only.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rise_time_s: Option<f64>,
}

/// One realization of a wave train.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RealizationReport {
    pub index: usize,
    pub sliding_m: f64,
    pub rigid_block_sliding_m: f64,
    pub max_horizontal_reaction_kn: f64,
    pub slip_events: u64,
    pub limited_waves: usize,
    pub breaking_waves: usize,
    pub steps: u64,
    pub waves: Vec<WaveReport>,
}

impl From<&RealizationResult> for RealizationReport {
    fn from(r: &RealizationResult) -> Self {
        RealizationReport {
            index: r.index,
            sliding_m: r.sliding_m,
            rigid_block_sliding_m: r.rigid_block_sliding_m,
            max_horizontal_reaction_kn: kn(r.max_horizontal_reaction_n),
            slip_events: r.slip_events,
            limited_waves: r.limited_waves,
            breaking_waves: r.waves.iter().filter(|w| w.record.regime == Regime::Breaking).count(),
            steps: r.solver.steps,
            waves: r
                .waves
                .iter()
                .map(|w| WaveReport {
                    start_s: w.start_s,
                    height_m: w.record.height_m,
                    regime: w.record.regime,
                    sliding_m: w.sliding_m,
                    rigid_block_sliding_m: w.rigid_block_sliding_m,
                    max_horizontal_reaction_kn: kn(w.max_horizontal_reaction_n),
                    rise_time_s: w.record.rise_time_s,
                })
                .collect(),
        }
    }
}

/// The trains of a wave scenario.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TrainReport {
    pub period_s: f64,
    pub waves: usize,
    pub realizations: usize,
    pub seed: u64,
    /// `"regular"` or `"irregular"`.
    pub kind: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub height_m: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub height_variability: Option<HeightVariability>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub significant_height_m: Option<f64>,
}

impl From<&TrainSpec> for TrainReport {
    fn from(t: &TrainSpec) -> Self {
        let (kind, height_m, height_variability, significant_height_m) = match t.kind {
            TrainKind::Regular { height_m, variability } => ("regular", Some(height_m), Some(variability), None),
            TrainKind::Irregular { significant_height_m } => ("irregular", None, None, Some(significant_height_m)),
        };
        TrainReport {
            period_s: t.period_s,
            waves: t.waves,
            realizations: t.realizations,
            seed: t.seed,
            kind,
            height_m,
            height_variability,
            significant_height_m,
        }
    }
}

/// Solver statistics summed over the realizations.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TrainSolverReport {
    pub steps: u64,
    pub newton_iterations: u64,
    pub substeps: u64,
    pub rejected_steps: u64,
    pub forced_min_steps: u64,
    pub min_step_s: f64,
    pub max_step_s: f64,
    pub max_residual: f64,
}

impl TrainSolverReport {
    fn of(rs: &[RealizationResult]) -> Self {
        let sum = |f: fn(&RealizationResult) -> u64| rs.iter().map(f).sum();
        let min_step = rs.iter().map(|r| r.solver.min_step_s).fold(f64::INFINITY, f64::min);
        TrainSolverReport {
            steps: sum(|r| r.solver.steps),
            newton_iterations: sum(|r| r.solver.newton_iterations),
            substeps: sum(|r| r.solver.substeps),
            rejected_steps: sum(|r| r.solver.rejected_steps),
            forced_min_steps: sum(|r| r.solver.forced_min_steps),
            min_step_s: if min_step.is_finite() { min_step } else { 0.0 },
            max_step_s: rs.iter().map(|r| r.solver.max_step_s).fold(0.0, f64::max),
            max_residual: rs.iter().map(|r| r.solver.max_residual).fold(0.0, f64::max),
        }
    }
}

/// The summary of a wave-train run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TrainRunReport {
    #[serde(flatten)]
    pub provenance: Provenance,
    /// The profile and model choices of the run ([`ModelReport`]).
    pub model: ModelReport,
    pub sliding_m: SpreadReport,
    pub rigid_block_sliding_m: SpreadReport,
    pub rigid_block_mu: f64,
    pub max_horizontal_reaction_kn: SpreadReport,
    pub slip_events: SpreadReport,
    pub regime: RegimeChoice,
    pub waves: TrainReport,
    pub realizations: Vec<RealizationReport>,
    pub foundation: FoundationReport,
    pub solver: TrainSolverReport,
    /// Plausibility warnings of the structure and of the realizations.
    pub warnings: Vec<Warning>,
}

impl TrainRunReport {
    /// The report of the realizations `s` of `waves` on `structure`.
    pub fn new(structure: &Structure, waves: &WaveSetup, s: &TrainSummary) -> Self {
        let model = structure.model();
        let f = FoundationSummary::new(&structure.caisson, &structure.foundation, &model);
        TrainRunReport {
            provenance: Provenance::CURRENT,
            model: ModelReport::new(structure, Some(waves)),
            sliding_m: SpreadReport::scaled(&s.sliding_m, 1.0),
            rigid_block_sliding_m: SpreadReport::scaled(&s.rigid_block_sliding_m, 1.0),
            rigid_block_mu: waves.rigid_block_mu(&structure.foundation),
            max_horizontal_reaction_kn: SpreadReport::in_kn(&s.max_horizontal_reaction_n),
            slip_events: SpreadReport::scaled(&s.slip_events, 1.0),
            regime: waves.regime(),
            waves: TrainReport::from(&waves.train),
            realizations: s.realizations.iter().map(RealizationReport::from).collect(),
            foundation: FoundationReport::from(&f),
            solver: TrainSolverReport::of(&s.realizations),
            warnings: {
                let mut w = structure_warnings(structure);
                w.extend(wave_load_warnings(structure, waves));
                w.extend(realization_warnings(&TrainCase { structure, waves }, &s.realizations));
                w
            },
        }
    }
}

/// The trains in words: kind, height (or "per condition" in a campaign), variability, period.
pub fn describe_train(t: &TrainSpec, height_per_condition: bool) -> String {
    match t.kind {
        TrainKind::Regular { height_m, variability } => {
            let v = match variability {
                HeightVariability::Normal { cov, truncation_sigmas } => {
                    format!("normal, COV {cov}, truncated at ±{truncation_sigmas}σ")
                }
                HeightVariability::Uniform { half_width } => format!("uniform ±{:.0} %", half_width * 100.0),
                HeightVariability::None => "no height variability".to_string(),
            };
            let h = if height_per_condition { "H per condition".to_string() } else { format!("H = {height_m} m") };
            format!("regular {h} ({v}), T = {} s", t.period_s)
        }
        TrainKind::Irregular { significant_height_m } => {
            let h = if height_per_condition {
                "H1/3 per condition".to_string()
            } else {
                format!("H1/3 = {significant_height_m} m")
            };
            format!("irregular (Rayleigh) {h}, T1/3 = {} s", t.period_s)
        }
    }
}
