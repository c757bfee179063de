//! The lifetime module's unit tests: what needs its private parts.

use super::life::*;
use super::outcome::*;
use super::params::*;
use super::screen::*;
use super::statistics::*;
use super::storm::*;
use crate::analysis::climate::{Climate, StormModel, MAX_STORM_RATE_PER_YEAR};
use crate::loads::generator::realization_rng;
use crate::waves::dispersion::wavenumber;
use crate::waves::periods::WavePeriods;
use crate::ParamError;
use std::cell::Cell;

thread_local! {
    /// The still waves [`settle_life`] ran on this thread.
    pub(super) static SETTLED: Cell<usize> = const { Cell::new(0) };
}

/// A life's largest rotation, settled once at its end, is that of running every wave the
/// screen lets through (the bound off): on 16 lives of 8 years of the small design's site
/// under small storms (H0's location 4 m), where a life's few simulated waves may all be
/// still and its largest rotation a still wave's, every output of every life is the same but
/// the counts, which move together, and [`settle_life`] runs waves.
#[test]
fn a_lifes_largest_rotation_settled_at_its_end_is_every_waves() {
    let text = include_str!("../../../tests/data/small_design.toml")
        .replace("life_years = 5", "life_years = 8")
        .replace("lives = 12", "lives = 16")
        .replace("seed = 3", "seed = 9")
        .replace("storm_location_m = 7.5", "storm_location_m = 4.0");
    let sc = crate::scenario::Scenario::from_toml(&text, std::path::Path::new("small.toml"), std::path::Path::new("."))
        .unwrap();
    let d = sc.design.clone().unwrap();
    let st = sc.storm_case(true).unwrap();
    let run = |stick_bound: bool| {
        let st = StormCase { stick_bound, ..st };
        (0..d.lives).map(|i| simulate_life(&st, &d.life, d.seed, i).unwrap()).collect::<Vec<_>>()
    };
    SETTLED.with(|n| n.set(0));
    let with = run(true);
    let settled = SETTLED.with(Cell::get);
    let without = run(false);
    let (mut lives, mut answered) = (0, 0);
    for (a, b) in with.iter().zip(&without) {
        let moved = b.simulated_waves - a.simulated_waves;
        assert_eq!(a.screened_waves, b.screened_waves + moved, "the counts move together");
        // The largest heel pressure too where it reaches the screen's 500 kPa; below, the
        // still waves are not run for it (module docs, "Heel pressure").
        let heel = if b.max_heel_pressure_kpa >= 500.0 { b.max_heel_pressure_kpa } else { a.max_heel_pressure_kpa };
        assert!(a.max_heel_pressure_kpa <= b.max_heel_pressure_kpa);
        let same = StormOutcome { simulated_waves: b.simulated_waves, screened_waves: b.screened_waves, ..*a };
        assert_eq!(
            StormOutcome { max_heel_pressure_kpa: heel, ..same },
            StormOutcome { max_heel_pressure_kpa: heel, ..*b }
        );
        lives += 1;
        answered += moved;
    }
    eprintln!("{lives} lives compared, {answered} waves answered by the bound, {settled} run at the lives' ends");
    assert_eq!(lives, 16);
    assert!(answered > 0 && settled > 0, "{answered} answered, {settled} settled");
}

/// The design example's scenario.
fn design_example() -> crate::scenario::Scenario {
    design_example_with(|t| t.to_string())
}

/// The design example's scenario with its text changed by `change`.
fn design_example_with(change: impl Fn(&str) -> String) -> crate::scenario::Scenario {
    let text = change(include_str!("../../../../../examples/design_breakwater.toml"));
    crate::scenario::Scenario::from_toml(&text, std::path::Path::new("design.toml"), std::path::Path::new("."))
        .expect("the design example")
}

