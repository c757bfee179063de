//! Cost of one wave-load evaluation: Goda + Sainflou + impact (with the regime decision, the
//! Miche toe limit, d_b and F*) for the PARI breaking case, and the history at one instant.
//!
//! cargo bench -p caisson --bench loads -- --warm-up-time 1 --measurement-time 3

use caisson::loads::model::{WaveLoadModel, WaveLoadOptions, WaveRecord, WaveSite};
use caisson::loads::regime::Regime;
use caisson::loads::LoadHistory;
use criterion::{black_box, criterion_group, criterion_main, Criterion};

fn pari() -> WaveLoadModel {
    let site = WaveSite {
        rho_w: 1000.0,
        depth_at_toe_m: 1.14,
        depth_at_wall_m: 0.4,
        base_depth_m: 0.8,
        crest_freeboard_m: 0.32,
        width_m: 0.78,
        length_m: 1.0,
        seabed_slope: 0.0,
        berm_width_m: None,
    };
    WaveLoadModel { site, options: WaveLoadOptions::default() }
}

fn bench(c: &mut Criterion) {
    let model = pari();
    c.bench_function("goda+sainflou+impact (PARI breaking, H = 0.428 m)", |b| {
        b.iter(|| model.evaluate(black_box(0.428), black_box(3.04)).unwrap())
    });
    let recs: Vec<WaveRecord> = (0..1000)
        .map(|j| WaveRecord {
            height_m: 0.428,
            period_s: 3.04,
            regime: Regime::Breaking,
            rise_time_s: Some(0.01 + 1e-4 * j as f64),
        })
        .collect();
    let train = model.train(&recs).unwrap();
    let mut t = 0.0;
    c.bench_function("wave train at(t), 1000 waves", |b| {
        b.iter(|| {
            t = (t + 0.0137) % 3040.0;
            train.at(black_box(t))
        })
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
