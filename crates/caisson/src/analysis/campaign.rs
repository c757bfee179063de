//! Campaigns: many test conditions × realizations of wave trains, run in parallel (seed §6,
//! Figs. 13 and 15).
//!
//! The work is the flat list of (condition, realization) pairs, run with rayon and collected in
//! order, so the results are identical for any number of threads (each realization's random
//! numbers depend only on the seed and its index, [`crate::loads::generator`]). The library does
//! not print: `tick` is called once per finished realization (the CLI moves a progress bar).

use super::train::{RealizationResult, TrainCase, TrainRunError, TrainSummary};
use crate::loads::model::WaveLoads;
use crate::loads::regime::RegimeError;
use crate::loads::safety::SafetyFactors;
use crate::scenario::campaign::{Condition, ConditionSetup};
use rayon::prelude::*;

/// The results of one condition.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ConditionResult {
    pub condition: Condition,
    /// The loads of the nominal wave (regime, Goda, impact) and Goda's static checks with μ_s.
    pub nominal: WaveLoads,
    pub safety: SafetyFactors,
    pub summary: TrainSummary,
}

/// The case of a condition (borrowing its setup).
pub fn case_of(s: &ConditionSetup) -> TrainCase<'_> {
    TrainCase {
        caisson: &s.scenario.caisson,
        foundation: &s.scenario.foundation,
        solver: s.scenario.solver,
        model: &s.waves.model,
        spec: &s.waves.train,
        regime: s.condition.regime,
        rigid_block_mu: s.waves.rigid_block_mu.unwrap_or(s.scenario.foundation.mu_static),
    }
}

/// Run every realization of every condition in parallel (module docs).
pub fn run_campaign(
    setups: &[ConditionSetup],
    tick: &(dyn Fn() + Sync),
) -> Result<Vec<ConditionResult>, TrainRunError> {
    let jobs: Vec<(usize, usize)> =
        setups.iter().enumerate().flat_map(|(c, s)| (0..s.waves.train.realizations).map(move |r| (c, r))).collect();
    let results: Vec<RealizationResult> = jobs
        .par_iter()
        .map(|&(c, r)| {
            let out = case_of(&setups[c]).run(r, None);
            tick();
            out
        })
        .collect::<Result<_, _>>()?;
    let mut results = results.into_iter();
    setups
        .iter()
        .map(|s| {
            let rs: Vec<RealizationResult> = results.by_ref().take(s.waves.train.realizations).collect();
            let nominal = s
                .waves
                .model
                .evaluate_with(s.waves.height_m, s.waves.period_s, s.condition.regime)
                .map_err(|e: RegimeError| TrainRunError::Regime(e))?;
            let safety =
                s.waves.model.safety(&nominal, s.scenario.caisson.weight_in_water_n, s.scenario.foundation.mu_static);
            Ok(ConditionResult { condition: s.condition, nominal, safety, summary: TrainSummary::new(rs) })
        })
        .collect()
}

/// Run the realizations of one wave scenario in parallel (`caisson run` on a `[waves]` scenario).
pub fn run_realizations(case: &TrainCase<'_>, tick: &(dyn Fn() + Sync)) -> Result<TrainSummary, TrainRunError> {
    let rs: Vec<RealizationResult> = (0..case.spec.realizations)
        .into_par_iter()
        .map(|r| {
            let out = case.run(r, None);
            tick();
            out
        })
        .collect::<Result<_, _>>()?;
    Ok(TrainSummary::new(rs))
}
