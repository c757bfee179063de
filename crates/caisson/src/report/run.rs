//! `caisson run` on a `[load]` scenario: `summary.json` (keys in docs/cli.md).

use super::{kn, FoundationReport, ModelReport, Provenance};
use crate::analysis::checks::{response_warnings, run_load_warnings, structure_warnings, Warning};
use crate::analysis::run::Response;
use crate::analysis::run::RunSummary;
use crate::analysis::Structure;
use crate::loads::LoadSpec;
use serde::Serialize;

/// Solver statistics of a single run.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RunSolverReport {
    pub steps: u64,
    pub newton_iterations: u64,
    pub substeps: u64,
    /// Largest converged residual, N.
    pub max_residual: f64,
}

/// The summary of a single run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RunReport {
    #[serde(flatten)]
    pub provenance: Provenance,
    /// The profile and model choices of the run ([`ModelReport`]).
    pub model: ModelReport,
    pub permanent_sliding_m: f64,
    pub max_horizontal_displacement_m: f64,
    pub max_rotation_rad: f64,
    pub max_horizontal_reaction_kn: f64,
    pub time_of_max_horizontal_reaction_s: f64,
    pub slip_events: u64,
    pub slip_event_times_s: Vec<f64>,
    pub max_spring_reaction_kn: f64,
    pub min_spring_reaction_kn: f64,
    pub max_spring_shear_kn: f64,
    pub final_displacement_m: f64,
    pub final_settlement_m: f64,
    pub final_rotation_rad: f64,
    pub duration_s: f64,
    pub spring_positions_m: Vec<f64>,
    pub foundation: FoundationReport,
    pub solver: RunSolverReport,
    /// Plausibility warnings ([`crate::analysis::checks`]).
    pub warnings: Vec<Warning>,
}

impl RunReport {
    /// The report of run `s` of `load` on `structure`, with the warnings of the structure, the
    /// load and the response.
    pub fn new(structure: &Structure, load: &LoadSpec, s: &RunSummary) -> Self {
        let mut warnings = structure_warnings(structure);
        warnings.extend(run_load_warnings(structure, load));
        warnings.extend(response_warnings(structure, &Response::from(s)));
        let spring_positions_m = structure.foundation.spring_positions(structure.caisson.width_m);
        RunReport {
            provenance: Provenance::CURRENT,
            model: ModelReport::new(structure, None),
            permanent_sliding_m: s.permanent_sliding_m,
            max_horizontal_displacement_m: s.max_horizontal_displacement_m,
            max_rotation_rad: s.max_rotation_rad,
            max_horizontal_reaction_kn: kn(s.max_horizontal_reaction_n),
            time_of_max_horizontal_reaction_s: s.time_of_max_horizontal_reaction_s,
            slip_events: s.slip_events,
            slip_event_times_s: s.slip_event_times_s.clone(),
            max_spring_reaction_kn: kn(s.max_spring_normal_n),
            min_spring_reaction_kn: kn(s.min_spring_normal_n),
            max_spring_shear_kn: kn(s.max_spring_shear_n),
            final_displacement_m: s.final_displacement_m,
            final_settlement_m: s.final_settlement_m,
            final_rotation_rad: s.final_rotation_rad,
            duration_s: s.duration_s,
            spring_positions_m,
            foundation: FoundationReport::from(&s.foundation),
            solver: RunSolverReport {
                steps: s.solver.steps,
                newton_iterations: s.solver.newton_iterations,
                substeps: s.solver.substeps,
                max_residual: s.solver.max_residual,
            },
            warnings,
        }
    }
}
