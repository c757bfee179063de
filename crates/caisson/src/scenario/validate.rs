//! Validation of a parsed [`ScenarioFile`] into a typed [`Scenario`]: the raw tables are read
//! into the parameter types of the modules that own them (converted to SI), which check their
//! own ranges; this module checks what only the file knows (missing keys, keys that do not go
//! together, names of choices, whole numbers) and names the key of every error. A value given in
//! kN or kPa is refused when not positive in the file's unit, before it is converted to SI (the
//! types check their own, wider ranges after).

use super::{
    campaign, coherence, design, fragility, keyed, size, waves, Scenario, ScenarioError, ScenarioFile, CAISSON_KEYS,
    FOUNDATION_KEYS, LOAD_KEYS, SOLVER_KEYS,
};
use crate::analysis::Structure;
use crate::dynamics::{Accel, AdaptiveParams, SolverParams};
use crate::foundation::{AddedMassSpec, DampingMode, FoundationSpec, Soil, VerticalDamping};
use crate::loads::pulse::{StaticRamp, TrianglePulse};
use crate::loads::series::ForceSeries;
use crate::loads::{LoadSpec, WaveForce};
use crate::structure::{Caisson, CaissonSpec, Construction, MassMatrix, MassSpec};
use crate::Profile;
use std::path::Path;

type R<T> = Result<T, ScenarioError>;

pub(super) fn positive(key: &str, v: f64, unit: &str) -> R<f64> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(ScenarioError::range(key, super::fmt_value(v), format!("must be a finite number > 0 ({unit})")))
    }
}

fn within(key: &str, v: f64, lo: f64, hi: f64, unit: &str) -> R<f64> {
    if v.is_finite() && v >= lo && v <= hi {
        Ok(v)
    } else {
        let (lo, hi) = (crate::fmt_number(lo), crate::fmt_number(hi));
        Err(ScenarioError::range(key, super::fmt_value(v), format!("must be between {lo} and {hi} ({unit})")))
    }
}

/// A whole number of the file as a count (a negative number is out of range).
fn whole(key: &str, v: i64, lo: i64, hi: i64) -> R<usize> {
    if (lo..=hi).contains(&v) {
        Ok(v as usize)
    } else {
        Err(ScenarioError::range(key, v, format!("must be a whole number from {lo} to {hi}")))
    }
}

pub(super) fn choice<T: Copy>(key: &str, v: &str, options: &[(&str, T)]) -> R<T> {
    options.iter().find(|(name, _)| *name == v).map(|(_, t)| *t).ok_or_else(|| {
        let names: Vec<String> = options.iter().map(|(n, _)| format!("\"{n}\"")).collect();
        ScenarioError::range(key, format!("\"{v}\""), format!("must be one of {}", names.join(", ")))
    })
}

/// Validate a parsed scenario. `base_dir` resolves relative file names (the series CSV).
pub(super) fn validate(f: &ScenarioFile, base_dir: &Path) -> R<Scenario> {
    let rho_w = match f.water.density_kg_per_m3 {
        Some(v) => within("[water] density_kg_per_m3", v, 500.0, 2000.0, "kg/m³")?,
        None => 1000.0,
    };
    let profile = match &f.model.profile {
        Some(p) => choice("[model] profile", p, &Profile::ALL)?,
        None => Profile::default(),
    };
    let caisson_spec = caisson_spec(f)?;
    let caisson = caisson_spec.build(rho_w, profile).map_err(|e| keyed("[caisson]", CAISSON_KEYS, e))?;
    let foundation_spec = foundation_spec(f)?;
    let foundation =
        foundation_spec.build(&caisson, rho_w, profile).map_err(|e| keyed("[foundation]", FOUNDATION_KEYS, e))?;
    let (wave_setup, breaking_load) = match f.waves {
        Some(_) => {
            let (w, given) = waves::validate_waves(f, &caisson, rho_w, profile)?;
            (Some(w), given)
        }
        None => (None, None),
    };
    if let Some(w) = &wave_setup {
        coherence::check_waves(&caisson, w)?;
    }
    let (load, duration_s) = load_and_duration(f, &caisson, wave_setup.as_ref(), base_dir)?;
    let solver = validate_solver(f, duration_s)?.for_profile(profile);
    let sc = Scenario {
        profile,
        water_density_kg_per_m3: rho_w,
        caisson_spec,
        foundation_spec,
        structure: Structure { caisson, foundation, solver, profile },
        load,
        duration_s,
        waves: wave_setup,
        breaking_load,
        campaign: None,
        design: None,
        fragility: None,
        fragility_refused: None,
        campaign_refused: None,
        size: None,
        size_refused: None,
    };
    coherence::check_time_step(&sc.structure)?;
    with_studies(f, sc)
}

