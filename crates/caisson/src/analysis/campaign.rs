//! Campaigns: many test conditions × realizations of wave trains, run in parallel (seed §6,
//! Figs. 13 and 15).
//!
//! A [`Condition`] is a nominal (or significant) wave height, a weight in water and a regime; its
//! [`ConditionSetup`] is the structure and waves of the scenario with those three changed (the
//! mass follows the weight through the displaced water, and a soil-derived foundation follows it
//! too, `scenario` builds them). The work is the flat list of (condition, realization) pairs, run
//! with rayon and collected in order, so the results are identical for any number of threads
//! (each realization's random numbers depend only on the seed and its index,
//! [`crate::loads::generator`]). `progress` is called once per finished realization.

use super::conventional::{DesignWave, StaticCheck};
use super::site::WaveSetup;
use super::train::{RealizationResult, TrainCase, TrainRunError, TrainSummary};
use super::{Progress, Structure};
use crate::check::positive;
use crate::loads::model::WaveLoads;
use crate::loads::regime::RegimeChoice;
use crate::loads::safety::SafetyFactors;
use crate::ParamError;
use rayon::prelude::*;

/// A test condition.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Condition {
    /// Nominal (regular) or significant (irregular) wave height, m.
    pub height_m: f64,
    /// Weight in water W', N.
    pub weight_in_water_n: f64,
    pub regime: RegimeChoice,
}

impl Condition {
    /// A condition of a wave height above 0 (m) and a weight in water above 0 (N); refused naming
    /// `height_m` or `weight_in_water_n`. (Whether the waves and the caisson of that height and
    /// weight are plausible is checked where the condition's setup is built.)
    pub fn new(height_m: f64, weight_in_water_n: f64, regime: RegimeChoice) -> Result<Self, ParamError> {
        let height_m = Self::checked_height_m(height_m)?;
        let weight_in_water_n = Self::checked_weight_in_water_n(weight_in_water_n)?;
        Ok(Condition { height_m, weight_in_water_n, regime })
    }

    /// A condition's wave height if above 0, m (the rule of [`Self::new`], for a grid's heights).
    pub fn checked_height_m(height_m: f64) -> Result<f64, ParamError> {
        positive("height_m", height_m)
    }

    /// A condition's weight in water if above 0, N (the rule of [`Self::new`], for a grid's
    /// weights).
    pub fn checked_weight_in_water_n(weight_in_water_n: f64) -> Result<f64, ParamError> {
        positive("weight_in_water_n", weight_in_water_n)
    }
}

/// A condition with the structure and waves it runs on.
#[derive(Debug, Clone)]
pub struct ConditionSetup {
    pub condition: Condition,
    pub structure: Structure,
    pub waves: WaveSetup,
}

impl ConditionSetup {
    /// The wave-train test of this condition.
    pub fn case(&self) -> TrainCase<'_> {
        TrainCase { structure: &self.structure, waves: &self.waves }
    }
}

/// A campaign: a title and its conditions, in the order they are reported.
#[derive(Debug, Clone)]
pub struct Campaign {
    pub title: String,
    pub setups: Vec<ConditionSetup>,
}

/// The results of one condition.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ConditionResult {
    pub condition: Condition,
    /// The loads of Goda's design wave (regular: the nominal H; irregular: H_max) and Goda's
    /// static checks with μ_s.
    pub nominal: WaveLoads,
    pub safety: SafetyFactors,
    pub summary: TrainSummary,
}

/// Run every realization of every condition in parallel (module docs).
pub fn run_campaign(setups: &[ConditionSetup], progress: Progress<'_>) -> Result<Vec<ConditionResult>, TrainRunError> {
    let jobs: Vec<(usize, usize)> =
        setups.iter().enumerate().flat_map(|(c, s)| (0..s.waves.train.realizations).map(move |r| (c, r))).collect();
    let results: Vec<RealizationResult> = jobs
        .par_iter()
        // A progress callback that unwinds (a Python call stopped by Ctrl-C) stops the items not yet begun.
        .panic_fuse()
        .map(|&(c, r)| {
            let out = setups[c].case().run(r, None);
            progress();
            out
        })
        .collect::<Result<_, _>>()?;
    let mut results = results.into_iter();
    setups
        .iter()
        .map(|s| {
            let rs: Vec<RealizationResult> = results.by_ref().take(s.waves.train.realizations).collect();
            // Goda's design wave of the condition (regular: H; irregular: H_max, docs/model.md §1.3).
            let c = &s.structure;
            let (w, mu) = (c.caisson.weight_in_water_n, c.foundation.mu_static);
            let check = StaticCheck::new(&s.waves, DesignWave::of(&s.waves), w, mu, s.condition.regime)?;
            let (nominal, safety) = (check.loads, check.safety);
            Ok(ConditionResult { condition: s.condition, nominal, safety, summary: TrainSummary::new(rs) })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A condition refuses a height or a weight that is not a finite number above 0 by itself,
    /// naming the quantity.
    #[test]
    fn condition_names_what_it_refuses() {
        let ok = Condition::new(0.5, 1.0e4, RegimeChoice::Forced(crate::loads::regime::Regime::Breaking)).unwrap();
        assert_eq!(
            (ok.height_m, ok.weight_in_water_n, ok.regime),
            (0.5, 1.0e4, RegimeChoice::Forced(crate::loads::regime::Regime::Breaking))
        );
        let mut checked = 0;
        for (h, w, quantity) in [
            (0.0, 1.0e4, "height_m"),
            (f64::NAN, 1.0e4, "height_m"),
            (0.5, -1.0, "weight_in_water_n"),
            (0.5, f64::INFINITY, "weight_in_water_n"),
        ] {
            assert_eq!(Condition::new(h, w, RegimeChoice::Auto).unwrap_err().quantity, quantity);
            checked += 1;
        }
        assert_eq!(checked, 4);
    }
}
