//! `[campaign]`: a grid (or list) of test conditions run on one scenario, as in the seed's PARI
//! campaigns (seed Tables 3 and 4). Each condition overrides the wave height of `[waves]`
//! (`height_m`, or `significant_height_m` for irregular waves), the caisson's weight in water
//! (the mass then follows from the displaced water, PHYSICS.md §8.2) and the regime; everything
//! else comes from the scenario's tables. Keys are documented in `docs/campaign.md`.
//!
//! Either the grid `heights_m` × `weights_in_water_kn` × `regimes`, or an explicit `conditions`
//! list (not both).

use super::waves::{validate_waves, WaveScenario};
use super::{validate, Scenario, ScenarioError, ScenarioFile};
use crate::loads::regime::{Regime, RegimeChoice};
use serde::Deserialize;
use std::path::Path;

type R<T> = Result<T, ScenarioError>;

/// `[campaign]` as written.
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct CampaignTable {
    /// Title of the campaign (tables and plots).
    pub title: Option<String>,
    /// Grid: nominal (or significant) wave heights, m.
    pub heights_m: Option<Vec<f64>>,
    /// Grid: caisson weights in water, kN.
    pub weights_in_water_kn: Option<Vec<f64>>,
    /// Grid: regimes, each `"auto"`, `"breaking"` or `"non-breaking"`. Default: `[waves] regime`.
    pub regimes: Option<Vec<String>>,
    /// Explicit conditions instead of the grid.
    pub conditions: Option<Vec<ConditionTable>>,
}

/// One entry of `[campaign] conditions`.
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct ConditionTable {
    pub height_m: Option<f64>,
    pub weight_in_water_kn: Option<f64>,
    pub regime: Option<String>,
}

/// A validated test condition.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Condition {
    /// Nominal (regular) or significant (irregular) wave height, m.
    pub height_m: f64,
    /// Weight in water W', N.
    pub weight_in_water_n: f64,
    #[serde(serialize_with = "regime_name")]
    pub regime: RegimeChoice,
}

fn regime_name<S: serde::Serializer>(r: &RegimeChoice, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(choice_name(*r))
}

/// The scenario name of a regime choice.
pub fn choice_name(r: RegimeChoice) -> &'static str {
    match r {
        RegimeChoice::Auto => "auto",
        RegimeChoice::Forced(Regime::Breaking) => "breaking",
        RegimeChoice::Forced(Regime::NonBreaking) => "non-breaking",
    }
}

/// A condition with its validated scenario.
#[derive(Debug, Clone)]
pub struct ConditionSetup {
    pub condition: Condition,
    pub scenario: Scenario,
    pub waves: WaveScenario,
}

/// A validated campaign.
#[derive(Debug, Clone)]
pub struct Campaign {
    pub title: String,
    pub setups: Vec<ConditionSetup>,
}

fn regime_of(key: &str, v: &str) -> R<RegimeChoice> {
    match v {
        "auto" => Ok(RegimeChoice::Auto),
        "breaking" => Ok(RegimeChoice::Forced(Regime::Breaking)),
        "non-breaking" => Ok(RegimeChoice::Forced(Regime::NonBreaking)),
        _ => Err(ScenarioError::range(
            key,
            format!("\"{v}\""),
            "must be one of \"auto\", \"breaking\", \"non-breaking\"",
        )),
    }
}

fn positive_list(key: &str, v: &[f64], unit: &str) -> R<()> {
    if v.is_empty() {
        return Err(ScenarioError::range(key, "[]", "must list at least one value"));
    }
    for (i, x) in v.iter().enumerate() {
        if !(x.is_finite() && *x > 0.0) {
            return Err(ScenarioError::range(
                &format!("{key}[{i}]"),
                x,
                format!("must be a finite number > 0 ({unit})"),
            ));
        }
    }
    Ok(())
}

