//! `caisson campaign`: `campaign.json` (keys in docs/campaign.md and docs/cli.md).

use super::train::{describe_train, RealizationReport};
use super::{kn, ModelReport, Provenance, SpreadReport};
use crate::analysis::campaign::{Campaign, ConditionResult};
use crate::analysis::checks::realization_warnings;
use crate::analysis::checks::{structure_warnings, wave_load_warnings, Warning};
use crate::foundation::DampingMode;
use crate::loads::regime::{Regime, RegimeChoice};
use serde::Serialize;

/// One condition of a campaign.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ConditionReport {
    pub height_m: f64,
    pub weight_in_water_kn: f64,
    pub regime: RegimeChoice,
    pub nominal_regime: Regime,
    pub goda_horizontal_force_kn_per_m: f64,
    pub goda_uplift_force_kn_per_m: f64,
    pub impact_horizontal_force_kn_per_m: f64,
    pub sliding_m: SpreadReport,
    pub rigid_block_sliding_m: SpreadReport,
    pub max_horizontal_reaction_kn: SpreadReport,
    pub slip_events: SpreadReport,
    pub realization_sliding_m: Vec<f64>,
    /// Goda's static sliding safety factor of the nominal wave (absent without a horizontal load).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sliding_safety_factor: Option<f64>,
    /// Every realization with its waves (`campaign.json` only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub realizations: Option<Vec<RealizationReport>>,
}

impl ConditionReport {
    pub fn new(r: &ConditionResult, with_realizations: bool) -> Self {
        let s = &r.summary;
        ConditionReport {
            height_m: r.condition.height_m,
            weight_in_water_kn: kn(r.condition.weight_in_water_n),
            regime: r.condition.regime,
            nominal_regime: r.nominal.regime.regime,
            goda_horizontal_force_kn_per_m: kn(r.nominal.goda.horizontal_force_n_per_m),
            goda_uplift_force_kn_per_m: kn(r.nominal.goda.uplift_force_n_per_m),
            impact_horizontal_force_kn_per_m: kn(r.nominal.peak.horizontal_force_n_per_m),
            sliding_m: SpreadReport::scaled(&s.sliding_m, 1.0),
            rigid_block_sliding_m: SpreadReport::scaled(&s.rigid_block_sliding_m, 1.0),
            max_horizontal_reaction_kn: SpreadReport::in_kn(&s.max_horizontal_reaction_n),
            slip_events: SpreadReport::scaled(&s.slip_events, 1.0),
            realization_sliding_m: s.realizations.iter().map(|x| x.sliding_m).collect(),
            sliding_safety_factor: r.safety.sliding,
            realizations: with_realizations.then(|| s.realizations.iter().map(RealizationReport::from).collect()),
        }
    }
}

/// The trains of a campaign (the height is per condition).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CampaignWavesReport {
    pub description: String,
    pub waves: usize,
    pub realizations: usize,
    pub seed: u64,
}

/// A campaign's results.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CampaignReport {
    #[serde(flatten)]
    pub provenance: Provenance,
    /// The profile and model choices of the run ([`ModelReport`]).
    pub model: ModelReport,
    pub title: String,
    pub waves: CampaignWavesReport,
    pub damping_mode: DampingMode,
    pub conditions: Vec<ConditionReport>,
    /// Plausibility warnings of the conditions' structures and realizations (numbered as the
    /// conditions, from 1).
    pub warnings: Vec<Warning>,
}

impl CampaignReport {
    /// The report of `results` of campaign `c` (with every realization and wave if asked).
    pub fn new(c: &Campaign, results: &[ConditionResult], with_realizations: bool) -> Self {
        let first = &c.setups[0];
        let t = &first.waves.train;
        CampaignReport {
            provenance: Provenance::CURRENT,
            model: ModelReport::new(&first.structure, Some(&first.waves)),
            title: c.title.clone(),
            waves: CampaignWavesReport {
                description: describe_train(t, true),
                waves: t.waves,
                realizations: t.realizations,
                seed: t.seed,
            },
            damping_mode: first.structure.foundation.damping_mode,
            conditions: results.iter().map(|r| ConditionReport::new(r, with_realizations)).collect(),
            warnings: c
                .setups
                .iter()
                .zip(results)
                .enumerate()
                .flat_map(|(i, (s, r))| {
                    let mut w = structure_warnings(&s.structure);
                    w.extend(wave_load_warnings(&s.structure, &s.waves));
                    w.extend(realization_warnings(&s.case(), &r.summary.realizations));
                    w.into_iter().map(move |mut w| {
                        w.message = format!("condition {}: {}", i + 1, w.message);
                        w
                    })
                })
                .collect(),
        }
    }
}