/// What the screen reads of the dynamic model (T0, the rocking period, the lift-off factor)
/// is the still-water model's to the bit at every water level and friction error, though the
/// storm's model weighs less: 5 tides by 3 friction factors on the design example.
#[test]
fn the_screen_reads_the_still_water_modes() {
    let sc = design_example();
    let st = sc.storm_case(true).expect("a design");
    let still = ScreenModes::still_water(&st);
    let mut checked = 0;
    for tide_m in [-1.0, 0.0, 0.7, 1.5, 3.0] {
        for friction_factor in [0.7, 1.0, 1.3] {
            let s = StormInput {
                h13_m: 5.0,
                hmax_m: 9.0,
                period_s: 11.0,
                periods: WavePeriods::Significant,
                waves: 1000,
                tide_m,
                angle_rad: 0.0,
                force_factor: 1.0,
                impact_factor: 1.0,
                friction_factor,
            };
            let site = StormSite::new(&st, &s, still);
            let own = ScreenModes::of(site.dyn_model());
            let bits = |m: ScreenModes| [m.t0_s, m.t_moment_s, m.lift_factor].map(f64::to_bits);
            assert_eq!(bits(own), bits(still), "tide {tide_m} m, friction x {friction_factor}");
            let weighs_less = site.dyn_model().weight_n < st.structure.caisson.weight_in_water_n;
            assert_eq!(weighs_less, tide_m > 0.0, "tide {tide_m} m");
            checked += 1;
        }
    }
    assert_eq!(checked, 15);
}

/// The screen's grid leaves out the nodes the bound of the loads up to their height holds:
/// the same grid as every node's loads, on the design example's site at 720 storms (heights
/// from calm to past breaking at the wall, three periods, tides, angles and force errors),
/// in most of which the bound leaves nodes out; under the seed's impact (`cuomo-2010`) and
/// under `goda-takahashi` on a high mound with a berm (d = 11 m, B_M = 18 m: impulsive
/// breaking waves).
#[test]
fn the_bisected_screen_grid_is_every_nodes_grid() {
    let cuomo = design_example_with(|t| t.replace("[waves]\n", "[waves]\nbreaking_load = \"cuomo-2010\"\n"));
    let high_mound = design_example_with(|t| {
        t.replace("[waves]\n", "[waves]\nbreaking_load = \"goda-takahashi\"\n")
            .replace("depth_at_wall_m = 16.5", "depth_at_wall_m = 11.0\nberm_width_m = 18.0")
    });
    let counts = |sc: &crate::scenario::Scenario| grid_counts(&sc.storm_case(true).expect("a design"));
    // Under cuomo-2010, 466 storms may slide, lift or press the heel to 500 kPa somewhere on
    // their grid; the bound leaves nodes out in 481. The lowest cell that may is the one
    // found cell by cell (above the first in each of the 466, on both grids).
    assert_eq!(counts(&cuomo), (720, 466, 481, 2 * 466));
    // On the high mound, 441 and 470.
    assert_eq!(counts(&high_mound), (720, 441, 470, 2 * 441));
}

/// The storms of the grid test on `st`, checked: (storms, storms that may slide somewhere,
/// storms whose bound leaves nodes out, grids whose lowest sliding cell is above the first).
fn grid_counts(st: &StormCase<'_>) -> (usize, usize, usize, usize) {
    let (mut storms, mut cut, mut sliding, mut lowest) = (0, 0, 0, 0);
    for h13 in [0.5, 1.5, 2.5, 3.5, 4.5, 5.5, 6.5, 8.0, 10.0, 12.0] {
        for period_s in [7.0, 10.0, 14.0] {
            for tide_m in [0.0, 1.5, 3.0] {
                for (angle_rad, force_factor) in [(0.0, 1.0), (0.4, 0.8), (0.0, 1.3), (0.2, 1.0)] {
                    for periods in [WavePeriods::Significant, WavePeriods::LonguetHiggins { spectral_width: 0.4 }] {
                        let s = StormInput {
                            h13_m: h13,
                            hmax_m: 1.8 * h13,
                            period_s,
                            periods,
                            waves: 1000,
                            tide_m,
                            angle_rad,
                            force_factor,
                            impact_factor: force_factor,
                            friction_factor: 1.0,
                        };
                        let site = StormSite::new(st, &s, ScreenModes::still_water(st));
                        let t13 = (&site.model.at_period(period_s), site.bound(period_s));
                        let (a, b) =
                            (StormScreen::grid(st, &s, &site, t13, true), StormScreen::grid(st, &s, &site, t13, false));
                        assert_eq!(a.node, b.node, "H1/3 {h13} m, T {period_s} s, tide {tide_m} m");
                        storms += 1;
                        sliding += usize::from(b.first_node.is_some());
                        for g in [&a, &b] {
                            assert_eq!(g.lowest_cell(), g.lowest_cell_by_cells());
                            lowest += usize::from(g.lowest_cell().is_some_and(|c| c > 0));
                        }
                        assert_eq!(b.bound_nodes, 0);
                        cut += usize::from(a.bound_nodes > 0);
                    }
                }
            }
        }
    }
    (storms, sliding, cut, lowest)
}

