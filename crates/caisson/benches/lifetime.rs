//! Cost of a storm of a lifetime run outside the dynamic model (issue 11): the screen and the wave
//! draws, on a calm storm of the design example that no wave can slide (H1/3 = 4 m, T = 10 s, 720
//! waves: everything but the dynamic model), drawing every wave and testing it (the drawing up to
//! results version 8) against drawing only the waves above the screen's threshold (the default;
//! here none, and the load bounds spare the grid). And one wave's loads: a full evaluation against
//! the screen's peak components at a prepared period.
//!
//! cargo bench -p caisson --bench lifetime -- --warm-up-time 1 --measurement-time 3

use caisson::analysis::lifetime::{simulate_storm, StormCase, StormInput, WaveDraws};
use caisson::loads::generator::realization_rng;
use caisson::loads::regime::RegimeChoice;
use caisson::scenario::Scenario;
use criterion::{black_box, criterion_group, criterion_main, Criterion};
use std::path::Path;

fn bench(c: &mut Criterion) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let path = dir.join("design_breakwater.toml");
    let text = std::fs::read_to_string(&path).unwrap();
    let sc = Scenario::from_toml(&text, &path, &dir).unwrap();
    let storm = StormInput {
        h13_m: 4.0,
        hmax_m: 7.2,
        period_s: 10.0,
        periods: Default::default(),
        waves: 720,
        tide_m: 1.0,
        angle_rad: 0.0,
        force_factor: 1.0,
        impact_factor: 1.0,
        friction_factor: 1.0,
    };
    let mut g = c.benchmark_group("mild_storm_720_waves");
    for (name, draws) in [("every_wave", WaveDraws::EveryWave), ("above_threshold", WaveDraws::AboveThreshold)] {
        let case = StormCase { draws, ..sc.storm_case(true).unwrap() };
        let mut i = 0;
        g.bench_function(name, |b| {
            b.iter(|| {
                i += 1;
                let o = simulate_storm(&case, black_box(&storm), &mut realization_rng(1, i)).unwrap();
                assert_eq!(o.simulated_waves, 0, "the storm must be mild");
                o.screened_waves
            })
        });
    }
    g.finish();
    let case = sc.storm_case(true).unwrap();
    let mut g = c.benchmark_group("one_wave_loads_T10s");
    g.bench_function("evaluate_with", |b| {
        b.iter(|| case.model.evaluate_with(black_box(6.0), black_box(10.0), RegimeChoice::Auto).unwrap())
    });
    let at = case.model.at_period(10.0);
    g.bench_function("prepared_period_peaks", |b| b.iter(|| at.peaks(black_box(6.0), RegimeChoice::Auto).unwrap()));
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
