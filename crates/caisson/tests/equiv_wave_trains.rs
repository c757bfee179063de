//! Wave trains and campaigns (loads/generator.rs, analysis/train.rs, analysis/campaign.rs;
//! docs/campaign.md): identical results on any number of threads, adaptive against fixed time
//! steps, the statistics of the wave-height generator, the height limit of a forced non-breaking
//! train, reproducible random numbers, and per-wave sliding that adds up to the total.
//!
//! The PARI campaigns are cut to a few conditions, realizations and waves: with adaptive steps a
//! 5-wave realization takes a few milliseconds, and the whole file well under a second in release
//! mode (the fixed-step references about 0.2 s).

mod support;

use caisson::analysis::campaign::{run_campaign, Campaign, Condition};
use caisson::analysis::site::WaveSetup;
use caisson::analysis::train::{RealizationResult, TrainCase};
use caisson::dynamics::Stepping;
use caisson::loads::generator::{realization_waves, RealizationWaves, TrainSpec};
use caisson::loads::regime::{Regime, RegimeChoice};
use caisson::scenario::campaign::CampaignSpec;
use support::scenario;

const NONBREAKING: &str = include_str!("../../../examples/pari_nonbreaking_campaign.toml");
const BREAKING: &str = include_str!("../../../examples/pari_breaking_campaign.toml");

/// A PARI campaign file cut to `waves` waves × `realizations` realizations and the listed
/// conditions (H m, W' kN, regime).
fn reduced(text: &str, waves: usize, realizations: usize, conditions: &[(f64, f64, &str)]) -> Campaign {
    let mut sc = scenario(text);
    let w = sc.waves.as_mut().unwrap();
    w.train.waves = waves;
    w.train.realizations = realizations;
    let conditions = conditions
        .iter()
        .map(|&(h, w, r)| Condition {
            height_m: h,
            weight_in_water_n: w * 1e3,
            regime: RegimeChoice::from_name(r).expect("a regime"),
        })
        .collect();
    sc.campaign = Some(CampaignSpec::new(None, conditions));
    sc.campaign().unwrap()
}

/// A deep site (h_s = 30 m, T = 10 s, a 20 m wide caisson) with the given `[waves]` keys besides
/// the period: the Miche limit at the toe (about 12 m) is far above any height drawn here, so the
/// drawn heights are also the heights the loads see.
fn deep_site(waves_keys: &str) -> WaveSetup {
    let text = format!(
        "[caisson]\nwidth_m = 20.0\nheight_m = 30.0\nbase_depth_m = 25.0\nweight_in_water_kn = 5000.0\n\
         [foundation]\ne100_kpa = 3.5e5\n\
         [water]\ndepth_at_toe_m = 30.0\ndepth_at_wall_m = 25.0\n\
         [waves]\nperiod_s = 10.0\n{waves_keys}\n"
    );
    scenario(&text).waves.expect("a [waves] table")
}

/// The waves of realization `index` of `spec` at the site of `w`.
fn draw(w: &WaveSetup, spec: &TrainSpec, choice: RegimeChoice, index: usize) -> RealizationWaves {
    realization_waves(&w.model, spec, choice, index).unwrap()
}

/// `n` heights of realization 0 at the site of `w` (the scenario's regime).
fn heights(w: &WaveSetup, n: usize) -> Vec<f64> {
    let spec = TrainSpec { waves: n, ..w.train };
    draw(w, &spec, w.model.options.regime, 0).records.iter().map(|r| r.height_m).collect()
}

/// Sample mean and standard deviation.
fn mean_sd(x: &[f64]) -> (f64, f64) {
    let n = x.len() as f64;
    let m = x.iter().sum::<f64>() / n;
    (m, (x.iter().map(|v| (v - m).powi(2)).sum::<f64>() / (n - 1.0)).sqrt())
}

/// `|got − want| ≤ 5 standard errors`.
fn within_5_se(what: &str, got: f64, want: f64, se: f64) {
    assert!((got - want).abs() <= 5.0 * se, "{what}: {got} vs {want} (5 standard errors = {})", 5.0 * se);
}

/// Heights per wave test: enough that 5 standard errors are a tight check (about 1 % of the
/// mean for the normal variability).
const N_STAT: usize = 20_000;

// ------------------------------------------------------------------------------------------------
// (a) Thread-count determinism
// ------------------------------------------------------------------------------------------------

