//! `[waves]` (and the wave keys of `[water]`): the incident waves and the options of the wave-load
//! models, read into a [`WaveSetup`] (a [`WaveLoadModel`], the design wave and its trains).
//!
//! This file reads keys: what is missing, which keys go together, names of choices, whole numbers.
//! The rules of the values are the types' own ([`WaveSetup::new`]: [`WaveSite::checked`],
//! [`TrainSpec::checked`], [`WaveLoadOptions::checked`]); `keyed_waves` names a refusal's key.
//!
//! Every key, with unit, default and allowed range, is documented in `docs/waves.md`. The caisson
//! geometry comes from `[caisson]`: base depth h' = `base_depth_m`, crest freeboard
//! h_c = `height_m − base_depth_m`, width B, alongshore length.

use super::{ScenarioError, ScenarioFile};
use crate::analysis::site::{place_caisson, WaveSetup};
use crate::loads::breaking_load::BreakingLoad;
use crate::loads::generator::{HeightVariability, TrainKind, TrainSpec};
use crate::loads::model::{SainflouDepth, WaveLoadModel, WaveLoadOptions, WaveParamError, WaveSite};
use crate::loads::regime::{Regime, RegimeChoice};
use crate::loads::risetime::{RiseTimeModel, RiseTimeParams};
use crate::loads::shapes::LoadShape;
use crate::structure::Caisson;
use crate::waves::breaking::{BreakerCriterion, GODA_BREAKER_A, MCCOWAN_GAMMA};
use crate::Profile;
use serde::Deserialize;

type R<T> = Result<T, ScenarioError>;

/// `[waves]` as written in the scenario file.
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct WavesTable {
    /// `"regular"`.
    pub kind: String,
    /// Incident wave height H (regular waves), m.
    pub height_m: Option<f64>,
    /// Wave period T, s.
    pub period_s: Option<f64>,
    /// Angle between the wave direction and the normal to the breakwater, degrees. Default 0.
    pub angle_deg: Option<f64>,
    /// `"auto"` (default), `"breaking"` or `"non-breaking"`.
    pub regime: Option<String>,
    /// The impulsive peak of a breaking wave: `"cuomo-2010"`, `"goda-takahashi"` or `"none"`.
    /// Default: the profile's.
    pub breaking_load: Option<String>,
    /// `"miche"` (default), `"goda"` or `"mccowan"`.
    pub breaker_criterion: Option<String>,
    /// α_max of seed Eq. 30. Default 1/1.8 (regular waves).
    pub alpha_max: Option<f64>,
    /// a_imp of seed Eq. 30. Default 1.
    pub a_imp: Option<f64>,
    /// α_qs of seed Eq. 29. Default 0.8.
    pub alpha_qs_nonbreaking: Option<f64>,
    /// α_qs of seed Eq. 31. Default 1.0.
    pub alpha_qs_breaking: Option<f64>,
    /// `"median"` (default) or `"literal"` reading of seed Eq. 34.
    pub rise_time_model: Option<String>,
    /// Time shape of breaking waves: `"seed"` (Eq. 31, default) or a Table 2 shape.
    pub load_shape: Option<String>,
    /// t_d / t_r for the shapes with a separate duration. Default 2.
    pub duration_ratio: Option<f64>,
    /// `"toe"` (default) or `"wall"`: the depth of the Sainflou standing wave.
    pub sainflou_depth: Option<String>,
    /// Significant wave height H1/3 at the toe (irregular waves), m.
    pub significant_height_m: Option<f64>,
    /// Waves per realization N_z. Default 15.
    pub waves: Option<i64>,
    /// Realizations (independent wave trains). Default 10.
    pub realizations: Option<i64>,
    /// Regular waves: `"normal"` (default), `"uniform"` or `"none"` (docs/model.md §10 item 26).
    pub height_variability: Option<String>,
    /// COV of the normal variability, or half-width of the uniform one, as a fraction of H.
    /// Default 0.2.
    pub height_variability_fraction: Option<f64>,
    /// Truncation of the normal variability, in standard deviations. Default 2.
    pub height_truncation_sigmas: Option<f64>,
    /// Seed of the random generator (heights and rise times). Default 1.
    pub seed: Option<i64>,
    /// Friction coefficient of the rigid-block (Shimosako) reference. Default `[foundation] mu_static`.
    pub rigid_block_mu: Option<f64>,
}

