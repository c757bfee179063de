//! `[campaign]`: a grid (or list) of test conditions run on one scenario, as in the seed's PARI
//! campaigns (seed Tables 3 and 4). Each condition overrides the wave height of `[waves]`
//! (`height_m`, or `significant_height_m` for irregular waves), the caisson's weight in water
//! (the mass then follows from the displaced water, docs/model.md §8.2) and the regime; everything
//! else comes from the scenario's tables. Keys are documented in `docs/campaign.md`.
//!
//! Either the grid `heights_m` × `weights_in_water_kn` × `regimes`, or an explicit `conditions`
//! list (not both).

use super::{Scenario, ScenarioError, ScenarioFile};
use crate::analysis::campaign::{Campaign, Condition, ConditionSetup};
use crate::loads::generator::TrainKind;
use crate::loads::regime::RegimeChoice;
use serde::Deserialize;

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

/// A validated `[campaign]`: its title (`None`: the caller names it, e.g. after the file) and
/// its conditions in order.
#[derive(Debug, Clone, PartialEq)]
pub struct CampaignSpec {
    pub title: Option<String>,
    pub conditions: Vec<Condition>,
    /// Where each condition is in the file, for messages.
    places: Vec<String>,
}

impl CampaignSpec {
    /// A campaign of `conditions` (named `conditions[i]` in messages).
    pub fn new(title: Option<String>, conditions: Vec<Condition>) -> Self {
        let places = (0..conditions.len()).map(|i| format!("[campaign] conditions[{i}]")).collect();
        CampaignSpec { title, conditions, places }
    }
}

/// The scenario name of a regime choice.
pub fn choice_name(r: RegimeChoice) -> &'static str {
    r.name()
}

fn regime_of(key: &str, v: &str) -> R<RegimeChoice> {
    RegimeChoice::from_name(v).ok_or_else(|| {
        ScenarioError::range(key, format!("\"{v}\""), "must be one of \"auto\", \"breaking\", \"non-breaking\"")
    })
}

/// A refused height (m) or weight in water (N) of a condition under `key`, with the value as
/// read (`read`: m or kN).
fn refused(key: &str, read: f64, e: crate::ParamError) -> ScenarioError {
    let unit = if e.quantity == "height_m" { "m" } else { "kN" };
    ScenarioError::range(key, read, e.allowed.describe(1.0, unit))
}

/// A grid's list `key` of heights (m) or weights in water (kN: `scale` 1e3 to N), each checked by
/// `check` (a rule of [`Condition::new`]).
fn grid_list(key: &str, v: &[f64], scale: f64, check: fn(f64) -> Result<f64, crate::ParamError>) -> R<()> {
    if v.is_empty() {
        return Err(ScenarioError::range(key, "[]", "must list at least one value"));
    }
    for (i, &x) in v.iter().enumerate() {
        check(x * scale).map_err(|e| refused(&format!("{key}[{i}]"), x, e))?;
    }
    Ok(())
}

/// The conditions of a campaign with their places in the file (for messages).
type Placed = Vec<(String, Condition)>;

/// Validate `[campaign]`: its conditions (each condition's setup is checked by [`build`]).
pub(super) fn validate_campaign(file: &ScenarioFile) -> R<CampaignSpec> {
    let c = file.campaign.as_ref().ok_or_else(|| {
        ScenarioError::missing(
            "[campaign]",
            "add a [campaign] table with heights_m and weights_in_water_kn (a grid) or a conditions list",
        )
    })?;
    if let Some(t) = c.title.as_deref().filter(|t| t.chars().any(char::is_control)) {
        return Err(ScenarioError::range(
            "[campaign] title",
            format!("{t:?}"),
            "must be text without control characters (line breaks, tabs, escape sequences): it titles the plots and the text output",
        ));
    }
    if file.load.is_some() {
        return Err(ScenarioError::Conflict {
            message: "a campaign runs wave trains from [waves]; remove the [load] table".into(),
        });
    }
    let wave_table = file.waves.as_ref().ok_or_else(|| {
        ScenarioError::missing("[waves]", "a campaign needs a [waves] table (kind, period_s, waves, realizations, ...)")
    })?;
    let default_regime = match &wave_table.regime {
        Some(r) => regime_of("[waves] regime", r)?,
        None => RegimeChoice::Auto,
    };
    let conditions = match (
        &c.conditions,
        c.heights_m.is_some() || c.weights_in_water_kn.is_some() || c.regimes.is_some(),
    ) {
        (Some(_), true) => return Err(ScenarioError::Conflict {
            message:
                "`[campaign]` has both a grid (heights_m, weights_in_water_kn, regimes) and a conditions list; keep one"
                    .into(),
        }),
        (Some(list), false) => listed(list, default_regime)?,
        (None, _) => grid(c, default_regime)?,
    };
    if conditions.len() > 100_000 {
        return Err(ScenarioError::range("[campaign]", conditions.len(), "at most 100000 conditions"));
    }
    let (places, conditions) = conditions.into_iter().map(|(k, c)| (k.trim_end().to_string(), c)).unzip();
    Ok(CampaignSpec { title: c.title.clone(), conditions, places })
}

