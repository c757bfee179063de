//! Adaptive stepping at its default controls (docs/scenario.md, [solver] `stepping =
//! "adaptive"`) against converged fixed steps: on the seed's Table 5 caisson under the consistent
//! profile (the dashpot beside the springs) and undamped, under triangular pulses that slide it,
//! rock it and lift its seaward springs, one of them grazing (within nanometres of lifting); and on
//! the 15-wave test; and, with the sticking phases solved exactly, converging to fixed steps as
//! the tolerance shrinks.

mod support;

use caisson::analysis::run::run;
use caisson::dynamics::{AdaptiveParams, SolverParams, Stepping};
use caisson::scenario::Scenario;
use support::{scenario, TABLE5};

/// The Table 5 caisson on its soil with the foundation keys `damping` and a triangular pulse.
fn case(damping: &str, peak_kn: f64, rise_s: f64, lever_m: f64, uplift_kn: f64) -> Scenario {
    scenario(&format!(
        r#"{TABLE5}
{damping}
[load]
kind = "triangle"
peak_horizontal_kn = {peak_kn}
rise_time_s = {rise_s}
horizontal_lever_m = {lever_m}
peak_uplift_kn = {uplift_kn}
duration_s = {d}
"#,
        d = 2.0 * rise_s + 0.3
    ))
}

fn sliding_m(s: &Scenario, stepping: Stepping, dt_s: f64) -> f64 {
    let solver = SolverParams { dt_s, stepping, ..s.solver() };
    let s = s.clone().with_solver(solver).unwrap();
    run(s.structure(), s.load.as_ref().unwrap(), s.duration_s, false).unwrap().summary.permanent_sliding_m
}

/// The reference is fixed steps of 1e-5 s (5e-6 s moves every case by at most 6e-6 of its
/// sliding; 3.3e-4 before results version 17 placed a spring's touch-down within the step).
/// Damped (the consistent profile's dashpots) and undamped, all 12 within max(1 µm, 1 %) of it, the
/// issue's bound. Every undamped case lifts its seaward springs (the rocking of a sliding caisson
/// does so even without uplift). Measured at results version 19 (default tolerance 5e-9 m):
/// damped at most 0.04 %, undamped 0.54 % (15 kN), 0.35 % (6 kN), 0.30 % (20 kN), the others
/// below 0.04 %; at 1e-8 m, the default before, the 15 kN case was 1.05 % off at results version
/// 18 (0.93 % at 17: the figure moves by ±0.1 % with any change of the step sequence). The undamped cases'
/// error is Newmark's lag of phase over 0.3 s of rocking on one or two springs, each step's error
/// within the tolerance and all of one sign (docs/model.md §9.1, "What the estimate sees"; at
/// results version 16 the 15 kN case was 1.37 % off, its touched-down springs loaded by the whole
/// step's displacement).
#[test]
fn adaptive_steps_meet_converged_fixed_steps() {
    let mut checked = 0;
    for damping in ["", "damping_kns_per_m = 0.0"] {
        for (peak, rise, lever, up) in [
            (12.0, 0.05, 0.3, 0.0),
            (9.0, 0.1, 0.4, 1.5),
            (20.0, 0.01, 0.2, 0.0),
            (7.0, 0.2, 0.5, 0.0),
            (6.0, 0.05, 0.3, 1.0),
            (15.0, 0.02, 0.6, 2.0),
        ] {
            let s = case(damping, peak, rise, lever, up);
            let fixed = sliding_m(&s, Stepping::Fixed, 1e-5);
            let adaptive = sliding_m(&s, Stepping::Adaptive(AdaptiveParams::default()), 1e-4);
            assert!(fixed > 2e-4, "the case slides: {fixed} m");
            let err = (adaptive - fixed).abs();
            assert!(
                err <= (1e-6f64).max(0.01 * fixed.abs()),
                "`{damping}` {peak} kN, {rise} s, lever {lever} m, uplift {up} kN: adaptive {adaptive} m, fixed {fixed} m"
            );
            checked += 1;
        }
    }
    assert_eq!(checked, 12);
}

/// Issue 19: the three uplift cases of `adaptive_steps_meet_converged_fixed_steps` undamped, with the exact sticking steps
/// on, at dt_max 5e-3 s (the default), 2e-3 s and 1e-3 s, against fixed steps of 1e-5 s (a
/// converged reference: above): within max(1 µm, 0.1 %) at tolerance 1e-10 m, and at the default
/// tolerance (5e-9 m) within max(1 µm, 1 %), the issue's bound, on all 18 runs (measured at
/// results version 19: at most 0.54 % at 5e-9 m, 0.042 % at 1e-10 m; at results version 17: at
/// most 0.93 % at 1e-8 m, 0.045 % at 1e-10 m; at results version 16 the
/// last case needed 1.6 %: 1.49 %). Before the exact step had an error estimate (results version
/// 15) they were off at 1e-10 m by up to 0.67 % at dt_max 5e-3 s, 9.1 % at 2e-3 s and 2.5 % at
/// 1e-3 s (Newmark alone: at most 0.06 %), and did not converge: a step of dt_max spans most of a
/// period of the undamped vertical and rocking modes (about 7 ms), over which R is far from its
/// interpolation, and the step was kept unchecked.
#[test]
fn exact_sticking_converges_to_fixed_steps() {
    let mut checked = 0;
    let mut worst = [0.0f64; 2];
    let default_tolerance_m = AdaptiveParams::default().tolerance_m;
    for (peak, rise, lever, up) in [(9.0, 0.1, 0.4, 1.5), (6.0, 0.05, 0.3, 1.0), (15.0, 0.02, 0.6, 2.0)] {
        let s = case("damping_kns_per_m = 0.0", peak, rise, lever, up);
        assert!(s.solver().accel.exact_sticking, "the default profile steps sticking phases exactly");
        let fixed = sliding_m(&s, Stepping::Fixed, 1e-5);
        assert!(fixed > 2e-4, "the case slides: {fixed} m");
        for dt_max_s in [5e-3, 2e-3, 1e-3] {
            for (k, (tolerance_m, bound)) in [(default_tolerance_m, 0.01), (1e-10, 0.001)].into_iter().enumerate() {
                let p = AdaptiveParams { tolerance_m, dt_max_s, ..AdaptiveParams::default() };
                let adaptive = sliding_m(&s, Stepping::Adaptive(p), 1e-4);
                let err = (adaptive - fixed).abs();
                worst[k] = worst[k].max(err / fixed);
                assert!(
                    err <= (1e-6f64).max(bound * fixed),
                    "{peak} kN, {rise} s, lever {lever} m, uplift {up} kN, dt_max {dt_max_s} s, \
                     tolerance {tolerance_m} m: adaptive {adaptive} m, fixed {fixed} m"
                );
                checked += 1;
            }
        }
    }
    println!("largest relative difference: {:.2e} at {default_tolerance_m:e} m, {:.2e} at 1e-10 m", worst[0], worst[1]);
    assert_eq!(checked, 18);
}

