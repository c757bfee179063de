//! The seed's qualitative findings (§5.2, §6; Figs. 7-8, 13, 15) on the PARI campaigns and the
//! Table 5 caisson, with the default damping placement, judged by the criteria of the validation
//! report (`caisson::analysis::findings`). The full report with both placements is
//! `docs/validation.md` (`caisson validation`); these tests keep the reproduced findings true.
//! The PARI campaigns (15 conditions × 10 realizations × 15 waves each) run in well under a
//! second in release mode, so the tests use them whole.

mod support;

use caisson::analysis::campaign::{run_campaign, ConditionResult};
use caisson::analysis::findings;
use caisson::analysis::spectrum::{log_space, sweep, SpectrumPoint};
use caisson::foundation::DampingMode;
use caisson::loads::generator::{HeightVariability, TrainKind};
use caisson::loads::LoadSpec;
use caisson::scenario::Scenario;
use caisson::Profile;
use support::scenario;

const NONBREAKING: &str = include_str!("../../../examples/pari_nonbreaking_campaign.toml");
const BREAKING: &str = include_str!("../../../examples/pari_breaking_campaign.toml");

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

#[test]
fn non_breaking_sliding_grows_with_height_and_falls_with_weight() {
    let rs = campaign(NONBREAKING, same);
    // F5 and F6 (tolerance 1 µm, so that two conditions that do not slide compare equal).
    let along_h = findings::monotonic(&rs, true, true);
    assert!(along_h.holds, "{}", along_h.detail);
    let along_w = findings::monotonic(&rs, false, false);
    assert!(along_w.holds, "{}", along_w.detail);
    // Table 3: 15 conditions on a 4 × 4 grid less one: 11 pairs along H and 11 along W.
    assert_eq!((along_h.checked, along_w.checked), (11, 11), "pairs checked");
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
    // F7.
    let along_w = findings::monotonic(&rs, false, false);
    assert!(along_w.holds, "{}", along_w.detail);
    // Table 4: 15 conditions, 4 heights at 3 to 5 weights each.
    assert_eq!(along_w.checked, 11, "pairs along W checked");
}

/// With every wave at its nominal height, the impacts dominate where the pulsating load alone
/// cannot slide the caisson (Goda SF ≥ 1): for W = 16.2 and 17.8 kN sliding peaks at H = 0.524
/// or 0.569 m and is not monotonic in H (F8, seed Fig. 15). With 20 % variability this is masked
/// (docs/validation.md §6).
#[test]
fn breaking_sliding_peaks_between_the_middle_heights_with_nominal_waves() {
    let heavy: Vec<ConditionResult> = campaign(BREAKING, nominal_heights)
        .into_iter()
        .filter(|r| [16.2, 17.8].iter().any(|w| (r.condition.weight_in_water_n / 1e3 - w).abs() < 1e-9))
        .collect();
    let f8 = findings::peaks_mid_height(&heavy);
    assert!(f8.holds, "{}", f8.detail);
    // Both weights were tested at all four heights.
    assert_eq!((heavy.len(), f8.checked), (8, 2), "conditions and weights checked");
}

fn table5_spectrum(peak_over_ssr: f64, ratios: &[f64], profile: Profile) -> Vec<SpectrumPoint> {
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
    ))
    .with_profile(profile)
    .unwrap();
    let Some(LoadSpec::Triangle(base)) = s.load.clone() else { panic!("a triangle") };
    sweep(s.structure(), base, ratios, &|| {}).unwrap()
}

/// Seed §5.2 / Fig. 8 with a pulse 10 % above the static sliding resistance: no sliding for
/// t_r ≪ T0 (F1); more than the static (Shimosako) approach near t_r ≈ T0 (F3); less shoreward
/// sliding for t_r ≫ T0 (F4) with the seed's literal model only: with the default the caisson
/// rocks and ends seaward, which the report counts as not reproduced (docs/validation.md §4).
#[test]
fn pulse_findings_of_figures_7_and_8() {
    let ratios = log_space(0.05, 10.0, 13);
    let pts = table5_spectrum(1.1, &ratios, Profile::Consistent);
    let (f1, f3, f4) = (
        findings::no_slide_for_short_pulses(&pts),
        findings::more_than_shimosako_near_t0(&pts),
        findings::less_than_shimosako_for_long_pulses(&pts),
    );
    for f in [&f1, &f3] {
        assert!(f.holds, "{}", f.detail);
    }
    assert!(!f4.holds && f4.detail.ends_with("2 of 2 points end seaward"), "{}", f4.detail);
    // 13 log-spaced ratios from 0.05 to 10: 2 at or below 0.1, 3 from 0.5 to 2, 2 at or above 5.
    assert_eq!((f1.checked, f3.checked, f4.checked), (2, 3, 2), "short, near-T0 and long pulses checked");
    let seed = findings::less_than_shimosako_for_long_pulses(&table5_spectrum(1.1, &ratios, Profile::Seed2011));
    assert!(seed.holds && seed.checked == 2, "{}", seed.detail);
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
    // So the elastic placement reproduces F9 by the report's criterion, and the default does not.
    let (f9_elastic, f9_total) = (findings::safer_than_rigid_block(&elastic), findings::safer_than_rigid_block(&total));
    assert!(f9_elastic.holds && !f9_total.holds, "elastic: {}; total: {}", f9_elastic.detail, f9_total.detail);
}
