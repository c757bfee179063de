//! The plausibility warnings (`analysis::checks`): each fires on the case it is for and stays
//! silent where it should, among them the bundled examples.

mod support;

use caisson::analysis::checks::{
    newmark_period_ratio, response_warnings, run_load_warnings, structure_warnings, wave_load_warnings,
};
use caisson::analysis::conventional::static_check;
use caisson::analysis::limits::FAILURE_FRACTION_OF_WIDTH;
use caisson::analysis::run::run;
use caisson::analysis::run::Response;
use caisson::scenario::Scenario;
use caisson::Profile;
use support::{example, scenario, site};

fn codes(w: &[caisson::analysis::checks::Warning]) -> Vec<&'static str> {
    w.iter().map(|w| w.code).collect()
}

fn run_codes(sc: &Scenario) -> Vec<&'static str> {
    let r = run(sc.structure(), sc.load.as_ref().unwrap(), sc.duration_s, false).unwrap().summary;
    let mut w = structure_warnings(sc.structure());
    w.extend(response_warnings(sc.structure(), &Response::from(&r)));
    codes(&w)
}

/// The prototype caisson of the design example with `caisson` and `foundation` keys replaced.
fn prototype(caisson: &str, foundation: &str) -> Scenario {
    scenario(&format!(
        "[caisson]\nwidth_m = 20.0\nheight_m = 24.5\nbase_depth_m = 17.5\n{caisson}\n[foundation]\n{foundation}\n[water]\ndensity_kg_per_m3 = 1030.0\n"
    ))
}

#[test]
fn every_bundled_example_has_plausible_inputs() {
    let names = [
        "breakwater_impact.toml",
        "design_breakwater.toml",
        "fifteen_waves.toml",
        "fragility.toml",
        "pari_breaking_campaign.toml",
        "pari_breaking_loads.toml",
        "pari_nonbreaking_campaign.toml",
        "pari_nonbreaking_loads.toml",
        "prototype_breaking_wave.toml",
        "table5_series.toml",
        "table5_triangle.toml",
    ];
    let mut tipping = 0;
    for name in names {
        let sc = example(name);
        assert_eq!(codes(&structure_warnings(sc.structure())), Vec::<&str>::new(), "{name}");
        // Their loads are a few times their weight or less: no `implausible-load`.
        let mut loads = Vec::new();
        if let Some(l) = &sc.load {
            loads.extend(run_load_warnings(sc.structure(), l));
        }
        if let Some(w) = &sc.waves {
            loads.extend(wave_load_warnings(sc.structure(), w));
        }
        if let Ok(c) = sc.campaign() {
            for s in &c.setups {
                let w = wave_load_warnings(&s.structure, &s.waves);
                // Goda's overturning check is a design judgement, not an input slip: the flume
                // caissons of the PARI breaking tests tip under Goda's loads of their highest
                // waves (their sliding factors are below 1 too, docs/validation.md). It fires
                // exactly where the static check says so.
                let sf_o = static_check(&s.structure, &s.waves).unwrap().safety.overturning;
                let tips = sf_o.is_some_and(|f| f < 1.0);
                assert_eq!(codes(&w).contains(&"overturning-under-design-wave"), tips, "{name}: {sf_o:?}");
                tipping += usize::from(tips);
                loads.extend(w.into_iter().filter(|w| w.code != "overturning-under-design-wave"));
            }
        }
        assert_eq!(codes(&loads), Vec::<&str>::new(), "{name}");
    }
    assert!(tipping > 0, "no campaign condition checked the overturning warning");
}

const TABLE5: &str = "[caisson]\nwidth_m = 0.78\nheight_m = 1.12\nbase_depth_m = 0.8\nweight_in_water_kn = 8.24\n[foundation]\ne100_kpa = 3.5e5\n[load]\nkind = \"triangle\"\npeak_horizontal_kn = PEAK\nrise_time_s = 0.05\n[solver]\nSOLVER\n";

