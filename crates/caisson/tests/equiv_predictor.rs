//! The Newton predictor (`Accel::predictor`, docs/model.md §9.1) changes how a step is
//! reached, not where it lands: every bundled example gives the same results with the default
//! predictor (the last step's acceleration carried over) as with the previous engine's first
//! iterate (δ = 0, results version 4 and before), to a stated tolerance, with far fewer Newton
//! corrections.
//!
//! Why the results move at all: both iterations stop anywhere inside the residual tolerance
//! (1e-9 W'), at different points; the adaptive stepper then chooses slightly different steps
//! from slightly different accelerations, and each step carries its own local error (up to the
//! stepper's `error_tolerance_m`), so the differences grow with the number of sliding steps.
//! Measured: at most 1.5e-6 of the largest value of a quantity on every example (and 5.7e-5 for
//! a fragility storm that slid 0.74 m, in the storms drawn before results version 4).
//! Tolerance: 1e-4 of the largest value of each quantity, plus 1e-9 (m, N) for quantities near
//! zero; fifteen times tighter than the adaptive stepper's own accuracy against fine fixed steps
//! (0.15 % on the design example, BENCHMARKS.md). A life or a storm of a lifetime or fragility
//! run sums many waves, each stepped to its own error tolerance (1e-6 m in the examples), so
//! there 5 tolerances more: since results version 17 (the slip positions in the error estimate)
//! the climate example's third life differs by 1.5e-6 m of 0.0153 m.

mod support;

use caisson::dynamics::{Accel, Predictor, Simulation, SolverParams, Stepping};
use caisson::loads::history::WaveTrain;
use caisson::loads::regime::RegimeChoice;
use caisson::scenario::Scenario;
use std::collections::BTreeMap;

type Results = BTreeMap<String, Vec<f64>>;

fn with_predictor(sc: &Scenario, predictor: Predictor) -> Scenario {
    support::signature::with_accel(sc, |a| Accel { predictor, ..a })
}

/// What an example computes (as in `regress_golden.rs`, without the time histories): a `[load]` run,
/// realization 0 of the wave trains, the first `GOLDEN_LIVES` (14) lives of a design, 2 storms of a fragility run;
/// and the Newton iterations where the driver reports them.
fn results(sc: &Scenario) -> (Results, Option<u64>) {
    let (all, stats) = support::signature::values(sc);
    let keys = [
        "permanent_sliding_m",
        "max_horizontal_displacement_m",
        "max_horizontal_reaction_n",
        "final_rotation_rad",
        "life_sliding_m",
        "life_max_storm_sliding_m",
        "storm_sliding_m",
        "wave_sliding_m",
        "wave_max_horizontal_reaction_n",
        "sliding_m",
    ];
    (support::signature::pick(all, &keys), stats.map(|s| s.newton_iterations))
}

#[test]
fn the_predictor_moves_no_example_beyond_the_newton_and_step_tolerances() {
    let examples = support::example_paths();
    let (mut compared, mut largest) = (0, (0.0f64, String::new()));
    let (mut before_iterations, mut after_iterations) = (0, 0);
    for path in &examples {
        let name = path.file_stem().unwrap().to_string_lossy().to_string();
        let sc = caisson::scenario::load(path).unwrap();
        let (old, old_it) = results(&with_predictor(&sc, Predictor::LastDisplacement));
        let (new, new_it) = results(&with_predictor(&sc, Predictor::ConstantAcceleration));
        // A lifetime or fragility run: its lives' and storms' sums of many waves (module docs).
        let reach_m = match sc.solver().stepping {
            Stepping::Adaptive(p) if sc.design.is_some() || sc.fragility.is_some() => 5.0 * p.tolerance_m,
            _ => 0.0,
        };
        for (key, o) in &old {
            let n = &new[key];
            assert_eq!(o.len(), n.len(), "{name} {key}");
            let scale = o.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            for (i, (a, b)) in o.iter().zip(n).enumerate() {
                let d = (a - b).abs();
                assert!(d <= 1e-4 * scale + 1e-9 + reach_m, "{name} {key}[{i}]: {b} with the predictor, {a} without");
                if scale > 0.0 && d / scale > largest.0 {
                    largest = (d / scale, format!("{name} {key}[{i}]"));
                }
                compared += 1;
            }
        }
        if let (Some(o), Some(n)) = (old_it, new_it) {
            before_iterations += o;
            after_iterations += n;
        }
    }
    println!(
        "{compared} values of {} examples; largest relative difference {:.2e} ({}); Newton iterations {before_iterations} -> {after_iterations}",
        examples.len(),
        largest.0,
        largest.1
    );
    assert_eq!(examples.len(), 15, "{examples:?}");
    assert!(compared > 100, "{compared} values compared");
    assert!(after_iterations < before_iterations, "{after_iterations} iterations against {before_iterations}");
}

/// The point of the predictor: on the waves of the design example that reach the dynamic model
/// (heights about its sliding threshold), about one Newton correction per step instead of two.
/// Measured with the all-sticking fast path off: with it on, an all-sticking step is solved
/// directly (`dynamics::sticking`) and no predictor is used.
#[test]
fn the_predictor_halves_the_newton_corrections_of_the_design_waves() {
    let sc = support::example("design_breakwater.toml");
    let site = &sc.waves.as_ref().unwrap().model;
    let period_s = 12.8;
    let per_step = |predictor| {
        let solver =
            SolverParams { accel: Accel { predictor, sticking_fast_path: false, ..sc.solver().accel }, ..sc.solver() };
        let (mut steps, mut iterations) = (0, 0);
        for h in [9.0, 10.0, 11.0, 11.5, 12.0, 12.5, 12.7, 12.79] {
            let loads = site.evaluate_with(h, period_s, RegimeChoice::Auto).unwrap();
            let train = WaveTrain::new(vec![site.event(&loads, None, 0.0)]).unwrap();
            let mut sim = Simulation::new(sc.structure().model(), solver, &train);
            sim.run_until(period_s, &train, &mut ()).unwrap();
            steps += sim.stats.steps;
            iterations += sim.stats.newton_iterations;
        }
        assert!(steps > 1000, "{steps} steps");
        iterations as f64 / steps as f64
    };
    let (before, after) = (per_step(Predictor::LastDisplacement), per_step(Predictor::ConstantAcceleration));
    assert!(before > 1.9 && after < 1.25, "{before:.3} corrections per step without the predictor, {after:.3} with");
}
