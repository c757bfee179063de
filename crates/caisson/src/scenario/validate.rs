//! Validation of a parsed [`ScenarioFile`] into typed SI parameters for the dynamic engine.

use super::{ScenarioError, ScenarioFile};
use crate::foundation::{AddedMass, DampingMode, Foundation, FoundationStiffness, Soil, VerticalDamping};
use crate::loads::pulse::{StaticRamp, TrianglePulse};
use crate::loads::series::ForceSeries;
use crate::loads::{LoadHistory, WaveForce};
use crate::structure::{Caisson, MassMatrix};
use crate::G_M_PER_S2;
use std::path::Path;

type R<T> = Result<T, ScenarioError>;

/// How the step length is chosen (see [`crate::dynamics`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Stepping {
    /// Every step is `dt_s` (halved only when Newton-Raphson fails).
    Fixed,
    /// Local error control (Zienkiewicz & Xie 1991), landing on the load's breakpoints.
    Adaptive(AdaptiveParams),
}

/// Controls of the adaptive stepper.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AdaptiveParams {
    /// Smallest step, s: a step this short is accepted whatever its error estimate.
    pub dt_min_s: f64,
    /// Largest step, s.
    pub dt_max_s: f64,
    /// Allowed local displacement error per step, m (rotation counted as θ·B/2).
    pub tolerance_m: f64,
}

impl Default for AdaptiveParams {
    fn default() -> Self {
        AdaptiveParams { dt_min_s: 1e-6, dt_max_s: 5e-3, tolerance_m: 1e-8 }
    }
}

/// Newmark and Newton-Raphson controls (PHYSICS.md §9.1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolverParams {
    /// Time step (fixed stepping) or first step (adaptive stepping), s.
    pub dt_s: f64,
    pub stepping: Stepping,
    /// Newmark γ (default ½) and β (default ¼): average acceleration.
    pub gamma: f64,
    pub beta: f64,
    /// Newton iterations allowed per (sub)step before the step is sub-stepped.
    pub max_iterations: usize,
    /// Times a failing step may be halved (2^levels sub-steps at most) before the run fails.
    pub max_substep_levels: usize,
    /// Convergence tolerance on the residual, relative to the weight in water W'.
    pub tolerance: f64,
    /// Interval between recorded history samples, s.
    pub output_interval_s: f64,
}

impl Default for SolverParams {
    fn default() -> Self {
        SolverParams {
            dt_s: 1e-4,
            stepping: Stepping::Fixed,
            gamma: 0.5,
            beta: 0.25,
            max_iterations: 30,
            max_substep_levels: 8,
            tolerance: 1e-9,
            output_interval_s: 1e-3,
        }
    }
}

/// The load of a `[load]` table.
#[derive(Debug, Clone)]
pub enum LoadSpec {
    Triangle(TrianglePulse),
    Static(StaticRamp),
    Series(ForceSeries),
}

impl LoadHistory for LoadSpec {
    #[inline]
    fn at(&self, t_s: f64) -> WaveForce {
        match self {
            LoadSpec::Triangle(l) => l.at(t_s),
            LoadSpec::Static(l) => l.at(t_s),
            LoadSpec::Series(l) => l.at(t_s),
        }
    }
    fn end_time_s(&self) -> Option<f64> {
        match self {
            LoadSpec::Triangle(l) => l.end_time_s(),
            LoadSpec::Static(l) => l.end_time_s(),
            LoadSpec::Series(l) => l.end_time_s(),
        }
    }
    fn next_breakpoint_s(&self, t_s: f64) -> f64 {
        match self {
            LoadSpec::Triangle(l) => l.next_breakpoint_s(t_s),
            LoadSpec::Static(l) => l.next_breakpoint_s(t_s),
            LoadSpec::Series(l) => l.next_breakpoint_s(t_s),
        }
    }
}

/// A validated scenario for the dynamic engine.
#[derive(Debug, Clone)]
pub struct Scenario {
    pub caisson: Caisson,
    pub foundation: Foundation,
    /// ρ_w, kg/m³.
    pub water_density_kg_per_m3: f64,
    /// The soil route, when the stiffness came from soil parameters.
    pub soil: Option<Soil>,
    /// The `[load]` table; `None` for a scenario that only describes waves.
    pub load: Option<LoadSpec>,
    /// Simulated time, s.
    pub duration_s: f64,
    pub solver: SolverParams,
}

fn finite(key: &str, v: f64) -> R<f64> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(ScenarioError::range(key, v, "must be a finite number"))
    }
}