/// The least spring normal force over a run of `s`, N (0 if a spring lifted), and its sliding, m.
fn least_normal_n(s: &Scenario, stepping: Stepping, dt_s: f64) -> (f64, f64) {
    use caisson::analysis::run::{permanent_sliding_m, Peaks};
    use caisson::dynamics::Simulation;
    let solver = SolverParams { dt_s, stepping, ..s.solver() };
    let load = s.load.clone().unwrap();
    let mut sim = Simulation::new(s.structure().model(), solver, &load);
    let mut peaks = Peaks::default();
    sim.run_until(s.duration_s, &load, &mut peaks).unwrap();
    (peaks.min_n, permanent_sliding_m(&sim))
}

/// Grazing contact: the undamped caisson under a pulse through its base (lever 0) slides and
/// rocks, and at `GRAZING_KN` its seaward spring comes within 0.3 N (about 20 nm of its
/// compression) of lifting (found by bisection on the load with fixed steps of 2.5e-6 s). On
/// loads from 1e-4 below to 1e-2 above it, across the load at which the spring starts to lift
/// (between +1e-5 and +3e-5), adaptive stepping at its defaults is within max(1 µm, 1 %) of fixed
/// steps of 1e-5 s (measured at most 0.08 % at results version 17, 0.07 % before, with lift-off
/// and re-contact located or not: this case's spring carries little shear when it lifts). The
/// reference is converged (fixed 2.5e-6 s within 4.7e-10 m; 1.8e-9 m before results version 17)
/// and continuous in the load to within the shear the lift-off resets: across
/// the threshold the sliding drops by 1.5e-7 m (0.02 %) where the neighbouring loads move it by
/// 8e-9 m, and the test holds the jump below 1 µm.
#[test]
fn grazing_contact_meets_converged_fixed_steps() {
    const GRAZING_KN: f64 = 6.45477294921875;
    let mut checked = 0;
    let mut last: Option<(f64, f64)> = None;
    for k in [-10.0, -1.0, 0.0, 1.0, 3.0, 10.0, 100.0, 1000.0] {
        let s = case("damping_kns_per_m = 0.0", GRAZING_KN * (1.0 + k * 1e-5), 0.1, 0.0, 0.0);
        let (least_n, fixed) = least_normal_n(&s, Stepping::Fixed, 1e-5);
        // Grazing at the found load, lifted from +3e-5 on.
        if k == 0.0 {
            assert!(least_n > 0.0 && least_n < 0.3, "grazing: least N {least_n} N");
        }
        assert_eq!(least_n == 0.0, k >= 3.0, "{k}e-5: least N {least_n} N");
        let (_, adaptive) = least_normal_n(&s, Stepping::Adaptive(AdaptiveParams::default()), 1e-4);
        assert!(fixed > 5e-4, "the case slides: {fixed} m");
        assert!(
            (adaptive - fixed).abs() <= (1e-6f64).max(0.01 * fixed),
            "{k}e-5: adaptive {adaptive} m, fixed {fixed} m"
        );
        if let Some((k0, f0)) = last.filter(|&(k0, _)| k - k0 <= 2.0) {
            assert!((fixed - f0).abs() <= 1e-6, "from {k0}e-5 to {k}e-5: {f0} m to {fixed} m");
        }
        last = Some((k, fixed));
        checked += 1;
    }
    assert_eq!(checked, 8);
}

/// Lift-off and re-contact are located (the steps cut at them) under the consistent profile with
/// adaptive steps: more events are located on a case that rocks and lifts than without; under
/// `seed-2011` the switch is off, so its numbers do not move.
#[test]
fn contact_events_are_located_under_the_consistent_profile() {
    use caisson::Profile;
    let s = case("damping_kns_per_m = 0.0", 15.0, 0.02, 0.6, 2.0);
    assert!(s.solver().locate_contact);
    assert!(!s.clone().with_profile(Profile::Seed2011).unwrap().solver().locate_contact);
    let events = |locate: bool| {
        let solver =
            SolverParams { locate_contact: locate, ..s.solver() }.with_adaptive(AdaptiveParams::default()).unwrap();
        let load = s.load.clone().unwrap();
        let mut sim = caisson::dynamics::Simulation::new(s.structure().model(), solver, &load);
        sim.run_until(s.duration_s, &load, &mut ()).unwrap();
        sim.stats.located_events
    };
    let (with, without) = (events(true), events(false));
    assert!(with > without + 10, "{with} events located with contact, {without} without");
}

/// The 15-wave test (`examples/fifteen_waves.toml`, the seed-2011 profile) with the adaptive
/// stepper at its defaults within 0.2 % of fixed steps of 1e-4 s (the issue's bound; measured
/// 0.05 % at results version 17 too; fixed 2.5e-5 s is 0.007 % from 1e-4 s, so the reference is
/// converged well within it). Not asserted: the same train under the consistent profile, which
/// rocks it to 0.021 rad, is 0.46 % from fixed 1e-4 s at results version 18 (0.35 % at 17), and
/// 0.51 % from the converged sliding (16.649 mm; 0.93 % at 17; 0.10 % at tolerance 1e-9 m): the
/// sum of the rocking phases' local errors; fixed 1e-4 s is 0.05 % from it (0.59 % at 17, first
/// order then: `verify_convergence_order.rs`).
#[test]
fn fifteen_waves_adaptive_within_0_2_percent_of_fixed_steps() {
    let s = support::example("fifteen_waves.toml");
    assert_eq!(s.solver().stepping, Stepping::Fixed);
    assert_eq!(s.solver().dt_s, 1e-4);
    let fixed = sliding_m(&s, Stepping::Fixed, 1e-4);
    let adaptive = sliding_m(&s, Stepping::Adaptive(AdaptiveParams::default()), 1e-4);
    assert!(fixed > 0.01, "it slides: {fixed} m");
    assert!((adaptive / fixed - 1.0).abs() <= 2e-3, "adaptive {adaptive} m, fixed {fixed} m");
}

/// The 15-wave test's adaptive steps each meet the tolerance: none is accepted at dt_min over it
/// (`SolverStats::forced_min_steps`). Its springs lift and touch down while the others stick;
/// when a touch-down's error (∝ h, `seed-2011`) was held per unit step with the sticking phase's
/// Newmark error (times T_x/(2h)), it did not shrink with the step: 16 steps were forced at
/// dt_min, 184 shorter than 1e-5 s, 10 152 steps in all (9 718 since, the step rejected for a
/// touch-down retaken to end just short of it).
#[test]
fn fifteen_waves_adaptive_steps_meet_the_tolerance() {
    let s = support::example("fifteen_waves.toml");
    let solver = s.solver().with_adaptive(AdaptiveParams::default()).unwrap();
    let load = s.load.clone().unwrap();
    let mut sim = caisson::dynamics::Simulation::new(s.structure().model(), solver, &load);
    sim.run_until(s.duration_s, &load, &mut ()).unwrap();
    let stats = sim.stats;
    assert!(stats.steps > 5000 && stats.min_step_s < 1e-3, "{stats:?}");
    assert_eq!(stats.forced_min_steps, 0, "{stats:?}");
    assert!(stats.min_step_s > AdaptiveParams::default().dt_min_s, "{stats:?}");
}