/// The conditions of a `[campaign] conditions` list, each with its regime or `default_regime`.
fn listed(list: &[ConditionTable], default_regime: RegimeChoice) -> R<Placed> {
    if list.is_empty() {
        return Err(ScenarioError::range("[campaign] conditions", "[]", "must list at least one condition"));
    }
    let mut conditions = Vec::with_capacity(list.len());
    for (i, t) in list.iter().enumerate() {
        let key = |k: &str| format!("[campaign] conditions[{i}].{k}");
        let h = t
            .height_m
            .ok_or_else(|| ScenarioError::missing(&key("height_m"), "the wave height of this condition, m"))?;
        let w = t.weight_in_water_kn.ok_or_else(|| {
            ScenarioError::missing(&key("weight_in_water_kn"), "the caisson weight in water of this condition, kN")
        })?;
        let c = Condition::new(h, w * 1e3, default_regime).map_err(|e| match e.quantity {
            "height_m" => refused(&key("height_m"), h, e),
            _ => refused(&key("weight_in_water_kn"), w, e),
        })?;
        let regime = match &t.regime {
            Some(r) => regime_of(&key("regime"), r)?,
            None => default_regime,
        };
        conditions.push((format!("[campaign] conditions[{i}]"), Condition { regime, ..c }));
    }
    Ok(conditions)
}

/// The conditions of the grid `heights_m` × `weights_in_water_kn` × `regimes` (default
/// `default_regime`), heights fastest.
fn grid(c: &CampaignTable, default_regime: RegimeChoice) -> R<Placed> {
    let hs = c.heights_m.as_ref().ok_or_else(|| {
        ScenarioError::missing("[campaign] heights_m", "the wave heights of the grid, m (or a conditions list)")
    })?;
    let ws = c.weights_in_water_kn.as_ref().ok_or_else(|| {
        ScenarioError::missing(
            "[campaign] weights_in_water_kn",
            "the caisson weights in water of the grid, kN (or a conditions list)",
        )
    })?;
    grid_list("[campaign] heights_m", hs, 1.0, Condition::checked_height_m)?;
    grid_list("[campaign] weights_in_water_kn", ws, 1e3, Condition::checked_weight_in_water_n)?;
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
    let mut conditions = Vec::new();
    for (ri, &r) in regimes.iter().enumerate() {
        for (wi, &w) in ws.iter().enumerate() {
            for (hi, &h) in hs.iter().enumerate() {
                let key = format!("[campaign] (heights_m[{hi}], weights_in_water_kn[{wi}], regimes[{ri}]) ");
                let c = Condition::new(h, w * 1e3, r).map_err(|e| refused(&key, h, e))?;
                conditions.push((key, c));
            }
        }
    }
    Ok(conditions)
}

/// The setup of every condition of the scenario's campaign: the scenario's caisson with the
/// condition's weight in water (the mass, and a soil-derived foundation, follow), its waves with
/// the condition's height and regime. Errors are prefixed with the condition's place in the file.
pub(super) fn build(sc: &Scenario, spec: &CampaignSpec) -> R<Campaign> {
    let mut setups = Vec::with_capacity(spec.conditions.len());
    for (i, cond) in spec.conditions.iter().enumerate() {
        let place = spec.places.get(i).cloned().unwrap_or_else(|| format!("[campaign] conditions[{i}]"));
        let prefix = |e: ScenarioError| ScenarioError::Conflict { message: format!("{place}: {e}") };
        let c = sc.clone().with_caisson(|c| *c = c.with_weight_in_water_n(cond.weight_in_water_n)).map_err(prefix)?;
        let mut waves = c.waves_for("a campaign")?.clone();
        let height_key = match waves.train.kind {
            TrainKind::Regular { .. } => "[waves] height_m",
            TrainKind::Irregular { .. } => "[waves] significant_height_m",
        };
        waves.train = waves
            .train
            .with_height_m(cond.height_m)
            .map_err(|e| prefix(ScenarioError::range(height_key, e.value, e.allowed.describe(1.0, ""))))?;
        waves.model.options.regime = cond.regime;
        // A forced regime must agree with the breaking criterion (non-breaking above the limit).
        waves.model.evaluate(waves.height_m(), waves.period_s()).map_err(|e| {
            prefix(ScenarioError::range(
                "[waves] regime",
                "\"non-breaking\"",
                format!("is not allowed here: {e}; use \"breaking\" or \"auto\""),
            ))
        })?;
        super::coherence::check_waves(c.caisson(), &waves).map_err(prefix)?;
        setups.push(ConditionSetup { condition: *cond, structure: c.structure().clone(), waves });
    }
    let title = spec.title.clone().unwrap_or_else(|| "campaign".to_string());
    Ok(Campaign { title, setups })
}
