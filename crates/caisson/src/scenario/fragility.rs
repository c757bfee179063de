//! `[fragility]`: the storms of a fragility analysis (docs/model.md §7), validated with the wave
//! scenario they act on into [`FragilityParams`]. Every key is documented in `docs/fragility.md`.
//!
//! The rest of the file is a wave scenario (`[caisson]`, `[foundation]`, `[water]`, `[waves]` with
//! kind = "irregular"); `[waves] significant_height_m` is the design wave (reported, not run),
//! and the train keys `waves`, `realizations` and `seed` of `[waves]` are not used (the storms
//! have their own duration and seed), so they are rejected rather than silently ignored.

use super::{design, Scenario, ScenarioError, ScenarioFile};
use crate::analysis::climate::{StormDuration, WaveDirection, WavePeriods};
use crate::analysis::fragility::{FragilityParamError, FragilityParams, MAX_LEVELS, MAX_STORMS_PER_HEIGHT};
use crate::analysis::lifetime::Errors;
use crate::analysis::limits::ROCKING_LIMIT_RAD;
use crate::analysis::site::WaveSetup;
use crate::loads::generator::TrainKind;
use serde::Deserialize;

type R<T> = Result<T, ScenarioError>;

/// `[fragility]` as written.
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct FragilityTable {
    /// The IM grid: H1/3 at the structure, m (> 0, increasing).
    pub significant_heights_m: Option<Vec<f64>>,
    /// Storms per height. Default 200.
    pub storms: Option<i64>,
    /// Sliding limits, m (> 0, increasing). Default [0.1, 0.3].
    pub limits_m: Option<Vec<f64>>,
    /// Duration of a storm, h. Default 2.
    pub storm_duration_h: Option<f64>,
    /// T1/3 of the storms, s. Default `[waves] period_s`.
    pub period_s: Option<f64>,
    /// Seed of the storms' generators. Default 1.
    pub seed: Option<i64>,
    /// A storm that rotates the caisson beyond this counts as exceeding every limit, rad.
    /// Default 0.01 (as `[design] failure_rotation_rad`).
    pub failure_rotation_rad: Option<f64>,
    /// The climate keys of `[design]` that apply to a storm (docs/design.md, "Climate").
    pub storm_duration_model: Option<String>,
    pub storm_duration_cov: Option<f64>,
    pub wave_direction: Option<String>,
    pub wave_direction_mean_deg: Option<f64>,
    pub wave_direction_spread_deg: Option<f64>,
    pub wave_periods: Option<String>,
    pub period_spectral_width: Option<f64>,
    /// Whether the load-model errors of `[design]` are drawn per storm (default true), and their
    /// keys (defaults those of `[design]`).
    pub errors: Option<bool>,
    pub wave_force_bias: Option<f64>,
    pub wave_force_cov: Option<f64>,
    pub friction_bias: Option<f64>,
    pub friction_cov: Option<f64>,
    pub impact_force_bias: Option<f64>,
    pub impact_force_cov: Option<f64>,
    pub error_truncation_sigmas: Option<f64>,
    pub error_truncated: Option<bool>,
}

/// A refused [`FragilityParams`] under its `[fragility]` key, the value as Rust writes it; the
/// climate's quantities and the failure rotation as `[design]`'s are shown.
fn keyed(e: FragilityParamError, duration_h: f64) -> ScenarioError {
    let list = |quantity: &str| match quantity {
        "heights_m" => "[fragility] significant_heights_m".to_string(),
        q => format!("[fragility] {q}"),
    };
    match e {
        FragilityParamError::Empty { quantity } => {
            ScenarioError::range(&list(quantity), "[]", "must list at least one value")
        }
        FragilityParamError::TooMany { quantity, count } => {
            ScenarioError::range(&list(quantity), format!("{count} values"), format!("at most {MAX_LEVELS} values"))
        }
        FragilityParamError::Element { index, error } => ScenarioError::range(
            &format!("{}[{index}]", list(error.quantity)),
            error.value,
            error.allowed.describe(1.0, ""),
        ),
        FragilityParamError::Param(e) => match e.quantity {
            "period_s" | "storms" => ScenarioError::range(&list(e.quantity), e.value, e.allowed.describe(1.0, "s")),
            // Shown in hours, as read (the rule's bounds in seconds, shown in hours).
            "storm_duration_s" => {
                ScenarioError::range("[fragility] storm_duration_h", duration_h, e.allowed.describe(1.0 / 3600.0, "h"))
            }
            _ => super::design::keyed("[fragility]", e),
        },
    }
}

