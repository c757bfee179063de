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
        assert!(s.solver().exact_sticking, "the default profile steps sticking phases exactly");
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
        let solver = SolverParams { exact_sticking: exact, ..sc.solver() }.with_adaptive(p).unwrap();
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
        assert_eq!(sc.solver().exact_sticking, *exact, "case {i}");
    }
    // The design waves with the seed-2011 scenario's solver controls take no exact step; with
    // the default one's they do.
    let steps = |sc: &Scenario| support::design_waves(sc.solver()).iter().map(|(_, s)| s.exact_steps).sum::<u64>();
    assert_eq!(steps(&seed), 0);
    assert!(steps(&design) > 100, "{} exact steps", steps(&design));
}
