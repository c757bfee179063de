//! The seed's qualitative findings (§5.2, §6; Figs. 7-8, 13, 15) on the PARI campaigns and the
//! Table 5 caisson, with the default damping placement. The full report with both placements is
//! `docs/validation.md` (`caisson validation`); these tests keep the reproduced findings true.
//! The PARI campaigns (15 conditions × 10 realizations × 15 waves each) run in well under a
//! second in release mode, so the tests use them whole.

mod support;

use caisson::analysis::campaign::{run_campaign, ConditionResult};
use caisson::analysis::spectrum::{log_space, sweep, SpectrumPoint};
use caisson::foundation::DampingMode;
use caisson::loads::generator::{HeightVariability, TrainKind};
use caisson::loads::LoadSpec;
use caisson::scenario::Scenario;
use support::scenario;

const NONBREAKING: &str = include_str!("../../../examples/pari_nonbreaking_campaign.toml");
const BREAKING: &str = include_str!("../../../examples/pari_breaking_campaign.toml");

/// "No sliding": below 1 µm (the elastic residue of a stuck caisson is far smaller; any slide of
/// interest is far larger).
const NO_SLIDE_M: f64 = 1e-6;

/// A PARI campaign example, changed by `edit` (typed), run whole.
fn campaign(text: &str, edit: impl FnOnce(Scenario) -> Scenario) -> Vec<ConditionResult> {
    let c = edit(scenario(text)).campaign().unwrap();
    assert_eq!(c.setups.len(), 15, "the PARI campaigns have 15 conditions");
    run_campaign(&c.setups, &|| {}).unwrap()
}

fn same(s: Scenario) -> Scenario {
    s
}

/// Every wave at its nominal height.
fn nominal_heights(mut s: Scenario) -> Scenario {
    match s.waves.as_mut().map(|w| &mut w.train.kind) {
        Some(TrainKind::Regular { variability, .. }) => *variability = HeightVariability::None,
        _ => panic!("the PARI campaigns are regular waves"),
    }
    s
}

fn mean(rs: &[ConditionResult], h: f64, w_kn: f64) -> Option<f64> {
    rs.iter()
        .find(|r| (r.condition.height_m - h).abs() < 1e-9 && (r.condition.weight_in_water_n - w_kn * 1e3).abs() < 1e-6)
        .map(|r| r.summary.sliding_m.mean)
}

const HEIGHTS: [f64; 4] = [0.428, 0.524, 0.569, 0.619];

/// Two tested (H, W) conditions and their mean slides.
type Pair = ((f64, f64), (f64, f64), f64, f64);

/// Consecutive tested pairs along H (for fixed W) or along W (for fixed H).
fn pairs(rs: &[ConditionResult], weights: &[f64], along_height: bool) -> Vec<Pair> {
    let mut out = Vec::new();
    if along_height {
        for &w in weights {
            let seq: Vec<(f64, f64)> = HEIGHTS.iter().filter_map(|&h| mean(rs, h, w).map(|m| (h, m))).collect();
            out.extend(seq.windows(2).map(|p| ((p[0].0, w), (p[1].0, w), p[0].1, p[1].1)));
        }
    } else {
        for &h in &HEIGHTS {
            let seq: Vec<(f64, f64)> = weights.iter().filter_map(|&w| mean(rs, h, w).map(|m| (w, m))).collect();
            out.extend(seq.windows(2).map(|p| ((h, p[0].0), (h, p[1].0), p[0].1, p[1].1)));
        }
    }
    out
}

#[test]
fn non_breaking_sliding_grows_with_height_and_falls_with_weight() {
    let rs = campaign(NONBREAKING, same);
    let weights = [7.5, 7.8, 8.2, 8.9];
    // Tolerance: 1 µm, so that two conditions that do not slide compare equal.
    let along_h = pairs(&rs, &weights, true);
    for (a, b, sa, sb) in &along_h {
        assert!(sb >= &(sa - NO_SLIDE_M), "H {:?} → {:?}: {sa} → {sb} m", a, b);
    }
    let along_w = pairs(&rs, &weights, false);
    for (a, b, sa, sb) in &along_w {
        assert!(sb <= &(sa + NO_SLIDE_M), "W {:?} → {:?}: {sa} → {sb} m", a, b);
    }
    // Table 3: 15 conditions on a 4 × 4 grid less one: 11 pairs along H and 11 along W.
    assert_eq!((along_h.len(), along_w.len()), (11, 11), "pairs checked");
    // And it does slide where Goda's static check fails (SF < 1): the finding is not vacuous.
    let failing: Vec<&ConditionResult> = rs.iter().filter(|r| r.safety.sliding.is_some_and(|s| s < 0.95)).collect();
    for r in &failing {
        assert!(r.summary.sliding_m.mean > 1e-3, "{:?} slides only {} m", r.condition, r.summary.sliding_m.mean);
    }
    assert_eq!(failing.len(), 10, "conditions with Goda SF < 0.95 checked");
}

#[test]
fn breaking_sliding_falls_with_weight() {
    let rs = campaign(BREAKING, same);
    let along_w = pairs(&rs, &[11.3, 13.7, 16.2, 17.8, 19.4], false);
    for (a, b, sa, sb) in &along_w {
        assert!(sb <= &(sa + NO_SLIDE_M), "W {:?} → {:?}: {sa} → {sb} m", a, b);
    }
    // Table 4: 15 conditions, 4 heights at 3 to 5 weights each.
    assert_eq!(along_w.len(), 11, "pairs along W checked");
}

