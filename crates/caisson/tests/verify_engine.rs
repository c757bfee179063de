//! Verification of the dynamic engine against closed forms (docs/model.md §6.3 rigid block, §9.2
//! shock spectrum), the seed's static push (§5.1, Fig. 6), Table 6, and convergence in dt.

mod support;

use caisson::analysis::closed_form::rigid_block_sliding_m;
use caisson::analysis::run::{run, RunResult};
use caisson::analysis::spectrum::sweep;
use caisson::loads::LoadSpec;
use caisson::scenario::Scenario;
use support::{scenario, TABLE5};

/// Run a scenario's `[load]` for its duration.
fn run_load(s: &Scenario, record_history: bool) -> RunResult {
    run(s.structure(), s.load.as_ref().expect("a [load] table"), s.duration_s, record_history).unwrap()
}

#[test]
fn table6_from_table5_inputs() {
    let s = scenario(TABLE5);
    let k = s.foundation().stiffness;
    // docs/model.md §8.2: K_y 1.404e5 kN/m, K_x 1.511e5 kN/m, M 1463.96 kg, C 598 kN·s/m
    // (Eq. 22; Table 6's 480 is the known slip). Tolerance 1 % as the issue asks.
    let rel = |a: f64, b: f64| (a / b - 1.0).abs();
    assert!(rel(k.ky_n_per_m, 1.404e8) < 0.01, "K_y {}", k.ky_n_per_m);
    assert!(rel(k.kx_n_per_m, 1.511e8) < 0.01, "K_x {}", k.kx_n_per_m);
    assert!(rel(s.caisson().mass_kg, 1463.96) < 0.01, "M {}", s.caisson().mass_kg);
    assert!(rel(k.damping_ns_per_m, 5.98e5) < 0.01, "C {}", k.damping_ns_per_m);
    // T0 rounds to the table's 0.02 s with every reading (§8.2 item 6): within 0.0195-0.0235 s.
    let t0 = s.structure().model().natural_period_s();
    assert!((0.0195..0.0235).contains(&t0), "T0 {t0}");
}

/// Shock spectrum, undamped, no sliding (μ = 10), force at the base, diagonal mass: the
/// horizontal mode is an exact SDOF. Ψ within 0.5 % of the closed form for t_r/T0 from 0.05
/// to 5 (the issue's tolerance; the sweep uses dt ≤ T0/200, whose Newmark period error is
/// ≈ (ω dt)²/12 = 8e-5).
#[test]
fn shock_spectrum_undamped_matches_closed_form() {
    let s = scenario(
        r#"
[caisson]
width_m = 0.78
height_m = 1.12
base_depth_m = 0.8
weight_in_water_kn = 8.24
mass_matrix = "diagonal"
[foundation]
e100_kpa = 3.5e5
damping_kns_per_m = 0.0
mu_static = 10.0
mu_dynamic = 10.0
[load]
kind = "triangle"
peak_horizontal_kn = 2.0
rise_time_s = 0.01
horizontal_lever_m = 0.0
"#,
    );
    let Some(LoadSpec::Triangle(base)) = s.load.clone() else { panic!() };
    let ratios = [0.05, 0.1, 0.2, 0.3, 0.452, 0.6, 0.75, 1.0, 1.25, 1.5, 2.0, 2.5, 3.3, 5.0];
    let pts = sweep(s.structure(), base, &ratios, &|| {}).unwrap();
    assert_eq!(pts.len(), ratios.len());
    for p in pts {
        let err = (p.psi / p.psi_closed_form - 1.0).abs();
        assert!(
            err < 0.005,
            "t_r/T0 = {}: Ψ {} vs closed form {} ({:.3} %)",
            p.tr_over_t0,
            p.psi,
            p.psi_closed_form,
            100.0 * err
        );
        assert!(p.permanent_sliding_m.abs() < 1e-12, "no sliding expected");
    }
}