/// The `[load]` of the file (checked against the caisson) and the simulated time of a run:
/// `[load] duration_s`, or the load's own (a wave-train scenario: its waves of its period; 1 s
/// without waves).
fn load_and_duration(
    f: &ScenarioFile,
    caisson: &Caisson,
    waves: Option<&crate::analysis::site::WaveSetup>,
    base_dir: &Path,
) -> R<(Option<LoadSpec>, f64)> {
    let (load, default_duration) = match &f.load {
        Some(_) => {
            let (l, d) = validate_load(f, caisson, base_dir)?;
            coherence::check_load(caisson, &l)?;
            (Some(l), d)
        }
        None => (None, waves.map_or(1.0, |w| w.train.waves as f64 * w.train.period_s)),
    };
    let duration_s = match f.load.as_ref().and_then(|l| l.duration_s) {
        Some(v) => positive("[load] duration_s", v, "s")?,
        None => default_duration,
    };
    Ok((load, duration_s))
}

/// The scenario with the studies of the file: `[campaign]`, `[design]`, `[fragility]`, `[size]`.
fn with_studies(f: &ScenarioFile, mut sc: Scenario) -> R<Scenario> {
    // A `[campaign]`, `[fragility]` or `[size]` table is refused only when its command asks for
    // it: a `run` or `loads` of the same file is not told to remove its `[load]`, or to add a
    // `[design]`, for another command's sake.
    if f.campaign.is_some() {
        match campaign_of(f, &sc) {
            Ok(spec) => sc.campaign = Some(spec),
            Err(e) => sc.campaign_refused = Some(e),
        }
    }
    if f.design.is_some() {
        let d = design::validate_design(f)?;
        coherence::check_floating(sc.caisson(), sc.water_density_kg_per_m3, &d)?;
        sc.design = Some(d);
    }
    if f.fragility.is_some() {
        match fragility::validate_fragility(f, &sc) {
            Ok(p) => sc.fragility = Some(p),
            Err(e) => sc.fragility_refused = Some(e),
        }
    }
    if f.size.is_some() {
        let size = sc
            .design
            .as_ref()
            .map(|d| (d.lives, d.auto))
            .ok_or_else(|| {
                ScenarioError::missing("[design]", "a [size] table sizes a design: add the [design] table it runs")
            })
            .and_then(|lives| size::validate_size(f, lives));
        match size {
            Ok(size) => {
                // The lifetime heel pressures of a sizing are held to `[size]
                // allowable_heel_pressure_kpa` where `[design]` gives no allowable of its own
                // (docs/size.md).
                let design_gives = f.design.as_ref().is_some_and(|t| t.allowable_heel_pressure_kpa.is_some());
                if let (Some(d), false) = (sc.design.as_mut(), design_gives) {
                    d.allowable_heel_pressure_pa = size.conventional.allowable_heel_pressure_pa;
                }
                sc.size = Some(size);
            }
            Err(e) => sc.size_refused = Some(e),
        }
    }
    Ok(sc)
}

/// The `[campaign]` of the file, every condition built on the rest of the scenario `sc`.
fn campaign_of(f: &ScenarioFile, sc: &Scenario) -> R<campaign::CampaignSpec> {
    if sc.caisson_spec.construction().is_some() {
        return Err(ScenarioError::Conflict {
            message: "a campaign gives the caisson's weight in water in each condition (`[campaign] weights_in_water_kn` or `weight_in_water_kn` of its conditions), which would replace the construction of `[caisson]` (`wall_thickness_m`, ...): give the caisson by its weight in water instead".into(),
        });
    }
    let spec = campaign::validate_campaign(f)?;
    // Every condition must build (its height, weight and regime on this scenario).
    campaign::build(sc, &spec)?;
    Ok(spec)
}