fn table5(peak: &str, solver: &str) -> Scenario {
    scenario(&TABLE5.replace("PEAK", peak).replace("SOLVER", solver))
}

/// Fixed steps over T0/10 (T0 = 0.0218 s for this caisson): the warning gives the period error
/// of the average-acceleration scheme; T0/20 or adaptive steps are silent.
#[test]
fn a_fixed_step_over_a_tenth_of_the_natural_period_is_flagged() {
    let coarse = table5("12.0", "dt_s = 0.005");
    let t0 = coarse.structure().model().natural_period_s();
    assert!((t0 - 0.0218).abs() < 1e-3, "T0 = {t0}");
    let w = structure_warnings(coarse.structure());
    assert_eq!(codes(&w), ["coarse-time-step"]);
    assert_eq!(w[0].numbers["dt_s"], 0.005);
    assert_eq!(w[0].numbers["period_ratio"], newmark_period_ratio(0.005 / t0));
    assert!(w[0].message.contains("[solver] dt_s") && w[0].message.contains("adaptive"), "{}", w[0].message);
    for fine in ["dt_s = 0.001", "dt_s = 0.005\nstepping = \"adaptive\""] {
        assert!(structure_warnings(table5("12.0", fine).structure()).is_empty(), "{fine}");
    }
}

/// The period elongation of the average-acceleration scheme, against an independent integration
/// of an undamped oscillator (ẍ + ω² x = 0 by Newmark γ = ½, β = ¼, written out here): the
/// period from the upward zero crossings of 200 cycles, at 4 and 10 steps per period. The
/// crossings are interpolated linearly (an error below 1e-3 of a step, over 200 periods).
#[test]
fn newmark_period_ratio_matches_an_integrated_oscillator() {
    for steps_per_period in [4.0, 10.0] {
        let (omega, dt) = (2.0 * std::f64::consts::PI, 1.0 / steps_per_period);
        let (mut x, mut v, mut a) = (0.0f64, 1.0f64, 0.0f64);
        let (mut t, mut crossings) = (0.0, Vec::new());
        while crossings.len() < 201 {
            // Newmark average acceleration: x1 = x + dt v + dt²/4 (a + a1), a1 = −ω² x1.
            let x1 = (x + dt * v + 0.25 * dt * dt * a) / (1.0 + 0.25 * dt * dt * omega * omega);
            let a1 = -omega * omega * x1;
            let v1 = v + 0.5 * dt * (a + a1);
            if x < 0.0 && x1 >= 0.0 {
                crossings.push(t + dt * (-x) / (x1 - x));
            }
            (x, v, a, t) = (x1, v1, a1, t + dt);
        }
        let period = (crossings[200] - crossings[0]) / 200.0;
        let ratio = newmark_period_ratio(dt);
        assert!((period / ratio - 1.0).abs() < 1e-3, "{steps_per_period} steps: {period} against {ratio}");
    }
    assert_eq!(newmark_period_ratio(0.0), 1.0);
    // 3 % at T0/10, 56 % at T0/2 (the numbers of the module docs).
    assert!((newmark_period_ratio(0.1) - 1.032).abs() < 1e-3);
    assert!((newmark_period_ratio(0.5) - 1.565).abs() < 1e-3);
}

/// A peak force over 100 W' (1200 kN on the 8.24 kN caisson: 146 W') is flagged, naming the key and
/// the unit to check (12 000 kN, a force in N in the kN key, is refused: tests/regress_absurd_inputs.rs);
/// 12 kN is not.
#[test]
fn a_load_over_100_times_the_weight_is_flagged() {
    let slip = table5("1200.0", "dt_s = 1e-4");
    let w = run_load_warnings(slip.structure(), slip.load.as_ref().unwrap());
    assert_eq!(codes(&w), ["implausible-load"]);
    assert!(w[0].message.contains("peak_horizontal_kn") && w[0].message.contains("146 times"), "{}", w[0].message);
    let right = table5("12.0", "dt_s = 1e-4");
    assert!(run_load_warnings(right.structure(), right.load.as_ref().unwrap()).is_empty());
}

