//! `caisson spectrum`: `spectrum.json` (keys in docs/cli.md).

use super::{kn, ModelReport, Provenance};
use crate::analysis::checks::{run_load_warnings, structure_warnings, Warning};
use crate::analysis::spectrum::SpectrumPoint;
use crate::analysis::Structure;
use crate::loads::pulse::TrianglePulse;
use crate::loads::LoadSpec;
use serde::Serialize;

/// One point of the spectrum.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SpectrumPointReport {
    pub tr_over_t0: f64,
    pub rise_time_s: f64,
    pub psi: f64,
    pub psi_closed_form: f64,
    pub permanent_sliding_m: f64,
    pub shimosako_sliding_m: f64,
    pub rigid_block_sliding_m: f64,
    pub max_horizontal_reaction_kn: f64,
}

impl From<&SpectrumPoint> for SpectrumPointReport {
    fn from(p: &SpectrumPoint) -> Self {
        SpectrumPointReport {
            tr_over_t0: p.tr_over_t0,
            rise_time_s: p.rise_time_s,
            psi: p.psi,
            psi_closed_form: p.psi_closed_form,
            permanent_sliding_m: p.permanent_sliding_m,
            shimosako_sliding_m: p.shimosako_sliding_m,
            rigid_block_sliding_m: p.rigid_block_sliding_m,
            max_horizontal_reaction_kn: kn(p.max_horizontal_reaction_n),
        }
    }
}

/// The shock spectrum of a caisson under a triangular pulse.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SpectrumReport {
    #[serde(flatten)]
    pub provenance: Provenance,
    /// The profile and model choices of the run ([`ModelReport`]).
    pub model: ModelReport,
    pub natural_period_s: f64,
    pub peak_horizontal_kn: f64,
    pub peak_uplift_kn: f64,
    pub static_sliding_resistance_kn: f64,
    pub points: Vec<SpectrumPointReport>,
    /// Plausibility warnings of the structure and of the pulse.
    pub warnings: Vec<Warning>,
}

impl SpectrumReport {
    /// The report of the sweep `points` of `base` (the scenario's triangle) on `structure`, with
    /// the warnings of the structure and of the pulse's peak forces.
    pub fn new(structure: &Structure, base: &TrianglePulse, points: &[SpectrumPoint]) -> Self {
        let mut warnings = structure_warnings(structure);
        warnings.extend(run_load_warnings(structure, &LoadSpec::Triangle(*base)));
        let resistance_n = structure.foundation.mu_static * structure.caisson.weight_in_water_n;
        SpectrumReport {
            provenance: Provenance::CURRENT,
            model: ModelReport::new(structure, None),
            natural_period_s: structure.model().natural_period_s(),
            peak_horizontal_kn: kn(base.peak.fx_n),
            peak_uplift_kn: kn(base.peak.fy_n),
            static_sliding_resistance_kn: kn(resistance_n),
            points: points.iter().map(SpectrumPointReport::from).collect(),
            warnings,
        }
    }
}
