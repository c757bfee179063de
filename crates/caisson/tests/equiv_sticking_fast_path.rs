//! The all-sticking fast path (`Accel::sticking_fast_path`, docs/model.md §9.1) is the
//! same model: with it on and off, every bundled example and the waves of the design example give
//! the same results to well within the Newton tolerance's reach, in the same steps and with no
//! more Newton iterations (to one in a thousand).
//!
//! Why they are not identical to the last bit: the path decides which springs stick by the spring
//! law's own operations, but sums the forces in closed form (n Σ, Σx_i, Σx_i² ... times the
//! displacements) instead of spring by spring, and it solves an all-sticking step directly (the
//! vertical and rocking rows eliminated, a quadratic in δ_x: `dynamics::sticking`), where Newton's
//! iteration stops anywhere inside the residual tolerance (1e-9 W'). The two steps land within
//! that tolerance of each other; the adaptive stepper's step lengths depend smoothly on the
//! accelerations and carry the difference on, and a wave that slides carries it into its slip.
//! Only a decision that falls within that reach of its threshold (an error estimate at its
//! limit, a spring at its friction cap) could take another branch; none does on these cases
//! (identical step counts but where an unlocated touch-down's estimate tips, below). Measured
//! before results version 24: at most 1.9e-7 of the largest value of a
//! quantity on the examples (the sliding of a fragility storm of 2 h), 5e-9 on the design waves
//! (`cargo test --release --test equiv_sticking_fast_path -- --nocapture` prints it). Tolerance: 1e-6 of the
//! largest value of each quantity plus 1e-12 (m, N) for quantities near zero, five times the
//! measured difference and three orders below the adaptive stepper's own accuracy (0.15 % on the
//! design example, BENCHMARKS.md). A lifetime or fragility run accepts or rejects thousands of
//! steps against its error tolerance, and one estimate within rounding of it can go either way,
//! which moves that wave's sliding by a few tolerances: since results version 17 (the slip
//! positions in the estimate) one does, on the fragility example's fourth storm (2.0e-6 m of
//! 0.77 m at its tolerance of 1e-6 m); those runs are held within 25 tolerances more: since the
//! sticking phases' error is held per unit step (the adaptive module docs), a step length that
//! parts there changes the steps of the rest of the sticking phase, each within its own error per
//! half period, and the fourth storm's sliding moves by 2.1e-5 m (21 tolerances, 1.5e-4 of its
//! 0.139 m; measured on the merge of that rule). So, since
//! results version 24, is every adaptive run: with contact events unlocated (below) a spring that
//! touches down within a step puts λ |Δu_x| into the error estimate, one more decision that the
//! Newton tolerance's reach can tip, and then the steps part: measured 16 steps of the examples
//! differ, 21 steps or rejections of the 1 329 steps of the design waves (at most 1 in 50 of a
//! run's steps and 1 in 20 of a wave's asserted, Newton iterations within 0.5 % and 5 %), the
//! values within 1.3e-4 of the largest (a life's largest storm sliding of the climate example)
//! and within 5 tolerances on the design waves (1.1e-3 of a wave's value, 1e-6 m tolerance).
//!
//! Both runs leave lift-off and re-contact unlocated (`SolverParams::locate_contact` off): a
//! located lift-off ends a step a millionth past N_i = 0, and whether a step lands on a spring
//! that grazes zero (and resets its shear) is then within the Newton tolerance's reach, so the
//! two paths take other steps (measured with it on: 3.4e-6 of the breakwater example's sliding,
//! 1.2e-6 of a design wave's; docs/model.md §9.1). The fast path's arithmetic is the same either
//! way; this file compares that.

mod support;

use caisson::dynamics::{Accel, SolverParams, Stepping};
use caisson::scenario::Scenario;
use std::collections::BTreeMap;

type Results = BTreeMap<String, Vec<f64>>;

/// Steps, Newton iterations and all-sticking iterates, where the driver reports them.
type Work = Option<(u64, u64, u64)>;

fn with_fast_path(sc: &Scenario, on: bool) -> Scenario {
    sc.clone()
        .with_solver(SolverParams {
            accel: Accel { sticking_fast_path: on, exact_sticking: false, ..sc.solver().accel },
            locate_contact: false,
            ..sc.solver()
        })
        .unwrap()
}

/// What an example computes (as in `equiv_predictor.rs`): a `[load]` run, realization 0 of the wave
/// trains, the first `GOLDEN_LIVES` (14) lives of a design, 2 storms of a fragility run.
fn results(sc: &Scenario) -> (Results, Work) {
    let (all, stats) = support::signature::values(sc);
    let keys = [
        "permanent_sliding_m",
        "max_horizontal_displacement_m",
        "max_rotation_rad",
        "max_horizontal_reaction_n",
        "max_spring_normal_n",
        "min_spring_normal_n",
        "max_spring_shear_n",
        "final_displacement_m",
        "final_rotation_rad",
        "max_dashpot_moment_nm",
        "slip_events",
        "life_sliding_m",
        "life_max_storm_sliding_m",
        "life_simulated_waves",
        "storm_sliding_m",
        "wave_sliding_m",
        "wave_max_horizontal_reaction_n",
        "sliding_m",
    ];
    (support::signature::pick(all, &keys), stats.map(|s| (s.steps, s.newton_iterations, s.sticking_iterates)))
}