fn positive(key: &str, v: f64, unit: &str) -> R<f64> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(ScenarioError::range(key, v, format!("must be a finite number > 0 ({unit})")))
    }
}

fn within(key: &str, v: f64, lo: f64, hi: f64, unit: &str) -> R<f64> {
    if v.is_finite() && v >= lo && v <= hi {
        Ok(v)
    } else {
        Err(ScenarioError::range(key, v, format!("must be between {lo} and {hi} ({unit})")))
    }
}

fn int_within(key: &str, v: i64, lo: i64, hi: i64) -> R<usize> {
    if v >= lo && v <= hi {
        Ok(v as usize)
    } else {
        Err(ScenarioError::range(key, v, format!("must be a whole number from {lo} to {hi}")))
    }
}

fn choice<T: Copy>(key: &str, v: &str, options: &[(&str, T)]) -> R<T> {
    options.iter().find(|(name, _)| *name == v).map(|(_, t)| *t).ok_or_else(|| {
        let names: Vec<String> = options.iter().map(|(n, _)| format!("\"{n}\"")).collect();
        ScenarioError::range(key, format!("\"{v}\""), format!("must be one of {}", names.join(", ")))
    })
}

/// Validate a parsed scenario. `base_dir` resolves relative file names (the series CSV).
pub fn validate(f: &ScenarioFile, base_dir: &Path) -> R<Scenario> {
    let rho_w = match f.water.density_kg_per_m3 {
        Some(v) => within("[water] density_kg_per_m3", v, 500.0, 2000.0, "kg/m³")?,
        None => 1000.0,
    };
    let caisson = validate_caisson(f, rho_w)?;
    let (foundation, soil) = validate_foundation(f, &caisson, rho_w)?;
    let (load, default_duration) = match &f.load {
        Some(_) => {
            let (l, d) = validate_load(f, &caisson, base_dir)?;
            (Some(l), d)
        }
        // A wave-train scenario: its waves (default 15) of its period.
        // (A bad period or count is reported by the [waves] validation, not here.)
        None => (
            None,
            f.waves.as_ref().map_or(1.0, |w| {
                let t = w.period_s.filter(|t| t.is_finite() && *t > 0.0 && *t <= 1e3).unwrap_or(1.0);
                t * w.waves.unwrap_or(15).clamp(1, 1_000_000) as f64
            }),
        ),
    };
    let duration_s = match f.load.as_ref().and_then(|l| l.duration_s) {
        Some(v) => positive("[load] duration_s", v, "s")?,
        None => default_duration,
    };
    let solver = validate_solver(f, duration_s)?;
    Ok(Scenario { caisson, foundation, water_density_kg_per_m3: rho_w, soil, load, duration_s, solver })
}

