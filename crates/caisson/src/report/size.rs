//! `caisson size`: `size.json` (keys in docs/size.md).

use super::{kn, Provenance};
use crate::analysis::checks::Warning;
use crate::analysis::conventional::{ChecksAtWidth, ConventionalCriteria, ConventionalWidth, DesignWave};
use crate::analysis::sizing::{Candidate, Criteria, ModelPoint, Required, SizeParams, Sizing};
use serde::Serialize;

/// One evaluated width (weights in kN).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CandidateReport {
    pub width_m: f64,
    pub weight_in_water_kn: f64,
    /// The failure limit at this width, m.
    pub failure_sliding_m: f64,
    /// Goda's static checks under the design wave (`null` where undefined).
    pub goda_sliding_safety_factor: Option<f64>,
    pub goda_overturning_safety_factor: Option<f64>,
    pub goda_heel_pressure_kpa: Option<f64>,
    pub dynamic: ModelPoint,
    pub rigid_block: ModelPoint,
    /// Whether the criteria hold at the estimate (dynamic model, rigid block).
    pub dynamic_meets: bool,
    pub rigid_block_meets: bool,
}

/// The width of Goda's conventional design (docs/size.md, [`crate::analysis::conventional`]):
/// the smallest with the sliding and overturning safety factors at their targets under the
/// design wave, with the heel pressure there beside its allowable value.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct GodaWidth {
    pub design_wave: DesignWave,
    pub sliding_safety_factor: f64,
    pub overturning_safety_factor: f64,
    pub allowable_heel_pressure_kpa: f64,
    pub heel_pressure_governs: bool,
    #[serde(flatten)]
    pub width: ConventionalWidth,
}

impl GodaWidth {
    pub fn new(design_wave: DesignWave, c: &ConventionalCriteria, width: ConventionalWidth) -> Self {
        GodaWidth {
            design_wave,
            sliding_safety_factor: c.sliding_safety_factor,
            overturning_safety_factor: c.overturning_safety_factor,
            allowable_heel_pressure_kpa: kn(c.allowable_heel_pressure_pa),
            heel_pressure_governs: c.heel_pressure_governs,
            width,
        }
    }
}

/// The results of a sizing run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SizeReport {
    #[serde(flatten)]
    pub provenance: Provenance,
    /// The variable sized.
    pub variable: &'static str,
    pub range_m: (f64, f64),
    pub criteria: Criteria,
    pub lives_per_candidate: usize,
    pub life_years: usize,
    pub seed: u64,
    /// The climate choices of `[design]` that are not today's model; absent if none (set by the
    /// caller: [`super::design::ClimateChoices::of`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub climate: Option<super::design::ClimateChoices>,
    pub tolerance_m: f64,
    /// The required width by the dynamic model and by the rigid block (Shimosako model).
    pub dynamic: Required,
    pub rigid_block: Required,
    pub goda: GodaWidth,
    /// Every evaluated width, by width.
    pub candidates: Vec<CandidateReport>,
    /// Lives simulated (candidates × lives per candidate).
    pub lives_simulated: usize,
    pub warnings: Vec<Warning>,
}

impl SizeReport {
    /// The report of `sizing`; `extra(width)` gives the failure limit (m) and Goda's static checks
    /// at each candidate's width.
    pub fn new(
        p: &SizeParams,
        life_years: usize,
        seed: u64,
        sizing: &Sizing,
        goda: GodaWidth,
        extra: &dyn Fn(&Candidate) -> (f64, Option<ChecksAtWidth>),
    ) -> Self {
        let candidates: Vec<CandidateReport> = sizing
            .candidates
            .iter()
            .map(|c| {
                let (failure_sliding_m, goda) = extra(c);
                CandidateReport {
                    width_m: c.width_m,
                    weight_in_water_kn: kn(c.weight_in_water_n),
                    failure_sliding_m,
                    goda_sliding_safety_factor: goda.and_then(|g| g.sliding_safety_factor),
                    goda_overturning_safety_factor: goda.and_then(|g| g.overturning_safety_factor),
                    goda_heel_pressure_kpa: goda.and_then(|g| g.heel_pressure_kpa),
                    dynamic: c.dynamic,
                    rigid_block: c.rigid_block,
                    dynamic_meets: p.criteria.met(&c.dynamic, c.lives, 0.0),
                    rigid_block_meets: p.criteria.met(&c.rigid_block, c.lives, 0.0),
                }
            })
            .collect();
        SizeReport {
            provenance: Provenance::CURRENT,
            variable: "width_m",
            range_m: p.range_m,
            criteria: p.criteria,
            lives_per_candidate: p.lives,
            life_years,
            seed,
            climate: None,
            tolerance_m: p.tolerance_m,
            dynamic: sizing.dynamic,
            rigid_block: sizing.rigid_block,
            goda,
            lives_simulated: sizing.candidates.iter().map(|c| c.lives).sum(),
            candidates,
            warnings: Vec::new(),
        }
    }
}
