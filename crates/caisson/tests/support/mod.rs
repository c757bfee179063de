//! Helpers shared by the integration tests.
#![allow(dead_code)]

pub mod imports;
pub mod pari;
pub mod signature;
pub mod site;

use caisson::scenario::Scenario;
use std::path::Path;

/// A scenario from TOML text (relative files are taken from the current directory).
pub fn scenario(text: &str) -> Scenario {
    Scenario::from_toml(text, Path::new("test.toml"), Path::new(".")).expect("a valid test scenario")
}

/// The bundled examples (`examples/*.toml`), sorted by name.
pub fn example_paths() -> Vec<std::path::PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let mut examples: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    examples.sort();
    examples
}

/// A bundled example, validated (its relative files are taken from `examples/`).
pub fn example(name: &str) -> Scenario {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    caisson::scenario::load(&dir.join(name)).unwrap_or_else(|e| panic!("examples/{name}: {e}"))
}

/// The seed's Table 5 caisson on its soil (docs/model.md §8.2; Table 6 from the soil route), the
/// `[caisson]` and `[foundation]` tables without a closing newline: tests append keys of their
/// own to `[foundation]` and their `[load]`.
pub const TABLE5: &str = r#"
[caisson]
width_m = 0.78
length_m = 1.0
height_m = 1.12
base_depth_m = 0.8
weight_in_water_kn = 8.24
[foundation]
e100_kpa = 3.5e5
poisson = 0.33
density_kg_per_m3 = 2300
"#;

/// The seed's Table 5 caisson (0.78 m wide, W' `weight_kn`) on a foundation 100 × stiffer than
/// Table 6, undamped, with μ_s = μ_d = `mu`: under a force through its base centre it is the
/// rigid block of docs/model.md §6.3 (tests/verify_engine.rs, tests/verify_sizing.rs). `width_m` replaces
/// the width.
pub fn rigid_block_caisson(width_m: f64, weight_kn: f64, mu: f64) -> String {
    format!(
        r#"
[caisson]
width_m = {width_m}
height_m = 1.12
base_depth_m = 0.8
weight_in_water_kn = {weight_kn}
mass_matrix = "diagonal"
[foundation]
kx_kn_per_m = 1.5e7
ky_kn_per_m = 1.4e7
damping_kns_per_m = 0.0
mu_static = {mu}
mu_dynamic = {mu}
"#
    )
}

/// The waves of the design example (`design_breakwater.toml`, period 12.8 s) that reach its
/// dynamic model, heights about its sliding threshold from sticking throughout to sliding and
/// rocking, each run from rest as the lifetime run takes them with `solver`: per wave the
/// permanent sliding, the peak u_x, θ, horizontal reaction and spring shear and the least spring
/// normal force (tests/equiv_sticking_fast_path.rs, tests/verify_adaptive_accuracy.rs), and the solver's statistics.
pub fn design_waves(solver: caisson::dynamics::SolverParams) -> Vec<([f64; 6], caisson::dynamics::SolverStats)> {
    use caisson::analysis::run::{permanent_sliding_m, Peaks};
    use caisson::loads::{history::WaveTrain, regime::RegimeChoice};
    let sc = example("design_breakwater.toml");
    let site = &sc.waves.as_ref().unwrap().model;
    let period_s = 12.8;
    let mut out = Vec::new();
    for h in [6.0, 8.0, 9.0, 10.0, 11.0, 11.5, 12.0, 12.5, 12.7, 12.79] {
        let loads = site.evaluate_with(h, period_s, RegimeChoice::Auto).unwrap();
        let train = WaveTrain::new(vec![site.event(&loads, None, 0.0)]).unwrap();
        let mut sim = caisson::dynamics::Simulation::new(sc.structure().model(), solver, &train);
        let mut peaks = Peaks::default();
        sim.run_until(period_s, &train, &mut peaks).unwrap();
        let sliding = permanent_sliding_m(&sim);
        out.push(([sliding, peaks.max_ux, peaks.max_theta, peaks.max_rx, peaks.max_shear, peaks.min_n], sim.stats));
    }
    out
}