/// The PARI breaking caisson with its length in mm (780 instead of 0.78 m, the weight a total):
/// refused now, its 16.17 kN being 0.003 of the water 1000 m of caisson displace (the weight's
/// lower bound, 0.2 of it). The wave-load warning stays for what passes that bound: a caisson
/// 11.3 mm wide (1/100 of its height) at 0.2 of its displaced water (0.018 kN) meets a largest
/// wave of 431 W'.
#[test]
fn a_length_in_mm_is_refused_and_wave_loads_far_above_the_weight_are_flagged() {
    let text = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/pari_breaking_loads.toml"),
    )
    .unwrap();
    assert!(text.contains("length_m = 1.0"));
    let slip = Scenario::from_toml(
        &text.replace("length_m = 1.0", "length_m = 1000.0"),
        std::path::Path::new("t.toml"),
        std::path::Path::new("."),
    )
    .expect_err("refused");
    assert_eq!(slip.key(), Some("[caisson] weight_in_water_kn"), "{slip}");
    assert!(slip.to_string().contains("this is 0.003 of it"), "{slip}");
    let slender = scenario(
        &text
            .replace("width_m = 0.78", "width_m = 0.0113")
            .replace("weight_in_water_kn = 16.17", "weight_in_water_kn = 0.018"),
    );
    let w = wave_load_warnings(slender.structure(), slender.waves.as_ref().unwrap());
    assert_eq!(codes(&w), ["implausible-load"]);
    assert!(w[0].message.contains("length_m") && w[0].numbers["peak_kn"] > 100.0 * 0.018, "{}", w[0].message);
}

/// E100 given in MPa (350 instead of 3.5e5 kPa): 1000 × softer, a static settlement of metres and
/// a natural period of seconds (the 24.7 m and 12.4 s are this caisson's).
#[test]
fn a_modulus_in_mpa_is_flagged() {
    let soft = prototype("weight_in_water_kn = 5500.0", "e100_kpa = 350.0");
    let w = structure_warnings(soft.structure());
    assert_eq!(codes(&w), ["implausible-settlement", "implausible-natural-period"]);
    assert!(w[0].message.contains("e100_kpa") && w[0].numbers["static_settlement_m"] > 1.0);
    let right = prototype("weight_in_water_kn = 5500.0", "e100_kpa = 3.5e5");
    assert!(structure_warnings(right.structure()).is_empty());
}

/// A weight in water given in MN (5.5 instead of 5500 kN) on a 20 m base: 0.275 kPa. In water it
/// is refused (0.002 of the water the caisson displaces); a caisson whose base is at the still
/// water level displaces none, and its base pressure is flagged.
#[test]
fn a_weight_in_mn_is_refused_in_water_and_flagged_on_a_base_above_it() {
    let text = "[caisson]\nwidth_m = 20.0\nheight_m = 24.5\nbase_depth_m = DEPTH\nweight_in_water_kn = 5.5\n[foundation]\ne100_kpa = 3.5e5\n[water]\ndensity_kg_per_m3 = 1030.0\n";
    let e =
        Scenario::from_toml(&text.replace("DEPTH", "17.5"), std::path::Path::new("t.toml"), std::path::Path::new("."))
            .expect_err("refused");
    assert_eq!(e.key(), Some("[caisson] weight_in_water_kn"), "{e}");
    let light = scenario(&text.replace("DEPTH", "0.0"));
    let w = structure_warnings(light.structure());
    assert!(codes(&w).contains(&"implausible-base-pressure"), "{:?}", codes(&w));
    assert!(w.iter().any(|w| w.message.contains("weight_in_water_kn")));
}