/// Read `[fragility]` for the validated rest of the file `sc` into [`FragilityParams`], whose
/// constructor checks the values ([`FragilityParams::checked`]).
pub(super) fn validate_fragility(file: &ScenarioFile, sc: &Scenario) -> R<FragilityParams> {
    let t = file.fragility.as_ref().ok_or_else(|| {
        ScenarioError::missing(
            "[fragility]",
            "add a [fragility] table with significant_heights_m (and storms, limits_m, ...)",
        )
    })?;
    let waves = storm_waves(file, sc)?;
    let heights = t.significant_heights_m.as_ref().ok_or_else(|| {
        ScenarioError::missing(
            "[fragility] significant_heights_m",
            "the grid of H1/3 at the structure, m, increasing (e.g. [3, 4, 5, 6, 7])",
        )
    })?;
    let storms = match t.storms {
        None => 200,
        Some(n) if (1..=MAX_STORMS_PER_HEIGHT as i64).contains(&n) => n as usize,
        Some(n) => {
            return Err(ScenarioError::range(
                "[fragility] storms",
                n,
                format!("must be a whole number from 1 to {MAX_STORMS_PER_HEIGHT}"),
            ))
        }
    };
    let duration_h = t.storm_duration_h.unwrap_or(2.0);
    let params = FragilityParams {
        heights_m: heights.clone(),
        storms,
        limits_m: t.limits_m.clone().unwrap_or_else(|| vec![0.1, 0.3]),
        storm_duration_s: duration_h * 3600.0,
        period_s: t.period_s.unwrap_or_else(|| waves.period_s()),
        seed: super::waves::seed_of("[fragility] seed", t.seed)?,
        failure_rotation_rad: t.failure_rotation_rad.unwrap_or(ROCKING_LIMIT_RAD),
        duration: StormDuration::Fixed,
        direction: WaveDirection::HeadOn,
        periods: WavePeriods::Significant,
        errors: errors(t)?,
    };
    Ok(FragilityParams {
        duration: design::duration_model("[fragility]", &t.storm_duration_model, t.storm_duration_cov)?,
        direction: design::direction(
            "[fragility]",
            &t.wave_direction,
            t.wave_direction_mean_deg,
            t.wave_direction_spread_deg,
        )?,
        periods: design::wave_periods("[fragility]", &t.wave_periods, t.period_spectral_width)?,
        ..params.checked().map_err(|e| keyed(e, duration_h))?
    })
}

/// The load-model errors of `[fragility]` (the keys of `[design]`, docs/fragility.md), or `None`
/// with `errors = false` (then none of their keys may be given).
fn errors(t: &FragilityTable) -> R<Option<Errors>> {
    let given = [
        ("wave_force_bias", t.wave_force_bias.is_some()),
        ("wave_force_cov", t.wave_force_cov.is_some()),
        ("friction_bias", t.friction_bias.is_some()),
        ("friction_cov", t.friction_cov.is_some()),
        ("impact_force_bias", t.impact_force_bias.is_some()),
        ("impact_force_cov", t.impact_force_cov.is_some()),
        ("error_truncation_sigmas", t.error_truncation_sigmas.is_some()),
        ("error_truncated", t.error_truncated.is_some()),
    ];
    if !t.errors.unwrap_or(true) {
        if let Some((key, _)) = given.iter().find(|(_, g)| *g) {
            return Err(ScenarioError::Conflict {
                message: format!("`[fragility] {key}` is not used with errors = false (no load-model errors drawn); remove one of them"),
            });
        }
        return Ok(None);
    }
    let keys = design::DesignTable {
        wave_force_bias: t.wave_force_bias,
        wave_force_cov: t.wave_force_cov,
        friction_bias: t.friction_bias,
        friction_cov: t.friction_cov,
        impact_force_bias: t.impact_force_bias,
        impact_force_cov: t.impact_force_cov,
        error_truncation_sigmas: t.error_truncation_sigmas,
        error_truncated: t.error_truncated,
        ..design::DesignTable::default()
    };
    design::errors("[fragility]", &keys).map(Some)
}

