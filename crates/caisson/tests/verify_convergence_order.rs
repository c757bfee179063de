//! Order of convergence in the time step of the consistent profile (docs/model.md §9.1): the
//! dashpot beside each spring follows the trapezoidal rule and the onsets of slip are located
//! within the step, so that the permanent sliding converges at second order, as Newmark's average
//! acceleration does.

mod support;

use caisson::analysis::run::run;
use caisson::dynamics::{AdaptiveParams, SolverParams, Stepping};
use caisson::scenario::Scenario;
use support::{scenario, TABLE5};

/// The seed's Table 5 caisson on its soil under the consistent profile (the dashpot beside the
/// springs, μ_d = μ_s), with a diagonal mass matrix and the force at the base, so that the springs
/// share their normal force and slip together; a triangular pulse of `peak_kn` and `rise_s`.
fn case(peak_kn: f64, rise_s: f64) -> Scenario {
    let diagonal = TABLE5.replace("weight_in_water_kn = 8.24", "weight_in_water_kn = 8.24\nmass_matrix = \"diagonal\"");
    scenario(&format!(
        r#"{diagonal}
[load]
kind = "triangle"
peak_horizontal_kn = {peak_kn}
rise_time_s = {rise_s}
horizontal_lever_m = 0.0
duration_s = 0.4
"#
    ))
}

/// The permanent sliding of `s` with fixed steps of `dt_s`.
fn sliding_m(s: &Scenario, dt_s: f64) -> f64 {
    let solver = SolverParams { dt_s, ..s.solver() };
    let s = s.clone().with_solver(solver).unwrap();
    run(s.structure(), s.load.as_ref().unwrap(), s.duration_s, false).unwrap().summary.permanent_sliding_m
}

/// The observed order log2((s(dt) − s(dt/2)) / (s(dt/2) − s(dt/4))) at dt = 2.5e-4 s (the
/// default 1e-4 s lies between dt/2 and dt/4) is 2 within 0.3, for a slow pulse (slip of 7 mm)
/// and a short impact (1.4 mm). The tolerance covers what is not located in the step (the kinks
/// of the force where the springs' response changes smoothly). With backward Euler for
/// the dashpot and no event location (results version 9), a 20 kN impact over 10 ms at a lever
/// of 0.2 m converged at order 1.0 (errors 3.5e-7 m at dt 2.5e-5 s; 3e-9 m now).
#[test]
fn consistent_profile_converges_at_second_order() {
    let mut checked = 0;
    for (peak_kn, rise_s, slides_m) in [(12.0, 0.05, 7e-3), (20.0, 0.01, 1.3e-3)] {
        let s = case(peak_kn, rise_s);
        let dt = 2.5e-4;
        let v: Vec<f64> = (0..3).map(|k| sliding_m(&s, dt / 2f64.powi(k))).collect();
        let order = ((v[0] - v[1]) / (v[1] - v[2])).abs().log2();
        assert!(v[2] > slides_m, "the case slides: {v:?}");
        assert!((order - 2.0).abs() <= 0.3, "{peak_kn} kN over {rise_s} s: sliding {v:?} m, order {order}");
        checked += 1;
    }
    assert_eq!(checked, 2);
}

/// The end of a slip located within the step (docs/model.md §9.1, "Events"; the consistent
/// profile): at fixed steps of 5e-4 s the slow pulse and a 9 kN pulse of 0.1 s rise miss the
/// converged sliding (fixed steps of 5e-6 s) by at most half as much with it as without it
/// (`SolverParams::locate_contact` off; measured 3.7e-8 against 1.21e-7 m and 5.6e-8 against
/// 1.24e-7 m). Without it the slip goes on to the step's end and stops there, or stops at the
/// step's start: a local error of the order of h |ṡ| at the slip's end, which the located end
/// leaves at the linear interpolation's.
#[test]
fn the_end_of_a_slip_is_located() {
    let mut checked = 0;
    for (peak_kn, rise_s) in [(12.0, 0.05), (9.0, 0.1)] {
        let s = case(peak_kn, rise_s);
        assert!(s.solver().locate_contact, "the consistent profile locates the events");
        let off = s.clone().with_solver(SolverParams { locate_contact: false, ..s.solver() }).unwrap();
        let reference = sliding_m(&s, 5e-6);
        let (with, without) = ((sliding_m(&s, 5e-4) - reference).abs(), (sliding_m(&off, 5e-4) - reference).abs());
        assert!(reference > 5e-3, "the case slides: {reference} m");
        assert!(with <= 0.5 * without, "{peak_kn} kN over {rise_s} s: {with:.2e} m off located, {without:.2e} m not");
        checked += 1;
    }
    assert_eq!(checked, 2);
}

