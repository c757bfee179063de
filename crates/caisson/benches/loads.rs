//! Cost of one wave-load evaluation: Goda + Sainflou + impact (with the regime decision, the
//! Miche toe limit, d_b and F*) for the PARI breaking case, and the history at one instant.
//!
//! cargo bench -p caisson --bench loads -- --warm-up-time 1 --measurement-time 3

use caisson::loads::model::{WaveLoadModel, WaveLoadOptions, WaveRecord};
use caisson::loads::regime::Regime;
use caisson::loads::LoadHistory;
use criterion::{black_box, criterion_group, criterion_main, Criterion};

#[path = "../tests/support/pari.rs"]
mod pari;
use pari::pari_site;

fn pari() -> WaveLoadModel {
    let site = pari_site(0.4);
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