pub use crate::loads::generator::MAX_TRAIN_WAVES;
pub use crate::loads::model::{MIN_LENGTH_M, MIN_PERIOD_S};

/// A finite number in (lo, hi] (`lo_open`) or [lo, hi], else a keyed range error.
pub(super) fn number(key: &str, v: f64, lo: f64, hi: f64, lo_open: bool, unit: &str) -> R<f64> {
    let above = if lo_open { v > lo } else { v >= lo };
    if v.is_finite() && above && v <= hi {
        Ok(v)
    } else {
        let low = if lo_open { format!("> {lo}") } else { format!("≥ {lo}") };
        Err(ScenarioError::range(
            key,
            super::fmt_value(v),
            format!("must be a finite number {low} and ≤ {hi} ({unit})"),
        ))
    }
}

fn pick<T: Copy>(key: &str, v: Option<&String>, default: T, options: &[(&str, T)]) -> R<T> {
    let Some(v) = v else { return Ok(default) };
    options.iter().find(|(n, _)| *n == v.as_str()).map(|(_, t)| *t).ok_or_else(|| {
        let names: Vec<String> = options.iter().map(|(n, _)| format!("\"{n}\"")).collect();
        ScenarioError::range(key, format!("\"{v}\""), format!("must be one of {}", names.join(", ")))
    })
}

pub(super) fn required(key: &str, v: Option<f64>, hint: &str) -> R<f64> {
    v.ok_or_else(|| ScenarioError::missing(key, hint))
}

/// A random seed: a whole number ≥ 0 (default 1).
pub(super) fn seed_of(key: &str, v: Option<i64>) -> R<u64> {
    match v {
        None => Ok(1),
        Some(s) if s >= 0 => Ok(s as u64),
        Some(s) => Err(ScenarioError::range(key, s, format!("must be a whole number from 0 to {}", i64::MAX))),
    }
}

/// The keys of the quantities of a [`WaveSetup`] (named as in their types) and their units.
const WAVE_KEYS: super::NamedKeys = &[
    ("rho_w", "[water] density_kg_per_m3", "kg/m³"),
    ("depth_at_toe_m", "[water] depth_at_toe_m", "m"),
    ("seabed_slope", "[water] seabed_slope", "tan θ, 0 for a flat bed"),
    ("berm_width_m", "[water] berm_width_m", "m"),
    ("period_s", "[waves] period_s", "s"),
    ("height_m", "[waves] height_m", "m"),
    ("significant_height_m", "[waves] significant_height_m", "m"),
    ("angle_deg", "[waves] angle_deg", ""),
    ("alpha_max", "[waves] alpha_max", "-"),
    ("a_imp", "[waves] a_imp", "-"),
    ("alpha_qs_nonbreaking", "[waves] alpha_qs_nonbreaking", "-"),
    ("alpha_qs_breaking", "[waves] alpha_qs_breaking", "-"),
    ("duration_ratio", "[waves] duration_ratio", "-"),
    ("waves", "[waves] waves", ""),
    ("realizations", "[waves] realizations", ""),
    ("height_variability_fraction", "[waves] height_variability_fraction", "-"),
    ("height_truncation_sigmas", "[waves] height_truncation_sigmas", "-"),
    ("rigid_block_mu", "[waves] rigid_block_mu", "-"),
];

/// A refused wave setup under the keys of `[water]`, `[waves]` and `[caisson]`.
fn keyed_waves(e: WaveParamError) -> ScenarioError {
    match e {
        WaveParamError::Param(e) => super::keyed_in(WAVE_KEYS, e),
        WaveParamError::WallDepth { depth_at_wall_m, depth_at_toe_m } => ScenarioError::range(
            "[water] depth_at_wall_m",
            super::fmt_value(depth_at_wall_m),
            format!("must be from {MIN_LENGTH_M} m (a laboratory flume's scale) to depth_at_toe_m = {depth_at_toe_m} m (the berm cannot be below the seabed)"),
        ),
        WaveParamError::BaseAboveWall { base_depth_m, depth_at_wall_m } => ScenarioError::range(
            "[caisson] base_depth_m",
            base_depth_m,
            format!("must be at least [water] depth_at_wall_m = {depth_at_wall_m} m: the caisson base sits on or in the mound, not above the water depth in front of the wall"),
        ),
        WaveParamError::BaseBelowToe { base_depth_m, depth_at_toe_m } => ScenarioError::range(
            "[caisson] base_depth_m",
            base_depth_m,
            format!("must be at most [water] depth_at_toe_m = {depth_at_toe_m} m: the base cannot be below the seabed at the toe"),
        ),
        WaveParamError::TooManyWaves { waves, realizations } => ScenarioError::range(
            "[waves] realizations",
            realizations,
            format!("times [waves] waves = {waves} gives {} waves in all; at most {MAX_TRAIN_WAVES}", waves * realizations),
        ),
        WaveParamError::Regime(e) => ScenarioError::range(
            "[waves] regime",
            "\"non-breaking\"",
            format!("is not allowed here: {e}; use \"breaking\" or \"auto\""),
        ),
    }
}