/// The waves of the design example that reach the dynamic model (heights about its sliding
/// threshold, from sticking throughout to sliding; as in `sticking.rs`), each from rest: at the
/// example's own controls (tolerance 1e-6 m, dt_max 0.5 s) with the all-sticking phases solved
/// exactly (`dynamics::exact`, the default), and by Newmark steps at the controls the example had
/// before (dt_max 0.2 s), against a converged reference (Newmark, tolerance 1e-9 m, dt_max
/// 0.02 s). Both within max(1 µm, 1 %) of the reference's sliding (measured at results version
/// 18: exact at most 6.7 µm, 0.42 %; Newmark 5.4 µm, 0.56 %; at 17: 1.3 µm, 0.13 % and 1.6 µm,
/// 0.14 %; the example's tolerance is 1e-6 m; the reference is converged: tolerance 1e-10 and
/// 1e-11 m and fixed steps of 1e-4 s agree with it within 1e-7 m),
/// 1 % of its peak displacement and rotation
/// (measured at results version 18, the peaks read on each step's cubic Hermite interpolant:
/// exact 0.025 % and 0.017 %, Newmark 0.019 % and 0.015 %; read at the steps' ends, 0.5 s apart
/// in an exact phase, 0.54 % and 0.16 %, 0.09 % and 0.09 %), and 1e-3 W'/n of its smallest spring normal force
/// (measured 8e-4 and 5e-4); the exact path takes a tenth of the steps or more (measured 17 %;
/// the sliding waves step by Newmark while they slip, and an exact step over the tolerance is
/// taken by Newmark: before the exact step had an error estimate, results version 15, 203 of
/// 895, 23 %, with the sliding at most 1.0 µm, 0.19 % off) and fewer steps in all (measured
/// 1 000 against 1 435).
#[test]
fn exact_sticking_phases_meet_the_newmark_steps() {
    let sc = support::example("design_breakwater.toml");
    let Stepping::Adaptive(controls) = sc.solver().stepping else { panic!("the example steps adaptively") };
    let run = |exact: bool, p: AdaptiveParams| {
        let solver = SolverParams {
            accel: caisson::dynamics::Accel { exact_sticking: exact, ..sc.solver().accel },
            ..sc.solver()
        }
        .with_adaptive(p)
        .unwrap();
        // Sliding, peak u_x and θ, least N.
        support::design_waves(solver).into_iter().map(|(v, s)| ([v[0], v[1], v[2], v[5]], s)).collect::<Vec<_>>()
    };
    let reference = run(false, AdaptiveParams { tolerance_m: 1e-9, dt_max_s: 0.02, ..controls });
    // Newmark at the controls the example had before the exact steps (dt_max 0.2 s).
    let (exact, newmark) = (run(true, controls), run(false, AdaptiveParams { dt_max_s: 0.2, ..controls }));
    let n_bar = sc.structure().model().weight_n / 10.0;
    let (mut checked, mut sliding_waves, mut exact_steps, mut steps, mut newmark_steps) = (0, 0, 0, 0, 0);
    // Largest |sliding − reference| (m), relative peak u_x and θ, relative sliding: exact, Newmark.
    let mut worst = [[0.0f64; 4]; 2];
    let mut worst_n = [0.0f64; 2];
    for (i, (r, (e, es))) in reference.iter().zip(&exact).enumerate() {
        for (what, x) in [("exact", e), ("newmark", &newmark[i].0)] {
            let r = r.0;
            let within = |k: usize, bound: f64| (x[k] - r[k]).abs() <= bound;
            assert!(
                within(0, (1e-6f64).max(0.01 * r[0].abs())),
                "wave {i}, {what}: sliding {} m, reference {} m",
                x[0],
                r[0]
            );
            assert!(within(1, 1e-2 * r[1].abs()), "wave {i}, {what}: peak u_x {} m, reference {} m", x[1], r[1]);
            assert!(within(2, 1e-2 * r[2].abs()), "wave {i}, {what}: peak θ {} rad, reference {} rad", x[2], r[2]);
            worst_n[usize::from(what == "newmark")] =
                worst_n[usize::from(what == "newmark")].max((x[3] - r[3]).abs() / n_bar);
            assert!(within(3, 1e-3 * n_bar), "wave {i}, {what}: least N {} N, reference {} N", x[3], r[3]);
            let w = &mut worst[usize::from(what == "newmark")];
            w[0] = w[0].max((x[0] - r[0]).abs());
            w[1] = w[1].max((x[1] - r[1]).abs() / r[1].abs());
            w[2] = w[2].max((x[2] - r[2]).abs() / r[2].abs());
            if r[0].abs() > 0.0 {
                w[3] = w[3].max((x[0] - r[0]).abs() / r[0].abs());
            }
            checked += 1;
        }
        sliding_waves += usize::from(r.0[0] > 1e-4);
        exact_steps += es.exact_steps;
        steps += es.steps;
        newmark_steps += newmark[i].1.steps;
        assert_eq!(newmark[i].1.exact_steps, 0, "the switch turns the exact path off");
    }
    println!(
        "exact (sliding m, u_x, θ, sliding relative) {:?}, Newmark {:?}; {exact_steps} exact of {steps} steps, {newmark_steps} Newmark steps without",
        worst[0], worst[1]
    );
    println!("least N: exact {:.2e} W'/n, Newmark {:.2e} W'/n", worst_n[0], worst_n[1]);
    assert_eq!(checked, 20);
    assert!((3..10).contains(&sliding_waves), "{sliding_waves} waves slide more than 0.1 mm");
    assert!(exact_steps as f64 > 0.1 * steps as f64, "{exact_steps} exact of {steps} steps");
    assert!(steps < newmark_steps, "{steps} steps with the exact path, {newmark_steps} without");
}

/// The exact sticking steps belong to the default profile: a scenario under `seed-2011`, read
/// so or switched to it, keeps Newmark's steps through its sticking phases (its numbers
/// reproduce the paper), and switched back takes them again.
#[test]
fn exact_sticking_follows_the_profile() {
    use caisson::Profile;
    let design = support::example("design_breakwater.toml");
    let seed = design.clone().with_profile(Profile::Seed2011).unwrap();
    let back = seed.clone().with_profile(Profile::Consistent).unwrap();
    let fifteen = support::example("fifteen_waves.toml");
    let cases = [(&design, true), (&seed, false), (&back, true), (&fifteen, false)];
    for (i, (sc, exact)) in cases.iter().enumerate() {
        assert_eq!(sc.solver().accel.exact_sticking, *exact, "case {i}");
    }
    // The design waves with the seed-2011 scenario's solver controls take no exact step; with
    // the default one's they do.
    let steps = |sc: &Scenario| support::design_waves(sc.solver()).iter().map(|(_, s)| s.exact_steps).sum::<u64>();
    assert_eq!(steps(&seed), 0);
    assert!(steps(&design) > 100, "{} exact steps", steps(&design));
}

