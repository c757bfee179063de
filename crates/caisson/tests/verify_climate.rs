//! The climates of a lifetime run (docs/design.md, "Climate"; `analysis::climate`) against their
//! closed forms, through `simulate_life` where the life's outcome shows them.

mod support;

use caisson::analysis::lifetime::{simulate_life, simulate_storm, StormCase, StormInput, StormOutcome, WaveDraws};
use caisson::loads::generator::realization_rng;
use caisson::scenario::Scenario;
use support::{scenario, site};

/// The shared small design (`support::site`) made a calm site (every storm far below what slides the caisson: the screen's load bound spares the
/// grid, so a life costs microseconds) with a constant period (b = 0: T1/3 = a = 10 s) and storms
/// of 0.15 h (54 waves): a life's `waves` is 54 × its number of storms.
fn calm_text() -> String {
    let text = site::without(site::SMALL_DESIGN, "foundation", &["damping_mode", "vertical_damping"]);
    let text = site::without(&text, "solver", &["dt_s"]);
    let text = site::without(&text, "design", &["tidal_range_m"]);
    site::with(
        &text,
        "design",
        "life_years = 4\nlives = 10\nseed = 5\nstorm_scale_m = 0.5\nstorm_location_m = 1.0\n\
         period_coefficient = 10.0\nperiod_exponent = 0.0\nstorm_duration_h = 0.15",
    )
}

/// `calm_text()` with `extra` keys appended to `[design]`.
fn calm(extra: &str) -> Scenario {
    scenario(&format!("{}{extra}\n", calm_text()))
}

/// Lives 0..n of `sc`.
fn lives(sc: &Scenario, n: usize) -> Vec<StormOutcome> {
    let d = sc.design.clone().unwrap();
    let st = StormCase { failure: None, ..sc.storm_case(true).unwrap() };
    (0..n).map(|i| simulate_life(&st, &d.life, d.seed, i).unwrap()).collect()
}

/// Mean and sample variance.
fn moments(x: &[f64]) -> (f64, f64) {
    let n = x.len() as f64;
    let mean = x.iter().sum::<f64>() / n;
    (mean, x.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0))
}

/// Peaks over threshold at λ = 2.5 storms a year over 4 years: a life's storms are Poisson of
/// mean and variance 4λ = 10. 4000 lives: the mean within 5 standard errors ((10/4000)^½ = 0.05),
/// the variance within 5 of its standard errors ((10 (1 + 20)/4000)^½ = 0.23). No storm slides
/// the caisson (the site is calm), so the lives are cheap.
#[test]
fn pot_storms_per_life_are_poisson_through_simulate_life() {
    let sc = calm("storm_model = \"peaks-over-threshold\"\nstorm_rate_per_year = 2.5\nstorm_threshold_m = 1.2");
    let n = 4000;
    let storms: Vec<f64> = lives(&sc, n)
        .iter()
        .map(|o| {
            assert_eq!(o.waves % 54, 0, "54 waves a storm");
            assert_eq!(o.simulated_waves, 0, "the site is calm");
            (o.waves / 54) as f64
        })
        .collect();
    assert_eq!(storms.len(), n);
    let (mean, var) = moments(&storms);
    assert!((mean - 10.0).abs() < 5.0 * (10.0f64 / n as f64).sqrt(), "mean {mean}");
    assert!((var - 10.0).abs() < 5.0 * (10.0 * 21.0 / n as f64).sqrt(), "variance {var}");
}

/// The annual maxima model (the default, and written out) gives one storm a year: 4 × 54 waves.
#[test]
fn annual_maxima_is_one_storm_a_year() {
    for sc in [calm(""), calm("storm_model = \"annual-maxima\"")] {
        let all = lives(&sc, 20);
        assert_eq!(all.len(), 20);
        assert!(all.iter().all(|o| o.waves == 4 * 54));
    }
}

