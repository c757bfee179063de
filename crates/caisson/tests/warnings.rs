//! The plausibility warnings (`analysis::checks`): each fires on the case it is for and stays
//! silent where it should, among them the bundled examples.

mod support;

use caisson::analysis::checks::{response_warnings, structure_warnings, Response, FAILURE_FRACTION_OF_WIDTH};
use caisson::analysis::run::run;
use caisson::scenario::Scenario;
use caisson::Profile;
use support::{example, scenario};

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
    for name in names {
        assert_eq!(codes(&structure_warnings(example(name).structure())), Vec::<&str>::new(), "{name}");
    }
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

/// A weight in water given in MN (5.5 instead of 5500 kN) on a 20 m base: 0.275 kPa.
#[test]
fn a_weight_in_mn_is_flagged() {
    let light = prototype("weight_in_water_kn = 5.5", "e100_kpa = 3.5e5");
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
