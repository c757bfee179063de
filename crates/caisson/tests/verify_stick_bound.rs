//! The bound of the all-sticking response ([`caisson::analysis::stick_bound`]) against the
//! engine: a pulsating wave just inside the bound neither lifts nor slips a spring, and its
//! rotation stays within the bound's and within 10 % of it; the same wave a little larger, where
//! the bound leaves the outer spring 2 % of N̄ short of contact (no reserve), lifts the caisson or
//! slides it: the lift bound is sharp to a few per cent.

mod support;

use caisson::analysis::stick_bound::{Margins, StickBound, LIFT_RESERVE};
use caisson::dynamics::{Observer, Simulation, StepView};
use caisson::loads::history::{LoadComponent, WaveEvent, WaveTrain};
use support::scenario;

/// The design example's caisson (W' 5500 kN/m, B = 20 m, 10 springs).
fn design_example() -> String {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/design_breakwater.toml");
    std::fs::read_to_string(path).unwrap()
}

/// A pulsating wave of period 12.8 s whose crest is `k` times a Goda-like load of the design
/// example (1.3 MN at 12 m above the base, 0.47 MN of uplift at two thirds of the base from the
/// heel) and whose trough is 60 % of its horizontal part.
fn wave(k: f64) -> WaveEvent {
    let crest = LoadComponent::from_levers(1.3e6 * k, 12.0, 4.7e5 * k, 20.0 * 2.0 / 3.0, 20.0);
    let trough = LoadComponent::from_levers(0.78e6 * k, 10.0, 0.0, 10.0, 20.0);
    WaveEvent::new(0.0, 12.8, crest, 1.0, trough, LoadComponent::default(), None)
}

/// Whether a spring lifted, and the largest |θ|, over the committed steps.
#[derive(Default)]
struct Watch {
    lifted: bool,
    max_rotation_rad: f64,
}

impl Observer for Watch {
    fn observe(&mut self, s: &StepView<'_>) {
        self.lifted |= s.reaction.contact_springs < s.state.springs.len();
        self.max_rotation_rad = self.max_rotation_rad.max(s.state.u[2].abs());
    }
}

/// The wave `k` through the engine: whether it lifted, whether a spring slipped, its largest
/// rotation.
fn simulate(k: f64) -> (bool, bool, f64) {
    let s = scenario(&design_example());
    let train = WaveTrain::new(vec![wave(k)]).unwrap();
    let mut sim = Simulation::new(s.structure().model(), s.solver(), &train);
    let mut watch = Watch::default();
    sim.run_until(12.8, &train, &mut watch).unwrap();
    let slipped = sim.state().springs.iter().any(|c| c.slip_m != 0.0);
    (watch.lifted, slipped, watch.max_rotation_rad)
}

fn margins(k: f64) -> Margins {
    let s = scenario(&design_example());
    let bound = StickBound::new(&s.structure().model()).expect("the design example's modes are damped");
    let at = bound.at_period(12.8).unwrap();
    let w = wave(k);
    bound.margins(&at, w.quasi.total(), w.trough.total())
}

#[test]
fn a_wave_just_inside_the_bound_stays_still_and_one_just_outside_moves() {
    // The outer spring's normal share falls linearly with k: 1 − a k.
    let a = 1.0 - margins(1.0).normal_share;
    assert!(a > 0.0);
    // Just inside: the largest k the bound answers, by bisection (here its friction test binds:
    // 0.95 μ_s at k = 1.043, with 7 % of N̄ left at the outer spring).
    let (mut lo, mut hi) = (0.0, (1.0 - LIFT_RESERVE) / a);
    for _ in 0..50 {
        let mid = 0.5 * (lo + hi);
        if margins(mid).still() {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let inside = margins(lo);
    assert!(inside.still() && lo > 0.5, "the bound answers the wave up to k = {lo}");
    let (lifted, slipped, rotation_rad) = simulate(lo);
    eprintln!("answered up to k = {lo:.4} ({inside:?}); rotation {rotation_rad:.4e} rad");
    assert!(!lifted && !slipped, "k = {lo}: lifted {lifted}, slipped {slipped}");
    assert!(
        rotation_rad <= inside.rotation_rad && rotation_rad >= 0.9 * inside.rotation_rad,
        "the rotation {rotation_rad} rad within the bound's {} rad and within 10 % of it",
        inside.rotation_rad
    );
    // Just outside: the bound leaves −2 % of N̄ at the outer spring.
    let k_out = 1.02 / a;
    assert!((margins(k_out).normal_share + 0.02).abs() < 1e-9);
    let (lifted, slipped, _) = simulate(k_out);
    assert!(lifted || slipped, "k = {k_out}: the wave must lift or slide the caisson");
}