/// Read `[water]` (depths, slope, berm) and `[waves]` and build their [`WaveSetup`] at `caisson`
/// (the validated caisson) in water of density `rho_w` (kg/m³, validated), with the breaking-wave
/// rule of `[waves] breaking_load` or else of `profile`; also returns the rule as given.
pub(super) fn validate_waves(
    file: &ScenarioFile,
    caisson: &Caisson,
    rho_w: f64,
    profile: Profile,
) -> R<(WaveSetup, Option<BreakingLoad>)> {
    let t = file.waves.as_ref().ok_or_else(|| {
        ScenarioError::missing("[waves]", "add a [waves] table with kind = \"regular\", height_m and period_s")
    })?;
    let mut site = site(&file.water, rho_w)?;
    place_caisson(&mut site, caisson);
    let train = train(t)?;
    let mut options = options(t, site.seabed_slope)?;
    let given = breaking_load_given(t, site.berm_width_m)?;
    options.breaking_load = breaking_load(given, profile);
    let setup = WaveSetup::new(WaveLoadModel { site, options }, train, t.rigid_block_mu).map_err(keyed_waves)?;
    Ok((setup, given))
}

/// `[waves] breaking_load` as given (`None`: the profile's), refused where it is
/// `"goda-takahashi"` without `[water] berm_width_m` (`berm_width_m`): Takahashi's α_I depends on
/// the berm width, which only the file knows.
fn breaking_load_given(t: &WavesTable, berm_width_m: Option<f64>) -> R<Option<BreakingLoad>> {
    let Some(name) = &t.breaking_load else { return Ok(None) };
    let rule = pick("[waves] breaking_load", Some(name), BreakingLoad::Cuomo2010, &BreakingLoad::ALL)?;
    if rule == BreakingLoad::GodaTakahashi && berm_width_m.is_none() {
        return Err(ScenarioError::missing(
            "[water] berm_width_m",
            "`[waves] breaking_load = \"goda-takahashi\"` takes Takahashi's impulsive coefficient α_I, which depends on B_M, the width of the mound's berm in front of the caisson (docs/model.md §1.4): add `berm_width_m` (m; 0 for no berm) to [water], or choose breaking_load = \"cuomo-2010\" or \"none\"",
        ));
    }
    Ok(Some(rule))
}

/// The breaking-wave rule: as given, or the profile's ([`BreakingLoad::for_profile`]).
pub(super) fn breaking_load(given: Option<BreakingLoad>, profile: Profile) -> BreakingLoad {
    given.unwrap_or_else(|| BreakingLoad::for_profile(profile))
}

/// The site of `[water]` (the caisson is placed on it after).
fn site(w: &super::WaterTable, rho_w: f64) -> R<WaveSite> {
    let depth_at_toe_m =
        required("[water] depth_at_toe_m", w.depth_at_toe_m, "h_s, the water depth at the toe of the mound, m")?;
    let depth_at_wall_m = required(
        "[water] depth_at_wall_m",
        w.depth_at_wall_m,
        "d, the water depth in front of the wall above the berm, m (= depth_at_toe_m without a mound)",
    )?;
    Ok(WaveSite {
        rho_w,
        depth_at_toe_m,
        depth_at_wall_m,
        base_depth_m: 0.0,
        crest_freeboard_m: 0.0,
        width_m: 0.0,
        length_m: 0.0,
        seabed_slope: w.seabed_slope.unwrap_or(0.0),
        berm_width_m: w.berm_width_m,
    })
}