fn caisson_spec(f: &ScenarioFile) -> R<CaissonSpec> {
    let c = &f.caisson;
    let required = |key: &str, v: Option<f64>, hint: &str| v.ok_or_else(|| ScenarioError::missing(key, hint));
    let width_m =
        required("[caisson] width_m", c.width_m, "B, the base width in the wave direction, m (a finite number > 0)")?;
    let height_m =
        required("[caisson] height_m", c.height_m, "the caisson height, base to crest, m (a finite number > 0)")?;
    let base_depth_m = required(
        "[caisson] base_depth_m",
        c.base_depth_m,
        "h', the depth of the base below still water, m (from 0 to height_m)",
    )?;
    let mass = match construction(c)? {
        Some(built) => MassSpec::Construction(built),
        None => weight_or_mass(c)?,
    };
    let mass_matrix = match &c.mass_matrix {
        Some(s) => Some(choice(
            "[caisson] mass_matrix",
            s,
            &[("coupled", MassMatrix::Coupled), ("diagonal", MassMatrix::Diagonal)],
        )?),
        None => None,
    };
    Ok(CaissonSpec {
        width_m,
        length_m: c.length_m.unwrap_or(1.0),
        height_m,
        base_depth_m,
        mass,
        cog_height_m: c.cog_height_m,
        inertia_cog_kg_m2: c.inertia_kg_m2,
        mass_matrix,
    })
}

/// The weight route of `[caisson]`: the weight in water, the mass in air, or both.
fn weight_or_mass(c: &super::CaissonTable) -> R<MassSpec> {
    // Forces are converted from kN here: check them in the file's unit first.
    let weight = |w: f64| positive("[caisson] weight_in_water_kn", w, "kN").map(|w| w * 1e3);
    Ok(match (c.weight_in_water_kn, c.mass_kg) {
        (None, None) => {
            return Err(ScenarioError::missing(
                "[caisson] weight_in_water_kn",
                "give the weight in water (kN) or the mass in air `mass_kg`, or both; or the construction (`wall_thickness_m`, `slab_thickness_m`, cells, densities: docs/scenario.md)",
            ))
        }
        (Some(w), None) => MassSpec::WeightInWater { weight_in_water_n: weight(w)? },
        (None, Some(m)) => MassSpec::MassInAir { mass_kg: m },
        (Some(w), Some(m)) => {
            positive("[caisson] mass_kg", m, "kg")?;
            MassSpec::Both { mass_kg: m, weight_in_water_n: weight(w)? }
        }
    })
}