/// A very stiff foundation (100 × Table 6) with μ_s = μ_d = 0.6, no damping, force and uplift
/// through the base centre (no rocking): the caisson is the rigid block of docs/model.md §6.3.
fn rigid_block(ratio_a_over_b: f64, uplift_over_w: f64) -> (f64, f64) {
    let w = 8.24;
    let mu = 0.6;
    let p = mu * (ratio_a_over_b * w - uplift_over_w * w); // A = P + μU = ratio·μW
    let tr = 0.1;
    let text = support::rigid_block_caisson(0.78, w, mu)
        + &format!(
            r#"
[load]
kind = "triangle"
peak_horizontal_kn = {p}
peak_uplift_kn = {u}
rise_time_s = {tr}
horizontal_lever_m = 0.0
uplift_lever_m = 0.39
duration_s = 1.5
[solver]
dt_s = 2e-5
"#,
            u = uplift_over_w * w
        );
    let s = scenario(&text);
    let m = s.structure().model().horizontal_mass_kg();
    let exact = rigid_block_sliding_m(ratio_a_over_b * mu * w * 1e3, mu * w * 1e3, m, 2.0 * tr);
    let r = run_load(&s, false);
    (r.summary.permanent_sliding_m, exact)
}

/// Within 1 % of the exact closed forms in both regimes (A/B = 1.5 stops before the pulse ends,
/// A/B = 3 after), with and without uplift. The residual difference is the elastic compliance
/// (e_s = μW'/K_x ≈ 3e-7 m) and the stick-slip transitions resolved to dt.
#[test]
fn rigid_block_sliding_matches_closed_form() {
    for (ratio, uplift) in [(1.5, 0.0), (3.0, 0.0), (1.5, 0.3), (3.0, 0.3)] {
        let (s, exact) = rigid_block(ratio, uplift);
        let err = (s / exact - 1.0).abs();
        assert!(err < 0.01, "A/B = {ratio}, U/W = {uplift}: {s} m vs exact {exact} m ({:.3} %)", 100.0 * err);
    }
}

/// Quasi-static push at the still-water level (seed §5.1, Fig. 6, d = 0.4 m): reactions linear
/// across the base while in contact, the seaward springs unload first, and sliding starts at
/// F = μ_s (W' − U) within 1 %.
///
/// Quasi-static means a ramp slow against every relaxation time of the model. The seed's global
/// dashpots (10 C on θ as N·m·s/rad) make rocking relax over ~1 s, and once the seaward springs
/// lift, rotation about the heel moves the base centre vertically into the global vertical
/// dashpot, which adds to ΣN (measured: onset 0.5 % late even with a 20 s ramp). The consistent
/// per-spring dashpots (`vertical_damping = "springs"`, docs/model.md §10 item 10 option B) with a
/// 20 s ramp converge to the static onset (measured 0.1 %).
#[test]
fn static_push_reproduces_fig6_behaviour() {
    for uplift_kn in [0.0, 2.0] {
        let text = format!(
            r#"
[caisson]
width_m = 0.78
height_m = 1.12
base_depth_m = 0.4
weight_in_water_kn = 8.24
[foundation]
springs = 4
e100_kpa = 3.5e5
vertical_damping = "springs"
[load]
kind = "static"
peak_horizontal_kn = 6.0
peak_uplift_kn = {uplift_kn}
horizontal_lever_m = 0.4
ramp_time_s = 20.0
duration_s = 19.5
[solver]
output_interval_s = 1e-3
"#
        );
        let s = scenario(&text);
        let r = run_load(&s, true);
        let h = r.history.unwrap();
        let n = h.springs();
        // The caisson slides when every spring in contact slips (an almost unloaded seaward
        // spring may slip alone before, its dashpot exceeding μ N: that is not sliding).
        let contact = |k: usize| h.spring_forces_n[k * 2 * n..k * 2 * n + n].iter().filter(|&&v| v > 0.0).count();
        let first_slip = (0..h.len())
            .find(|&k| h.sliding_springs[k] > 0 && h.sliding_springs[k] as usize == contact(k))
            .expect("the push must slide the caisson");
        let f = h.fx_n[first_slip];
        let expected = 0.6 * (8240.0 - h.fy_n[first_slip]);
        assert!(
            (f / expected - 1.0).abs() < 0.01,
            "U = {uplift_kn} kN: sliding starts at {f} N, expected {expected} N"
        );
        // Before sliding, at every sample: N increases from the seaward to the shoreward end,
        // and the springs in contact lie on a line (rigid base), both to 1e-6 of W' (the start
        // of the ramp excites a dynamic transient of a few 1e-6 N, see the coupled mass).
        let mut lifted_order = Vec::new();
        for k in 1..first_slip {
            let nk = &h.spring_forces_n[k * 2 * n..k * 2 * n + n];
            for i in 1..n {
                assert!(nk[i] >= nk[i - 1] - 1e-6 * 8240.0, "sample {k}: N not increasing shoreward: {nk:?}");
            }
            let contact: Vec<usize> = (0..n).filter(|&i| nk[i] > 0.0).collect();
            if contact.len() >= 3 {
                let (i0, i1) = (contact[0], contact[1]);
                let slope = (nk[i1] - nk[i0]) / (h.spring_x_m[i1] - h.spring_x_m[i0]);
                for &i in &contact[2..] {
                    let pred = nk[i0] + slope * (h.spring_x_m[i] - h.spring_x_m[i0]);
                    assert!((nk[i] - pred).abs() < 1e-6 * 8240.0, "sample {k}: reactions not linear: {nk:?}");
                }
            }
            for (i, &force) in nk.iter().enumerate() {
                if force == 0.0 && !lifted_order.contains(&i) {
                    lifted_order.push(i);
                }
            }
        }
        // The seaward spring (index 0) is the first to lift off.
        assert_eq!(lifted_order.first(), Some(&0), "lift-off order {lifted_order:?}");
    }
}