/// Adaptive stepping at its defaults (first step 1e-4 s) and fixed steps of dt0/16 = 6.25e-6 s
/// on a held-out scenario file of `tests/data/accuracy/`, with the first step replaced by
/// `dt0_s`: (permanent sliding m, peak u_x m, largest |θ| rad) of each.
fn adaptive_and_converged(s: &Scenario, dt0_s: f64) -> ([f64; 3], [f64; 3]) {
    let one = |stepping: Stepping, dt_s: f64| {
        let solver = SolverParams { dt_s, stepping, ..s.solver() };
        let s = s.clone().with_solver(solver).unwrap();
        let r = run(s.structure(), s.load.as_ref().unwrap(), s.duration_s, false).unwrap().summary;
        [r.permanent_sliding_m, r.max_horizontal_displacement_m, r.max_rotation_rad]
    };
    (one(Stepping::Adaptive(AdaptiveParams::for_first_step(dt0_s)), dt0_s), one(Stepping::Fixed, 6.25e-6))
}

fn accuracy_case(name: &str) -> Scenario {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/accuracy").join(name);
    caisson::scenario::load(&path).unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// Issue 34's second held-out case (`tests/data/accuracy/pari_ten_springs.toml`: the PARI flume
/// caisson, seed-2011 profile with the coupled mass, 10 springs, μ_s = 0.8, μ_d = 0.3, no dashpot,
/// a 0.019 s triangle with uplift): the caisson rocks on its shoreward springs after the pulse and
/// its seaward springs touch down again and again while it slides back. Under `seed-2011` a
/// touch-down is not located, so the spring takes the step's start u_x,n as its slip position,
/// λ Δu_x from where it touches (λ the fraction of the step at the touch): an error of the slip
/// position of first order in the step that the Zienkiewicz-Xie estimate of the displacements
/// does not see. The sliding back then depended on where the steps fell: from first steps of
/// 1e-3 to 1e-5 s, 4.59 to 4.97 mm against the converged 4.9646 mm (up to −7.5 %; the issue's
/// 4.722 mm). With λ |Δu_x| in the slip positions' estimate (`slip_error_m`), measured 4.895 to
/// 4.983 mm: within max(1 µm, 1.5 %) on all six (1.4 % at 5e-4 s, the others within 0.4 %),
/// and the peak u_x within 0.2 %. With the sticking steps held per unit step (results version
/// 24): −1.34 %, −1.31 %, +0.23 %, −1.34 %, −0.11 %, −0.06 % (first steps 1e-3 to 1e-5 s): the
/// runs 1.3 % off missed a slip of two toe springs at 0.186 s (1 ms, the caisson on five
/// springs) that the converged run has. Not a step over it: the steps there are 25-50 µs, and the
/// elastic displacement of the toe spring peaks at 0.986 e_s instead of e_s, the state being
/// already off by 1-3 µm in the springs' u_x − s_i (u_x 7 µm off from 0.1 s on; tolerance /2 and
/// /4 missed the slip on all six first steps, /10 and /100 met it). The error was born at the
/// slip onsets: with μ_d < μ_s the friction drops at an onset, and the step landed on it had
/// weighed the drop by h/2 in its trapezoidal velocity (the 31 µs step to the onset of all ten
/// springs at 0.0111 s left u̇_x 102 µm/s off, 1 % of it), a first-order error that the
/// flights and landings after it grew (module docs of `caisson::dynamics`, "Events";
/// `Simulation::correct_onset_jumps`). Corrected: within 0.01 % on all six (measured 9e-5 at
/// most); at loads from −3e-3 to +3e-3 of the case's (11 loads, 66 runs) within 0.03 % but at
/// +1e-3, where all six agree to 0.01 % and are 1.43 % below the converged run (fixed steps of
/// 6.25e-6 to 1.5625e-6 s within 0.006 % of one another there): the same toe slip, marginal
/// there, found 0.19 ms late and 0.25 ms long against 0.73 ms, the second toe spring's missed
/// (met at a tenth of the tolerance, not at a quarter); before, 33 of the 66 runs were beyond
/// 1 %. The peak within 0.2 %.
#[test]
fn pari_ten_springs_meets_converged_fixed_steps() {
    let s = accuracy_case("pari_ten_springs.toml");
    let mut checked = 0;
    let mut worst = 0.0f64;
    let converged = adaptive_and_converged(&s, 1e-4).1;
    assert!((converged[0] - 4.9646e-3).abs() < 1e-6, "converged sliding {} m", converged[0]);
    for dt0_s in [1e-3, 5e-4, 2e-4, 1e-4, 5e-5, 1e-5] {
        let (adaptive, _) = adaptive_and_converged(&s, dt0_s);
        let rel = (adaptive[0] - converged[0]).abs() / converged[0];
        worst = worst.max(rel);
        assert!(rel <= 0.01, "first step {dt0_s} s: adaptive {} m, converged {} m", adaptive[0], converged[0]);
        assert!((adaptive[1] - converged[1]).abs() <= 2e-3 * converged[1], "first step {dt0_s} s: peak {:?}", adaptive);
        checked += 1;
    }
    println!("pari_ten_springs: worst relative error of the sliding {worst:.2e}");
    assert_eq!(checked, 6);
}

/// Issue 34's first held-out case (`tests/data/accuracy/pari_two_springs.toml`: diagonal mass,
/// 2 springs, μ_s = 0.6, μ_d = 0.4, a 0.06 s triangle with uplift) is a knife's edge of the
/// model: its seaward spring lifts, the caisson stands on the shoreward spring alone, and the
/// spring's elastic displacement u_x − s peaks 7.5e-11 m (2e-6 of it) above its static limit
/// e_s = μ_s W'/K_x = 32.96 µm. Reaching e_s releases (μ_s − μ_d) N at once, so the converged
/// sliding is discontinuous in the load: 13.19 mm at the case's 9.1266 kN and at 9.12655 kN,
/// 12.73 mm at 9.1265 kN (−1.1e-5 of it). The converged answer is well defined (fixed steps of
/// 1e-4 to 1.6e-6 s within 0.06 % of one another: average acceleration keeps the amplitude of
/// the rocking whatever the step) but ill-conditioned: a method meets it only with u_x − s
/// within 7.5e-11 m at the peak, 1/70 of the default tolerance. Measured (results version 24
/// with the sticking steps held per unit step): adaptive at tolerances 5e-9 to 5e-12 m, 12.72
/// to 12.73 mm, the branch below the edge, converging to the other side only beyond that; at
/// the default tolerance adaptive follows the branch below the edge up to 9.13 kN (+4e-4) and
/// the branch above from 9.135 kN (+9.4e-4: an error of about 3e-8 m in u_x − s at the peak;
/// from 9.15 kN before, +2.6e-3). Held here: the edge itself (the converged results on either
/// side of it), and the adaptive result within 1 % of the converged one on either branch a
/// little further from the edge (−1.1e-5 below, +1.5e-3 above), which it follows.
#[test]
fn pari_two_springs_is_a_knife_edge_of_the_model() {
    let s = accuracy_case("pari_two_springs.toml");
    let with_peak = |kn: f64| {
        let text = std::fs::read_to_string(
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/accuracy/pari_two_springs.toml"),
        )
        .unwrap();
        support::scenario(&text.replace("peak_horizontal_kn = 9.1266", &format!("peak_horizontal_kn = {kn}")))
    };
    let (adaptive, at_case) = adaptive_and_converged(&s, 1e-4);
    let (adaptive_below, below) = adaptive_and_converged(&with_peak(9.1265), 1e-4);
    let (_, just_above) = adaptive_and_converged(&with_peak(9.12655), 1e-4);
    let (adaptive_above, above) = adaptive_and_converged(&with_peak(9.14), 1e-4);
    // The edge: 3.5 % between two loads 1.1e-5 apart, the case above it.
    assert!(at_case[0] > 1.03 * below[0], "at the case {} m, 1.1e-5 below {} m", at_case[0], below[0]);
    assert!((just_above[0] - at_case[0]).abs() < 1e-3 * at_case[0], "{} m, {} m", just_above[0], at_case[0]);
    assert!((above[0] - at_case[0]).abs() < 1e-2 * at_case[0], "{} m, {} m", above[0], at_case[0]);
    // Either branch, away from the edge: the adaptive result within 1 % of the converged one.
    let mut checked = 0;
    for (what, a, c) in [("below", adaptive_below, below), ("above", adaptive_above, above)] {
        assert!((a[0] - c[0]).abs() <= 0.01 * c[0], "{what} the edge: adaptive {} m, converged {} m", a[0], c[0]);
        checked += 1;
    }
    assert_eq!(checked, 2);
    println!(
        "two springs: adaptive {:.6e} m, converged {:.6e} m, below the edge {:.6e} m (adaptive {:.6e}), 1.5e-3 above {:.6e} m (adaptive {:.6e})",
        adaptive[0], at_case[0], below[0], adaptive_below[0], above[0], adaptive_above[0]
    );
}

/// Issue 34's third held-out case (`tests/data/accuracy/grazing_toe.toml`: the seed's Table 5
/// caisson undamped under the consistent profile, a 0.1 s triangle 0.1 m above its base): it
/// slides (0.139 mm) and rocks, and its seaward spring comes within 0.05 N of lifting (least N
/// of fixed steps of 6.25e-6 s; 3.125e-6 s and 1e-5 s within 0.4 mN of it, and their sliding
/// within 1e-10 m). A lift resets the spring's shear, and the run that lifts it (the load 1.8e-5
/// higher, 5.6837 kN) slides 2.1 % more: a wrong lift, one step's error in u_y of that spring,
/// would be seen by the bound. Adaptive stepping at its defaults (first steps 1e-3 to 1e-5 s)
/// within max(1 µm, 1 %) of the converged sliding, not lifting it either. Measured at results
/// version 24 with the sticking steps held per unit step: 0.041 % (least N 0.31 N; at 5.6837 kN
/// adaptive does not lift the spring either and is 2.07 % below the converged run that does,
/// the same knife's edge as `pari_two_springs_is_a_knife_edge_of_the_model`, 1e-5 of the load).
#[test]
fn grazing_toe_meets_converged_fixed_steps() {
    let s = accuracy_case("grazing_toe.toml");
    let (least_n, converged) = least_normal_n(&s, Stepping::Fixed, 6.25e-6);
    assert!(least_n > 0.0 && least_n < 0.3, "grazing: least N {least_n} N");
    assert!(converged > 1e-4, "it slides: {converged} m");
    let text = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/accuracy/grazing_toe.toml"),
    )
    .unwrap();
    let lifting = support::scenario(&text.replace("peak_horizontal_kn = 5.6836", "peak_horizontal_kn = 5.6837"));
    let (least_lifting, sliding_lifting) = least_normal_n(&lifting, Stepping::Fixed, 6.25e-6);
    assert_eq!(least_lifting, 0.0, "1.8e-5 more load lifts the spring");
    assert!(sliding_lifting > 1.015 * converged, "the lift's shear reset: {sliding_lifting} m against {converged} m");
    let mut checked = 0;
    let mut worst = 0.0f64;
    for dt0_s in [1e-3, 1e-4, 1e-5] {
        let solver =
            SolverParams { dt_s: dt0_s, ..s.solver() }.with_adaptive(AdaptiveParams::for_first_step(dt0_s)).unwrap();
        let (_, adaptive) = least_normal_n(&s.clone().with_solver(solver).unwrap(), solver.stepping, dt0_s);
        let err = (adaptive - converged).abs();
        worst = worst.max(err / converged);
        assert!(
            err <= (1e-6f64).max(0.01 * converged),
            "first step {dt0_s} s: adaptive {adaptive} m, converged {converged} m"
        );
        checked += 1;
    }
    println!("grazing toe: worst relative error of the sliding {worst:.2e}");
    assert_eq!(checked, 3);
}