/// The construction route of `[caisson]` (docs/model.md §8.4), if any of its keys is given. It
/// excludes the weight route (`weight_in_water_kn`, `mass_kg`) and the keys it computes
/// (`cog_height_m`, `inertia_kg_m2`). Ranges and fits are checked by the [`Construction`] when the
/// caisson is built.
fn construction(c: &super::CaissonTable) -> R<Option<Construction>> {
    let keys = [
        ("wall_thickness_m", c.wall_thickness_m.is_some()),
        ("slab_thickness_m", c.slab_thickness_m.is_some()),
        ("partition_thickness_m", c.partition_thickness_m.is_some()),
        ("cells_across", c.cells_across.is_some()),
        ("cells_along", c.cells_along.is_some()),
        ("unit_length_m", c.unit_length_m.is_some()),
        ("cap_height_m", c.cap_height_m.is_some()),
        ("concrete_density_kg_per_m3", c.concrete_density_kg_per_m3.is_some()),
        ("cap_density_kg_per_m3", c.cap_density_kg_per_m3.is_some()),
        ("fill_density_kg_per_m3", c.fill_density_kg_per_m3.is_some()),
        ("fill_density_above_water_kg_per_m3", c.fill_density_above_water_kg_per_m3.is_some()),
    ];
    let Some(first) = keys.iter().find(|(_, given)| *given).map(|(k, _)| *k) else {
        return Ok(None);
    };
    not_with_construction(c, first)?;
    let required = |key: &str, v: Option<f64>, hint: &str| v.ok_or_else(|| ScenarioError::missing(key, hint));
    let wall = required(
        "[caisson] wall_thickness_m",
        c.wall_thickness_m,
        "the thickness of the outer walls, m, for a caisson given by its construction (or give `weight_in_water_kn` instead)",
    )?;
    let slab = required(
        "[caisson] slab_thickness_m",
        c.slab_thickness_m,
        "the thickness of the base slab, m, for a caisson given by its construction (or give `weight_in_water_kn` instead)",
    )?;
    let (across, along, partition_thickness_m) = cells(c)?;
    let d = Construction::new(wall, slab);
    Ok(Some(Construction {
        partition_thickness_m,
        cells_across: across,
        cells_along: along,
        unit_length_m: c.unit_length_m,
        cap_height_m: c.cap_height_m.unwrap_or(d.cap_height_m),
        concrete_density_kg_per_m3: c.concrete_density_kg_per_m3.unwrap_or(d.concrete_density_kg_per_m3),
        cap_density_kg_per_m3: c.cap_density_kg_per_m3.unwrap_or(d.cap_density_kg_per_m3),
        fill_density_kg_per_m3: c.fill_density_kg_per_m3.unwrap_or(d.fill_density_kg_per_m3),
        fill_density_above_water_kg_per_m3: c
            .fill_density_above_water_kg_per_m3
            .unwrap_or(d.fill_density_above_water_kg_per_m3),
        ..d
    }))
}

/// The cells of a construction (across, along; 1 by default) and the thickness of their
/// partitions, m (given exactly when there is more than one cell).
fn cells(c: &super::CaissonTable) -> R<(usize, usize, f64)> {
    let count = |key: &str, v: Option<i64>| match v {
        Some(n) => whole(&format!("[caisson] {key}"), n, 1, 100),
        None => Ok(1),
    };
    let (across, along) = (count("cells_across", c.cells_across)?, count("cells_along", c.cells_along)?);
    let partition_thickness_m = match (c.partition_thickness_m, across > 1 || along > 1) {
        (Some(t), true) => t,
        (None, true) => {
            return Err(ScenarioError::missing(
                "[caisson] partition_thickness_m",
                format!("the thickness of the partition walls between the {across} × {along} cells, m"),
            ))
        }
        (Some(_), false) => {
            return Err(ScenarioError::Conflict {
                message: "`[caisson] partition_thickness_m` is given but the caisson has one cell (`cells_across` = `cells_along` = 1): remove it, or give the number of cells".into(),
            })
        }
        (None, false) => 0.0,
    };
    Ok((across, along, partition_thickness_m))
}

/// Refuse the keys of the weight route, and the keys the construction computes, beside a
/// construction key (`first`, the first given).
fn not_with_construction(c: &super::CaissonTable, first: &str) -> R<()> {
    for (key, given) in [("weight_in_water_kn", c.weight_in_water_kn.is_some()), ("mass_kg", c.mass_kg.is_some())] {
        if given {
            return Err(ScenarioError::Conflict {
                message: format!(
                    "`[caisson] {key}` and `[caisson] {first}` are two routes to the caisson's weight: give the weight in water (or the mass), or the construction (wall and slab thicknesses, cells, densities), not both"
                ),
            });
        }
    }
    for (key, given) in [("cog_height_m", c.cog_height_m.is_some()), ("inertia_kg_m2", c.inertia_kg_m2.is_some())] {
        if given {
            return Err(ScenarioError::Conflict {
                message: format!(
                    "`[caisson] {key}` is computed from the construction (`[caisson] {first}`, ...); remove it, or give the caisson by its weight in water"
                ),
            });
        }
    }
    Ok(())
}