/// Both regimes, several weights, 4 realizations each: the full results (every realization, every
/// wave, solver statistics) are identical on 1 and on 3 threads.
#[test]
fn a_campaign_gives_identical_results_on_one_and_three_threads() {
    let mut setups = reduced(NONBREAKING, 4, 4, &[(0.524, 7.5, "auto"), (0.619, 8.9, "auto")]).setups;
    setups.extend(reduced(BREAKING, 4, 4, &[(0.524, 13.7, "auto"), (0.428, 19.4, "breaking")]).setups);
    let on = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
        pool.install(|| run_campaign(&setups, &|| {})).unwrap()
    };
    let one = on(1);
    let three = on(3);
    assert_eq!(one.len(), 4);
    assert!(
        one.iter().all(|c| c.summary.realizations.len() == 4 && c.summary.sliding_m.max > 1e-4),
        "every condition slides"
    );
    assert!(one == three, "1 and 3 threads differ");
}

// ------------------------------------------------------------------------------------------------
// (b) Adaptive against fixed time steps
// ------------------------------------------------------------------------------------------------

/// Total sliding of one 5-wave realization with the default adaptive steps against fixed steps of
/// 1e-4 s (the seed's step), for a sliding non-breaking (H = 0.569 m, W' = 7.8 kN, about 8 mm) and
/// a sliding breaking (H = 0.524 m, W' = 13.7 kN, about 10 mm) PARI condition.
///
/// Tolerance 0.5 %: the fixed-step totals are converged (dt = 5e-5 s and 2.5e-5 s change them by
/// less than 1e-5 relative), so the difference is the adaptive stepper's. Its local error bound is
/// 1e-8 m per step; over the ~3200 steps of the realization these add up to at most ~3e-5 m, about
/// 0.4 % of the slide. The observed differences are 0.04 % (non-breaking) and 0.0003 % (breaking).
#[test]
fn b_adaptive_steps_slide_as_far_as_fixed_steps_of_1e_4_s() {
    for (text, h, w) in [(NONBREAKING, 0.569, 7.8), (BREAKING, 0.524, 13.7)] {
        let c = reduced(text, 5, 1, &[(h, w, "auto")]);
        let case = c.setups[0].case();
        assert!(
            matches!(case.structure.solver.stepping, Stepping::Adaptive(_)),
            "a wave campaign steps adaptively by default"
        );
        let adaptive = case.run(0, None).unwrap();
        let mut fixed_structure = case.structure.clone();
        fixed_structure.solver.stepping = Stepping::Fixed;
        fixed_structure.solver.dt_s = 1e-4;
        let fixed = TrainCase { structure: &fixed_structure, ..case }.run(0, None).unwrap();
        assert!(fixed.sliding_m > 5e-3, "H = {h} m, W' = {w} kN must slide (it slides {} m)", fixed.sliding_m);
        let rel = (adaptive.sliding_m - fixed.sliding_m).abs() / fixed.sliding_m;
        assert!(
            rel <= 5e-3,
            "H = {h} m, W' = {w} kN: adaptive {} m vs fixed {} m ({:.3} %)",
            adaptive.sliding_m,
            fixed.sliding_m,
            rel * 100.0
        );
        assert!(
            adaptive.solver.steps * 10 < fixed.solver.steps,
            "adaptive {} steps, fixed {}",
            adaptive.solver.steps,
            fixed.solver.steps
        );
    }
}

// ------------------------------------------------------------------------------------------------
// (c) Statistics of the generator
// ------------------------------------------------------------------------------------------------

/// Heights H (1 + δ), δ symmetric about 0, of standard deviation `sigma` (m): the sample mean is H
/// and the sample sd `sigma`, both within 5 standard errors (for the sd σ/sqrt(2n), the normal
/// distribution's, which is conservative for the lighter-tailed truncated normal and uniform);
/// every height within H (1 ± `bound`), and the extremes beyond H (1 ± `reach`): the spread is not
/// narrower than it should be.
fn check_symmetric(x: &[f64], h: f64, sigma: f64, bound: f64, reach: f64) {
    let n = x.len() as f64;
    let (m, sd) = mean_sd(x);
    within_5_se("mean", m, h, sigma / n.sqrt());
    within_5_se("sd", sd, sigma, sigma / (2.0 * n).sqrt());
    let (lo, hi) = (h * (1.0 - bound) * (1.0 - 1e-12), h * (1.0 + bound) * (1.0 + 1e-12));
    assert!(
        x.iter().all(|&v| (lo..=hi).contains(&v)),
        "a height outside H (1 ± {bound}): {:?}",
        x.iter().find(|&&v| !(lo..=hi).contains(&v))
    );
    let (min, max) = x.iter().fold((f64::INFINITY, 0.0f64), |(a, b), &v| (a.min(v), b.max(v)));
    assert!(min < h * (1.0 - reach) && max > h * (1.0 + reach), "heights only from {min} to {max} m");
}