/// Family case `k` drawn from `rng` (the draws in order: every case draws them all): its scenario
/// text, its profile and a one-line description.
fn family_case(rng: &mut rand_chacha::ChaCha8Rng, k: usize) -> (String, String) {
    use rand::Rng;
    let profile = if k.is_multiple_of(2) { "consistent" } else { "seed-2011" };
    let springs = rng.gen_range(2..=40usize);
    let mu_s: f64 = rng.gen_range(0.5..0.8);
    let mu_d = mu_s - rng.gen_range(0.1..0.3);
    let damping = if rng.gen_bool(0.5) { 0.0 } else { 20.0 };
    let impulsive = rng.gen_bool(0.5);
    let (rise, factor) = if impulsive {
        (rng.gen_range(0.005..0.03), rng.gen_range(1.1..2.0))
    } else {
        (rng.gen_range(0.1..0.4), rng.gen_range(1.0..1.4))
    };
    let peak = factor * mu_s * 8.24;
    let lever: f64 = rng.gen_range(0.1..0.8);
    let uplift = if rng.gen_bool(0.5) { rng.gen_range(0.1..0.25) * peak } else { 0.0 };
    let text = format!(
        r#"
[model]
profile = "{profile}"
[caisson]
width_m = 1.0
height_m = 1.12
base_depth_m = 0.8
weight_in_water_kn = 8.24
mass_kg = 1464.0
cog_height_m = 0.56
inertia_kg_m2 = 275.04
[foundation]
springs = {springs}
mu_static = {mu_s}
mu_dynamic = {mu_d}
kx_kn_per_m = 1.5e5
ky_kn_per_m = 1.4e5
damping_kns_per_m = {damping}
added_mass = false
[load]
kind = "triangle"
peak_horizontal_kn = {peak}
rise_time_s = {rise}
horizontal_lever_m = {lever}
peak_uplift_kn = {uplift}
duration_s = {d}
"#,
        d = 2.0 * rise + 0.3
    );
    let about = format!(
        "{profile}, {springs} springs, μ {mu_s:.2}/{mu_d:.2}, C {damping}, rise {rise:.3} s, {peak:.2} kN at {lever:.2} m, uplift {uplift:.2} kN"
    );
    (text, about)
}

