//! `caisson size`: `size.json` (keys in docs/size.md).

use super::{kn, ModelReport, Provenance};
use crate::analysis::checks::{
    breaking_load_warnings, candidate_warnings, impulsive_warnings, precision_warning, structure_warnings, Warning,
};
use crate::analysis::conventional::Reached;
use crate::analysis::conventional::{ChecksAtWidth, ConventionalCriteria, ConventionalWidth, DesignWave};
use crate::analysis::lifetime::{DesignParams, HeelPressureExceedance};
use crate::analysis::site::WaveSetup;
use crate::analysis::sizing::{Candidate, Criteria, ModelPoint, Required, SizeParams, Sizing};
use crate::analysis::Structure;
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
    /// The lives' largest heel pressure against the allowable one (the dynamic model's).
    pub heel_pressure_exceedance: HeelPressureExceedance,
    /// Whether the criteria hold at the estimate (dynamic model, rigid block).
    pub dynamic_meets: bool,
    pub rigid_block_meets: bool,
    /// `[size] lives = "auto"`: the lives this width took and the rule's verdict on them
    /// ([`Candidate::judge`]); absent with a fixed number of lives.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub precision: Option<crate::analysis::lifetime::AutoPrecision>,
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
    /// The profile and model choices of the run ([`ModelReport`]).
    pub model: ModelReport,
    /// The variable sized.
    pub variable: &'static str,
    pub range_m: (f64, f64),
    pub criteria: Criteria,
    /// Lives per candidate; with `[size] lives = "auto"` the most a candidate may take
    /// (`max_lives`), each candidate's own in its `precision`.
    pub lives_per_candidate: usize,
    /// `[size] lives = "auto"`: the target relative error of each candidate's E|S| and
    /// P(failure); absent with a fixed number of lives.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub target_relative_error: Option<f64>,
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
    /// Lives simulated (the candidates' lives summed).
    pub lives_simulated: usize,
    pub warnings: Vec<Warning>,
}

impl SizeReport {
    /// The report of `sizing` of `structure` (the scenario's caisson) over the lives of `design`,
    /// with its warnings: the structure's, a range that does not bracket the answer, Goda's
    /// design, the life warnings of every candidate and what the impulsive waves make of the
    /// required width's lives (on the scenario's `waves`). `extra(width)` gives the failure limit
    /// (m) and Goda's static checks at each candidate's width.
    pub fn new(
        p: &SizeParams,
        design: &DesignParams,
        (structure, waves): (&Structure, Option<&WaveSetup>),
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
                    heel_pressure_exceedance: c.heel_pressure_exceedance,
                    dynamic_meets: p.criteria.met(&c.dynamic, c.lives, 0.0),
                    rigid_block_meets: p.criteria.met(&c.rigid_block, c.lives, 0.0),
                    precision: c.precision,
                }
            })
            .collect();
        let mut report = SizeReport {
            provenance: Provenance::CURRENT,
            model: ModelReport::new(structure, waves),
            variable: "width_m",
            range_m: p.range_m,
            criteria: p.criteria,
            lives_per_candidate: p.lives,
            target_relative_error: p.auto.map(|a| a.target_relative_error),
            life_years: design.life.life_years,
            seed: design.seed,
            climate: super::design::ClimateChoices::of(&design.life),
            tolerance_m: p.tolerance_m,
            dynamic: sizing.dynamic,
            rigid_block: sizing.rigid_block,
            goda,
            lives_simulated: sizing.candidates.iter().map(|c| c.life_counts.lives).sum(),
            candidates,
            warnings: Vec::new(),
        };
        report.warnings = structure_warnings(structure);
        report.warnings.extend(waves.map_or_else(Vec::new, |ws| breaking_load_warnings(structure, ws)));
        report.warnings.extend(range_warnings(&report));
        report.warnings.extend(goda_warnings(&report));
        report.warnings.extend(candidate_life_warnings(&sizing.candidates, &report, design));
        report.warnings.extend(required_impulsive_warnings(&sizing.candidates, &report, waves));
        report
    }
}

/// Warnings when the range does not bracket the answer.
fn range_warnings(r: &SizeReport) -> Vec<Warning> {
    let mut out = Vec::new();
    for (name, req) in [("dynamic model", &r.dynamic), ("rigid block", &r.rigid_block)] {
        let (code, message) = match req {
            Required::AtLowerBound { width_m } => (
                "size-at-lower-bound",
                format!("the {name} meets the criterion already at the smallest width {width_m} m: lower `[size] range_m`'s first value to find the required width"),
            ),
            Required::NotInRange { largest_m } => (
                "size-not-in-range",
                format!("the {name} does not meet the criterion at the largest width {largest_m} m: raise `[size] range_m`'s second value"),
            ),
            Required::Found { .. } => continue,
        };
        out.push(Warning {
            code,
            message,
            numbers: [("range_low_m", r.range_m.0), ("range_high_m", r.range_m.1)].into_iter().collect(),
        });
    }
    out
}