/// `[waves] kind` and the keys that go with it: the trains.
fn train(t: &WavesTable) -> R<TrainSpec> {
    let irregular = pick("[waves] kind", Some(&t.kind), false, &[("regular", false), ("irregular", true)])?;
    let period_s = required("[waves] period_s", t.period_s, "the wave period T (T1/3 for irregular waves), s")?;
    let conflict = |key: &str, kind: &str| ScenarioError::Conflict {
        message: format!("`[waves] {key}` is not used with kind = \"{kind}\"; remove it"),
    };
    let kind = if irregular {
        for (key, given) in [
            ("height_m", t.height_m.is_some()),
            ("height_variability", t.height_variability.is_some()),
            ("height_variability_fraction", t.height_variability_fraction.is_some()),
            ("height_truncation_sigmas", t.height_truncation_sigmas.is_some()),
        ] {
            if given {
                return Err(conflict(key, "irregular"));
            }
        }
        let h = required(
            "[waves] significant_height_m",
            t.significant_height_m,
            "the significant wave height H1/3 at the toe, m",
        )?;
        TrainKind::Irregular { significant_height_m: h }
    } else {
        if t.significant_height_m.is_some() {
            return Err(conflict("significant_height_m", "regular"));
        }
        let height_m = required("[waves] height_m", t.height_m, "the incident wave height H, m")?;
        TrainKind::Regular { height_m, variability: variability(t)? }
    };
    let count = |key: &str, v: Option<i64>, default: usize| -> R<usize> {
        match v {
            None => Ok(default),
            Some(n) if (1..=1_000_000).contains(&n) => Ok(n as usize),
            Some(n) => Err(ScenarioError::range(key, n, "must be a whole number from 1 to 1000000")),
        }
    };
    let waves = count("[waves] waves", t.waves, 15)?;
    let realizations = count("[waves] realizations", t.realizations, 10)?;
    let seed = seed_of("[waves] seed", t.seed)?;
    Ok(TrainSpec { kind, period_s, waves, realizations, seed })
}

/// `[waves] height_variability` and its keys (regular waves).
fn variability(t: &WavesTable) -> R<HeightVariability> {
    let name = t.height_variability.as_ref();
    let which = pick("[waves] height_variability", name, 0, &[("normal", 0), ("uniform", 1), ("none", 2)])?;
    if which == 2 && (t.height_variability_fraction.is_some() || t.height_truncation_sigmas.is_some()) {
        return Err(ScenarioError::Conflict { message: "`[waves] height_variability_fraction` and `height_truncation_sigmas` are not used with height_variability = \"none\"; remove them".into() });
    }
    if which == 1 && t.height_truncation_sigmas.is_some() {
        return Err(ScenarioError::Conflict {
            message: "`[waves] height_truncation_sigmas` is only used with height_variability = \"normal\"; remove it"
                .into(),
        });
    }
    let c = t.height_variability_fraction.unwrap_or(0.2);
    Ok(match which {
        0 => HeightVariability::Normal { cov: c, truncation_sigmas: t.height_truncation_sigmas.unwrap_or(2.0) },
        1 => HeightVariability::Uniform { half_width: c },
        _ => HeightVariability::None,
    })
}