/// A random family of held-out cases (seeded, so the same cases every run): the PARI flume
/// caisson (B = 1 m, W' 8.24 kN, m 1464 kg) under both profiles, 2 to 40 springs, μ_s from 0.5 to
/// 0.8 with μ_d 0.1 to 0.3 below it, K_x 1.5e5 and K_y 1.4e5 kN/m, undamped or with C = 20 kN·s/m,
/// without added mass; a triangle impulsive (rise 5 to 30 ms) or pulsating (0.1 to 0.4 s), 1.1 to
/// 2.0 times μ_s W' (impulsive) or 1.0 to 1.4 (pulsating), at 0.1 to 0.8 m, with uplift of 0.1
/// to 0.25 of it or none. Adaptive stepping at its defaults against fixed steps of dt0/16 =
/// 6.25e-6 s (dt0/32 within 0.04 % of it on every case beyond the bound): the permanent sliding
/// and the peak u_x within max(1 µm, 1 %). A case whose converged run rotates the caisson beyond
/// the model's small rotations (`ROCKING_LIMIT_RAD`, 0.01 rad: the `rocking` warning tells a user
/// the model does not hold there) is printed but not held to the bound: two of the 40 (case 28,
/// 0.078 rad, which ends airborne, below; case 35, 0.015 rad, within the bound). Knife's edges of the model
/// (`pari_two_springs_is_a_knife_edge_of_the_model`) can fall in such a family; the count of
/// cases beyond the bound is held at what was measured (a ratchet: the test fails if it grows),
/// and every case is printed with its errors. Measured: 13 of 40 before the sticking steps were
/// held per unit step (results version 24: seven of them `seed-2011` cases whose slip onset
/// moved with Newmark's phase lag of the sticking vibration, up to 11 % and 16 %; module docs of
/// `caisson::dynamics`), 3 after: three undamped cases of the consistent profile that rock on
/// part of their base (1.5 %, 2.0 % and 12.7 % in the sliding), where a slip onset or a lift of
/// a toe spring that converged steps find in a short excursion is found or not. With the
/// friction's jump at slip onsets taken out of the adaptive steps (`correct_onset_jumps`, module
/// docs of `caisson::dynamics`, "Events"), still 3: case 12 met (sliding +1.52 % → +0.96 %, peak
/// +0.41 % → +0.83 %), case 16 closer (sliding −2.25 % → +0.71 %, peak −1.80 % → +1.27 %), case
/// 28 as before (+12.7 % → +11.6 %, below), and case 22 (37 springs, sliding 39 µm) now beyond
/// the 1 µm floor (+0.88 µm → +1.60 µm, its peak −0.63 % → −0.03 %); case 2, the most sensitive
/// (+0.03 % at the default tolerance but +0.96 % at 1/10 and +1.55 % at dt_max 1 ms before),
/// −0.05 %.
///
/// Diagnosed (issue 34 item 4; `diagnose_family_case`, run with `CAISSON_CASE=k`; results
/// version 24): no step kind or quantity that the error estimate ignores stands out, and no fix
/// was made. Each run traced step by step against fixed steps of 6.25e-6 s; first step end where a
/// quantity departs by more than 1e-3 of its largest magnitude over the run:
/// - case 28 (21 springs, μ 0.68/0.56, a 0.35 s pulsating triangle at 0.79 m): u_x, u_y and θ
///   agree to 1e-3 until 0.8715 s (u_x first: a Newmark step of 9.1e-5 s while the caisson rocks
///   on part of its base after its one slip episode, 0.8486-0.8631 s in both runs). From 0.8789 s
///   (adaptive; 0.8792 s converged) to the run's end, 0.9915 s, no spring is in contact: the
///   caisson is airborne, 3.2 cm up, tumbling at θ̇ = −0.3242 rad/s (converged −0.3237: 0.16 %),
///   so its "permanent sliding" is the base centre's u_x in flight, which grows at v_x,G + h_G θ̇,
///   3.60e-3 m/s (converged 3.12e-3), the difference of two terms of 0.18 m/s: a 0.16 % error of
///   θ̇ becomes 15 % of that rate and the 12.7 %. Smaller steps move it: +2.7 % at a tenth of the
///   tolerance, +0.79 % at a hundredth, +3.1 % at dt_max/5; with the exact sticking steps off
///   +5.9 %, +8.7 %, +2.4 %, +6.7 %. The case measures a flight, not a permanent sliding (and
///   it rotates up to 0.078 rad, beyond the model's validity: not held since issue 34's third
///   session).
/// - case 12 (12 springs, impulsive, no uplift): θ departs first, at 0.0190 s (a Newmark step of
///   5.1e-4 s in the main slide, 0.0145-0.054 s), then the rocking that follows lags: θ's upward
///   zero crossings 0.12, 0.32, 0.69 and 1.2 ms behind at 0.096, 0.167, 0.237 and 0.306 s (a
///   period of about 70 ms; mostly exact partial-contact steps there), and the toe springs' slips
///   move (adaptive 0.0835-0.0846 and 0.1415-0.1437 s, converged 0.1117-0.1128 s instead).
///   +1.52 % at the default tolerance, +0.87 % and +0.92 % at 1/10 and 1/100 of it, −0.01 % at
///   1/1000; +0.43 % at dt_max/5; exact steps off +0.19 %, +0.96 %, +0.95 %, +0.24 %, +1.36 %.
/// - case 16 (6 springs, impulsive, uplift): u_x departs at 0.1322 s (a Newmark step of 6.9e-4 s
///   in the third slip episode); the second episode starts 0.23 ms late and lasts 1.03 ms
///   against 0.81 ms. −2.25 % at the default tolerance, −1.21 % at 1/10, +0.09 % at 1/100;
///   −1.26 % at dt_max/5; exact steps off −1.21 %, −0.16 %, +0.08 %, −1.21 %.
///
/// Issue 34 item 4, results version 28 (the exact step's error estimate with the velocity over ω_x:
/// module docs of `caisson::dynamics::exact`): each step of cases 16 and 22 integrated again from
/// its start by fixed steps of 2.5e-7 s (its true local error), against the error estimate. The
/// exact sticking steps' estimate (R's interpolation in the middle) was within 30 % of the true
/// error of the end's displacement, but the true velocity error over ω_x was 10 and 5 times it at
/// dt_max/8 and dt_max/4 (2/(ω_x h): a force error through the step's middle moves the velocity by
/// 2/h times the displacement), and in the rocking phases of both cases the exact steps left the
/// most of that error (case 22 up to 0.0556 s, the Euclidean norm of the six: 3.1e-7 m summed over
/// 23 full-contact exact steps, 1.2e-7 m over 24 partial ones, 2.4e-7 m over 69 Newmark steps in
/// partial contact). Case 16 met: sliding +0.71 % → −0.21 %, peak +1.27 % → +0.02 % (at tolerances
/// 2.5e-9 to 5e-11 m within 0.27 %), for more steps on these undamped rocking cases (case 16 739 →
/// 1 569, case 22 911 → 1 396; design_500 0.26 % fewer instructions). Case 22 (37 springs,
/// undamped, sliding 39 µm) still beyond the 1 µm floor (+1.60 µm → +1.99 µm) and a knife's edge:
/// the converged run is converged (fixed steps of 6.25e-6, 3.125e-6 and 1.5625e-6 s: 39.3716,
/// 39.3730, 39.3732 µm), but adaptive stepping at tolerances from 5e-9 to 5e-10 m gives 41.36,
/// 41.39, 41.32, 41.28 µm, and 39.40 µm at 5e-11 m (before: 40.97 µm at 5e-9 m, 39.44 µm at 5e-10
/// m): two branches, not a convergence. The branch is a slip of one toe spring at 0.2550-0.2556 s
/// (0.44 µm) in the converged run that the adaptive run does not have, then the last slip episode
/// (0.265-0.270 s) 9.2 µm against 11.1 µm. The state's difference before it is not the adaptive
/// steps' own: it grows from 4e-7 to 1.7e-6 m (the Euclidean norm of u_x, u_y, θ B/2 and their
/// rates over ω_x) from 0.228 to 0.234 s, a sequence of touch-downs of heel springs, while fixed
/// steps of 6.25e-6 s from the adaptive state at 0.2279 s meet the adaptive one at 0.2349 s within
/// 6e-9 m (its rates 2.5e-5 m/s): the touch-downs amplify the difference carried into them fourfold
/// in 6 ms (and the slip episode at 0.057 s sixfold before the fix). Held at one miss.
///
/// Case 22 met (results version 28: the Newmark steps with springs lifted held per unit step where
/// the vibration outlives half its period; module docs of `caisson::dynamics::adaptive`,
/// `coherent_partial_s`): sliding +1.99 µm → +0.04 µm (39.41 µm against 39.37; 39.41 and 39.39 µm
/// at tolerances 1.6e-9 and 5e-10 m, where they were 41.36 and 41.28: converging now), its
/// steps 1 396 → 2 094 (every such step held per unit step: 2 478, and 5.4 % more instructions
/// on design_500). Diagnosed: every adaptive step integrated again from its start by fixed
/// steps of 2.5e-7 s; no step kind's error departs from the tolerance by a fixed amount (no
/// threshold), but the 437 Newmark steps taken among springs lifted before 0.228 s (the exact
/// path declined them while it bracketed touch-downs and lift-offs) were held per step: each
/// within the tolerance (their displacement errors summed to 4.8e-7 m, as their estimates did),
/// the state's difference from the converged run 4e-7 to 5e-7 m from 0.06 s on (the difference
/// the touch-downs at 0.228 s amplify), and 2.8e-7 m still at a tenth of the tolerance, 8e-8 at a
/// hundredth (against 1e-7 m for fixed steps of 5e-5 s, which meet the converged sliding). Their
/// velocity error over ω_x was 1.5 times the estimate in the median, up to 37 times (the first
/// such step 0.021358-0.021850 s, h 4.9e-4 s after an exact step: estimate 2.8e-9 m, true
/// error 6.5e-9 m and 1.47e-5 m/s, 4.6e-8 m over ω_x, where ü_x changes sign and Δü over the
/// step is small): an estimate of it from the previous step's acceleration catches that step
/// but not those landed on events, and left the run on the other branch (41.38 µm). Case 28
/// (outside the model's validity) +12.4 → +0.4 times the bound, case 24 0.39 → 0.08, case 16
/// 0.21 → 0.48; worst of those held 0.92 (case 12).
///
/// Undamped rocking with friction: the answers jump between branches as the tolerance shrinks
/// (not monotone in it, with the exact steps on or off), as on a knife's edge. The exact steps
/// make all three worse at the default tolerance (exact steps off: +0.19 %, −1.21 %, +5.9 %) but
/// case 28 better at 1/10 of it, so switching them off is no fix. A previous diagnosis sampled
/// the cubic Hermite of the accepted steps and found no margin dipping below zero inside a step.
#[test]
fn random_family_meets_converged_fixed_steps() {
    use caisson::analysis::limits::ROCKING_LIMIT_RAD;
    use rand::SeedableRng;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(34);
    // Cases held to the bound, those beyond it, those outside the model's validity, and the
    // worst ratio of the error to the bound (sliding or peak) of those held.
    let (mut checked, mut missed, mut outside, mut worst) = (0, 0, 0, 0.0f64);
    for k in 0..FAMILY_CASES {
        let (text, about) = family_case(&mut rng, k);
        let s = support::scenario(&text);
        let (adaptive, converged) = adaptive_and_converged(&s, 1e-4);
        let err = [(adaptive[0] - converged[0]).abs(), (adaptive[1] - converged[1]).abs()];
        let bound = [(1e-6f64).max(0.01 * converged[0].abs()), (1e-6f64).max(0.01 * converged[1].abs())];
        let beyond = err[0] > bound[0] || err[1] > bound[1];
        // Rotated beyond the model's small rotations (the `rocking` warning): not held.
        let invalid = converged[2] > ROCKING_LIMIT_RAD;
        println!(
            "case {k}: {about}: sliding {:.4e} m (converged {:.4e}), peak {:.4e} m ({:.4e}), |θ| up to {:.2e} rad{}",
            adaptive[0],
            converged[0],
            adaptive[1],
            converged[1],
            converged[2],
            match (invalid, beyond) {
                (true, _) => "  OUTSIDE the model's validity (rocking beyond 0.01 rad): not held",
                (false, true) => "  MISS",
                (false, false) => "",
            }
        );
        if invalid {
            outside += 1;
            continue;
        }
        worst = worst.max(err[0] / bound[0]).max(err[1] / bound[1]);
        missed += usize::from(beyond);
        checked += 1;
    }
    println!(
        "{missed} of {checked} beyond max(1 µm, 1 %), {outside} outside the model's validity; worst error {worst:.2} times the bound"
    );
    assert_eq!((checked, outside), (FAMILY_CASES - FAMILY_OUTSIDE, FAMILY_OUTSIDE));
    // The ratchet at 0 (`FAMILY_MISSES`): `missed <= FAMILY_MISSES` is `==` there.
    assert_eq!(missed, FAMILY_MISSES, "{missed} of {checked} cases beyond max(1 µm, 1 %)");
}

