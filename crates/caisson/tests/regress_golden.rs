//! Golden results of every bundled example: each `examples/*.toml` is parsed, validated and run
//! briefly, and what it computes is compared with `tests/golden/<example>.json`.
//!
//! * a `[load]` example: its whole run, the time history sampled at 41 instants (u_x, u_y, θ,
//!   F_x, R_x) and the permanent sliding;
//! * a wave example (`[waves]`, no `[design]` / `[fragility]`): realization 0 of its wave trains
//!   with its time history sampled at 41 instants and the sliding of every wave (both models);
//! * a design example: its first 14 lives (`support::signature::GOLDEN_LIVES`: both models, wave
//!   counts, the impulsive waves' sliding and the largest heel pressure), enough that every
//!   accelerator acts on them ([`the_golden_lives_exercise_every_accelerator`]);
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

/// What the golden lives of each design example (`support::signature::GOLDEN_LIVES`) do, so that
/// every accelerator (`caisson::dynamics::Accel`, ARCHITECTURE.md "Accelerators") acts on them:
/// waves reach the dynamic model (simulated > 0), the screen skips some (screened > 0), a life
/// slides (and rocks), and each accelerator that moves a number when off does move one: the
/// predictor, the all-sticking fast path and, under the `consistent` profile, the exact sticking
/// steps (some golden value changes bit; the exact steps are the only user of the cached
/// propagators), the stick bound (more waves simulated without it) and the drawing above the
/// threshold (other waves drawn: the simulated counts or the sliding change); the stick bound
/// where the waves are pulsating (it leaves impulsive ones to the engine). The screen's load
/// bound and the contact runs claim the same bits, so nothing shows them off; they act on every
/// screened storm and every step (the lifetime unit test
/// `the_bisected_screen_grid_is_every_nodes_grid` asserts that the load bound cuts nodes).
#[test]
fn the_golden_lives_exercise_every_accelerator() {
    use caisson::dynamics::{Accel, Predictor, SolverParams};
    let run = |sc: &Scenario, accel: Accel| -> Vec<caisson::analysis::lifetime::StormOutcome> {
        let sc = sc.clone().with_solver(SolverParams { accel, ..sc.solver() }).unwrap();
        match support::signature::signature(&sc, false) {
            Signature::Lives(lives) => lives,
            _ => unreachable!("a design example"),
        }
    };
    let values = |lives: &[caisson::analysis::lifetime::StormOutcome]| -> Vec<u64> {
        lives
            .iter()
            .flat_map(|o| {
                [o.sliding_m, o.max_rotation_rad, o.max_heel_pressure_kpa, o.simulated_waves as f64].map(f64::to_bits)
            })
            .collect()
    };
    let (mut designs, mut pulsating) = (0, 0);
    for path in support::example_paths() {
        let sc = caisson::scenario::load(&path).unwrap();
        if sc.design.is_none() {
            continue;
        }
        let name = path.file_stem().unwrap().to_string_lossy().into_owned();
        let on = sc.solver().accel;
        let lives = run(&sc, on);
        assert_eq!(lives.len(), support::signature::GOLDEN_LIVES, "{name}");
        let total =
            |f: fn(&caisson::analysis::lifetime::StormOutcome) -> u64, lives: &[_]| lives.iter().map(f).sum::<u64>();
        let (simulated, screened) = (total(|o| o.simulated_waves, &lives), total(|o| o.screened_waves, &lives));
        let (sliding, rocking) =
            (lives.iter().filter(|o| o.sliding_m != 0.0).count(), total(|o| o.rocking_waves, &lives));
        println!(
            "{name}: {simulated} waves simulated, {screened} screened, {sliding} lives slide, {rocking} rocking waves"
        );
        assert!(simulated > 0 && screened > 0, "{name}: the dynamic model and the screen must be reached");
        assert!(sliding > 0 && rocking > 0, "{name}: a golden life must slide and rock");
        let mut moves = vec![
            ("predictor", Accel { predictor: Predictor::LastDisplacement, ..on }),
            ("sticking_fast_path", Accel { sticking_fast_path: false, ..on }),
            ("draw_above_threshold", Accel { draw_above_threshold: false, ..on }),
        ];
        if on.exact_sticking {
            moves.push(("exact_sticking", Accel { exact_sticking: false, ..on }));
        }
        for (switch, accel) in moves {
            assert_ne!(values(&run(&sc, accel)), values(&lives), "{name}: {switch} off moves no golden number");
        }
        let without = run(&sc, Accel { stick_bound: false, ..on });
        let answered = total(|o| o.simulated_waves, &without) - simulated;
        let impulsive = total(|o| o.impulsive_waves, &lives);
        println!("{name}: the stick bound answered {answered} waves ({impulsive} of {simulated} simulated impulsive)");
        // It leaves impulsive waves to the engine: under breaking_site_15m's breaking waves nearly
        // every wave the screen lets through is impulsive (1237 of 1239), and it answers none.
        if impulsive == 0 {
            assert!(answered > 0, "{name}: the stick bound answered no golden wave");
            pulsating += 1;
        }
        designs += 1;
    }
    assert_eq!(designs, 4, "design examples checked");
    assert_eq!(pulsating, 3, "design examples whose stick bound was checked");
}