/// The largest difference of `new` from `old` relative to the largest |value| of each quantity,
/// asserted within the tolerance of the module docs (plus `reach_m`, m, for an adaptive run's
/// decisions: module docs); returns it and the number of values.
fn compare(name: &str, old: &Results, new: &Results, reach_m: f64, largest: &mut (f64, String)) -> usize {
    let mut compared = 0;
    assert_eq!(old.len(), new.len(), "{name}");
    for (key, o) in old {
        let n = &new[key];
        assert_eq!(o.len(), n.len(), "{name} {key}");
        let scale = o.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for (i, (a, b)) in o.iter().zip(n).enumerate() {
            let d = (a - b).abs();
            assert!(d <= 1e-6 * scale + 1e-12 + reach_m, "{name} {key}[{i}]: {b} with the fast path, {a} without");
            if scale > 0.0 && d / scale > largest.0 {
                *largest = (d / scale, format!("{name} {key}[{i}]"));
            }
            compared += 1;
        }
    }
    compared
}

#[test]
fn the_fast_path_moves_no_example_beyond_rounding() {
    let examples = support::example_paths();
    let (mut compared, mut largest) = (0, (0.0f64, String::new()));
    let (mut iterations, mut sticking, mut step_diffs) = (0, 0, 0);
    for path in &examples {
        let name = path.file_stem().unwrap().to_string_lossy().to_string();
        let sc = caisson::scenario::load(path).unwrap();
        let (old, old_work) = results(&with_fast_path(&sc, false));
        let (new, new_work) = results(&with_fast_path(&sc, true));
        // A lifetime or fragility run takes thousands of adaptive steps, each accepted or
        // rejected against the error tolerance (module docs).
        let reach_m = match sc.solver().stepping {
            Stepping::Adaptive(p) => 25.0 * p.tolerance_m,
            _ => 0.0,
        };
        compared += compare(&name, &old, &new, reach_m, &mut largest);
        if let (Some(o), Some(n)) = (old_work, new_work) {
            // The same steps but where an unlocated touch-down's estimate tipped (module docs).
            assert!(o.0.abs_diff(n.0) * 50 <= o.0, "{name}: {} steps without and {} with the fast path", o.0, n.0);
            step_diffs += o.0.abs_diff(n.0);
            // A direct step counts one iteration, where Newton's predictor may have landed inside
            // the tolerance with none (at rest, under no load).
            assert!(
                n.1 as f64 <= 1.005 * o.1 as f64,
                "{name}: {} Newton iterations with the fast path, {} without",
                n.1,
                o.1
            );
            assert_eq!(o.2, 0, "{name}: the switch turns the fast path off");
            iterations += n.1 + n.0;
            sticking += n.2;
        }
    }
    println!(
        "{compared} values of {} examples; largest relative difference {:.2e} ({}); {sticking} of {iterations} resisting forces all-sticking; {step_diffs} steps differ",
        examples.len(),
        largest.0,
        largest.1
    );
    assert_eq!(examples.len(), 15, "{examples:?}");
    assert!(compared > 100, "{compared} values compared");
    assert!(sticking > 0, "the fast path was taken");
}

/// The waves of the design example that reach the dynamic model (heights about its sliding
/// threshold, from sticking throughout to sliding and rocking), each from rest as the lifetime run
/// takes them: the permanent sliding, the peak displacement, rotation, base reaction and spring
/// shear, and the smallest spring normal force (within the tolerance of the module docs); the
/// same steps, no more Newton iterations; and most step attempts all-sticking (solved directly).
#[test]
fn the_design_waves_are_the_same_with_the_fast_path() {
    let sc = support::example("design_breakwater.toml");
    let waves = |on: bool| {
        support::design_waves(SolverParams {
            accel: Accel { sticking_fast_path: on, exact_sticking: false, ..sc.solver().accel },
            locate_contact: false,
            ..sc.solver()
        })
    };
    let (old, new) = (waves(false), waves(true));
    // Five error tolerances, as for the examples' adaptive runs (module docs).
    let Stepping::Adaptive(p) = sc.solver().stepping else { panic!("the example steps adaptively") };
    let reach_m = 5.0 * p.tolerance_m;
    let (mut steps, mut attempts, mut sticking, mut sliding_waves, mut step_diffs) = (0, 0, 0, 0, 0);
    let mut largest = 0.0f64;
    for (i, ((o, os), (n, ns))) in old.iter().zip(&new).enumerate() {
        for (a, b) in o.iter().zip(n) {
            let d = (a - b).abs();
            assert!(d <= 1e-6 * a.abs() + 1e-12 + reach_m, "wave {i}: {b} with the fast path, {a} without");
            if a.abs() > 0.0 {
                largest = largest.max(d / a.abs());
            }
        }
        assert!(
            os.steps.abs_diff(ns.steps) * 20 <= os.steps,
            "wave {i}: {} steps without, {} with",
            os.steps,
            ns.steps
        );
        step_diffs += os.steps.abs_diff(ns.steps) + os.rejected_steps.abs_diff(ns.rejected_steps);
        assert!(ns.newton_iterations as f64 <= 1.05 * os.newton_iterations as f64, "wave {i}: Newton iterations");
        assert_eq!(os.sticking_iterates, 0);
        steps += ns.steps;
        attempts += ns.steps + ns.rejected_steps;
        sticking += ns.sticking_iterates;
        sliding_waves += usize::from(o[0].abs() > 1e-3);
    }
    println!("largest relative difference {largest:.2e}; {sticking} all-sticking resisting forces in {attempts} step attempts, {steps} steps; {step_diffs} steps or rejections differ");
    assert!(steps > 1000, "{steps} steps");
    assert!(sliding_waves >= 3 && sliding_waves < old.len(), "{sliding_waves} waves slid more than 1 mm");
    assert!(sticking as f64 > 0.5 * attempts as f64, "{sticking} all-sticking in {attempts} attempts");
}