/// Halving the default time step changes the permanent sliding of a sliding case by < 0.5 %.
#[test]
fn sliding_converges_in_dt() {
    let base = format!(
        "{TABLE5}\n[load]\nkind = \"triangle\"\npeak_horizontal_kn = 12.0\nrise_time_s = 0.05\nhorizontal_lever_m = 0.3\nduration_s = 0.6\n"
    );
    let s1 = scenario(&base);
    let half = caisson::dynamics::SolverParams { dt_s: 0.5 * s1.solver().dt_s, ..s1.solver() };
    let s2 = s1.clone().with_solver(half).unwrap();
    let a = run_load(&s1, false).summary.permanent_sliding_m;
    let b = run_load(&s2, false).summary.permanent_sliding_m;
    assert!(a > 1e-4, "the case must slide: {a} m");
    assert!((a / b - 1.0).abs() < 0.005, "dt 1e-4: {a} m, dt 5e-5: {b} m");
}

/// Below the sliding resistance the run reports no slip event and no permanent slide.
#[test]
fn no_sliding_below_resistance() {
    let text = format!(
        "{TABLE5}\n[load]\nkind = \"triangle\"\npeak_horizontal_kn = 1.0\nrise_time_s = 0.05\nduration_s = 0.3\n"
    );
    let r = run_load(&scenario(&text), false).summary;
    assert_eq!(r.slip_events, 0);
    assert!(r.permanent_sliding_m.abs() < 1e-9, "{} m", r.permanent_sliding_m);
}

/// The simulated settlement under a held uplift U through the base centre is (W' − U)/K_y: the
/// caisson starts at W'/K_y and must rise by U/K_y (linear springs in compression, no moment).
/// 2 s after the 1 s ramp the heave has decayed (vertical damping ratio of order 1); tolerance
/// 1e-6 relative, far below the 24 % change being checked.
#[test]
fn settlement_follows_the_held_uplift() {
    let text = format!(
        "{TABLE5}\n[load]\nkind = \"static\"\npeak_horizontal_kn = 0.0\npeak_uplift_kn = 2.0\nuplift_lever_m = 0.39\nramp_time_s = 1.0\nduration_s = 3.0\n"
    );
    let s = scenario(&text);
    let r = run_load(&s, false).summary;
    let ky = s.foundation().stiffness.ky_n_per_m;
    let expected = (8240.0 - 2000.0) / ky;
    assert!(
        (r.final_settlement_m / expected - 1.0).abs() < 1e-6,
        "settled {} m, (W' − U)/K_y = {expected} m",
        r.final_settlement_m
    );
    assert!((r.foundation.static_settlement_m / expected - 1.0).abs() > 0.2, "the uplift must change the settlement");
    assert_eq!(r.slip_events, 0);
}