/// The family's size, the cases whose converged run rotates beyond the model's validity
/// (`ROCKING_LIMIT_RAD`, 0.01 rad: cases 28 and 35), and the cases held to the bound that are
/// beyond it, measured (the ratchet): none of the 38 held since results version 28 (case 22
/// before, and case 16 too before results version 28; above).
const FAMILY_CASES: usize = 40;
const FAMILY_OUTSIDE: usize = 2;
const FAMILY_MISSES: usize = 0;

/// One committed step of a traced run: time, whether it was an exact sticking step (no Newton
/// iteration), u = (u_x, u_y, θ), the least normal force of the springs, N, the least friction
/// margin μ_s N − |F| of the springs in contact, N, and whether any spring slips.
type TraceRow = (f64, bool, [f64; 3], f64, f64, bool);

struct Trace {
    mu_s: f64,
    rows: Vec<TraceRow>,
}

impl caisson::dynamics::Observer for Trace {
    fn observe(&mut self, v: &caisson::dynamics::StepView<'_>) {
        let least_n = v.springs.iter().map(|r| r.normal_n).fold(f64::INFINITY, f64::min);
        let margin = v
            .springs
            .iter()
            .filter(|r| r.normal_n > 0.0)
            .map(|r| self.mu_s * r.normal_n - r.shear_n.abs())
            .fold(f64::INFINITY, f64::min);
        let sliding = v.state.springs.iter().any(|s| s.sliding);
        self.rows.push((v.t_s, v.iterations == 0, v.state.u, least_n, margin, sliding));
    }
}