/// The storm heights of peaks over threshold t = 1.2 m are the fitted Weibull (A = 0.5 m,
/// k = 1.4, B = 1 m) given H > t: on 10 000 evenly spaced uniforms, the share above x is
/// (1 − F(x))/(1 − F(t)) = exp[−((x − B)/A)^k + ((t − B)/A)^k] to 1/10 000, at four heights; none
/// is below the threshold.
#[test]
fn pot_heights_are_the_exceedances_of_the_threshold() {
    let sc = calm("storm_model = \"peaks-over-threshold\"\nstorm_rate_per_year = 2.5\nstorm_threshold_m = 1.2");
    let life = &sc.design.as_ref().unwrap().life;
    let n = 10_000;
    let h: Vec<f64> = (0..n).map(|i| life.storm_height_m((i as f64 + 0.5) / n as f64)).collect();
    assert!(h.iter().all(|&x| x >= 1.2));
    let z = |x: f64| ((x - 1.0) / 0.5f64).powf(1.4);
    let mut checked = 0;
    for x in [1.3, 1.6, 2.0, 2.5] {
        let share = h.iter().filter(|&&v| v > x).count() as f64 / n as f64;
        let exact = (-z(x) + z(1.2)).exp();
        assert!((share - exact).abs() <= 1.0 / n as f64 + 1e-12, "x = {x}: {share} vs {exact}");
        checked += 1;
    }
    assert_eq!(checked, 4);
}

/// Lognormal durations of mean 2 h and COV 0.5 with T1/3 = 1 s (a = 1, b = 0) and one storm a
/// life: a life's `waves` is round(D / 1 s), of mean 7200 and standard deviation 3600 (the
/// rounding adds 1/12 to the variance). 4000 lives: the mean within 5 standard errors
/// (3600/√4000 = 57), the standard deviation within 6 % (its standard error is about 1.6 %
/// at this COV, the lognormal's kurtosis 3 + 6.6 with σ² = ln 1.25).
#[test]
fn lognormal_durations_through_simulate_life() {
    let text = calm_text()
        .replace("life_years = 4", "life_years = 1")
        .replace("period_coefficient = 10.0", "period_coefficient = 1.0")
        .replace("storm_duration_h = 0.15", "storm_duration_h = 2.0");
    let sc = scenario(&format!("{text}storm_duration_model = \"lognormal\"\nstorm_duration_cov = 0.5\n"));
    let n = 4000;
    let waves: Vec<f64> = lives(&sc, n).iter().map(|o| o.waves as f64).collect();
    assert_eq!(waves.len(), n);
    let (mean, var) = moments(&waves);
    assert!((mean - 7200.0).abs() < 5.0 * 3600.0 / (n as f64).sqrt(), "mean {mean}");
    assert!((var.sqrt() / 3600.0 - 1.0).abs() < 0.06, "sd {}", var.sqrt());
    // Fixed durations: every life 7200 waves.
    let fixed = scenario(&text);
    assert!(lives(&fixed, 10).iter().all(|o| o.waves == 7200));
}

/// Errors per life: every storm of a life has the same errors. With H0 = 2 m in every storm
/// (a Weibull of scale 10⁻¹² m at 2 m), T1/3 = H0 (a = 1, b = 1) and 2 h storms, a storm has
/// round(3600 / e) waves, e its deep-water error, and a life of 4 storms has 4 times the
/// variance of one storm's count with errors per storm, 16 times with errors per life: the
/// ratio of the two variances of the life totals is 4. 4000 lives each: each variance within
/// about 2.2 % (one standard error), the ratio within 15 %. Per life, a life's total is 4 times
/// one storm's.
#[test]
fn errors_per_life_are_shared_by_the_storms() {
    let text = calm_text()
        .replace("storm_scale_m = 0.5", "storm_scale_m = 1e-12")
        .replace("storm_location_m = 1.0", "storm_location_m = 2.0")
        .replace("period_coefficient = 10.0", "period_coefficient = 1.0")
        .replace("period_exponent = 0.0", "period_exponent = 1.0")
        .replace("storm_duration_h = 0.15", "storm_duration_h = 2.0");
    let n = 4000;
    let var_of = |extra: &str| {
        let all = lives(&scenario(&format!("{text}{extra}\n")), n);
        assert_eq!(all.len(), n);
        let w: Vec<f64> = all.iter().map(|o| o.waves as f64).collect();
        (moments(&w).1, all)
    };
    let (per_storm, _) = var_of("");
    let (per_life, all) = var_of("error_scope = \"life\"");
    assert!(all.iter().all(|o| o.waves % 4 == 0), "four equal storms a life");
    let ratio = per_life / per_storm;
    assert!((ratio - 4.0).abs() < 0.15 * 4.0, "ratio {ratio}");
}

