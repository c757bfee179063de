//! Rocking without slip (docs/design.md): a push high on the wall lifts the seaward springs, they
//! re-contact at the displaced base with zero shear, and the caisson ends displaced shoreward with
//! no spring slipping. The permanent sliding must be where it comes to rest, whenever it is read
//! after the load has gone: not move with the decaying rocking.

mod support;

use caisson::analysis::run::{permanent_sliding_m, Peaks};
use caisson::dynamics::Simulation;
use caisson::loads::{LoadHistory, WaveForce};
use support::scenario;

/// The design example's caisson at still water, dashpot on the total velocity (no spring slips).
const CAISSON: &str = r#"
[caisson]
width_m = 20.0
height_m = 24.5
base_depth_m = 17.5
weight_in_water_kn = 5500.0
[foundation]
mu_static = 0.6
mu_dynamic = 0.6
e100_kpa = 3.5e5
density_kg_per_m3 = 2000
damping_mode = "total"
vertical_damping = "springs"
[water]
density_kg_per_m3 = 1030.0
[solver]
dt_s = 1e-3
"#;

/// 2000 kN (0.6 of μ W') at 22 m above the base: M = 0.8 W' B/2, seven of the ten springs lift.
/// Ramped up over 3 s, held 1 s, ramped down over 3 s, then zero.
struct Push;

impl LoadHistory for Push {
    fn at(&self, t: f64) -> WaveForce {
        let k = if t < 3.0 {
            t / 3.0
        } else if t < 4.0 {
            1.0
        } else if t < 7.0 {
            (7.0 - t) / 3.0
        } else {
            0.0
        };
        WaveForce { fx_n: 2.0e6 * k, fy_n: 0.0, m_nm: 2.0e6 * 22.0 * k }
    }
}

#[test]
fn rocking_displacement_is_read_where_the_caisson_comes_to_rest() {
    let s = scenario(CAISSON);
    let mut sim = Simulation::new(s.structure().model(), s.solver(), &Push);
    let mut peaks = Peaks::default();
    sim.run_until(7.0, &Push, &mut peaks).unwrap();
    // The load has just gone; the caisson still rocks (spring forces far from W'/n).
    let unloaded = permanent_sliding_m(&sim);
    sim.run_until(12.0, &Push, &mut peaks).unwrap();
    let rest = permanent_sliding_m(&sim);
    assert_eq!(peaks.slip_events, 0, "no spring slips");
    assert!(peaks.min_n == 0.0 && peaks.max_theta > 5e-3, "the seaward springs lift off");
    assert!(rest > 1e-3, "the re-contacted springs leave the caisson displaced ({rest} m)");
    assert!((rest - sim.state().u[0]).abs() < 1e-5, "at rest u_x = {} m vs {rest} m", sim.state().u[0]);
    assert!((unloaded - rest).abs() < 1e-6, "read at 7 s {unloaded} m vs at rest {rest} m");
}

/// A pure moment ramped up over 60 s (quasi-static: the rocking period is about 1 s) to `ratio`
/// times the lift-off moment of the screen, (6 M/B) f = W'.
struct MomentRamp {
    moment_nm: f64,
}

impl LoadHistory for MomentRamp {
    fn at(&self, t: f64) -> WaveForce {
        WaveForce { fx_n: 0.0, fy_n: 0.0, m_nm: self.moment_nm * (t / 60.0).min(1.0) }
    }
}

/// The screen's lift-off test (analysis::lifetime, docs/design.md) against the engine: n equal
/// springs lift their outermost one at (6 M/B) · n/(n + 1) = W' (closed form of
/// `Model::lift_off_factor`), so 2 % below that moment every spring stays in contact and 2 %
/// above the seaward one lifts. The 2 % margin covers the dynamic overshoot of a 60 s ramp,
/// 1 + T_θ/(π 60 s) ≈ 1.005.
#[test]
fn the_outermost_spring_lifts_where_the_screen_says() {
    let s = scenario(CAISSON);
    let model = s.structure().model();
    let n = model.x_m.len() as f64;
    assert_eq!(n, 10.0);
    assert!((model.lift_off_factor() - n / (n + 1.0)).abs() < 1e-12, "f = {}", model.lift_off_factor());
    assert!(model.rocking_period_s() < 2.0, "T_θ = {} s", model.rocking_period_s());
    let (w, b) = (model.weight_n, model.width_m);
    let lift_moment_nm = w * b / (6.0 * model.lift_off_factor());
    for (ratio, lifts) in [(0.98, false), (1.02, true)] {
        let load = MomentRamp { moment_nm: ratio * lift_moment_nm };
        let mut sim = Simulation::new(s.structure().model(), s.solver(), &load);
        let mut peaks = Peaks::default();
        sim.run_until(61.0, &load, &mut peaks).unwrap();
        assert_eq!(peaks.min_n == 0.0, lifts, "M = {ratio} × the lift-off moment: min N = {} N", peaks.min_n);
    }
}