/// A storm given the life's toe wave number (solved once for the shoaling and the loads)
/// is the storm that solves for it itself, to the bit: 12 storms of the design example's site
/// (three heights and periods, two tides, two force errors), 7 of them simulating waves.
#[test]
fn a_storm_given_the_toe_wave_number_is_the_storm_that_solves_for_it() {
    let sc = design_example();
    let st = sc.storm_case(true).expect("a design");
    let (mut storms, mut simulating) = (0, 0);
    for (h13, period_s) in [(3.0, 8.0), (6.0, 11.0), (9.0, 14.0)] {
        for tide_m in [0.0, 2.0] {
            for force_factor in [1.0, 1.3] {
                let s = StormInput {
                    h13_m: h13,
                    hmax_m: 1.8 * h13,
                    period_s,
                    periods: WavePeriods::Significant,
                    waves: 300,
                    tide_m,
                    angle_rad: 0.0,
                    force_factor,
                    impact_factor: force_factor,
                    friction_factor: 1.0,
                };
                let k = wavenumber(period_s, toe_depth_m(&st, tide_m));
                let run = |toe_k| {
                    let mut rng = realization_rng(7, storms);
                    let rng = &mut StormRng::Given(&mut rng);
                    storm_from(&st, &s, rng, StormStart::ALONE, toe_k, &mut StormScratch::default()).unwrap()
                };
                let (given, solved) = (run(Some(k)), run(None));
                assert_eq!(format!("{given:?}"), format!("{solved:?}"), "H1/3 {h13} m, tide {tide_m} m");
                storms += 1;
                simulating += usize::from(solved.simulated_waves > 0);
            }
        }
    }
    assert_eq!(storms, 12);
    assert!(simulating >= 4, "{simulating} storms simulate waves");
}

#[test]
fn extreme_value_quantiles_invert_their_distributions() {
    let w = StormDistribution::Weibull { scale_m: 1.5, shape: 1.4, location_m: 2.0 };
    let g = StormDistribution::Gumbel { location_m: 4.0, scale_m: 0.8 };
    for p in [0.01, 0.3, 0.5, 0.9, 0.99] {
        let h = w.quantile_m(p);
        assert!((1.0 - (-((h - 2.0) / 1.5f64).powf(1.4)).exp() - p).abs() < 1e-12);
        let h = g.quantile_m(p);
        assert!(((-(-(h - 4.0) / 0.8f64).exp()).exp() - p).abs() < 1e-12);
    }
}

/// 200 000 errors of COV 0.1: truncated at ±2σ the variance of z is
/// 1 − 2k φ(k)/(2Φ(k) − 1) = 1 − 4 · 0.053991/0.954500 = 0.773741 (the doubly truncated
/// normal), untruncated 1; the sample variance of (m − 1 − bias)/cov within 2 % of each (its
/// standard error is about 0.3 %); truncated, none beyond 1 + bias ± 2 cov.
#[test]
fn error_variance_truncated_and_not() {
    let n = 200_000;
    let mut checked = 0;
    for (k, var_z) in [(Some(2.0), 0.773741), (None, 1.0)] {
        let m = ErrorModel { bias: -0.09, cov: 0.1, truncation_sigmas: k };
        let mut rng = crate::loads::generator::realization_rng(9, 2);
        let z: Vec<f64> = (0..n).map(|_| (m.draw(&mut rng) - 0.91) / 0.1).collect();
        let mean = z.iter().sum::<f64>() / n as f64;
        let var = z.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1) as f64;
        assert!((var / var_z - 1.0).abs() < 0.02, "k = {k:?}: variance {var}");
        assert!(mean.abs() < 5.0 / (n as f64).sqrt());
        assert_eq!(k.is_some(), z.iter().all(|v| v.abs() <= 2.0 + 1e-9));
        checked += 1;
    }
    assert_eq!(checked, 2);
}