/// A storm of the design example: 300 waves of H1/3 = 9 m limited to 13.45 m at T = 12.8 s, no
/// tide, from the angle `angle_rad` with the impact factor `impact_factor` (the other factors 1).
fn design_storm(case: &StormCase<'_>, angle_rad: f64, impact_factor: f64) -> StormOutcome {
    let s = StormInput {
        h13_m: 9.0,
        hmax_m: 13.45,
        period_s: 12.8,
        periods: Default::default(),
        waves: 300,
        tide_m: 0.0,
        angle_rad,
        force_factor: 1.0,
        impact_factor,
        friction_factor: 1.0,
    };
    simulate_storm(case, &s, &mut realization_rng(4, 0)).unwrap()
}

/// The design example under the seed's impact (`breaking_load = "cuomo-2010"`), whose breaking
/// waves are impulsive (the default `goda-takahashi` gives its low mound none).
fn design_with_impacts() -> Scenario {
    let mut sc = support::example("design_breakwater.toml");
    sc.waves.as_mut().unwrap().model.options.breaking_load = caisson::loads::breaking_load::BreakingLoad::Cuomo2010;
    sc
}

/// The impulsive component's own error multiplies the impact only: a storm of the design
/// example under the seed's impact (300 waves of H1/3 = 9 m, limited to 13.45 m, at T = 12.8 s:
/// some 5 waves above the breaker height at the wall, 12.79 m, impulsive), the quasi-static
/// factor kept at 1.
#[test]
fn the_impact_factor_scales_the_impulsive_component() {
    let sc = design_with_impacts();
    let case = StormCase { failure: None, ..sc.storm_case(true).unwrap() };
    let storm = |impact_factor: f64| design_storm(&case, 0.0, impact_factor);
    let (none, one, two) = (storm(0.0), storm(1.0), storm(2.0));
    // The rigid block slides under the impacts only (their own factor; the quasi-static load of
    // this storm alone cannot slide it): 0, then more with each factor.
    assert_eq!(none.rigid_block_sliding_m, 0.0, "{none:?}");
    assert!(one.rigid_block_sliding_m > 0.005, "{one:?}");
    assert!(two.rigid_block_sliding_m > 2.0 * one.rigid_block_sliding_m, "{two:?}");
    // The dynamic model (the foundation's compliance spreads an impulse of 25 ms) hardly slides
    // more at the factor 1 than at 0 (its sliding here is the quasi-static one's), more at 2.
    assert!(two.sliding_m > one.sliding_m + 0.01, "{one:?} {two:?}");
    assert!((one.sliding_m - none.sliding_m).abs() < 1e-3, "{none:?} {one:?}");
}

/// The sea-level rise reaches the storms: with 4.5 m of rise over the life (linear) and a tidal
/// range of 19 m, the water at the last storm rises by up to 19 + 4.5 · 3.5/4 = 22.94 m, beyond
/// W'/(ρ_w g B l) = 4500 kN / (1030 · 9.80665 · 20 m² ) = 22.28 m: the caisson would float, and
/// the file is refused naming the weight and the rise; without the rise it is accepted.
#[test]
fn a_caisson_that_floats_at_the_risen_sea_is_refused() {
    let text = format!("{}tidal_range_m = 19.0\n", calm_text());
    assert!(Scenario::from_toml(&text, std::path::Path::new("t.toml"), std::path::Path::new(".")).is_ok());
    let e = Scenario::from_toml(
        &format!("{text}sea_level_rise_m = 4.5\n"),
        std::path::Path::new("t.toml"),
        std::path::Path::new("."),
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("[caisson] weight_in_water_kn") && e.contains("sea-level rise of up to 3.9375 m"), "{e}");
}

