//! Sizing through the real engine against a closed form (issue 11, docs/size.md): a caisson on a
//! foundation so stiff and undamped that the dynamic model is the rigid block of docs/model.md
//! §6.3, pushed by one triangular pulse through its base centre (no rocking). Its slide has the
//! exact closed form `closed_form::rigid_block_sliding_m`, so the width at which it equals the
//! allowed sliding is known; `sizing::size` running the engine at each candidate width must
//! return it.

mod support;

use caisson::analysis::closed_form::rigid_block_sliding_m;
use caisson::analysis::lifetime::LifeCounts;
use caisson::analysis::run::run;
use caisson::analysis::sizing::{size, Candidate, Criteria, ModelPoint, Required, SizeParams};
use caisson::scenario::Scenario;
use support::scenario;

/// W' per metre of width, kN/m: the seed's Table 5 caisson (8.24 kN at B = 0.78 m) with its
/// weight proportional to its width, as a caisson of a given cross-section fill.
const WEIGHT_PER_WIDTH_KN_PER_M: f64 = 8.24 / 0.78;
const MU: f64 = 0.6;
/// Peak horizontal force of the pulse, kN (twice μ W' at B = 0.78 m), and its rise time, s.
const PEAK_KN: f64 = 2.0 * MU * 8.24;
const RISE_S: f64 = 0.1;
/// The engine against the closed form: relative and absolute tolerance (test docs).
const ENGINE_REL: f64 = 0.01;
const ENGINE_ABS_M: f64 = 1e-6;

/// The caisson of width `b` m on the stiff, undamped foundation of tests/verify_engine.rs
/// (`rigid_block_sliding_matches_closed_form`), the pulse through the base centre.
fn at_width(b: f64) -> Scenario {
    let caisson = support::rigid_block_caisson(b, WEIGHT_PER_WIDTH_KN_PER_M * b, MU);
    scenario(
        &(caisson
            + &format!(
                r#"
[load]
kind = "triangle"
peak_horizontal_kn = {PEAK_KN}
rise_time_s = {RISE_S}
horizontal_lever_m = 0.0
duration_s = 1.5
[solver]
dt_s = 2e-5
"#
            )),
    )
}

/// The exact slide at width `b`, m (A = P, B = μ W', t_d = 2 t_r; the mass m_c + M_a of the
/// model at that width).
fn exact_m(b: f64) -> f64 {
    let m = at_width(b).structure().model().horizontal_mass_kg();
    rigid_block_sliding_m(PEAK_KN * 1e3, MU * WEIGHT_PER_WIDTH_KN_PER_M * b * 1e3, m, 2.0 * RISE_S)
}

/// The width at which the exact slide falls to `s_m` (it falls with the width), by bisection of
/// the closed form to 1e-9 m.
fn exact_width_m(s_m: f64) -> f64 {
    let (mut lo, mut hi) = (0.5, 1.5);
    assert!(exact_m(lo) > s_m && exact_m(hi) < s_m, "the root is bracketed");
    while hi - lo > 1e-9 {
        let mid = 0.5 * (lo + hi);
        if exact_m(mid) > s_m {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    hi
}

/// A deterministic "life": its one slide, with no spread.
fn point(s: f64) -> ModelPoint {
    ModelPoint {
        expected_sliding_m: s,
        expected_sliding_standard_error_m: 0.0,
        p50_m: s,
        p95_m: s,
        expected_sliding_uncapped_m: s,
        ..ModelPoint::default()
    }
}

/// The engine's slide is within 1 % + 1 µm of the closed form (the stick-slip transitions
/// resolved to dt, tests/verify_engine.rs, and the elastic compliance: the springs' stick limit
/// e_s = μ W'/K_x is at most 0.6 µm here), so the width it gives lies between the exact widths
/// of (S_a + 1 µm)·1.01 and (S_a − 1 µm)/1.01, plus the search's tolerance (the answer is the upper
/// end of a bracket narrower than it). The rigid-block column carries the closed form itself,
/// whose answer must be within the tolerance above the exact width. Checked for two S_a, with
/// the width growing as S_a falls.
#[test]
fn sizing_through_the_engine_returns_the_closed_form_width() {
    let tolerance_m = 0.005;
    let mut engine_runs = 0;
    let mut last_width = 0.0;
    for s_a in [0.004, 0.001] {
        let p = SizeParams {
            range_m: (0.5, 1.5),
            criteria: Criteria { expected_sliding_m: Some(s_a), ..Criteria::default() },
            lives: 1,
            auto: None,
            tolerance_m,
            curve_points: 5,
            conventional: Default::default(),
        };
        let sizing = size::<String>(&p, &mut |b| {
            let sc = at_width(b);
            let r = run(sc.structure(), sc.load.as_ref().unwrap(), sc.duration_s, false).map_err(|e| e.to_string())?;
            engine_runs += 1;
            let s = r.summary.permanent_sliding_m;
            let e = exact_m(b);
            assert!((s - e).abs() <= ENGINE_REL * e + ENGINE_ABS_M, "B = {b} m: engine {s} m vs exact {e} m");
            Ok(Candidate {
                width_m: b,
                weight_in_water_n: WEIGHT_PER_WIDTH_KN_PER_M * b * 1e3,
                lives: 1,
                dynamic: point(s),
                rigid_block: point(exact_m(b)),
                heel_pressure_exceedance: Default::default(),
                life_counts: LifeCounts::default(),
                precision: None,
            })
        })
        .unwrap();
        let exact = exact_width_m(s_a);
        let Required::Found { width_m, .. } = sizing.dynamic else { panic!("S_a = {s_a}: {:?}", sizing.dynamic) };
        let (lo, hi) = (
            exact_width_m((s_a + ENGINE_ABS_M) * (1.0 + ENGINE_REL)),
            exact_width_m((s_a - ENGINE_ABS_M) / (1.0 + ENGINE_REL)),
        );
        assert!(
            width_m >= lo && width_m <= hi + tolerance_m,
            "S_a = {s_a} m: sized {width_m} m, exact {exact} m, allowed [{lo}, {}] m",
            hi + tolerance_m
        );
        let rigid = sizing.rigid_block.width_m().expect("the closed form's width is found");
        assert!(rigid >= exact && rigid - exact <= tolerance_m, "closed form: {rigid} m vs {exact} m");
        assert!(width_m > last_width, "the width grows as S_a falls");
        last_width = width_m;
    }
    // Two searches of 5 grid widths and ceil(log2(0.25/0.005)) = 6 bisection steps each (the
    // rigid block's bisection reuses or adds a few).
    assert!(engine_runs >= 22, "{engine_runs} engine runs");
}