/// The options of the wave-load models (`slope`: the seabed's, for Goda's breaker criterion).
fn options(t: &WavesTable, slope: f64) -> R<WaveLoadOptions> {
    let regime = pick(
        "[waves] regime",
        t.regime.as_ref(),
        RegimeChoice::Auto,
        &[
            ("auto", RegimeChoice::Auto),
            ("breaking", RegimeChoice::Forced(Regime::Breaking)),
            ("non-breaking", RegimeChoice::Forced(Regime::NonBreaking)),
        ],
    )?;
    let criterion = pick(
        "[waves] breaker_criterion",
        t.breaker_criterion.as_ref(),
        BreakerCriterion::Miche,
        &[
            ("miche", BreakerCriterion::Miche),
            ("goda", BreakerCriterion::Goda { a: GODA_BREAKER_A, slope }),
            ("mccowan", BreakerCriterion::McCowan { gamma: MCCOWAN_GAMMA }),
        ],
    )?;
    let load_shape = pick("[waves] load_shape", t.load_shape.as_ref(), LoadShape::Seed, &LoadShape::ALL)?;
    if t.duration_ratio.is_some() && !load_shape.uses_duration() {
        return Err(ScenarioError::Conflict {
            message: format!(
                "`[waves] duration_ratio` is not used with load_shape = \"{}\" (its duration is 2 t_r); remove it or choose \"goda-1994\", \"oumeraci-kortenhaus-1994\" or \"oumeraci-2001\"",
                load_shape.name()
            ),
        });
    }
    let rise_time_model = pick(
        "[waves] rise_time_model",
        t.rise_time_model.as_ref(),
        RiseTimeModel::Median,
        &[("median", RiseTimeModel::Median), ("literal", RiseTimeModel::Literal)],
    )?;
    let sainflou_depth = pick(
        "[waves] sainflou_depth",
        t.sainflou_depth.as_ref(),
        SainflouDepth::Toe,
        &[("toe", SainflouDepth::Toe), ("wall", SainflouDepth::Wall)],
    )?;
    let d = WaveLoadOptions::default();
    WaveLoadOptions {
        regime,
        criterion,
        alpha_max: t.alpha_max.unwrap_or(d.alpha_max),
        a_imp: t.a_imp.unwrap_or(d.a_imp),
        alpha_qs_nonbreaking: t.alpha_qs_nonbreaking.unwrap_or(d.alpha_qs_nonbreaking),
        alpha_qs_breaking: t.alpha_qs_breaking.unwrap_or(d.alpha_qs_breaking),
        rise_time: RiseTimeParams { model: rise_time_model, ..RiseTimeParams::default() },
        load_shape,
        duration_ratio: t.duration_ratio.unwrap_or(d.duration_ratio),
        sainflou_depth,
        ..d
    }
    .with_angle_deg(t.angle_deg.unwrap_or(0.0))
    .map_err(|e| keyed_waves(e.into()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenario::Scenario;
    use std::path::Path;

    const PARI: &str = r#"
[caisson]
width_m = 0.78
length_m = 1.0
height_m = 1.12
base_depth_m = 0.8
weight_in_water_kn = 16.17
[foundation]
e100_kpa = 3.5e5
[water]
depth_at_toe_m = 1.14
depth_at_wall_m = 0.4
[waves]
kind = "regular"
height_m = 0.428
period_s = 3.04
"#;

    fn run(text: &str) -> R<WaveSetup> {
        let s = Scenario::from_toml(text, Path::new("t.toml"), Path::new("."))?;
        s.waves_for("this test").cloned()
    }

    fn key_of(text: &str) -> String {
        match run(text) {
            Err(e) => e.key().map(str::to_string).unwrap_or_else(|| format!("{e}")),
            Ok(_) => panic!("expected an error for\n{text}"),
        }
    }

    #[test]
    fn pari_breaking_scenario_validates() {
        let w = run(PARI).unwrap();
        assert_eq!(w.model.site.crest_freeboard_m, 1.12 - 0.8);
        assert_eq!(w.height_m(), 0.428);
        assert_eq!(w.model.options.load_shape, LoadShape::Seed);
    }

    #[test]
    fn bad_inputs_name_their_key() {
        let cases = [
            ("height_m = 0.428", "height_m = -0.1", "[waves] height_m"),
            ("height_m = 0.428", "height_m = nan", "[waves] height_m"),
            ("height_m = 0.428", "height_m = 5.0", "[waves] height_m"),
            ("period_s = 3.04", "period_s = 0.0", "[waves] period_s"),
            ("period_s = 3.04", "period_s = inf", "[waves] period_s"),
            ("depth_at_wall_m = 0.4", "depth_at_wall_m = 1.5", "[water] depth_at_wall_m"),
            ("depth_at_wall_m = 0.4", "depth_at_wall_m = 0.9", "[caisson] base_depth_m"),
            ("depth_at_toe_m = 1.14", "depth_at_toe_m = 0.3", "[water] depth_at_wall_m"),
            ("depth_at_toe_m = 1.14", "depth_at_toe_m = 0.7", "[caisson] base_depth_m"),
            ("depth_at_wall_m = 0.4", "depth_at_wall_m = 0.4\nberm_width_m = -1.0", "[water] berm_width_m"),
            ("depth_at_wall_m = 0.4", "depth_at_wall_m = 0.4\nseabed_slope = -0.1", "[water] seabed_slope"),
            ("period_s = 3.04", "period_s = 3.04\nregime = \"non-breaking\"", "[waves] regime"),
            ("period_s = 3.04", "period_s = 3.04\nregime = \"sometimes\"", "[waves] regime"),
            ("period_s = 3.04", "period_s = 3.04\nload_shape = \"church\"", "[waves] load_shape"),
            ("period_s = 3.04", "period_s = 3.04\nalpha_max = 0", "[waves] alpha_max"),
            ("period_s = 3.04", "period_s = 3.04\nangle_deg = 90", "[waves] angle_deg"),
            ("kind = \"regular\"", "kind = \"jonswap\"", "[waves] kind"),
            ("height_m = 0.428\n", "", "[waves] height_m"),
            ("depth_at_toe_m = 1.14\n", "", "[water] depth_at_toe_m"),
        ];
        for (from, to, key) in cases {
            let text = PARI.replace(from, to);
            assert_eq!(key_of(&text), key, "{to}");
        }
        let no_waves = &PARI[..PARI.find("[waves]").unwrap()];
        assert_eq!(key_of(no_waves), "[waves]");
        // Unknown key and a key that does nothing with the chosen shape.
        assert!(matches!(
            run(&PARI.replace("period_s = 3.04", "period_s = 3.04\nfoo = 1")),
            Err(ScenarioError::Syntax { .. })
        ));
        assert!(matches!(
            run(&PARI.replace("period_s = 3.04", "period_s = 3.04\nduration_ratio = 3")),
            Err(ScenarioError::Conflict { .. })
        ));
    }

    /// `[waves] breaking_load`: read by name; `"goda-takahashi"` refused without `[water]
    /// berm_width_m`, naming that key and what to add; absent, the profile's rule, which
    /// [`Scenario::with_profile`] changes, while a rule the file gives stays.
    #[test]
    fn the_breaking_load_is_read_and_goda_takahashi_needs_the_berm() {
        let rule = |text: &str| run(text).map(|w| w.model.options.breaking_load);
        let given = |r: &str| PARI.replace("period_s = 3.04", &format!("period_s = 3.04\nbreaking_load = \"{r}\""));
        let berm = |text: &str| text.replace("depth_at_wall_m = 0.4", "depth_at_wall_m = 0.4\nberm_width_m = 0.5");
        assert_eq!(rule(&given("none")), Ok(BreakingLoad::None));
        assert_eq!(rule(&given("cuomo-2010")), Ok(BreakingLoad::Cuomo2010));
        assert_eq!(rule(&berm(&given("goda-takahashi"))), Ok(BreakingLoad::GodaTakahashi));
        match rule(&given("goda-takahashi")) {
            Err(e @ ScenarioError::Missing { .. }) => {
                assert_eq!(e.key(), Some("[water] berm_width_m"));
                let m = e.to_string();
                assert!(m.contains("breaking_load = \"goda-takahashi\"") && m.contains("add `berm_width_m`"), "{m}");
            }
            other => panic!("{other:?}"),
        }
        assert_eq!(key_of(&given("takahashi")), "[waves] breaking_load");
        // The profile's rule where the file gives none, and with_profile follows it.
        let from = |text: &str| Scenario::from_toml(text, Path::new("t.toml"), Path::new(".")).unwrap();
        let of = |s: &Scenario| s.waves.as_ref().unwrap().model.options.breaking_load;
        let default = from(PARI);
        assert_eq!(of(&default), BreakingLoad::for_profile(Profile::Consistent));
        assert_eq!(of(&default.with_profile(Profile::Seed2011).unwrap()), BreakingLoad::Cuomo2010);
        let seed = from(&format!("[model]\nprofile = \"seed-2011\"\n{PARI}"));
        assert_eq!(of(&seed), BreakingLoad::Cuomo2010);
        assert_eq!(
            of(&seed.with_profile(Profile::Consistent).unwrap()),
            BreakingLoad::for_profile(Profile::Consistent)
        );
        let none = from(&given("none"));
        assert_eq!(of(&none.with_profile(Profile::Seed2011).unwrap()), BreakingLoad::None);
    }

    #[test]
    fn options_are_read() {
        let text = PARI.replace(
            "period_s = 3.04",
            "period_s = 3.04\nregime = \"breaking\"\nload_shape = \"oumeraci-2001\"\nduration_ratio = 4\nrise_time_model = \"literal\"\nsainflou_depth = \"wall\"\nalpha_qs_breaking = 0.8\nbreaker_criterion = \"goda\"",
        );
        let o = run(&text).unwrap().model.options;
        assert_eq!(o.load_shape, LoadShape::Oumeraci2001);
        assert_eq!(o.duration_ratio, 4.0);
        assert_eq!(o.rise_time.model, RiseTimeModel::Literal);
        assert_eq!(o.sainflou_depth, SainflouDepth::Wall);
        assert_eq!(o.alpha_qs_breaking, 0.8);
        assert_eq!(o.regime, RegimeChoice::Forced(Regime::Breaking));
        assert!(matches!(o.criterion, BreakerCriterion::Goda { .. }));
    }
}