fn foundation_spec(f: &ScenarioFile) -> R<FoundationSpec> {
    let t = &f.foundation;
    let d = FoundationSpec::default();
    let kilo = |key: &str, v: Option<f64>, unit: &str, allow_zero: bool| -> R<Option<f64>> {
        match v {
            None => Ok(None),
            Some(v) if allow_zero && v.is_finite() && v >= 0.0 => Ok(Some(v * 1e3)),
            Some(v) if allow_zero => Err(ScenarioError::range(
                &format!("[foundation] {key}"),
                super::fmt_value(v),
                format!("must be a finite number ≥ 0 ({unit})"),
            )),
            Some(v) => positive(&format!("[foundation] {key}"), v, unit).map(|v| Some(v * 1e3)),
        }
    };
    let soil = soil(t)?;
    let spec = FoundationSpec {
        springs: match t.springs {
            Some(v) => whole("[foundation] springs", v, 2, 1000)?,
            None => d.springs,
        },
        mu_static: t.mu_static.unwrap_or(d.mu_static),
        mu_dynamic: t.mu_dynamic,
        soil,
        kx_n_per_m: kilo("kx_kn_per_m", t.kx_kn_per_m, "kN/m", false)?,
        ky_n_per_m: kilo("ky_kn_per_m", t.ky_kn_per_m, "kN/m", false)?,
        damping_ns_per_m: kilo("damping_kns_per_m", t.damping_kns_per_m, "kN·s/m", true)?,
        vertical_damping_factor: t.vertical_damping_factor.unwrap_or(d.vertical_damping_factor),
        damping_mode: match &t.damping_mode {
            Some(s) => Some(choice(
                "[foundation] damping_mode",
                s,
                &[("total", DampingMode::Total), ("elastic", DampingMode::Elastic)],
            )?),
            None => d.damping_mode,
        },
        vertical_damping: match &t.vertical_damping {
            Some(s) => Some(choice(
                "[foundation] vertical_damping",
                s,
                &[("seed", VerticalDamping::Seed), ("springs", VerticalDamping::Springs)],
            )?),
            None => d.vertical_damping,
        },
        added_mass: if t.added_mass.unwrap_or(true) {
            AddedMassSpec::Westergaard { depth_m: t.added_mass_depth_m }
        } else {
            if t.added_mass_depth_m.is_some() {
                return Err(ScenarioError::Conflict {
                    message: "`[foundation] added_mass_depth_m` is given but `added_mass = false`".into(),
                });
            }
            AddedMassSpec::Off
        },
    };
    stiffness_or_soil(&spec)?;
    Ok(spec)
}

/// The soil route of `[foundation]` (`e100_kpa` and its companions), if given.
fn soil(t: &super::FoundationTable) -> R<Option<Soil>> {
    Ok(match t.e100_kpa {
        Some(e) => Some(Soil {
            e100_pa: positive("[foundation] e100_kpa", e, "kPa")? * 1e3,
            poisson: t.poisson.unwrap_or(0.33),
            density_kg_per_m3: t.density_kg_per_m3.unwrap_or(2300.0),
            reference_stress_pa: match t.reference_stress_kpa {
                Some(v) => positive("[foundation] reference_stress_kpa", v, "kPa")? * 1e3,
                None => 1e5,
            },
        }),
        None => {
            for (key, v) in [
                ("poisson", t.poisson),
                ("density_kg_per_m3", t.density_kg_per_m3),
                ("reference_stress_kpa", t.reference_stress_kpa),
            ] {
                if v.is_some() {
                    return Err(ScenarioError::Conflict {
                        message: format!(
                            "`[foundation] {key}` is part of the soil route and needs `[foundation] e100_kpa`"
                        ),
                    });
                }
            }
            None
        }
    })
}

/// Without the soil, each of the stiffnesses and the damping must be given.
fn stiffness_or_soil(spec: &FoundationSpec) -> R<()> {
    if spec.soil.is_none() {
        for (key, given) in [
            ("kx_kn_per_m", spec.kx_n_per_m),
            ("ky_kn_per_m", spec.ky_n_per_m),
            ("damping_kns_per_m", spec.damping_ns_per_m),
        ] {
            if given.is_none() {
                return Err(ScenarioError::missing(
                    &format!("[foundation] {key}"),
                    "give the soil (`e100_kpa`, optional `poisson`, `density_kg_per_m3`) or all of `kx_kn_per_m`, `ky_kn_per_m`, `damping_kns_per_m`",
                ));
            }
        }
    }
    Ok(())
}