fn validate_caisson(f: &ScenarioFile, rho_w: f64) -> R<Caisson> {
    let c = &f.caisson;
    let width_m = positive(
        "[caisson] width_m",
        c.width_m.ok_or_else(|| {
            ScenarioError::missing(
                "[caisson] width_m",
                "B, the base width in the wave direction, m (a finite number > 0)",
            )
        })?,
        "m",
    )?;
    let length_m = match c.length_m {
        Some(v) => positive("[caisson] length_m", v, "m")?,
        None => 1.0,
    };
    let height_m = positive(
        "[caisson] height_m",
        c.height_m.ok_or_else(|| {
            ScenarioError::missing("[caisson] height_m", "the caisson height, base to crest, m (a finite number > 0)")
        })?,
        "m",
    )?;
    let base_depth_m = finite(
        "[caisson] base_depth_m",
        c.base_depth_m.ok_or_else(|| {
            ScenarioError::missing(
                "[caisson] base_depth_m",
                "h', the depth of the base below still water, m (from 0 to height_m)",
            )
        })?,
    )?;
    if base_depth_m < 0.0 || base_depth_m > height_m {
        return Err(ScenarioError::range(
            "[caisson] base_depth_m",
            base_depth_m,
            format!("must be between 0 and the caisson height {height_m} m (a base deeper than the caisson is tall leaves it under water)"),
        ));
    }
    let displaced = Caisson::displaced_water_kg(width_m, length_m, base_depth_m, height_m, rho_w);
    let (mass_kg, weight_in_water_n) = match (c.weight_in_water_kn, c.mass_kg) {
        (None, None) => {
            return Err(ScenarioError::missing(
                "[caisson] weight_in_water_kn",
                "give the weight in water (kN) or the mass in air `mass_kg`, or both",
            ))
        }
        (Some(w), None) => {
            let w = positive("[caisson] weight_in_water_kn", w, "kN")? * 1e3;
            (Caisson::mass_from_weight_in_water(w, displaced), w)
        }
        (None, Some(m)) => {
            let m = positive("[caisson] mass_kg", m, "kg")?;
            if m <= displaced {
                return Err(ScenarioError::range(
                    "[caisson] mass_kg",
                    m,
                    format!("must exceed the {displaced:.1} kg of water the caisson displaces, or it floats"),
                ));
            }
            (m, (m - displaced) * G_M_PER_S2)
        }
        (Some(w), Some(m)) => {
            (positive("[caisson] mass_kg", m, "kg")?, positive("[caisson] weight_in_water_kn", w, "kN")? * 1e3)
        }
    };
    let cog_height_m = match c.cog_height_m {
        Some(v) => within("[caisson] cog_height_m", v, 0.0, height_m, "m above the base")?,
        None => 0.5 * height_m,
    };
    let inertia_cog_kg_m2 = match c.inertia_kg_m2 {
        Some(v) => positive("[caisson] inertia_kg_m2", v, "kg·m² about the centre of gravity")?,
        None => Caisson::uniform_block_inertia_kg_m2(mass_kg, width_m, height_m),
    };
    let mass_matrix = match &c.mass_matrix {
        Some(s) => {
            choice("[caisson] mass_matrix", s, &[("coupled", MassMatrix::Coupled), ("diagonal", MassMatrix::Diagonal)])?
        }
        None => MassMatrix::Coupled,
    };
    Ok(Caisson {
        width_m,
        length_m,
        height_m,
        base_depth_m,
        mass_kg,
        weight_in_water_n,
        cog_height_m,
        inertia_cog_kg_m2,
        mass_matrix,
    })
}

