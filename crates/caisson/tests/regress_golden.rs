//! Golden results of every bundled example: each `examples/*.toml` is parsed, validated and run
//! briefly, and what it computes is compared with `tests/golden/<example>.json`.
//!
//! * a `[load]` example: its whole run, the time history sampled at 41 instants (u_x, u_y, θ,
//!   F_x, R_x) and the permanent sliding;
//! * a wave example (`[waves]`, no `[design]` / `[fragility]`): realization 0 of its wave trains
//!   with its time history sampled at 41 instants and the sliding of every wave (both models);
//! * a design example: its first 3 lives (both models, wave counts, the impulsive waves' sliding
//!   and the largest heel pressure);
//! * the fragility example: 2 storms at its lowest and highest heights.
//!
//! Tolerance: |a − b| ≤ 1e-6 · max |series| (+ 1e-12 for all-zero series). The same build gives
//! identical numbers (`scripts/same-numbers.sh`); the allowance is for another platform's libm
//! and floating-point contraction. A change of the model, of a default or of a random stream
//! moves these numbers by far more, and must bump `RESULTS_VERSION` and re-bless:
//! `CAISSON_BLESS=1 cargo test --release -p caisson --test regress_golden`.

mod support;

use caisson::analysis::run::History;
use caisson::scenario::Scenario;
use std::collections::BTreeMap;
use std::path::Path;
use support::signature::Signature;

type Series = BTreeMap<String, Vec<f64>>;

/// 41 samples of a history, evenly spaced in sample index.
fn sampled(h: &History, out: &mut Series) {
    let n = h.len();
    assert!(n > 41, "a history of {n} samples");
    let pick = |v: &[f64]| (0..=40).map(|k| v[k * (n - 1) / 40]).collect::<Vec<f64>>();
    out.insert("t_s".into(), pick(&h.t_s));
    out.insert("ux_m".into(), pick(&h.ux_m));
    out.insert("uy_m".into(), pick(&h.uy_m));
    out.insert("theta_rad".into(), pick(&h.theta_rad));
    out.insert("fx_n".into(), pick(&h.fx_n));
    out.insert("reaction_x_n".into(), pick(&h.reaction_x_n));
}

/// What the example computes, briefly (module docs; [`support::signature`]).
fn signature(sc: &Scenario) -> Series {
    let mut out = Series::new();
    match support::signature::signature(sc, true) {
        Signature::Load(r) => {
            sampled(r.history.as_ref().unwrap(), &mut out);
            out.insert("permanent_sliding_m".into(), vec![r.summary.permanent_sliding_m]);
            out.insert("max_horizontal_reaction_n".into(), vec![r.summary.max_horizontal_reaction_n]);
        }
        Signature::Lives(lives) => {
            out.insert("sliding_m".into(), lives.iter().map(|o| o.sliding_m).collect());
            out.insert("rigid_block_sliding_m".into(), lives.iter().map(|o| o.rigid_block_sliding_m).collect());
            out.insert("waves".into(), lives.iter().map(|o| o.waves as f64).collect());
            out.insert("simulated".into(), lives.iter().map(|o| o.simulated_waves as f64).collect());
            out.insert("impulsive_sliding_m".into(), lives.iter().map(|o| o.impulsive_sliding_m).collect());
            out.insert("max_heel_pressure_kpa".into(), lives.iter().map(|o| o.max_heel_pressure_kpa).collect());
        }
        Signature::Storms(storms) => {
            out.insert("sliding_m".into(), storms.iter().map(|o| o.sliding_m).collect());
            out.insert("rigid_block_sliding_m".into(), storms.iter().map(|o| o.rigid_block_sliding_m).collect());
            out.insert("simulated".into(), storms.iter().map(|o| o.simulated_waves as f64).collect());
        }
        Signature::Train(r, h) => {
            sampled(h.as_ref().unwrap(), &mut out);
            out.insert("wave_sliding_m".into(), r.waves.iter().map(|w| w.sliding_m).collect());
            out.insert("wave_rigid_block_sliding_m".into(), r.waves.iter().map(|w| w.rigid_block_sliding_m).collect());
            out.insert("wave_height_m".into(), r.waves.iter().map(|w| w.record.height_m).collect());
        }
    }
    out
}

fn compare(name: &str, got: &Series, want: &Series) -> usize {
    assert_eq!(got.keys().collect::<Vec<_>>(), want.keys().collect::<Vec<_>>(), "{name}: the series differ");
    let mut values = 0;
    for (key, g) in got {
        let w = &want[key];
        assert_eq!(g.len(), w.len(), "{name} {key}: length");
        let scale = w.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for (i, (a, b)) in g.iter().zip(w).enumerate() {
            assert!((a - b).abs() <= 1e-6 * scale + 1e-12, "{name} {key}[{i}]: {a} against golden {b}");
            values += 1;
        }
    }
    values
}

#[test]
fn every_example_matches_its_golden_results() {
    let bless = std::env::var_os("CAISSON_BLESS").is_some();
    let examples = support::example_paths();
    let mut checked = 0;
    for path in &examples {
        let name = path.file_stem().unwrap().to_str().unwrap().to_string();
        let sc = caisson::scenario::load(path).unwrap_or_else(|e| panic!("{name}: {e}"));
        let got = signature(&sc);
        let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/golden").join(format!("{name}.json"));
        if bless {
            std::fs::write(&file, serde_json::to_string_pretty(&got).unwrap() + "\n").unwrap();
        }
        let text = std::fs::read_to_string(&file).unwrap_or_else(|e| {
            panic!("{}: {e} (a new example needs its golden file: CAISSON_BLESS=1)", file.display())
        });
        let want: Series = serde_json::from_str(&text).unwrap();
        assert!(compare(&name, &got, &want) > 0, "{name}: nothing compared");
        checked += 1;
    }
    assert_eq!(checked, 15, "examples checked: {examples:?}");
}