/// The time histories run to the end of the run when its duration is not a multiple of
/// `output_interval_s` (docs/cli.md): a 0.6005 s run sampled every 1 ms has rows at 0, 1 ms, ...,
/// 600 ms and a last one at 600.5 ms, whose state is the run's final state; kept whole
/// ([`History`]) and streamed ([`Rows`], what `caisson run --out` writes), alike. A wave train
/// (its own driver) ends on its last row too.
#[test]
fn history_rows_run_to_the_end() {
    use caisson::analysis::run::{run_observed, HistoryRow, Rows, Sampler};
    let text = format!(
        "{TABLE5}\n[load]\nkind = \"triangle\"\npeak_horizontal_kn = 12.0\nrise_time_s = 0.05\nhorizontal_lever_m = 0.3\nduration_s = 0.6005\n"
    );
    let s = scenario(&text);
    assert_eq!(s.solver().output_interval_s, 1e-3);
    let r = run_load(&s, true);
    let h = r.history.unwrap();
    assert_eq!(h.len(), 602, "rows at 0, 1 ms, ..., 600 ms and 600.5 ms");
    assert!((h.t_s[600] - 0.6).abs() < 1e-9 && (h.t_s[601] - 0.6005).abs() < 1e-12, "{:?}", &h.t_s[599..]);
    assert_eq!(h.ux_m[601], r.summary.final_displacement_m);
    let mut streamed = Vec::new();
    let mut rows = Rows::new(Sampler::of(s.structure()), |row: &HistoryRow<'_>| streamed.push((row.t_s, row.ux_m)));
    run_observed(s.structure(), s.load.as_ref().unwrap(), s.duration_s, Some(&mut rows)).unwrap();
    drop(rows);
    assert_eq!(streamed, h.t_s.iter().copied().zip(h.ux_m.iter().copied()).collect::<Vec<_>>());
    // A run that ends on a row keeps it once.
    let whole = scenario(&text.replace("duration_s = 0.6005", "duration_s = 0.6"));
    assert_eq!(run_load(&whole, true).history.unwrap().len(), 601);
    // A wave train of the PARI non-breaking set-up (its own driver): it ends on a row with the
    // default interval (5 ms, its longest step), and on a row of its own with one of 12.3 ms,
    // longer than its steps (rows fall on the first step at or after each interval, so the
    // last gap is less than an interval and a step), which does not divide its duration.
    let sc = support::example("pari_nonbreaking_loads.toml");
    let case = sc.train_case().unwrap();
    let row_times = |interval_s: f64| {
        let mut structure = case.structure.clone();
        structure.solver.output_interval_s = interval_s;
        let mut times = Vec::new();
        let mut rows = Rows::new(Sampler::of(&structure), |row: &HistoryRow<'_>| times.push(row.t_s));
        caisson::analysis::train::TrainCase { structure: &structure, ..case }.run(0, Some(&mut rows)).unwrap();
        drop(rows);
        times
    };
    let default = row_times(case.structure.solver.output_interval_s);
    let end = *default.last().unwrap();
    let odd = row_times(0.0123);
    let n = odd.len();
    assert!((end / 0.0123 - (end / 0.0123).round()).abs() > 1e-3, "12.3 ms does not divide {end} s");
    assert!(
        odd[n - 1] == end && end - odd[n - 2] < 0.0123 + 5e-3 && n > 1000,
        "{n} rows, the last {:?}",
        &odd[n - 3..]
    );
}