/// Validate `[campaign]` and every condition's scenario. `base_dir` as in [`validate`].
pub fn validate_campaign(file: &ScenarioFile, base_dir: &Path, default_title: &str) -> R<Campaign> {
    let c = file.campaign.as_ref().ok_or_else(|| {
        ScenarioError::missing(
            "[campaign]",
            "add a [campaign] table with heights_m and weights_in_water_kn (a grid) or a conditions list",
        )
    })?;
    if file.load.is_some() {
        return Err(ScenarioError::Conflict {
            message: "a campaign runs wave trains from [waves]; remove the [load] table".into(),
        });
    }
    let wave_table = file.waves.as_ref().ok_or_else(|| {
        ScenarioError::missing("[waves]", "a campaign needs a [waves] table (kind, period_s, waves, realizations, ...)")
    })?;
    let irregular = wave_table.kind == "irregular";
    let default_regime = match &wave_table.regime {
        Some(r) => regime_of("[waves] regime", r)?,
        None => RegimeChoice::Auto,
    };
    let mut conditions = Vec::new();
    match (&c.conditions, c.heights_m.is_some() || c.weights_in_water_kn.is_some() || c.regimes.is_some()) {
        (Some(_), true) => return Err(ScenarioError::Conflict {
            message:
                "`[campaign]` has both a grid (heights_m, weights_in_water_kn, regimes) and a conditions list; keep one"
                    .into(),
        }),
        (Some(list), false) => {
            if list.is_empty() {
                return Err(ScenarioError::range("[campaign] conditions", "[]", "must list at least one condition"));
            }
            for (i, t) in list.iter().enumerate() {
                let key = |k: &str| format!("[campaign] conditions[{i}].{k}");
                let h = t
                    .height_m
                    .ok_or_else(|| ScenarioError::missing(&key("height_m"), "the wave height of this condition, m"))?;
                let w = t.weight_in_water_kn.ok_or_else(|| {
                    ScenarioError::missing(
                        &key("weight_in_water_kn"),
                        "the caisson weight in water of this condition, kN",
                    )
                })?;
                positive_list(&key("height_m"), &[h], "m")?;
                positive_list(&key("weight_in_water_kn"), &[w], "kN")?;
                let regime = match &t.regime {
                    Some(r) => regime_of(&key("regime"), r)?,
                    None => default_regime,
                };
                conditions.push((
                    format!("[campaign] conditions[{i}]"),
                    Condition { height_m: h, weight_in_water_n: w * 1e3, regime },
                ));
            }
        }
        (None, _) => {
            let hs = c.heights_m.as_ref().ok_or_else(|| {
                ScenarioError::missing("[campaign] heights_m", "the wave heights of the grid, m (or a conditions list)")
            })?;
            let ws = c.weights_in_water_kn.as_ref().ok_or_else(|| {
                ScenarioError::missing(
                    "[campaign] weights_in_water_kn",
                    "the caisson weights in water of the grid, kN (or a conditions list)",
                )
            })?;
            positive_list("[campaign] heights_m", hs, "m")?;
            positive_list("[campaign] weights_in_water_kn", ws, "kN")?;
            let regimes = match &c.regimes {
                Some(list) if list.is_empty() => {
                    return Err(ScenarioError::range("[campaign] regimes", "[]", "must list at least one regime"))
                }
                Some(list) => list
                    .iter()
                    .enumerate()
                    .map(|(i, r)| regime_of(&format!("[campaign] regimes[{i}]"), r))
                    .collect::<R<Vec<_>>>()?,
                None => vec![default_regime],
            };
            for (ri, r) in regimes.iter().enumerate() {
                for (wi, w) in ws.iter().enumerate() {
                    for (hi, h) in hs.iter().enumerate() {
                        let key = format!("[campaign] (heights_m[{hi}], weights_in_water_kn[{wi}], regimes[{ri}]) ");
                        conditions.push((key, Condition { height_m: *h, weight_in_water_n: w * 1e3, regime: *r }));
                    }
                }
            }
        }
    }
    if conditions.len() > 100_000 {
        return Err(ScenarioError::range("[campaign]", conditions.len(), "at most 100000 conditions"));
    }
    let mut setups = Vec::with_capacity(conditions.len());
    for (key, cond) in conditions {
        let mut f = file.clone();
        f.caisson.weight_in_water_kn = Some(cond.weight_in_water_n / 1e3);
        f.caisson.mass_kg = None;
        let waves = f.waves.as_mut().expect("checked above");
        if irregular {
            waves.significant_height_m = Some(cond.height_m);
        } else {
            waves.height_m = Some(cond.height_m);
        }
        waves.regime = Some(choice_name(cond.regime).to_string());
        f.campaign = None;
        let prefix = |e: ScenarioError| ScenarioError::Conflict { message: format!("{}: {e}", key.trim_end()) };
        let scenario = validate(&f, base_dir).map_err(prefix)?;
        let waves = validate_waves(&f, &scenario.caisson).map_err(prefix)?;
        setups.push(ConditionSetup { condition: cond, scenario, waves });
    }
    Ok(Campaign { title: c.title.clone().unwrap_or_else(|| default_title.to_string()), setups })
}