/// The constructors' rules by hand: a truncated error of bias −0.09 reaches 1 − 0.09 − 2 · 0.455
/// = 0 at COV 0.455 (refused, naming the COV), untruncated it is allowed; a Weibull of B = 7.5 m,
/// A = 1.5 m, k = 1.4 is exceeded at 10 m (1 − F = exp(−(2.5/1.5)^1.4) = 0.106) but not at 90 m.
#[test]
fn constructors_refuse_what_cannot_be_drawn() {
    let e = ErrorModel::new(-0.09, 0.455, Some(2.0)).unwrap_err();
    assert_eq!((e.quantity, e.value), ("cov", 0.455));
    assert!(ErrorModel::new(-0.09, 0.45, Some(2.0)).is_ok() && ErrorModel::new(-0.09, 0.9, None).is_ok());
    let w = StormDistribution::Weibull { scale_m: 1.5, shape: 1.4, location_m: 7.5 };
    assert_eq!(
        w.peaks_over_threshold(3.0, 10.0),
        Ok(StormModel::PeaksOverThreshold { rate_per_year: 3.0, threshold_m: 10.0 })
    );
    assert!((1.0 - w.cdf(10.0) - (-(2.5f64 / 1.5).powf(1.4)).exp()).abs() < 1e-15);
    assert_eq!(w.peaks_over_threshold(3.0, 90.0).unwrap_err().quantity, "threshold_m");
}