/// The irregular waves of `sc` the storms take their site and period from: no `[load]` or
/// `[campaign]`, and none of `[waves]`'s train keys (the storms have their own).
fn storm_waves<'a>(file: &ScenarioFile, sc: &'a Scenario) -> R<&'a WaveSetup> {
    if file.load.is_some() {
        return Err(ScenarioError::Conflict {
            message: "a fragility runs storms of waves from [waves]; remove the [load] table".into(),
        });
    }
    if file.campaign.is_some() {
        return Err(ScenarioError::Conflict {
            message: "a fragility file cannot hold a [campaign] table; run the campaign from its own file".into(),
        });
    }
    let wt = file.waves.as_ref().ok_or_else(|| {
        ScenarioError::missing(
            "[waves]",
            "a fragility needs a [waves] table with kind = \"irregular\", significant_height_m and period_s",
        )
    })?;
    for (key, given) in
        [("waves", wt.waves.is_some()), ("realizations", wt.realizations.is_some()), ("seed", wt.seed.is_some())]
    {
        if given {
            return Err(ScenarioError::Conflict {
                message: format!("`[waves] {key}` is not used by a fragility (storms have [fragility] storm_duration_h, storms and seed); remove it"),
            });
        }
    }
    let waves = sc.waves_for("a fragility")?;
    if !matches!(waves.train.kind, TrainKind::Irregular { .. }) {
        return Err(ScenarioError::range(
            "[waves] kind",
            format!("\"{}\"", wt.kind),
            "must be \"irregular\" for a fragility (storms of Rayleigh waves of the given H1/3)",
        ));
    }
    Ok(waves)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::Path;

    const BASE: &str = r#"