/// Normal variability (defaults: COV c = 0.2, truncated at ±2σ): H (1 + c z). Mean H, standard
/// deviation c·0.880·H (the sd of a standard normal truncated at ±2 is
/// sqrt(1 − 4 φ(2)/(2Φ(2) − 1)) = 0.8796); every height within H (1 ± 2c).
#[test]
fn c_normal_variability_has_the_nominal_mean_the_truncated_cov_and_stays_within_two_sigma() {
    let w = deep_site("kind = \"regular\"\nheight_m = 2.0");
    check_symmetric(&heights(&w, N_STAT), 2.0, 0.2 * 0.879_62 * 2.0, 0.4, 0.38);
}

/// Uniform variability (half-width 0.2): mean H, sd 0.2 H/sqrt(3), every height within
/// H (1 ± 0.2).
#[test]
fn c_uniform_variability_stays_within_20_percent() {
    let w = deep_site("kind = \"regular\"\nheight_m = 2.0\nheight_variability = \"uniform\"");
    check_symmetric(&heights(&w, N_STAT), 2.0, 0.2 * 2.0 / 3f64.sqrt(), 0.2, 0.19);
}

/// Irregular waves: Rayleigh heights with P(H > x) = exp[−2 (x/H1/3)²]. Mean H1/3 sqrt(π/8) and sd
/// H1/3 sqrt((4 − π)/8) within 5 standard errors, and the fraction above H1/3 is exp(−2) = 0.135
/// within 5 binomial standard errors.
#[test]
fn c_irregular_heights_are_rayleigh_of_the_significant_height() {
    let w = deep_site("kind = \"irregular\"\nsignificant_height_m = 2.0");
    let (hs, n) = (2.0, N_STAT as f64);
    let x = heights(&w, N_STAT);
    let (m, s) = mean_sd(&x);
    let sd = hs * ((4.0 - std::f64::consts::PI) / 8.0).sqrt();
    within_5_se("mean", m, hs * (std::f64::consts::PI / 8.0).sqrt(), sd / n.sqrt());
    // Standard error of a sample sd: σ sqrt((κ − 1)/(4n)), κ = 3.245 the Rayleigh kurtosis.
    within_5_se("sd", s, sd, sd * (2.245 / (4.0 * n)).sqrt());
    let p = (-2.0f64).exp();
    let above = x.iter().filter(|&&v| v > hs).count() as f64 / n;
    within_5_se("P(H > H1/3)", above, p, (p * (1.0 - p) / n).sqrt());
    assert!(x.iter().all(|&v| v.is_finite() && v >= 1e-3 * hs));
}

// ------------------------------------------------------------------------------------------------
// (d) Forced non-breaking trains
// ------------------------------------------------------------------------------------------------

/// The PARI breaking site (d = 0.4 m, H_br = 0.336 m by Miche) with a nominal H = 0.3 m forced
/// non-breaking: a drawn height at or above H_br is limited to just below it and counted; the
/// others are exactly the heights drawn with `auto` (the same random numbers).
#[test]
fn d_forced_non_breaking_trains_limit_heights_to_the_breaker_height_and_count_them() {
    let c = reduced(BREAKING, 200, 1, &[(0.3, 16.2, "non-breaking")]);
    let s = &c.setups[0];
    let (model, spec) = (&s.waves.model, &s.waves.train);
    let hbr = model.breaker_height_at_wall_m(spec.period_s);
    assert!((hbr - 0.3364).abs() < 1e-4, "H_br = {hbr}");
    let forced = realization_waves(model, spec, RegimeChoice::Forced(Regime::NonBreaking), 0).unwrap();
    let auto = realization_waves(model, spec, RegimeChoice::Auto, 0).unwrap();
    let mut limited = 0;
    for (f, a) in forced.records.iter().zip(&auto.records) {
        assert_eq!(f.regime, Regime::NonBreaking);
        assert!(f.height_m < hbr, "{} m is not below H_br = {hbr} m", f.height_m);
        if a.height_m >= hbr {
            limited += 1;
            assert!((f.height_m - hbr).abs() <= 1e-8 * hbr, "limited to {} m, H_br = {hbr} m", f.height_m);
        } else {
            assert_eq!(f.height_m, a.height_m);
        }
    }
    assert_eq!(forced.limited_waves, limited);
    assert_eq!(auto.limited_waves, 0);
    // Nominal 0.3 m with COV 0.2: about 28 % of the waves reach 0.336 m.
    assert!((20..=100).contains(&limited), "{limited} of 200 waves limited");
    // A realization run reports the same count.
    let run = s.case().run(0, None).unwrap();
    assert_eq!(run.limited_waves, limited);
    assert!(run.waves.iter().all(|w| w.record.regime == Regime::NonBreaking && w.record.height_m < hbr));
}

