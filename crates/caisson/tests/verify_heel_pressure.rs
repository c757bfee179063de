//! The heel pressure of a design life (docs/design.md, "Heel pressure"): the heel value of the
//! linear base pressure without tension that carries the springs' normal forces
//! ([`base_heel_pressure_pa`]) is Goda's static heel pressure p_e under a static load, by hand.

mod support;

use caisson::analysis::lifetime::base_heel_pressure_pa;
use caisson::analysis::run::run;
use support::scenario;

/// A caisson 0.78 m wide (W' = 8240 N on 1 m) under a held static load: P at 0.4 m above the
/// base and U = 1 kN with its resultant 0.52 m (2B/3) from the heel. Goda (2000; docs/model.md
/// §1.5) by hand: M_e = W' B/2 − U · 0.52 − P · 0.4, V_e = W' − U = 7240 N, t_e = M_e/V_e;
///
/// * P = 1 kN: M_e = 3213.6 − 520 − 400 = 2293.6 N·m, t_e = 0.316796 m > B/3, the whole base
///   pressed: p_e = (2 V_e/B)(2 − 3 t_e/B) = 14 508.9 Pa;
/// * P = 3 kN: M_e = 1493.6 N·m, t_e = 0.206298 m ≤ B/3, part of the base unloaded (springs
///   lifted): p_e = 2 V_e/(3 t_e) = 23 396.5 Pa.
///
/// The springs' resultant after 2 s at the held load gives the same to 1e-6 (the settlement test
/// of verify_engine holds its static state to 1e-6 likewise; the heel pressure is the springs' V
/// and moment, which static equilibrium makes the load's).
#[test]
fn the_heel_pressure_of_the_springs_is_godas_under_a_static_load() {
    let mut checked = 0;
    for (p_kn, lifted) in [(1.0, false), (3.0, true)] {
        let text = format!(
            r#"
[caisson]
width_m = 0.78
height_m = 1.12
base_depth_m = 0.4
weight_in_water_kn = 8.24
[foundation]
springs = 10
e100_kpa = 3.5e5
vertical_damping = "springs"
[load]
kind = "static"
peak_horizontal_kn = {p_kn}
peak_uplift_kn = 1.0
horizontal_lever_m = 0.4
uplift_lever_m = 0.52
ramp_time_s = 1.0
duration_s = 3.0
[solver]
output_interval_s = 1e-2
"#
        );
        let s = scenario(&text);
        let r = run(s.structure(), s.load.as_ref().unwrap(), s.duration_s, true).unwrap();
        // (A spring about to lift may slip alone: microns, not sliding; the springs' resultant is
        // the load's whatever they slip.)
        let slid = r.summary.permanent_sliding_m.abs();
        assert!(slid < 1e-5, "P = {p_kn} kN must not slide the caisson: {slid} m");
        let h = r.history.unwrap();
        let n = h.springs();
        let last = h.len() - 1;
        let normal = &h.spring_forces_n[last * 2 * n..last * 2 * n + n];
        let v: f64 = normal.iter().sum();
        let m: f64 = normal.iter().zip(&h.spring_x_m).map(|(f, x)| f * x).sum();
        assert_eq!(normal.iter().any(|&f| f <= 0.0), lifted, "P = {p_kn} kN: springs {normal:?}");
        let q = base_heel_pressure_pa(v, m, 0.78, 1.0);
        // By hand (doc comment).
        let (w, u, b): (f64, f64, f64) = (8240.0, 1000.0, 0.78);
        let me = w * b / 2.0 - u * 0.52 - p_kn * 1e3 * 0.4;
        let ve = w - u;
        let te = me / ve;
        let hand = if te <= b / 3.0 { 2.0 * ve / (3.0 * te) } else { 2.0 * ve / b * (2.0 - 3.0 * te / b) };
        let written = if lifted { 23_396.5 } else { 14_508.9 };
        assert!((hand / written - 1.0).abs() < 1e-5, "the hand calculation {hand} Pa, written {written} Pa");
        assert!((q / hand - 1.0).abs() < 1e-6, "P = {p_kn} kN: the springs give {q} Pa, Goda {hand} Pa");
        checked += 1;
    }
    assert_eq!(checked, 2);
}

/// The edge pressure's three branches by hand on a base 10 m wide carrying 1000 kN/m: the
/// resultant at the centre gives the uniform 100 kPa; 1 m shoreward of it (t_e = 4 m > B/3),
/// (2V/B)(2 − 3·0.4) = 160 kPa; 3 m shoreward (t_e = 2 m ≤ B/3), 2V/(3 t_e) = 333.3 kPa; 3 m
/// seaward (t_e = 8 m ≥ 2B/3) the heel is unloaded: 0; no normal force: 0.
#[test]
fn the_heel_pressure_of_a_resultant_by_hand() {
    let q = |m_nm: f64| base_heel_pressure_pa(1e6, m_nm, 10.0, 1.0);
    assert!((q(0.0) - 1e5).abs() < 1e-6);
    assert!((q(1e6) - 1.6e5).abs() < 1e-6);
    assert!((q(3e6) - 2e6 / 6.0).abs() < 1e-6);
    assert_eq!(q(-3e6), 0.0);
    assert_eq!(base_heel_pressure_pa(0.0, 5.0, 10.0, 1.0), 0.0);
}
