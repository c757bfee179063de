//! Engine benchmarks: one time step with 10 springs, and a 15-wave test (45.6 s of loading,
//! 15 waves of 3.04 s, at dt = 1e-4 s and with the adaptive stepper) on the seed's Table 5 caisson;
//! the waves of a design run (examples/design_breakwater.toml: one reused `Simulation`, reset to
//! rest before each wave, no observer, as `analysis::lifetime` runs them) and one realization of a
//! wave campaign (examples/pari_breaking_campaign.toml: 15 waves with the run's peak observers).
//!
//! Run: `cargo bench -p caisson --bench engine`. Figures are recorded in BENCHMARKS.md.

use caisson::analysis::run::run;
use caisson::analysis::Structure;
use caisson::dynamics::{AdaptiveParams, Simulation, SolverParams, Stepping};
use caisson::loads::history::WaveTrain;
use caisson::loads::regime::RegimeChoice;
use caisson::loads::{LoadHistory, WaveForce};
use caisson::scenario::Scenario;
use criterion::{black_box, criterion_group, criterion_main, Criterion};
use std::path::Path;

/// A regular non-breaking wave train in the shape of seed Eq. 29: 0.8 × Goda on the crest
/// half, Sainflou on the trough half (PARI H = 0.569 m values, docs/model.md §11 and §2.4).
struct RegularTrain;

impl LoadHistory for RegularTrain {
    #[inline]
    fn at(&self, t: f64) -> WaveForce {
        let period = 3.04;
        let phase = (t / period).fract();
        let s = (2.0 * std::f64::consts::PI * phase).sin();
        if phase < 0.5 {
            WaveForce { fx_n: 0.8 * 4939.0 * s, fy_n: 0.8 * 1525.0 * s, m_nm: 0.8 * (2727.0 + 1525.0 * 0.13) * s }
        } else {
            WaveForce { fx_n: 2391.0 * s, fy_n: 1602.0 * s, m_nm: (737.0 + 1602.0 * 0.13) * s }
        }
    }
}

fn table5() -> Structure {
    // The seed's literal model (the figures of BENCHMARKS.md before the profiles were measured on it).
    let text = r#"
[model]
profile = "seed-2011"
[caisson]
width_m = 0.78
height_m = 1.12
base_depth_m = 0.8
weight_in_water_kn = 7.5
[foundation]
e100_kpa = 3.5e5
springs = 10
"#;
    Scenario::from_toml(text, Path::new("bench.toml"), Path::new(".")).unwrap().structure().clone()
}

fn bench(c: &mut Criterion) {
    let s = table5();
    let load = RegularTrain;
    // One step, measured on a running simulation (state advances: a representative mix of
    // sticking and sliding steps over the first wave).
    c.bench_function("step_10_springs", |b| {
        let mut sim = Simulation::new(s.model(), s.solver, &load);
        b.iter(|| {
            if sim.state().t_s > 3.0 {
                sim = Simulation::new(s.model(), s.solver, &load);
            }
            sim.step(black_box(&load), &mut ()).unwrap();
        })
    });
    let mut g = c.benchmark_group("fifteen_waves");
    g.sample_size(10);
    g.bench_function("45.6s_dt1e-4", |b| {
        b.iter(|| run(&s, black_box(&load), 45.6, false).unwrap().summary.permanent_sliding_m)
    });
    // The same test with the adaptive stepper at its defaults (the wave-train default).
    let mut adaptive = s.clone();
    adaptive.solver.stepping = Stepping::Adaptive(AdaptiveParams::default());
    g.bench_function("45.6s_adaptive", |b| {
        b.iter(|| run(&adaptive, black_box(&load), 45.6, false).unwrap().summary.permanent_sliding_m)
    });
    g.finish();

    // The waves of a design run that reach the dynamic model: heights about the sliding threshold
    // of the design example's caisson (T = 12.8 s, automatic regime: the highest break on the wall
    // with an impact), each from rest through one reused simulation.
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let design = caisson::scenario::load(&root.join("examples/design_breakwater.toml")).unwrap();
    let site = &design.waves.as_ref().unwrap().model;
    let period_s = 12.8;
    let trains: Vec<WaveTrain> = [9.0, 10.0, 11.0, 11.5, 12.0, 12.5, 12.7, 12.79]
        .iter()
        .map(|&h| {
            let loads = site.evaluate_with(h, period_s, RegimeChoice::Auto).unwrap();
            WaveTrain::new(vec![site.event(&loads, None, 0.0)]).unwrap()
        })
        .collect();
    // At the example's controls (the sticking phases in exact steps of dt_max = 0.5 s), and by
    // Newmark steps at the controls it had before them (dt_max 0.2 s, `exact_sticking` off).
    let Stepping::Adaptive(controls) = design.solver().stepping else { panic!("the example steps adaptively") };
    let newmark = SolverParams {
        accel: caisson::dynamics::Accel { exact_sticking: false, ..design.solver().accel },
        ..design.solver()
    }
    .with_adaptive(AdaptiveParams { dt_max_s: 0.2, ..controls })
    .unwrap();
    let mut g = c.benchmark_group("design_waves");
    for (name, solver) in [("8_waves_T12.8s", design.solver()), ("8_waves_T12.8s_newmark_dt0.2", newmark)] {
        let mut sim = Simulation::new(design.structure().model(), solver, &trains[0]);
        g.bench_function(name, |b| {
            b.iter(|| {
                let mut sliding_m = 0.0;
                for train in &trains {
                    sim.reset(train);
                    sim.run_until(period_s, black_box(train), &mut ()).unwrap();
                    sliding_m += caisson::analysis::run::permanent_sliding_m(&sim);
                }
                sliding_m
            })
        });
    }
    g.finish();

    // One realization of the PARI breaking campaign (15 irregular breaking waves, the run's peak
    // observers on every step).
    let campaign = caisson::scenario::load(&root.join("examples/pari_breaking_campaign.toml")).unwrap();
    let case = campaign.train_case().unwrap();
    let mut g = c.benchmark_group("campaign");
    g.bench_function("pari_breaking_realization", |b| b.iter(|| case.run(black_box(0), None).unwrap().sliding_m));
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
