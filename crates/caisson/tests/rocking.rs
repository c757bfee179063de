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