/// The keys of each `[load] kind` (any other key given is refused).
const LOAD_KINDS: [(&str, &[&str]); 3] = [
    (
        "triangle",
        &[
            "peak_horizontal_kn",
            "rise_time_s",
            "peak_uplift_kn",
            "horizontal_lever_m",
            "uplift_lever_m",
            "start_time_s",
        ],
    ),
    ("static", &["peak_horizontal_kn", "ramp_time_s", "peak_uplift_kn", "horizontal_lever_m", "uplift_lever_m"]),
    ("series", &["file"]),
];

/// `[load]`: its kind, the keys that go with it, and the load ([`TrianglePulse::new`],
/// [`StaticRamp::new`], a [`ForceSeries`]) with its own duration, s.
fn validate_load(f: &ScenarioFile, c: &Caisson, base_dir: &Path) -> R<(LoadSpec, f64)> {
    let t = f.load.as_ref().expect("checked by caller");
    let kind_name = t
        .kind
        .as_deref()
        .ok_or_else(|| ScenarioError::missing("[load] kind", "one of \"triangle\", \"static\", \"series\""))?;
    let kinds: Vec<(&str, usize)> = LOAD_KINDS.iter().enumerate().map(|(i, (n, _))| (*n, i)).collect();
    let kind = choice("[load] kind", kind_name, &kinds)?;
    only_keys_of(t, kind_name, LOAD_KINDS[kind].1)?;
    let load_err = |e| keyed("[load]", LOAD_KEYS, e);
    Ok(match kind {
        0 => {
            let rise_s = t.rise_time_s.ok_or_else(|| {
                ScenarioError::missing("[load] rise_time_s", "the rise time t_r of the triangular pulse, s")
            })?;
            let pulse = TrianglePulse::new(peak(t, c)?, rise_s, t.start_time_s.unwrap_or(0.0)).map_err(load_err)?;
            (LoadSpec::Triangle(pulse), pulse.start_s + 2.0 * pulse.rise_s + 1.0)
        }
        1 => {
            let ramp = StaticRamp::new(peak(t, c)?, t.ramp_time_s.unwrap_or(1.0)).map_err(load_err)?;
            (LoadSpec::Static(ramp), ramp.ramp_s)
        }
        _ => {
            let name = t.file.as_ref().ok_or_else(|| {
                ScenarioError::missing("[load] file", "the CSV force series, relative to the scenario file")
            })?;
            let path = base_dir.join(name);
            let text = read_series(&path).map_err(|message| ScenarioError::Series { path: path.clone(), message })?;
            let series = ForceSeries::from_csv_str(&text, c.width_m)
                .map_err(|e| ScenarioError::Series { path: path.clone(), message: e.to_string() })?;
            let end = series.last_time_s();
            (LoadSpec::Series(series), end)
        }
    })
}

/// Refuse a key of `[load]` that its kind (`kind_name`, whose keys are `relevant`) does not use.
fn only_keys_of(t: &super::LoadTable, kind_name: &str, relevant: &[&str]) -> R<()> {
    let given = [
        ("peak_horizontal_kn", t.peak_horizontal_kn.is_some()),
        ("rise_time_s", t.rise_time_s.is_some()),
        ("peak_uplift_kn", t.peak_uplift_kn.is_some()),
        ("horizontal_lever_m", t.horizontal_lever_m.is_some()),
        ("uplift_lever_m", t.uplift_lever_m.is_some()),
        ("start_time_s", t.start_time_s.is_some()),
        ("ramp_time_s", t.ramp_time_s.is_some()),
        ("file", t.file.is_some()),
    ];
    for (key, present) in given {
        if present && !relevant.contains(&key) {
            return Err(ScenarioError::Conflict {
                message: format!(
                    "`[load] {key}` is not used with kind = \"{}\"; remove it (keys for this kind: {})",
                    kind_name,
                    relevant.join(", ")
                ),
            });
        }
    }
    Ok(())
}