/// Diagnosis of the family's case `CAISSON_CASE` (28 by default): the adaptive run at its
/// defaults and fixed steps of 6.25e-6 s traced step by step; prints the scenario, and for each
/// quantity the first adaptive step end where it differs from the converged run (interpolated
/// linearly between its steps) by more than 1e-3 of the quantity's largest magnitude over the
/// run, with the step's kind and length there. Slow (a fixed run of 6.25e-6 s): ignored.
#[test]
#[ignore]
fn diagnose_family_case() {
    use caisson::dynamics::Simulation;
    use rand::SeedableRng;
    let want: usize = std::env::var("CAISSON_CASE").ok().and_then(|s| s.parse().ok()).unwrap_or(28);
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(34);
    let (mut text, mut about) = (String::new(), String::new());
    for k in 0..=want {
        (text, about) = family_case(&mut rng, k);
    }
    println!("case {want}: {about}\n{text}");
    let mu_s: f64 = text.lines().find_map(|l| l.strip_prefix("mu_static = ")).unwrap().trim().parse().unwrap();
    let s = support::scenario(&text);
    let trace = |stepping: Stepping, dt_s: f64| {
        let solver = SolverParams { dt_s, stepping, ..s.solver() };
        let load = s.load.clone().unwrap();
        let mut sim = Simulation::new(s.structure().model(), solver, &load);
        let mut t = Trace { mu_s, rows: Vec::new() };
        sim.run_until(s.duration_s, &load, &mut t).unwrap();
        println!("{stepping:?}: {:?}", sim.stats);
        t.rows
    };
    let adaptive = trace(Stepping::Adaptive(AdaptiveParams::for_first_step(1e-4)), 1e-4);
    let fixed = trace(Stepping::Fixed, 6.25e-6);
    let q = |r: &TraceRow| [r.2[0], r.2[1], r.2[2], r.3.min(1e9), r.4.min(1e9)];
    let names = ["u_x", "u_y", "theta", "least N", "least margin"];
    let scale: Vec<f64> = (0..5)
        .map(|i| fixed.iter().map(|r| q(r)[i].abs()).filter(|x| x.is_finite() && *x < 1e9).fold(0.0, f64::max))
        .collect();
    let at = |t: f64| {
        let j = fixed.partition_point(|r| r.0 < t).clamp(1, fixed.len() - 1);
        let (a, b) = (&fixed[j - 1], &fixed[j]);
        let w = ((t - a.0) / (b.0 - a.0)).clamp(0.0, 1.0);
        let (qa, qb) = (q(a), q(b));
        (0..5).map(|i| qa[i] + w * (qb[i] - qa[i])).collect::<Vec<_>>()
    };
    let mut first = [None::<usize>; 5];
    for (n, r) in adaptive.iter().enumerate() {
        let c = at(r.0);
        for i in 0..5 {
            if first[i].is_none() && (q(r)[i] - c[i]).abs() > 1e-3 * scale[i] {
                first[i] = Some(n);
            }
        }
    }
    for i in 0..5 {
        if let Some(n) = first[i] {
            let r = &adaptive[n];
            let h = r.0 - adaptive[n.saturating_sub(1)].0;
            println!(
                "{}: first beyond 1e-3 of {:.4e} at t {:.6} s (step {n}, {} h {:.3e} s, sliding {}): adaptive {:.6e}, converged {:.6e}",
                names[i],
                scale[i],
                r.0,
                if r.1 { "exact" } else { "newmark" },
                h,
                r.5,
                q(r)[i],
                at(r.0)[i]
            );
        }
    }
    if let Ok(path) = std::env::var("CAISSON_TRACE_DIR") {
        for (what, rows) in [("adaptive", &adaptive), ("fixed", &fixed)] {
            let mut out = String::from("t,exact,ux,uy,theta,least_n,least_margin,sliding\n");
            for r in rows {
                out +=
                    &format!("{},{},{},{},{},{},{},{}\n", r.0, r.1 as u8, r.2[0], r.2[1], r.2[2], r.3, r.4, r.5 as u8);
            }
            std::fs::write(std::path::Path::new(&path).join(format!("{what}.csv")), out).unwrap();
        }
    }
    // The permanent sliding: adaptive with and without the exact sticking steps, and converged.
    let sliding = |exact: bool, stepping: Stepping, dt_s: f64| {
        let solver = SolverParams {
            dt_s,
            stepping,
            accel: caisson::dynamics::Accel { exact_sticking: exact, ..s.solver().accel },
            ..s.solver()
        };
        sliding_m(&s.clone().with_solver(solver).unwrap(), stepping, dt_s)
    };
    let converged = sliding(true, Stepping::Fixed, 6.25e-6);
    let d = AdaptiveParams::for_first_step(1e-4);
    for (tolerance_m, dt_max_s) in [
        (d.tolerance_m, d.dt_max_s),
        (d.tolerance_m / 10.0, d.dt_max_s),
        (d.tolerance_m / 100.0, d.dt_max_s),
        (d.tolerance_m, d.dt_max_s / 5.0),
    ] {
        for exact in [true, false] {
            let p = AdaptiveParams { tolerance_m, dt_max_s, ..d };
            let a = sliding(exact, Stepping::Adaptive(p), 1e-4);
            println!(
                "tolerance {tolerance_m:e} m, dt_max {dt_max_s:e} s, exact sticking {exact}: adaptive {a:.6e} m, converged {converged:.6e} m ({:+.2} %)",
                100.0 * (a / converged - 1.0)
            );
        }
    }
    assert!(!adaptive.is_empty() && !fixed.is_empty());
}