// ------------------------------------------------------------------------------------------------
// (e) Reproducible random numbers
// ------------------------------------------------------------------------------------------------

/// The same seed and realization give the same records (heights, regimes, rise times); another
/// seed or another realization index gives others; the same seed and index at another nominal
/// height give the same relative heights and rise-time draws (common random numbers).
#[test]
fn e_the_same_seed_reproduces_the_records_and_other_seeds_or_indices_differ() {
    let c = reduced(BREAKING, 15, 1, &[(0.524, 13.7, "auto"), (0.428, 13.7, "auto")]);
    let (w, spec) = (&c.setups[0].waves, c.setups[0].waves.train);
    let choice = RegimeChoice::Auto;
    let first = draw(w, &spec, choice, 3);
    assert!(first.records.iter().any(|r| r.rise_time_s.is_some()), "the breaking site draws rise times");
    assert_eq!(first, draw(w, &spec, choice, 3));
    let other_index = draw(w, &spec, choice, 4);
    let other_seed = draw(w, &TrainSpec { seed: spec.seed + 1, ..spec }, choice, 3);
    for other in [&other_index, &other_seed] {
        assert!(first.records.iter().zip(&other.records).all(|(a, b)| a.height_m != b.height_m), "a height repeated");
    }
    let lower = &c.setups[1].waves;
    let scaled = draw(lower, &lower.train, choice, 3);
    for (a, b) in first.records.iter().zip(&scaled.records) {
        assert!((a.height_m / 0.524 - b.height_m / 0.428).abs() < 1e-12);
    }
    // The dynamic runs repeat too.
    let case = c.setups[0].case();
    assert_eq!(case.run(3, None).unwrap(), case.run(3, None).unwrap());
}

// ------------------------------------------------------------------------------------------------
// (f) Per-wave sliding
// ------------------------------------------------------------------------------------------------

/// Σ per-wave sliding = total sliding of the realization (telescoping differences of the permanent
/// sliding: to rounding, 1e-12 m on slides of millimetres), and the rigid-block total is the sum
/// of its per-wave slides. Waves follow each other every period.
#[test]
fn f_per_wave_sliding_sums_to_the_total() {
    let check = |r: &RealizationResult, period_s: f64| {
        let dynamic: f64 = r.waves.iter().map(|w| w.sliding_m).sum();
        assert!((dynamic - r.sliding_m).abs() <= 1e-12, "Σ per wave {dynamic} m vs total {} m", r.sliding_m);
        let block: f64 = r.waves.iter().map(|w| w.rigid_block_sliding_m).sum();
        assert!((block - r.rigid_block_sliding_m).abs() <= 1e-12 * block.max(1.0));
        for (j, w) in r.waves.iter().enumerate() {
            assert!((w.start_s - j as f64 * period_s).abs() < 1e-9);
            assert!(w.max_horizontal_reaction_n <= r.max_horizontal_reaction_n);
        }
    };
    for (text, h, w) in [(NONBREAKING, 0.619, 7.5), (BREAKING, 0.619, 13.7)] {
        let c = reduced(text, 6, 2, &[(h, w, "auto")]);
        let s = &c.setups[0];
        for i in 0..2 {
            let r = s.case().run(i, None).unwrap();
            assert!(r.sliding_m > 1e-3, "H = {h} m, W' = {w} kN slides only {} m", r.sliding_m);
            assert!(r.waves.iter().filter(|w| w.sliding_m > 0.0).count() >= 2, "more than one wave slides");
            check(&r, s.waves.period_s());
        }
    }
}