#[test]
fn an_undamped_foundation_with_adaptive_steps_is_flagged() {
    let text = "[caisson]\nwidth_m = 0.78\nheight_m = 1.12\nbase_depth_m = 0.8\nweight_in_water_kn = 8.24\n[foundation]\ne100_kpa = 3.5e5\ndamping_kns_per_m = DAMP\n[load]\nkind = \"triangle\"\npeak_horizontal_kn = 2.0\nrise_time_s = 0.05\n[solver]\nstepping = \"adaptive\"\n";
    let undamped = scenario(&text.replace("DAMP", "0.0"));
    assert_eq!(codes(&structure_warnings(undamped.structure())), ["undamped-adaptive"]);
    let damped = scenario(&text.replace("DAMP", "100.0"));
    assert!(structure_warnings(damped.structure()).is_empty());
}

/// The README's example in the seed's literal model: its dashpot on the total velocity carries
/// more than friction while it slides, and its rotational dashpot most of the wave moment. The
/// consistent profile's dashpots do neither; that caisson then rocks beyond 0.01 rad (the
/// pulse's moment is three times the restoring moment).
#[test]
fn the_seeds_dashpots_are_flagged_and_the_consistent_ones_are_not() {
    let seed = example("table5_triangle.toml");
    assert_eq!(seed.profile(), Profile::Seed2011);
    assert_eq!(run_codes(&seed), ["dashpot-exceeds-friction", "rotational-dashpot-moment"]);
    let consistent = seed.with_profile(Profile::Consistent).unwrap();
    assert_eq!(run_codes(&consistent), ["rocking"]);
}

/// The response rules on their own: a displacement without slip, and a slide beyond a quarter of
/// the base width.
#[test]
fn rocking_without_slip_and_beyond_failure_are_flagged() {
    let sc = example("design_breakwater.toml");
    let s = sc.structure();
    let quiet = Response { sliding_m: 2e-3, slip_events: 3, ..Response::default() };
    assert!(response_warnings(s, &quiet).is_empty());
    let rocked = Response { sliding_m: 2e-3, slip_events: 0, ..Response::default() };
    assert_eq!(codes(&response_warnings(s, &rocked)), ["rocking-without-slip"]);
    let limit = FAILURE_FRACTION_OF_WIDTH * 20.0;
    let far = Response { sliding_m: -1.01 * limit, slip_events: 40, ..Response::default() };
    assert_eq!(codes(&response_warnings(s, &far)), ["beyond-failure"]);
    let near = Response { sliding_m: 0.99 * limit, slip_events: 40, ..Response::default() };
    assert!(response_warnings(s, &near).is_empty());
}