/// With every wave at its nominal height, the impacts dominate where the pulsating load alone
/// cannot slide the caisson (Goda SF ≥ 1): sliding peaks at H = 0.524 m and is not monotonic in H
/// (seed Fig. 15). With 20 % variability this is masked (docs/validation.md §6).
#[test]
fn breaking_sliding_peaks_between_the_middle_heights_with_nominal_waves() {
    let rs = campaign(BREAKING, nominal_heights);
    for w in [16.2, 17.8] {
        let s: Vec<f64> = HEIGHTS.iter().map(|&h| mean(&rs, h, w).unwrap()).collect();
        let (imax, _) =
            s.iter().enumerate().fold((0, f64::NEG_INFINITY), |a, (i, &v)| if v > a.1 { (i, v) } else { a });
        assert!(imax == 1 || imax == 2, "W = {w}: sliding {:?} m peaks at H = {}", s, HEIGHTS[imax]);
        assert!(s[3] < s[imax] && s[0] < s[imax], "W = {w}: not monotonic expected, got {s:?}");
    }
}

fn table5_spectrum(peak_over_ssr: f64, ratios: &[f64]) -> Vec<SpectrumPoint> {
    let peak = peak_over_ssr * 0.6 * 8.24;
    let s = scenario(&format!(
        r#"
[caisson]
width_m = 0.78
height_m = 1.12
base_depth_m = 0.8
weight_in_water_kn = 8.24
[foundation]
mu_static = 0.6
mu_dynamic = 0.6
e100_kpa = 3.5e5
[load]
kind = "triangle"
peak_horizontal_kn = {peak}
rise_time_s = 0.02
horizontal_lever_m = 0.8
"#
    ));
    let Some(LoadSpec::Triangle(base)) = s.load.clone() else { panic!("a triangle") };
    sweep(s.structure(), base, ratios, &|| {}).unwrap()
}

/// Seed §5.2 / Fig. 8 with a pulse 10 % above the static sliding resistance: no sliding for
/// t_r ≪ T0; more than the static (Shimosako) approach near t_r ≈ T0; less for t_r ≫ T0.
#[test]
fn pulse_findings_of_figures_7_and_8() {
    let ratios = log_space(0.05, 10.0, 13);
    let pts = table5_spectrum(1.1, &ratios);
    let short: Vec<&SpectrumPoint> = pts.iter().filter(|p| p.tr_over_t0 <= 0.1).collect();
    for p in &short {
        assert!(p.permanent_sliding_m < NO_SLIDE_M, "t_r/T0 = {}: slides {} m", p.tr_over_t0, p.permanent_sliding_m);
    }
    // 13 log-spaced ratios from 0.05 to 10: 2 at or below 0.1, 2 at or above 5.
    assert_eq!(short.len(), 2, "short pulses checked");
    assert_eq!(pts.iter().filter(|p| p.tr_over_t0 >= 5.0).count(), 2, "long pulses checked");
    assert!(
        pts.iter()
            .filter(|p| (0.5..=2.0).contains(&p.tr_over_t0))
            .any(|p| p.permanent_sliding_m > p.shimosako_sliding_m),
        "no point near t_r ≈ T0 slides more than Shimosako: {:?}",
        pts.iter().map(|p| (p.tr_over_t0, p.permanent_sliding_m, p.shimosako_sliding_m)).collect::<Vec<_>>()
    );
    for p in pts.iter().filter(|p| p.tr_over_t0 >= 5.0) {
        assert!(
            p.permanent_sliding_m < p.shimosako_sliding_m,
            "t_r/T0 = {}: {} ≥ Shimosako {}",
            p.tr_over_t0,
            p.permanent_sliding_m,
            p.shimosako_sliding_m
        );
    }
}

/// The other dashpot placement gives more sliding than the rigid block (Shimosako model, μ = 0.6)
/// in every sliding non-breaking test, as the seed says of its model (Fig. 13); the default
/// placement gives less. Both are reported in docs/validation.md.
#[test]
fn elastic_placement_slides_more_than_the_rigid_block_and_total_less() {
    let elastic =
        campaign(NONBREAKING, |s| s.with_foundation(|f| f.damping_mode = Some(DampingMode::Elastic)).unwrap());
    let total = campaign(NONBREAKING, same);
    let mut checked = 0;
    for (e, t) in elastic.iter().zip(&total) {
        let rb = e.summary.rigid_block_sliding_m.mean;
        assert_eq!(rb, t.summary.rigid_block_sliding_m.mean, "the reference does not depend on the dashpot");
        if rb > 1e-3 {
            assert!(
                e.summary.sliding_m.mean > rb,
                "{:?}: elastic {} vs rigid block {rb}",
                e.condition,
                e.summary.sliding_m.mean
            );
            assert!(
                t.summary.sliding_m.mean < rb,
                "{:?}: total {} vs rigid block {rb}",
                t.condition,
                t.summary.sliding_m.mean
            );
            checked += 1;
        }
    }
    assert_eq!(checked, 13, "sliding conditions compared");
}
