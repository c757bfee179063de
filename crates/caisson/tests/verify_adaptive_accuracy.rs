//! Adaptive stepping at its default controls (docs/scenario.md, [solver] `stepping =
//! "adaptive"`) against converged fixed steps: on the seed's Table 5 caisson under the consistent
//! profile (the dashpot beside the springs) and undamped, under triangular pulses that slide it,
//! rock it and (with uplift) lift its seaward springs; and on the 15-wave test.

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

/// The reference is fixed steps of 1e-5 s (2e-5 s moves every case by at most 1.9e-7 m, 0.04 %).
/// Damped (the consistent profile's dashpots): within max(1 µm, 1 %) of it, the issue's bound
/// (measured: at most 1.76e-5 m, 0.23 %). Undamped: within max(1 µm, 3 %); two of the six, the
/// ones with uplift and rocking that persists, miss the 1 % (1.1 % and 2.7 %) and reach it only
/// at a tolerance of 1e-9 m (0.13 % and 0.2 %): the local error estimate does not see the
/// error that the undamped rocking accumulates, and lift-off is not located (module docs of
/// `dynamics`). The tolerance records that gap; it is not the goal.
#[test]
fn adaptive_steps_meet_converged_fixed_steps() {
    let mut checked = 0;
    for (damping, bound) in [("", 0.01), ("damping_kns_per_m = 0.0", 0.03)] {
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
                err <= (1e-6f64).max(bound * fixed.abs()),
                "`{damping}` {peak} kN, {rise} s, lever {lever} m, uplift {up} kN: adaptive {adaptive} m, fixed {fixed} m"
            );
            checked += 1;
        }
    }
    assert_eq!(checked, 12);
}

/// The 15-wave test (`examples/fifteen_waves.toml`, the seed-2011 profile) with the adaptive
/// stepper at its defaults within 0.2 % of fixed steps of 1e-4 s (the issue's bound; measured
/// 0.05 %; fixed 2.5e-5 s is 0.007 % from 1e-4 s, so the reference is converged well within it).
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