/// Issue 12, "a 500 kN caisson gives 53 km of expected sliding": sliding beyond the base width B
/// is `sliding-beyond-width` (with `beyond-failure`), for a run, for a design's lives (their mean
/// |S| beyond B: one storm beyond it is a failed life, which sound designs have, e.g. one storm
/// of 105 m in the 5000 lives of the design example) and for a fragility's storms; just below B
/// it is not.
#[test]
fn sliding_beyond_the_base_width_is_flagged_for_runs_lives_and_storms() {
    use caisson::analysis::checks::{life_warnings, storm_warnings};
    use caisson::analysis::lifetime::{FailureLimits, StormOutcome};
    let limits = FailureLimits { sliding_m: 5.0, rotation_rad: 0.01, heel_pressure_pa: None };
    let sc = example("design_breakwater.toml");
    let s = sc.structure();
    let b = 20.0;
    let off = Response { sliding_m: 1.01 * b, slip_events: 40, ..Response::default() };
    assert_eq!(codes(&response_warnings(s, &off)), ["beyond-failure", "sliding-beyond-width"]);
    let on = Response { sliding_m: -0.99 * b, slip_events: 40, ..Response::default() };
    assert_eq!(codes(&response_warnings(s, &on)), ["beyond-failure"]);
    let life = |sliding_m: f64, max_storm_sliding_m: f64| StormOutcome {
        sliding_m,
        max_storm_sliding_m,
        ..StormOutcome::default()
    };
    let beyond = |lives: &[StormOutcome]| codes(&life_warnings(lives, &limits, b)).contains(&"sliding-beyond-width");
    // The mean |S| (52 km, the finding) beyond B; within B, not, even with a storm beyond it.
    assert!(beyond(&[life(52_288.0, 3_000.0)]));
    assert!(beyond(&[life(0.0, 0.0), life(-41.0, 10.0)]), "a mean |S| of 20.5 m");
    assert!(!beyond(&[life(40.0, 105.0), life(0.0, 0.0)]), "a mean |S| of 20 m");
    assert!(!beyond(&[life(19.9, 19.9), life(-19.9, 19.9)]));
    let w = life_warnings(&[life(52_288.0, 3_000.0)], &limits, b);
    let m = &w.iter().find(|w| w.code == "sliding-beyond-width").unwrap().message;
    assert!(m.contains("2614.4 times the base width") && m.contains("weight_in_water_kn"), "{m}");
    // A life of 6 m whose rigid block slid 900 m (a flooded shell): the rigid block's mean tells.
    let ended = StormOutcome { rigid_block_sliding_m: 900.0, ..life(6.0, 6.0) };
    let w = life_warnings(&[ended, life(0.0, 0.0)], &limits, b);
    let m = &w.iter().find(|w| w.code == "sliding-beyond-width").expect("the rigid block's 450 m").message;
    assert!(m.contains("450.0000 m on average (E|S| of the rigid block over the whole lives"), "{m}");
    let storms = [life(25.0, 25.0), life(1.0, 1.0), life(-0.5, 0.5)];
    let w = storm_warnings(storms.iter(), b);
    assert_eq!(codes(&w), ["sliding-beyond-width"]);
    assert!(w[0].message.starts_with("1 of 3 storms slid the caisson beyond its base width"), "{}", w[0].message);
    assert!(storm_warnings(storms[1..].iter(), b).is_empty());
}

/// `impulsive-coefficient-without-berm`: the default breaking-wave load (`goda-takahashi`) takes
/// B_M = 0 where the file gives no berm width. On a high mound (d/h = 0.45) whose design wave
/// breaks at the wall, a berm of 0.12 L would make Takahashi's α_I (by hand: about 1.3) exceed
/// α2 (about 0.4): it warns, naming the key to give. Silent with the berm given, under the seed's
/// impact (explicit or by the `seed-2011` profile), and on the design example's low mound (d/h =
/// 0.825: α_I ≤ 0 for every berm).
#[test]
fn the_default_breaking_load_warns_where_a_berm_would_make_it_impulsive() {
    let high = site::with(site::SMALL_DESIGN, "water", "depth_at_wall_m = 9.0");
    let warned = |text: &str| {
        let sc = scenario(text);
        let w = wave_load_warnings(sc.structure(), sc.waves.as_ref().unwrap());
        w.into_iter().find(|w| w.code == "impulsive-coefficient-without-berm")
    };
    let w = warned(&high).expect("the high mound without a berm warns");
    assert!(w.message.contains("`[water] berm_width_m`") && w.message.contains("B_M = 0"), "{}", w.message);
    let n = |k: &str| w.numbers[k];
    assert!(n("alpha_i_with_berm_of_0_12_l") > 1.0 && n("alpha2") < 0.6, "{:?}", w.numbers);
    assert!(n("alpha_i_without_berm") < n("alpha2"), "B_M = 0 leaves the wave pulsating: {:?}", w.numbers);
    assert!(warned(&site::with(&high, "water", "berm_width_m = 12.0")).is_none());
    assert!(warned(&site::with(&high, "waves", "breaking_load = \"cuomo-2010\"")).is_none());
    assert!(warned(&format!("[model]\nprofile = \"seed-2011\"\n{high}")).is_none());
    assert!(warned(site::SMALL_DESIGN).is_none());
}
