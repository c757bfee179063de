//! The hot loops allocate nothing: the time loop (fixed and adaptive steps, through sticking,
//! sliding, lift-off and re-contact) and the wave-train load history the engine calls every step.
//! Allocations are counted per thread (`support/counting_alloc.rs`), so the harness's other
//! threads cannot disturb the count.

#[path = "support/counting_alloc.rs"]
mod counting_alloc;
mod support;

use caisson::dynamics::Simulation;
use caisson::loads::model::{WaveLoadModel, WaveLoadOptions, WaveRecord};
use caisson::loads::pulse::TrianglePulse;
use caisson::loads::regime::Regime;
use caisson::loads::shapes::LoadShape;
use caisson::loads::{LoadHistory, WaveForce};
use counting_alloc::count_allocations;
use support::pari::pari_site;
use support::scenario;

#[test]
fn time_loop_does_not_allocate() {
    let text = "[caisson]\nwidth_m = 0.78\nheight_m = 1.12\nbase_depth_m = 0.8\nweight_in_water_kn = 8.24\n[foundation]\ne100_kpa = 3.5e5\ndamping_mode = \"elastic\"\nvertical_damping = \"springs\"\n";
    let s = scenario(text);
    // A pulse of 3 × the sliding resistance at the SWL: the caisson slides and rocks, and the
    // seaward springs lift off.
    let load = TrianglePulse { peak: WaveForce::from_levers(15e3, 0.8, 3e3, 0.52, 0.78), rise_s: 0.05, start_s: 0.0 };
    let mut sim = Simulation::new(s.structure().model(), s.solver(), &load);
    let mut peaks = caisson::analysis::run::Peaks::default();
    let ((), allocations) = count_allocations(|| {
        for _ in 0..3000 {
            sim.step(&load, &mut peaks).unwrap();
        }
    });
    assert!(peaks.slip_events >= 1 && peaks.min_n == 0.0, "the test must exercise sliding and lift-off");
    assert_eq!(allocations, 0, "allocations in the time loop");
}

/// The adaptive stepper (rejections, breakpoints, step-size changes, the exact sticking steps of
/// the free vibration after the pulse) allocates nothing either.
#[test]
fn adaptive_time_loop_does_not_allocate() {
    let text = "[caisson]\nwidth_m = 0.78\nheight_m = 1.12\nbase_depth_m = 0.8\nweight_in_water_kn = 8.24\n[foundation]\ne100_kpa = 3.5e5\n[load]\nkind = \"triangle\"\npeak_horizontal_kn = 15.0\nrise_time_s = 0.05\n[solver]\nstepping = \"adaptive\"\n";
    let s = scenario(text);
    let load = TrianglePulse { peak: WaveForce::from_levers(15e3, 0.8, 3e3, 0.52, 0.78), rise_s: 0.05, start_s: 0.0 };
    let mut sim = Simulation::new(s.structure().model(), s.solver(), &load);
    let mut peaks = caisson::analysis::run::Peaks::default();
    let (result, allocations) = count_allocations(|| sim.run_until(0.6, &load, &mut peaks));
    result.unwrap();
    assert!(
        peaks.slip_events >= 1 && sim.stats.rejected_steps > 0 && sim.stats.exact_steps > 0,
        "the test must exercise sliding, step rejection and exact sticking steps"
    );
    assert_eq!(allocations, 0, "allocations in the adaptive time loop");
}

/// `WaveTrain::at` (the wave-load `LoadHistory`) allocates nothing, for every load shape.
#[test]
fn wave_train_at_does_not_allocate() {
    let site = pari_site(0.4);
    let mut checked = 0;
    for (_, shape) in LoadShape::ALL {
        let model =
            WaveLoadModel { site, options: WaveLoadOptions { load_shape: shape, ..WaveLoadOptions::default() } };
        let recs: Vec<WaveRecord> = (0..50)
            .map(|j| WaveRecord {
                height_m: 0.428,
                period_s: 3.04,
                regime: if j % 3 == 0 { Regime::NonBreaking } else { Regime::Breaking },
                rise_time_s: Some(0.01 + 1e-3 * j as f64),
            })
            .map(|r| if r.regime == Regime::NonBreaking { WaveRecord { height_m: 0.3, ..r } } else { r })
            .collect();
        let train = model.train(&recs).unwrap();
        let (sum, allocations) =
            count_allocations(|| (0..200_000).map(|k| train.at(k as f64 * 1e-3).fx_n).sum::<f64>());
        assert_eq!(allocations, 0, "{shape:?}: at() allocated");
        assert!(sum.is_finite() && sum != 0.0, "{shape:?}: the train must load the caisson");
        checked += 1;
    }
    assert_eq!(checked, LoadShape::ALL.len());
}

/// The counter is not vacuous: it sees this thread's allocations and not another thread's.
#[test]
fn the_counter_sees_this_threads_allocations_only() {
    let (v, here) = count_allocations(|| vec![1u8; 64]);
    assert_eq!((v.len(), here), (64, 1));
    let ((), elsewhere) = count_allocations(|| {
        std::thread::scope(|s| {
            let h = s.spawn(|| (1..=1000).map(|n| vec![0u8; n].len()).sum::<usize>());
            assert_eq!(h.join().unwrap(), 500_500);
        })
    });
    // Spawning a thread allocates its handle on the spawning thread (a few allocations); the
    // other thread's 1000 vectors must not be counted here.
    assert!(elsewhere < 100, "{elsewhere}");
}