/// The storm's angle reaches Goda's β: the storm of the impact test (the seed's impact, factor 1) at θ = 10°
/// is the head-on storm exactly (β = max(0, |θ| − 15°) = 0), at −10° too; at 60° (β = 45°: p1 and
/// the uplift times (1 + cos 45°)/2 = 0.854, the α2 term times cos² 45° = ½ more) the
/// dynamic model, which slides here under the quasi-static load, slides less than half as far
/// (3.2 cm → 1.0 cm); the rigid block, which only the impacts slide, slides less (the uplift under
/// them is smaller, the friction larger) but still slides: the impact has no angle.
#[test]
fn the_storm_angle_acts_through_goda_beta() {
    let sc = design_with_impacts();
    let case = StormCase { failure: None, ..sc.storm_case(true).unwrap() };
    let storm = |deg: f64| design_storm(&case, deg.to_radians(), 1.0);
    let head_on = storm(0.0);
    assert_eq!(storm(10.0), head_on);
    assert_eq!(storm(-10.0), head_on);
    let oblique = storm(60.0);
    assert!(oblique.sliding_m < 0.5 * head_on.sliding_m, "{head_on:?} {oblique:?}");
    assert!(oblique.rigid_block_sliding_m < head_on.rigid_block_sliding_m);
    assert!(oblique.rigid_block_sliding_m > 1e-3, "the impact, unreduced, still slides the block: {oblique:?}");
}

/// The work estimate of the climate example (peaks over threshold, 3 storms a year; oblique
/// waves; the sea rising) counts the storms a year: its waves against those of the first 100
/// lives (3 % allowed, as for the design example, tests/verify_work_estimates.rs), its screened share against
/// theirs within a factor of 3.
#[test]
fn the_work_estimate_counts_the_storms_of_a_pot_climate() {
    let sc = support::example("design_climate.toml");
    let d = sc.design.clone().unwrap();
    let case = sc.storm_case(true).unwrap();
    let e = caisson::analysis::work::design(&case, &d, sc.waves.as_ref().unwrap());
    let lives: Vec<usize> = (0..100).collect();
    let r = caisson::analysis::lifetime::run_lives(&case, &d.life, d.seed, &lives, &|_, _| {
        std::ops::ControlFlow::Continue(())
    })
    .unwrap();
    let (waves, simulated) = r.iter().fold((0u64, 0u64), |(w, s), (_, o)| (w + o.waves, s + o.simulated_waves));
    let real_per_life = waves as f64 / 100.0;
    let per_life = e.waves / d.lives as f64;
    assert!((per_life / real_per_life - 1.0).abs() < 0.03, "{per_life} waves per life, ran {real_per_life}");
    let ratio = e.simulated_share / (simulated as f64 / waves as f64);
    assert!(
        (1.0 / 3.0..3.0).contains(&ratio),
        "share {} against {}",
        e.simulated_share,
        simulated as f64 / waves as f64
    );
    assert!(e.basis.contains("× 3 storms a year"), "{}", e.basis);
}

/// The defaults leave the checkpoint fingerprint of earlier runs as it was: the serialized life
/// model of a file without climate keys has none of the new fields (and the truncation is the
/// number it was), one with them has them; the fingerprints differ.
#[test]
fn default_climate_leaves_the_fingerprint_unchanged() {
    let sc = support::example("design_breakwater.toml");
    let d = sc.design.clone().unwrap();
    let json = serde_json::to_value(&d.life).unwrap();
    assert!(json.get("climate").is_none(), "climate in {json}");
    let errors = &json["errors"];
    assert!(errors.get("impact_force").is_none() && errors.get("scope").is_none(), "{errors}");
    assert_eq!(errors["wave_force"]["truncation_sigmas"], 2.0);
    let climate = support::example("design_climate.toml");
    let c = climate.design.clone().unwrap();
    assert!(serde_json::to_value(&c.life).unwrap().get("climate").is_some());
    let fp = |s: &Scenario, p: &caisson::analysis::lifetime::DesignParams| {
        caisson::report::design::design_fingerprint(&s.storm_case(true).unwrap(), p)
    };
    assert_ne!(fp(&sc, &d), fp(&climate, &c));
}

/// The four lives of the shared test site (`support::site`, whose storms slide its caisson: 3
/// storms of 0.15 h near H1/3 = 7.5 m, as tests/equiv_lifetime.rs) with `extra` keys in
/// `[design]`, run to their end, every wave drawn ([`WaveDraws::EveryWave`]: the screened and
/// unscreened runs draw the same waves and periods) or only those above the screen's threshold.
fn sliding_lives(extra: &str, screen: bool, draws: WaveDraws) -> Vec<StormOutcome> {
    let keys = format!("life_years = 3\nlives = 4\nseed = 11\nstorm_duration_h = 0.15\n{extra}");
    let sc = scenario(&support::site::with(support::site::SMALL_DESIGN, "design", &keys));
    let d = sc.design.clone().unwrap();
    let st = StormCase { rigid_block_mu: 0.6, draws, failure: None, ..sc.storm_case(screen).unwrap() };
    (0..d.lives).map(|i| simulate_life(&st, &d.life, d.seed, i).unwrap()).collect()
}