/// Each constructor refuses a value outside its range by itself, naming the quantity: the
/// ranges' ends are allowed (B = 0 m and k = 0.1 for a Weibull whose 10 000-year storm stays
/// within [`MAX_STORM_HEIGHT_M`], 1000 years, 72 h, 20 m of tide), the values just beyond them
/// are not.
#[test]
fn life_constructors_name_what_they_refuse() {
    let q = |r: Result<StormDistribution, ParamError>| r.unwrap_err().quantity;
    assert!(StormDistribution::weibull(1e-10, 0.1, 0.0).is_ok() && StormDistribution::gumbel(90.0, 1.0).is_ok());
    assert!(StormDistribution::weibull(80.0, 20.0, 0.0).is_ok());
    assert_eq!(q(StormDistribution::weibull(0.0, 1.4, 0.0)), "scale_m");
    assert_eq!(q(StormDistribution::weibull(1.5, 0.09, 0.0)), "shape");
    assert_eq!(q(StormDistribution::weibull(1.5, 1.4, -0.1)), "location_m");
    assert_eq!(q(StormDistribution::gumbel(0.0, 1.0)), "location_m");
    assert_eq!(q(StormDistribution::gumbel(4.0, f64::NAN)), "scale_m");
    let w = StormDistribution::weibull(1.5, 1.4, 2.0).unwrap();
    assert_eq!(w.peaks_over_threshold(0.0, 3.0).unwrap_err().quantity, "rate_per_year");
    assert_eq!(w.peaks_over_threshold(MAX_STORM_RATE_PER_YEAR * 1.01, 3.0).unwrap_err().quantity, "rate_per_year");
    assert_eq!(w.peaks_over_threshold(3.0, -0.1).unwrap_err().quantity, "threshold_m");
    for (bias, cov, k, quantity) in
        [(-0.91, 0.1, Some(2.0), "bias"), (0.0, 1.01, None, "cov"), (0.0, 0.1, Some(0.4), "truncation_sigmas")]
    {
        assert_eq!(ErrorModel::new(bias, cov, k).unwrap_err().quantity, quantity);
    }
    let life = LifeParams {
        life_years: 1000,
        storms: w,
        period_coefficient: 3.3,
        period_exponent: 0.63,
        storm_duration_s: 72.0 * 3600.0,
        tidal_range_m: 20.0,
        errors: Errors::default(),
        climate: Climate::default(),
    };
    assert_eq!(life.clone().checked(), Ok(life.clone()));
    let refused = |l: LifeParams| l.checked().unwrap_err().quantity;
    assert_eq!(refused(LifeParams { life_years: 1001, ..life.clone() }), "life_years");
    assert_eq!(refused(LifeParams { period_coefficient: 0.0, ..life.clone() }), "period_coefficient");
    assert_eq!(refused(LifeParams { period_exponent: 2.1, ..life.clone() }), "period_exponent");
    assert_eq!(refused(LifeParams { storm_duration_s: 72.0 * 3600.0 + 1.0, ..life.clone() }), "storm_duration_s");
    assert_eq!(refused(LifeParams { tidal_range_m: 20.5, ..life.clone() }), "tidal_range_m");
    let friction = ErrorModel { bias: 0.0, cov: 0.6, truncation_sigmas: Some(2.0) };
    assert_eq!(refused(LifeParams { errors: Errors { friction, ..Errors::default() }, ..life.clone() }), "cov");
    let storms = StormModel::PeaksOverThreshold { rate_per_year: 3.0, threshold_m: 90.0 };
    assert_eq!(
        refused(LifeParams { climate: Climate { storms, ..Climate::default() }, ..life.clone() }),
        "threshold_m"
    );
    let design = DesignParams {
        life,
        lives: 10,
        seed: 1,
        thresholds_m: DesignParams::thresholds_m(&[0.3, 0.05]).unwrap(),
        screen: true,
        failure_sliding_m: Some(1000.0),
        failure_rotation_rad: MAX_FAILURE_ROTATION_RAD,
        allowable_heel_pressure_pa: 500e3,
        failure_heel_pressure_pa: Some(1e7),
        sampling: Sampling::Plain,
        auto: None,
    };
    assert_eq!(design.thresholds_m, [0.03, 0.05, 0.1, 0.3, 1.0, 3.0]);
    assert_eq!(DesignParams::thresholds_m(&[0.2, -0.1]).unwrap_err().0, 1);
    assert_eq!(design.clone().checked(), Ok(design.clone()));
    let refused = |d: DesignParams| d.checked().unwrap_err().quantity;
    assert_eq!(refused(DesignParams { lives: 0, ..design.clone() }), "lives");
    assert_eq!(refused(DesignParams { thresholds_m: vec![0.3, 0.1], ..design.clone() }), "thresholds_m");
    assert_eq!(refused(DesignParams { failure_sliding_m: Some(0.0), ..design.clone() }), "failure_sliding_m");
    assert_eq!(refused(DesignParams { failure_rotation_rad: 0.11, ..design.clone() }), "failure_rotation_rad");
    assert_eq!(
        refused(DesignParams { allowable_heel_pressure_pa: 1e4, ..design.clone() }),
        "allowable_heel_pressure_pa"
    );
    assert_eq!(
        refused(DesignParams { failure_heel_pressure_pa: Some(1.1e7), ..design.clone() }),
        "failure_heel_pressure_pa"
    );
    assert_eq!(
        refused(DesignParams { life: LifeParams { life_years: 0, ..design.life.clone() }, ..design }),
        "life_years"
    );
}

/// Limit 1 m; lives |S| 0.1, 0.5 (failed by rotation), 3 (failed by sliding), 0.2: the
/// capped values 0.1, 1, 1, 0.2 (mean 0.575); above 2 m only the failed lives exceed.
#[test]
fn capped_statistics_of_a_sample_by_hand() {
    let s = capped_statistics(&[0.1, 0.5, 3.0, 0.2], &[false, true, true, false], 1.0, &[0.15, 0.5, 2.0]);
    assert!((s.mean_m - 0.575).abs() < 1e-15);
    assert_eq!(s.percentiles_m[1], (50.0, 0.2));
    assert_eq!(s.percentiles_m[3], (99.0, 1.0));
    assert_eq!(s.exceedance, vec![(0.15, 0.75), (0.5, 0.5), (2.0, 0.5)]);
}

#[test]
fn statistics_of_a_sample() {
    let s = life_statistics(&[0.0, 0.1, 0.2, 0.5, 2.0], &[0.1, 1.0]);
    assert!((s.mean_m - 0.56).abs() < 1e-12);
    assert_eq!(s.percentiles_m[1], (50.0, 0.2));
    assert_eq!(s.exceedance, vec![(0.1, 0.6), (1.0, 0.2)]);
}