/// The peak of a pulse of `[load]` on caisson `c` ([`WaveForce::from_levers_on`]): the forces in
/// kN, the levers by default at the base depth and two thirds of the width from the heel.
fn peak(t: &super::LoadTable, c: &Caisson) -> R<WaveForce> {
    let fx_kn = t.peak_horizontal_kn.ok_or_else(|| {
        ScenarioError::missing("[load] peak_horizontal_kn", "the peak horizontal force, kN (positive shoreward)")
    })?;
    let fy_kn = t.peak_uplift_kn.unwrap_or(0.0);
    let lever = t.horizontal_lever_m.unwrap_or(c.base_depth_m);
    let uplift_lever = t.uplift_lever_m.unwrap_or(2.0 * c.width_m / 3.0);
    WaveForce::from_levers_on(fx_kn * 1e3, lever, fy_kn * 1e3, uplift_lever, c.height_m, c.width_m)
        .map_err(|e| keyed("[load]", LOAD_KEYS, e))
}

/// Largest force-series file read, bytes (a file that never ends, `/dev/zero`, is refused).
pub const MAX_SERIES_BYTES: u64 = 128 << 20;

/// The text of a series file of at most [`MAX_SERIES_BYTES`] (checked before and while reading).
fn read_series(path: &Path) -> Result<String, String> {
    super::read_limited(path, MAX_SERIES_BYTES, "a force series", "a CSV file")
}

fn validate_solver(f: &ScenarioFile, duration_s: f64) -> R<SolverParams> {
    let t = &f.solver;
    let err = |e| keyed("[solver]", SOLVER_KEYS, e);
    let d = SolverParams::default();
    let mut s = SolverParams::fixed(t.dt_s.unwrap_or(d.dt_s)).map_err(err)?;
    // The run's length first (the value as Rust writes it).
    s = s.within(duration_s).map_err(|e| super::keyed_in(&[("dt_s", "[solver] dt_s", "s")], e))?;
    s = s.with_newmark(t.gamma.unwrap_or(d.gamma), t.beta.unwrap_or(d.beta)).map_err(err)?;
    let stepping_default = if f.load.is_none() && f.waves.is_some() { "adaptive" } else { "fixed" };
    let adaptive = choice(
        "[solver] stepping",
        t.stepping.as_deref().unwrap_or(stepping_default),
        &[("fixed", false), ("adaptive", true)],
    )?;
    if adaptive {
        let a = AdaptiveParams::for_first_step(s.dt_s);
        s = s
            .with_adaptive(AdaptiveParams {
                dt_min_s: t.dt_min_s.unwrap_or(a.dt_min_s),
                dt_max_s: t.dt_max_s.unwrap_or(a.dt_max_s),
                tolerance_m: t.error_tolerance_m.unwrap_or(a.tolerance_m),
            })
            .map_err(err)?;
    } else {
        for (key, given) in [
            ("dt_min_s", t.dt_min_s.is_some()),
            ("dt_max_s", t.dt_max_s.is_some()),
            ("error_tolerance_m", t.error_tolerance_m.is_some()),
        ] {
            if given {
                return Err(ScenarioError::Conflict {
                    message: format!(
                        "`[solver] {key}` is only used with stepping = \"adaptive\"; remove it or set stepping = \"adaptive\""
                    ),
                });
            }
        }
    }
    let max_iterations = match t.max_iterations {
        Some(v) => whole("[solver] max_iterations", v, 1, 1000)?,
        None => d.max_iterations,
    };
    let levels = match t.max_substep_levels {
        Some(v) => whole("[solver] max_substep_levels", v, 0, 20)?,
        None => d.max_substep_levels,
    };
    s = s.with_iterations(max_iterations, levels).map_err(err)?;
    s = s.with_tolerance(t.tolerance.unwrap_or(d.tolerance)).map_err(err)?;
    if let Some(v) = t.output_interval_s {
        s = s.with_output_interval_s(v);
    }
    // The profile then turns the exact steps off where it does not take them (`for_profile`).
    s.accel = choice(
        "[solver] accel",
        t.accel.as_deref().unwrap_or("auto"),
        &[("auto", Accel::auto()), ("none", Accel::none())],
    )?;
    s.check_run(duration_s).map_err(err)?;
    Ok(s)
}