[caisson]
width_m = 20.0
height_m = 22.0
base_depth_m = 16.0
weight_in_water_kn = 5850.0
[foundation]
e100_kpa = 3.5e5
[water]
density_kg_per_m3 = 1025.0
depth_at_toe_m = 20.0
depth_at_wall_m = 14.0
[waves]
kind = "irregular"
significant_height_m = 7.5
period_s = 12.0
[fragility]
significant_heights_m = [4.0, 6.0, 8.0]
"#;

    fn run(text: &str) -> R<FragilityParams> {
        Scenario::from_toml(text, Path::new("f.toml"), Path::new("."))?.fragility_for("this test").cloned()
    }

    fn key_of(text: &str) -> String {
        match run(text) {
            Err(e) => e.key().map(str::to_string).unwrap_or_else(|| format!("{e}")),
            Ok(_) => panic!("expected an error for\n{text}"),
        }
    }

    #[test]
    fn defaults() {
        let p = run(BASE).unwrap();
        assert_eq!(
            p,
            FragilityParams {
                heights_m: vec![4.0, 6.0, 8.0],
                storms: 200,
                limits_m: vec![0.1, 0.3],
                storm_duration_s: 7200.0,
                period_s: 12.0,
                seed: 1,
                failure_rotation_rad: 0.01,
                duration: crate::analysis::climate::StormDuration::Fixed,
                direction: crate::analysis::climate::WaveDirection::HeadOn,
                periods: crate::analysis::climate::WavePeriods::Significant,
                // On by default: the wave force's, the friction's and the impulsive component's
                // errors of [design] (Errors::default: bias −0.09 COV 0.10; 0, 0.10; truncated at 2σ).
                errors: Some(Errors::default()),
            }
        );
        assert_eq!(p.waves_per_storm(), 600);
        // Off, and its keys refused with it; a key given sets that error, named in a refusal.
        assert_eq!(run(&BASE.replace("[4.0, 6.0, 8.0]", "[4.0, 6.0, 8.0]\nerrors = false")).unwrap().errors, None);
        let e = run(&BASE.replace("[4.0, 6.0, 8.0]", "[4.0, 6.0, 8.0]\nerrors = false\nfriction_cov = 0.2"));
        assert!(e.unwrap_err().to_string().contains("[fragility] friction_cov"));
        let given = run(&BASE.replace("[4.0, 6.0, 8.0]", "[4.0, 6.0, 8.0]\nimpact_force_cov = 0.3")).unwrap();
        assert_eq!(given.errors.unwrap().impact_force.map(|m| (m.bias, m.cov)), Some((-0.09, 0.3)));
        let e = run(&BASE.replace("[4.0, 6.0, 8.0]", "[4.0, 6.0, 8.0]\nwave_force_cov = 1.5"));
        assert!(e.unwrap_err().to_string().contains("[fragility] wave_force_cov"));
        let text = BASE.replace(
            "[4.0, 6.0, 8.0]",
            "[4.0, 6.0]\nstorms = 7\nlimits_m = [0.05]\nstorm_duration_h = 1.5\nperiod_s = 10.0\nseed = 9\nfailure_rotation_rad = 0.02",
        );
        let p = run(&text).unwrap();
        assert_eq!(
            (p.storms, p.limits_m.clone(), p.storm_duration_s, p.period_s, p.seed, p.waves_per_storm()),
            (7, vec![0.05], 5400.0, 10.0, 9, 540)
        );
        assert_eq!(p.failure_rotation_rad, 0.02);
    }

    #[test]
    fn bad_inputs_name_their_key() {
        let h = "significant_heights_m = [4.0, 6.0, 8.0]";
        let cases = [
            (h, "significant_heights_m = []", "[fragility] significant_heights_m"),
            (h, "significant_heights_m = [4.0, -6.0]", "[fragility] significant_heights_m[1]"),
            (h, "significant_heights_m = [4.0, 4.0]", "[fragility] significant_heights_m[1]"),
            (h, "significant_heights_m = [4.0, nan]", "[fragility] significant_heights_m[1]"),
            (h, "significant_heights_m = [4.0, 40.0]", "[fragility] significant_heights_m[1]"),
            (h, "", "[fragility] significant_heights_m"),
            (h, "significant_heights_m = [4.0]\nstorms = 0", "[fragility] storms"),
            (h, "significant_heights_m = [4.0]\nstorms = 2000000", "[fragility] storms"),
            (h, "significant_heights_m = [4.0, 6.0, 8.0, 9.0, 10.0, 11.0, 12.0, 13.0, 14.0, 15.0, 16.0]\nstorms = 1000000", "[fragility] storms"),
            (h, "significant_heights_m = [4.0]\nlimits_m = [0.3, 0.1]", "[fragility] limits_m[1]"),
            (h, "significant_heights_m = [4.0]\nlimits_m = [0.0]", "[fragility] limits_m[0]"),
            (h, "significant_heights_m = [4.0]\nlimits_m = []", "[fragility] limits_m"),
            (h, "significant_heights_m = [4.0]\nstorm_duration_h = 0", "[fragility] storm_duration_h"),
            (h, "significant_heights_m = [4.0]\nperiod_s = -1", "[fragility] period_s"),
            (h, "significant_heights_m = [4.0]\nseed = -1", "[fragility] seed"),
            (h, "significant_heights_m = [4.0]\nfailure_rotation_rad = 0.0", "[fragility] failure_rotation_rad"),
            (h, "significant_heights_m = [4.0]\nfailure_rotation_rad = 0.2", "[fragility] failure_rotation_rad"),
            (h, "significant_heights_m = [4.0]\nfailure_rotation_rad = nan", "[fragility] failure_rotation_rad"),
            ("kind = \"irregular\"\nsignificant_height_m = 7.5", "kind = \"regular\"\nheight_m = 7.5", "[waves] kind"),
        ];
        for (from, to, key) in cases {
            assert!(BASE.contains(from));
            assert_eq!(key_of(&BASE.replace(from, to)), key, "{to}");
        }
        assert_eq!(key_of(&BASE.replace("[fragility]\n", "").replace(h, "")), "[fragility]");
        assert!(matches!(
            run(&BASE.replace(h, "significant_heights_m = [4.0]\nfoo = 1")),
            Err(ScenarioError::Syntax { .. })
        ));
        assert!(matches!(
            run(&BASE.replace("period_s = 12.0", "period_s = 12.0\nseed = 3")),
            Err(ScenarioError::Conflict { .. })
        ));
        assert!(matches!(
            run(&BASE.replace("period_s = 12.0", "period_s = 12.0\nwaves = 3")),
            Err(ScenarioError::Conflict { .. })
        ));
    }
}
