//! The time loop allocates nothing: a counting global allocator sees zero allocations over
//! thousands of steps that include sticking, sliding, lift-off and re-contact.

use caisson::dynamics::{Model, Simulation};
use caisson::loads::pulse::TrianglePulse;
use caisson::loads::WaveForce;
use caisson::scenario::{parse_str, validate};
use std::alloc::{GlobalAlloc, Layout, System};
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};

struct Counting;
static ALLOCS: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, l: Layout) -> *mut u8 {
        ALLOCS.fetch_add(1, Ordering::SeqCst);
        System.alloc(l)
    }
    unsafe fn dealloc(&self, p: *mut u8, l: Layout) {
        System.dealloc(p, l)
    }
}

#[global_allocator]
static A: Counting = Counting;

/// The counter is global: the tests take turns so that one's set-up does not land in the other's
/// counting window.
static TURN: std::sync::Mutex<()> = std::sync::Mutex::new(());

#[test]
fn time_loop_does_not_allocate() {
    let _turn = TURN.lock().unwrap_or_else(|e| e.into_inner());
    let text = "[caisson]\nwidth_m = 0.78\nheight_m = 1.12\nbase_depth_m = 0.8\nweight_in_water_kn = 8.24\n[foundation]\ne100_kpa = 3.5e5\ndamping_mode = \"elastic\"\nvertical_damping = \"springs\"\n";
    let s = validate(&parse_str(text, Path::new("t.toml")).unwrap(), Path::new(".")).unwrap();
    // A pulse of 3 × the sliding resistance at the SWL: the caisson slides and rocks, and the
    // seaward springs lift off.
    let load = TrianglePulse { peak: WaveForce::from_levers(15e3, 0.8, 3e3, 0.52, 0.78), rise_s: 0.05, start_s: 0.0 };
    let mut sim = Simulation::new(Model::new(&s.caisson, &s.foundation), s.solver, &load);
    let mut peaks = caisson::analysis::run::Peaks::default();
    let before = ALLOCS.load(Ordering::SeqCst);
    for _ in 0..3000 {
        sim.step(&load, &mut peaks).unwrap();
    }
    let after = ALLOCS.load(Ordering::SeqCst);
    assert!(peaks.slip_events >= 1 && peaks.min_n == 0.0, "the test must exercise sliding and lift-off");
    assert_eq!(after - before, 0, "allocations in the time loop");
}

/// The adaptive stepper (rejections, breakpoints, step-size changes) allocates nothing either.
#[test]
fn adaptive_time_loop_does_not_allocate() {
    let _turn = TURN.lock().unwrap_or_else(|e| e.into_inner());
    let text = "[caisson]\nwidth_m = 0.78\nheight_m = 1.12\nbase_depth_m = 0.8\nweight_in_water_kn = 8.24\n[foundation]\ne100_kpa = 3.5e5\n[load]\nkind = \"triangle\"\npeak_horizontal_kn = 15.0\nrise_time_s = 0.05\n[solver]\nstepping = \"adaptive\"\n";
    let s = validate(&parse_str(text, Path::new("t.toml")).unwrap(), Path::new(".")).unwrap();
    let load = TrianglePulse { peak: WaveForce::from_levers(15e3, 0.8, 3e3, 0.52, 0.78), rise_s: 0.05, start_s: 0.0 };
    let mut sim = Simulation::new(Model::new(&s.caisson, &s.foundation), s.solver, &load);
    let mut peaks = caisson::analysis::run::Peaks::default();
    let before = ALLOCS.load(Ordering::SeqCst);
    sim.run_until(0.6, &load, &mut peaks).unwrap();
    let after = ALLOCS.load(Ordering::SeqCst);
    assert!(peaks.slip_events >= 1 && sim.stats.rejected_steps > 0, "the test must exercise sliding and step rejection");
    assert_eq!(after - before, 0, "allocations in the adaptive time loop");
}