fn validate_foundation(f: &ScenarioFile, c: &Caisson, rho_w: f64) -> R<(Foundation, Option<Soil>)> {
    let t = &f.foundation;
    let springs = match t.springs {
        Some(v) => int_within("[foundation] springs", v, 2, 1000)?,
        None => 10,
    };
    let mu_static = match t.mu_static {
        Some(v) => within("[foundation] mu_static", v, 1e-6, 10.0, "-")?,
        None => 0.6,
    };
    let mu_dynamic = match t.mu_dynamic {
        Some(v) => within("[foundation] mu_dynamic", v, 1e-6, 10.0, "-")?,
        None => 0.4f64.min(mu_static),
    };
    if mu_dynamic > mu_static {
        return Err(ScenarioError::range(
            "[foundation] mu_dynamic",
            mu_dynamic,
            format!("must not exceed mu_static = {mu_static} (dynamic friction is at most static friction)"),
        ));
    }
    let soil = match t.e100_kpa {
        Some(e) => Some(Soil {
            e100_pa: positive("[foundation] e100_kpa", e, "kPa")? * 1e3,
            poisson: match t.poisson {
                Some(v) => within("[foundation] poisson", v, 0.0, 0.49, "-")?,
                None => 0.33,
            },
            density_kg_per_m3: match t.density_kg_per_m3 {
                Some(v) => within("[foundation] density_kg_per_m3", v, 500.0, 5000.0, "kg/m³")?,
                None => 2300.0,
            },
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
    };
    let derived = soil.map(|s| s.derive(c.weight_in_water_n, c.width_m, c.length_m).stiffness);
    let pick = |key: &str, given: Option<f64>, from_soil: Option<f64>, allow_zero: bool| -> R<f64> {
        let full = format!("[foundation] {key}");
        match (given, from_soil) {
            (Some(v), _) if allow_zero => within(&full, v, 0.0, f64::MAX, "kN·s/m").map(|v| v * 1e3),
            (Some(v), _) => positive(&full, v, "kN/m").map(|v| v * 1e3),
            (None, Some(v)) => Ok(v),
            (None, None) => Err(ScenarioError::missing(
                &full,
                "give the soil (`e100_kpa`, optional `poisson`, `density_kg_per_m3`) or all of `kx_kn_per_m`, `ky_kn_per_m`, `damping_kns_per_m`",
            )),
        }
    };
    let stiffness = FoundationStiffness {
        kx_n_per_m: pick("kx_kn_per_m", t.kx_kn_per_m, derived.map(|d| d.kx_n_per_m), false)?,
        ky_n_per_m: pick("ky_kn_per_m", t.ky_kn_per_m, derived.map(|d| d.ky_n_per_m), false)?,
        damping_ns_per_m: pick("damping_kns_per_m", t.damping_kns_per_m, derived.map(|d| d.damping_ns_per_m), true)?,
    };
    let vertical_damping_factor = match t.vertical_damping_factor {
        Some(v) => within("[foundation] vertical_damping_factor", v, 0.0, 1e3, "-")?,
        None => 10.0,
    };
    let damping_mode = match &t.damping_mode {
        Some(s) => {
            choice("[foundation] damping_mode", s, &[("total", DampingMode::Total), ("elastic", DampingMode::Elastic)])?
        }
        None => DampingMode::Total,
    };
    let vertical_damping = match &t.vertical_damping {
        Some(s) => choice(
            "[foundation] vertical_damping",
            s,
            &[("seed", VerticalDamping::Seed), ("springs", VerticalDamping::Springs)],
        )?,
        None => VerticalDamping::Seed,
    };
    let added_mass = if t.added_mass.unwrap_or(true) {
        let d = match t.added_mass_depth_m {
            Some(v) => within("[foundation] added_mass_depth_m", v, 0.0, 1e3, "m")?,
            None => c.base_depth_m,
        };
        AddedMass::new(rho_w, d, c.length_m)
    } else {
        if t.added_mass_depth_m.is_some() {
            return Err(ScenarioError::Conflict {
                message: "`[foundation] added_mass_depth_m` is given but `added_mass = false`".into(),
            });
        }
        AddedMass::default()
    };
    Ok((
        Foundation {
            springs,
            mu_static,
            mu_dynamic,
            stiffness,
            vertical_damping_factor,
            damping_mode,
            vertical_damping,
            added_mass,
        },
        soil,
    ))
}

fn validate_load(f: &ScenarioFile, c: &Caisson, base_dir: &Path) -> R<(LoadSpec, f64)> {
    let t = f.load.as_ref().expect("checked by caller");
    let kind_name = t
        .kind
        .as_deref()
        .ok_or_else(|| ScenarioError::missing("[load] kind", "one of \"triangle\", \"static\", \"series\""))?;
    let kind = choice("[load] kind", kind_name, &[("triangle", 0), ("static", 1), ("series", 2)])?;
    let relevant: &[&str] = match kind {
        0 => &[
            "peak_horizontal_kn",
            "rise_time_s",
            "peak_uplift_kn",
            "horizontal_lever_m",
            "uplift_lever_m",
            "start_time_s",
        ],
        1 => &["peak_horizontal_kn", "ramp_time_s", "peak_uplift_kn", "horizontal_lever_m", "uplift_lever_m"],
        _ => &["file"],
    };
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
    let peak = |t: &crate::scenario::LoadTable| -> R<WaveForce> {
        let fx = finite(
            "[load] peak_horizontal_kn",
            t.peak_horizontal_kn.ok_or_else(|| {
                ScenarioError::missing(
                    "[load] peak_horizontal_kn",
                    "the peak horizontal force, kN (positive shoreward)",
                )
            })?,
        )? * 1e3;
        let fy = finite("[load] peak_uplift_kn", t.peak_uplift_kn.unwrap_or(0.0))? * 1e3;
        let lever = match t.horizontal_lever_m {
            Some(v) => {
                within("[load] horizontal_lever_m", v, 0.0, c.height_m, "m above the base, at most the caisson height")?
            }
            None => c.base_depth_m,
        };
        let ulever = match t.uplift_lever_m {
            Some(v) => within("[load] uplift_lever_m", v, 0.0, c.width_m, "m from the heel, at most the base width")?,
            None => 2.0 * c.width_m / 3.0,
        };
        Ok(WaveForce::from_levers(fx, lever, fy, ulever, c.width_m))
    };
    Ok(match kind {
        0 => {
            let rise_s = positive(
                "[load] rise_time_s",
                t.rise_time_s.ok_or_else(|| {
                    ScenarioError::missing("[load] rise_time_s", "the rise time t_r of the triangular pulse, s")
                })?,
                "s",
            )?;
            let start_s = match t.start_time_s {
                Some(v) => within("[load] start_time_s", v, 0.0, 1e6, "s")?,
                None => 0.0,
            };
            let pulse = TrianglePulse { peak: peak(t)?, rise_s, start_s };
            (LoadSpec::Triangle(pulse), start_s + 2.0 * rise_s + 1.0)
        }
        1 => {
            let ramp_s = match t.ramp_time_s {
                Some(v) => positive("[load] ramp_time_s", v, "s")?,
                None => 1.0,
            };
            (LoadSpec::Static(StaticRamp { peak: peak(t)?, ramp_s }), ramp_s)
        }
        _ => {
            let name = t.file.as_ref().ok_or_else(|| {
                ScenarioError::missing("[load] file", "the CSV force series, relative to the scenario file")
            })?;
            let path = base_dir.join(name);
            let text = std::fs::read_to_string(&path)
                .map_err(|e| ScenarioError::Series { path: path.clone(), message: e.to_string() })?;
            let series = ForceSeries::from_csv_str(&text, c.width_m)
                .map_err(|e| ScenarioError::Series { path: path.clone(), message: e.to_string() })?;
            let end = series.last_time_s();
            (LoadSpec::Series(series), end)
        }
    })
}

fn validate_solver(f: &ScenarioFile, duration_s: f64) -> R<SolverParams> {
    let t = &f.solver;
    let d = SolverParams::default();
    let dt_s = match t.dt_s {
        Some(v) => positive("[solver] dt_s", v, "s")?,
        None => d.dt_s,
    };
    if dt_s > duration_s {
        return Err(ScenarioError::range(
            "[solver] dt_s",
            dt_s,
            format!("must not exceed the simulated time {duration_s} s"),
        ));
    }
    let gamma = match t.gamma {
        Some(v) => within("[solver] gamma", v, 0.5, 1.0, "-")?,
        None => d.gamma,
    };
    let beta = match t.beta {
        Some(v) => within("[solver] beta", v, 0.5 * gamma, 0.5, "-; unconditional stability needs 2·beta ≥ gamma")?,
        None => d.beta,
    };
    let stepping_default = if f.load.is_none() && f.waves.is_some() { "adaptive" } else { "fixed" };
    let adaptive = choice(
        "[solver] stepping",
        t.stepping.as_deref().unwrap_or(stepping_default),
        &[("fixed", false), ("adaptive", true)],
    )?;
    let stepping = if adaptive {
        let a = AdaptiveParams::default();
        let dt_max_s = match t.dt_max_s {
            Some(v) => within("[solver] dt_max_s", v, dt_s, 1.0, "s, from dt_s to 1 s")?,
            None => a.dt_max_s.max(dt_s),
        };
        let dt_min_s = match t.dt_min_s {
            Some(v) => within("[solver] dt_min_s", v, 1e-9, dt_s, "s, from 1e-9 s to dt_s")?,
            None => a.dt_min_s.min(dt_s),
        };
        let tolerance_m = match t.error_tolerance_m {
            Some(v) => within("[solver] error_tolerance_m", v, 1e-12, 1e-3, "m of local displacement error per step")?,
            None => a.tolerance_m,
        };
        Stepping::Adaptive(AdaptiveParams { dt_min_s, dt_max_s, tolerance_m })
    } else {
        // Fixed steps: dt_s is every step, so bound their number.
        if duration_s / dt_s > 1e9 {
            return Err(ScenarioError::range(
                "[solver] dt_s",
                dt_s,
                format!("gives {:.2e} steps for {duration_s} s; at most 1e9", duration_s / dt_s),
            ));
        }
        for (key, given) in [
            ("dt_min_s", t.dt_min_s.is_some()),
            ("dt_max_s", t.dt_max_s.is_some()),
            ("error_tolerance_m", t.error_tolerance_m.is_some()),
        ] {
            if given {
                return Err(ScenarioError::Conflict { message: format!("`[solver] {key}` is only used with stepping = \"adaptive\"; remove it or set stepping = \"adaptive\"") });
            }
        }
        Stepping::Fixed
    };
    Ok(SolverParams {
        dt_s,
        stepping,
        gamma,
        beta,
        max_iterations: match t.max_iterations {
            Some(v) => int_within("[solver] max_iterations", v, 1, 1000)?,
            None => d.max_iterations,
        },
        max_substep_levels: match t.max_substep_levels {
            Some(v) => int_within("[solver] max_substep_levels", v, 0, 20)?,
            None => d.max_substep_levels,
        },
        tolerance: match t.tolerance {
            Some(v) => within("[solver] tolerance", v, 1e-15, 1e-2, "relative to the weight in water")?,
            None => d.tolerance,
        },
        output_interval_s: match t.output_interval_s {
            Some(v) => within(
                "[solver] output_interval_s",
                v,
                dt_s,
                duration_s.max(dt_s),
                "s, from dt_s to the simulated time",
            )?,
            None => d.output_interval_s.max(dt_s),
        },
    })
}