/// Issue 19: the 15-wave test (`examples/fifteen_waves.toml`) under the consistent profile, which
/// rocks the caisson to 0.021 rad and lands it on its heel once a wave (the landing slides it
/// 1.35 mm seaward), converges at second order in fixed steps. Its vertical dashpots beside the
/// springs switch on at a touch-down and off at a lift-off, a jump of the force that Newmark's
/// trapezoidal velocity weighted by h/2 in the step that holds it: located or not, a
/// first-order error (before results version 18: 0.59 % off at 1e-4 s, the errors at 4e-4 to
/// 2.5e-5 s alternating in sign). Now the contact events are located in fixed steps too and the
/// acceleration restarts across the jump (docs/model.md §9.1, "Events"). The reference is fixed
/// steps of 1.25e-5 s (6.25e-6 and 3.125e-6 s move it by 1e-5 of itself). Measured: 0.14 %,
/// 0.05 % and 0.009 % off at 2e-4, 1e-4 and 5e-5 s, an observed order of 1.9 over the two
/// halvings. Asserted: 1e-4 s within 0.1 %, the order over 2e-4 to 5e-5 s at least 1.5, and
/// adaptive stepping at its defaults within 0.2 % of fixed 1e-4 s and of the reference
/// (what remains: events within a hundredth of a step's end are not located, each a
/// first-order term a hundredth of the unlocated one).
#[test]
fn fifteen_waves_consistent_profile_converges_at_second_order() {
    use caisson::Profile;
    let s = support::example("fifteen_waves.toml").with_profile(Profile::Consistent).unwrap();
    assert!(s.solver().locate_contact);
    let reference = sliding_m(&s, 1.25e-5);
    let err: Vec<f64> =
        [2e-4, 1e-4, 5e-5].iter().map(|&dt| (sliding_m(&s, dt) - reference).abs() / reference.abs()).collect();
    assert!(reference.abs() > 0.016, "it slides: {reference} m");
    assert!(err[1] <= 1e-3, "1e-4 s: {:.3e} off, {err:?}", err[1]);
    let order = (err[0] / err[2]).log2() / 2.0;
    assert!(order >= 1.5, "relative errors {err:?} at 2e-4, 1e-4, 5e-5 s: order {order}");

    // Issue 19's bound: adaptive stepping at its defaults within 0.2 % of fixed 1e-4 s (and of
    // the converged reference). Measured at results version 20: 0.114 % and 0.165 % (18 050 ->
    // 19 589 steps for 1e-8 -> 5e-9 m; at 1e-8 m, the default before version 19, 0.46 % and
    // 0.51 %).
    let fixed = sliding_m(&s, 1e-4);
    let adaptive = {
        let solver = SolverParams { stepping: Stepping::Adaptive(AdaptiveParams::default()), ..s.solver() };
        let s = s.clone().with_solver(solver).unwrap();
        run(s.structure(), s.load.as_ref().unwrap(), s.duration_s, false).unwrap().summary.permanent_sliding_m
    };
    for (what, against) in [("fixed 1e-4 s", fixed), ("the converged reference", reference)] {
        let off = (adaptive - against).abs() / against.abs();
        assert!(off <= 2e-3, "adaptive {adaptive} m is {off:.3e} off {what} ({against} m)");
    }
}