/// With wave-by-wave periods (Longuet-Higgins, ν = 0.39) the screen (its grid over heights and
/// periods, then each wave's own loads at its own period) skips only waves that slide neither
/// model: on the same waves and periods, the screened and unscreened lives agree, the rigid block
/// to rounding and the dynamic model to 1 µm per life (as tests/equiv_lifetime.rs holds for periods at
/// T1/3). The run must screen waves and slide, and the periods must move the lives (against every
/// wave at T1/3, the same storms slide differently).
#[test]
fn the_screen_keeps_the_lives_with_wave_by_wave_periods() {
    let lh = "wave_periods = \"longuet-higgins\"";
    let with = sliding_lives(lh, true, WaveDraws::EveryWave);
    let without = sliding_lives(lh, false, WaveDraws::EveryWave);
    let t13 = sliding_lives("", true, WaveDraws::EveryWave);
    assert_eq!((with.len(), without.len()), (4, 4));
    let (mut screened, mut sliding, mut moved) = (0, 0.0, 0);
    for ((a, b), c) in with.iter().zip(&without).zip(&t13) {
        assert_eq!((a.waves, b.screened_waves), (b.waves, 0), "the same waves, none screened without the screen");
        assert_eq!(a.waves, c.waves, "the same storms with either period model");
        screened += a.screened_waves;
        sliding += b.sliding_m;
        moved += usize::from((a.sliding_m - c.sliding_m).abs() > 1e-4);
        assert!(
            (a.rigid_block_sliding_m - b.rigid_block_sliding_m).abs() <= 1e-12 * b.rigid_block_sliding_m.abs().max(1.0),
            "rigid block {a:?} vs {b:?}"
        );
        assert!((a.sliding_m - b.sliding_m).abs() <= 1e-6, "dynamic {} vs {} m", a.sliding_m, b.sliding_m);
    }
    assert!(screened > 0 && sliding > 0.01, "the test must screen waves and slide ({screened} screened, {sliding} m)");
    assert!(moved > 0, "the periods must change a life");
}

/// The work estimate of the climate example with wave-by-wave periods: its screened share within
/// a factor of 3 of that of the first 40 lives (as for its periods at T1/3, above), its simulated
/// time that share of the storms' waves at the mean period τ̄ = 0.89 T1/3 (the high waves'
/// period), and its basis says so.
#[test]
fn the_work_estimate_runs_the_wave_by_wave_periods() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/design_climate.toml");
    let text = std::fs::read_to_string(path).unwrap();
    let text = text.replace("sea_level_rise_m = 0.5", "sea_level_rise_m = 0.5\nwave_periods = \"longuet-higgins\"");
    let sc = scenario(&text);
    let d = sc.design.clone().unwrap();
    assert!(!d.life.climate.periods.is_significant());
    let case = sc.storm_case(true).unwrap();
    let e = caisson::analysis::work::design(&case, &d, sc.waves.as_ref().unwrap());
    let lives: Vec<usize> = (0..40).collect();
    let r = caisson::analysis::lifetime::run_lives(&case, &d.life, d.seed, &lives, &|_, _| {
        std::ops::ControlFlow::Continue(())
    })
    .unwrap();
    let (waves, simulated) = r.iter().fold((0u64, 0u64), |(w, s), (_, o)| (w + o.waves, s + o.simulated_waves));
    let real = simulated as f64 / waves as f64;
    assert!((1.0 / 3.0..3.0).contains(&(e.simulated_share / real)), "share {} against {real}", e.simulated_share);
    let storms = d.lives as f64 * 100.0 * 3.0;
    let at_t13 = storms * d.life.storm_duration_s * e.simulated_share;
    assert!((e.simulated_s / at_t13 - 0.89).abs() < 1e-12, "{} s against {at_t13} s at T1/3", e.simulated_s);
    assert!(e.basis.contains("wave-by-wave periods"), "{}", e.basis);
}