/// The life warnings of every candidate width (failed lives, large rotations, seaward lives: as
/// `caisson design` gives them for one width), each message prefixed with its width; the required
/// width's first, so that the text's summary of a code shows it.
fn candidate_life_warnings(candidates: &[Candidate], r: &SizeReport, design: &DesignParams) -> Vec<Warning> {
    let required = r.dynamic.width_m();
    let mut order: Vec<&Candidate> = candidates.iter().collect();
    order.sort_by_key(|c| Some(c.width_m) != required);
    order
        .into_iter()
        .flat_map(|c| {
            let precision = c.precision.and_then(|p| precision_warning(&p, "this candidate's lives"));
            candidate_warnings(c, &design.failure_limits(c.width_m)).into_iter().chain(precision).map(move |mut w| {
                let which = if Some(c.width_m) == required { ", the required width" } else { "" };
                w.message = format!("at B = {:.2} m{which}: {}", c.width_m, w.message);
                w.numbers.insert("width_m", c.width_m);
                w
            })
        })
        .collect()
}

/// What the impulsive waves make of the lives of the dynamic model's required width (or, where it
/// is not found, the largest candidate): `impulsive-share` and its site check, each message
/// prefixed with the width.
fn required_impulsive_warnings(candidates: &[Candidate], r: &SizeReport, waves: Option<&WaveSetup>) -> Vec<Warning> {
    let Some(ws) = waves else { return Vec::new() };
    let at = r.dynamic.width_m().and_then(|w| candidates.iter().find(|c| c.width_m == w)).or(candidates.last());
    let Some(c) = at else { return Vec::new() };
    impulsive_warnings([&c.dynamic.impulsive, &c.rigid_block.impulsive], &ws.model, Some(ws))
        .into_iter()
        .map(|mut w| {
            w.message = format!("at B = {:.2} m: {}", c.width_m, w.message);
            w.numbers.insert("width_m", c.width_m);
            w
        })
        .collect()
}

/// Warnings of Goda's conventional design: its width outside the search, a heel pressure above the
/// allowable value there, candidates that would overturn under the design wave.
fn goda_warnings(r: &SizeReport) -> Vec<Warning> {
    let g = &r.goda;
    let mut out = Vec::new();
    if let Reached::NotInRange { largest_m } = g.width.reached {
        out.push(Warning {
            code: "goda-width-not-in-range",
            message: format!("no width up to {largest_m} m meets Goda's static checks under the design wave (H_D = {:.2} m): the site's design wave is beyond what this caisson's construction can hold; check `[waves]` and `[caisson]`", g.design_wave.design_height_m),
            numbers: [("largest_width_m", largest_m), ("design_height_m", g.design_wave.design_height_m)].into_iter().collect(),
        });
    }
    if let (true, Some(a)) = (g.width.heel_pressure_above_allowable, g.width.at_width) {
        let p = a.heel_pressure_kpa;
        out.push(Warning {
            code: "heel-pressure-above-allowable",
            message: format!(
                "at Goda's width {:.2} m the heel pressure under the design wave is {}, above the allowable {} kPa (`[size] allowable_heel_pressure_kpa`): the mound needs a bearing-capacity check (or a footing); `[size] heel_pressure_governs = true` makes it a criterion of the width",
                a.width_m,
                p.map_or("undefined (the resultant leaves the base)".to_string(), |p| format!("{p:.0} kPa")),
                g.allowable_heel_pressure_kpa
            ),
            numbers: [("width_m", a.width_m), ("heel_pressure_kpa", p.unwrap_or(f64::INFINITY)), ("allowable_kpa", g.allowable_heel_pressure_kpa)]
                .into_iter()
                .filter(|(_, v)| v.is_finite())
                .collect(),
        });
    }
    let tipping: Vec<&CandidateReport> =
        r.candidates.iter().filter(|k| k.goda_overturning_safety_factor.is_some_and(|f| f < 1.0)).collect();
    if let (Some(first), Some(last)) = (tipping.first(), tipping.last()) {
        out.push(Warning {
            code: "overturning-under-design-wave",
            message: format!(
                "{} candidate widths ({:.2} to {:.2} m) have Goda's overturning safety factor below 1 under the design wave (H_D = {:.2} m): they would tip about the heel, which the dynamic model does not follow; read their lives' rotation failures, and Goda's width",
                tipping.len(),
                first.width_m,
                last.width_m,
                g.design_wave.design_height_m
            ),
            numbers: [("candidates", tipping.len() as f64), ("largest_width_m", last.width_m)].into_iter().collect(),
        });
    }
    out
}
