//! Issue 37 (hardening, third round): every number that can leave its finite range is bounded
//! where it enters, refused naming its key or ending a life as failed, never a whole run. The
//! library's side of each finding; the CLI's (exit codes, shards, merge, resume, messages) is
//! `crates/caisson-cli/tests/cli_bounded_inputs.rs`.

use caisson::analysis::lifetime::{
    simulate_life, simulate_storm, StormDistribution, StormInput, StormOutcome, LIFE_COLUMNS, MAX_STORM_HEIGHT_M,
};
use caisson::analysis::limits::ROCKING_LIMIT_RAD;
use caisson::loads::risetime::load_rng;
use caisson::scenario::Scenario;
use caisson::waves::periods::WavePeriods;
use std::path::Path;

mod support;
use support::site::{with, SMALL_DESIGN};

const DESIGN: &str = include_str!("../../../examples/design_breakwater.toml");

fn scenario(text: &str) -> Scenario {
    Scenario::from_toml(text, Path::new("t.toml"), Path::new(".")).expect("accepted")
}

fn key_of(text: &str) -> String {
    match Scenario::from_toml(text, Path::new("t.toml"), Path::new(".")) {
        Err(e) => e.key().map(str::to_string).unwrap_or_else(|| format!("{e}")),
        Ok(_) => panic!("expected an error"),
    }
}

fn message_of(text: &str) -> String {
    Scenario::from_toml(text, Path::new("t.toml"), Path::new(".")).expect_err("refused").to_string()
}

/// Every column of `o` that is a length or a rotation (six and one) is a finite number; returns
/// how many.
fn finite_columns(o: &StormOutcome) -> usize {
    let mut n = 0;
    for (name, c) in LIFE_COLUMNS {
        if let caisson::analysis::lifetime::LifeColumn::Metres(f)
        | caisson::analysis::lifetime::LifeColumn::Radians(f)
        | caisson::analysis::lifetime::LifeColumn::Kilopascals(f) = c
        {
            assert!(f(o).is_finite(), "{name} = {} in {o:?}", f(o));
            n += 1;
        }
    }
    n
}

/// Item 1: untruncated friction errors draw multipliers ≤ 0 (with bias −0.9 and COV 1, nearly half
/// the storms: Φ(−0.1) = 0.46); the rigid block's μ was then 0 and its slide after the wave,
/// M v² / (2 μ W'), infinite. A storm's friction is now at least 1e-6: every life is finite, and
/// the lives with frictionless storms fail by sliding in both models.
#[test]
fn a_friction_multiplier_of_zero_gives_finite_lives_that_fail_by_sliding() {
    let text =
        with(SMALL_DESIGN, "design", "lives = 6\nerror_truncated = false\nfriction_bias = -0.9\nfriction_cov = 1.0");
    let sc = scenario(&text);
    let d = sc.design.clone().unwrap();
    let st = sc.storm_case(true).unwrap();
    let limits = d.failure_limits(sc.caisson().width_m);
    let (mut checked, mut failed_both) = (0, 0);
    for life in 0..d.lives {
        let o = simulate_life(&st, &d.life, d.seed, life).expect("a life with frictionless storms runs");
        checked += finite_columns(&o);
        // Five storms, each frictionless with probability 0.46: a life that met one has a rigid
        // block beyond the sliding limit (it slid without friction after some wave).
        if o.rigid_block_sliding_m > limits.sliding_m && o.failed_by_sliding == 1 {
            failed_both += 1;
        }
    }
    assert_eq!(checked, 6 * 10, "every life's eight lengths, its rotation and its heel pressure were checked");
    assert!(failed_both >= 4, "{failed_both} of 6 lives failed by sliding in both models");
}

/// Item 1 at the storm: a friction multiplier of exactly 0 (what the untruncated draw gives below
/// zero) slides both models beyond any limit, finitely.
#[test]
fn a_storm_with_a_friction_factor_of_zero_is_finite() {
    let sc = scenario(SMALL_DESIGN);
    let st = caisson::analysis::lifetime::StormCase { failure: None, ..sc.storm_case(true).unwrap() };
    let storm = StormInput {
        h13_m: 6.0,
        hmax_m: 10.8,
        period_s: 12.0,
        periods: WavePeriods::Significant,
        waves: 30,
        tide_m: 0.0,
        angle_rad: 0.0,
        force_factor: 1.0,
        impact_factor: 1.0,
        friction_factor: 0.0,
    };
    let o = simulate_storm(&st, &storm, &mut load_rng(7)).expect("runs");
    assert_eq!(finite_columns(&o), 10);
    // With μ = 1e-6 every wave slides the block on, at almost no deceleration after it: far beyond
    // the caisson's width.
    assert!(o.rigid_block_sliding_m > 1e3 && o.sliding_m > 1.0, "{o:?}");
}

/// Item 1: `[waves] rigid_block_mu = 6e-301` (then allowed "> 0") slid the block 4.7e299 m; the
/// least friction is now that of `[foundation] mu_static`, 1e-6, where the model still runs.
#[test]
fn rigid_block_mu_6e_301_is_refused_and_1e_6_is_the_least() {
    let waves =
        |mu: &str| DESIGN.replacen("period_s = 12.8\n", &format!("period_s = 12.8\nrigid_block_mu = {mu}\n"), 1);
    assert_eq!(key_of(&waves("6e-301")), "[waves] rigid_block_mu");
    assert_eq!(key_of(&waves("0.0")), "[waves] rigid_block_mu");
    assert_eq!(key_of(&waves("2.01")), "[waves] rigid_block_mu");
    assert!(message_of(&waves("6e-301")).contains("between 1e-6 and 2"), "{}", message_of(&waves("6e-301")));
    let sc = scenario(&waves("1e-6"));
    assert_eq!(sc.storm_case(true).unwrap().rigid_block_mu, 1e-6);
}

/// Item 3: the foundation's numbers given directly are bounded per metre of caisson length (1 to
/// 1e9 kN/m for the stiffnesses, 0 to 1e7 kN·s/m for the damping) and the reference stress from 1
/// to 10 000 kPa: the values are refused naming their key; the ends are accepted, also
/// scaled by a caisson 20 m long.
#[test]
fn foundation_numbers_beyond_their_ranges_name_their_key_and_scale_with_the_length() {
    let table5 =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/table5_triangle.toml"))
            .unwrap();
    let soil = "e100_kpa = 3.5e5";
    assert!(table5.contains(soil));
    let given = |line: &str| table5.replacen(soil, &format!("{soil}\n{line}"), 1);
    for (line, key) in [
        ("ky_kn_per_m = 1e-200", "[foundation] ky_kn_per_m"),
        ("kx_kn_per_m = 5e-324", "[foundation] kx_kn_per_m"),
        ("ky_kn_per_m = 1e300", "[foundation] ky_kn_per_m"),
        ("kx_kn_per_m = 1.1e9", "[foundation] kx_kn_per_m"),
        ("ky_kn_per_m = 0.99", "[foundation] ky_kn_per_m"),
        ("damping_kns_per_m = 1e300", "[foundation] damping_kns_per_m"),
        ("damping_kns_per_m = 1.1e7", "[foundation] damping_kns_per_m"),
        ("reference_stress_kpa = 1e-300", "[foundation] reference_stress_kpa"),
        ("reference_stress_kpa = 0.99", "[foundation] reference_stress_kpa"),
        ("reference_stress_kpa = 10001", "[foundation] reference_stress_kpa"),
    ] {
        assert_eq!(key_of(&given(line)), key, "{line}");
    }
    let m = message_of(&given("ky_kn_per_m = 1e-200"));
    assert!(m.contains("= 1e-200:") && m.contains("between 1 and 1e9 (kN/m)") && m.contains("per metre"), "{m}");
    for line in [
        "kx_kn_per_m = 1",
        "ky_kn_per_m = 1e9",
        "damping_kns_per_m = 1e7",
        "reference_stress_kpa = 1",
        "reference_stress_kpa = 10000",
    ] {
        let sc = scenario(&given(line));
        assert!(sc.foundation().stiffness.kx_n_per_m.is_finite(), "{line}");
    }
    // 20 m long (and 20 times as heavy): 20 to 2e10 kN/m (the soil route scales K by the length
    // too).
    let long = |line: &str| {
        given(line).replacen("length_m = 1.0", "length_m = 20.0", 1).replacen(
            "weight_in_water_kn = 8.24",
            "weight_in_water_kn = 164.8",
            1,
        )
    };
    assert_eq!(scenario(&long("ky_kn_per_m = 2e10")).foundation().stiffness.ky_n_per_m, 2e13);
    assert_eq!(key_of(&long("ky_kn_per_m = 19.9")), "[foundation] ky_kn_per_m");
}

/// Item 4: a 1 m wide, 24.5 m tall caisson (the design example's weight) under the example's
/// storms: life 1898 met a wave that rotated it 0.18 rad, where the engine stopped converging, and
/// the whole run failed after every life had run. That wave now ends at the engine's last
/// converged step and the life fails by rotation; so life 3633 of the 0.5 m wide one (0.086 rad).
#[test]
fn a_slender_caisson_that_rocks_over_ends_its_life_failed_by_rotation() {
    for (width, life) in [("1.0", 1898), ("0.5", 3633)] {
        let sc = scenario(&DESIGN.replacen("width_m = 20.0", &format!("width_m = {width}"), 1));
        let d = sc.design.clone().unwrap();
        let st = sc.storm_case(true).unwrap();
        let o = simulate_life(&st, &d.life, d.seed, life).expect("the life ends, failed");
        assert_eq!(finite_columns(&o), 10);
        assert!(o.failed_by_rotation == 1 && o.max_rotation_rad > 5.0 * ROCKING_LIMIT_RAD, "{width} m: {o:?}");
        assert!(o.large_rotation_waves >= 1, "counted (and warned about) as a large rotation");
    }
}

/// Item 4: the storm of the issue's `storm_shape = 0.12` (H0 = 8990 m, T1/3 = 1022 s, Goda's
/// surf-zone H1/3 = 1505 m at the wall), which the engine could not integrate (the caisson had
/// slid 2.5e6 m and turned thousands of radians): it now ends failed, with finite numbers. Such a
/// distribution is refused by its 10 000-year storm; a storm drawn far in the tail of an accepted
/// one ends the same way.
#[test]
fn a_storm_far_beyond_any_climate_ends_failed_and_finite() {
    let sc = scenario(DESIGN);
    let st = sc.storm_case(true).unwrap();
    let storm = StormInput {
        h13_m: 1504.515201515061,
        hmax_m: 2787.840029575583,
        period_s: 1021.880445695687,
        periods: WavePeriods::Significant,
        waves: 7,
        tide_m: 1.9962987622715187,
        angle_rad: 0.0,
        force_factor: 0.907004076575976,
        impact_factor: 0.907004076575976,
        friction_factor: 0.9832797493251617,
    };
    let o = simulate_storm(&st, &storm, &mut load_rng(3)).expect("the storm ends, failed");
    assert_eq!(finite_columns(&o), 10);
    assert!(o.failed(), "{o:?}");
}

/// Item 4: a storm distribution whose 10 000-year storm F⁻¹(1 − 10⁻⁴) exceeds 100 m is refused.
/// By hand: Weibull, H = B + A (−ln 10⁻⁴)^(1/k) = B + A · 9.21034^(1/k); with A = 1.2, B = 4.5 and
/// k = 0.12, 9.21034^8.3333 = e^(8.3333 · 2.22034) = e^18.503 = 1.085e8: H = 1.30e8 m. At k = 1.4,
/// 9.21034^0.714286 = e^1.58596 = 4.8838: H = B + 4.8838 A reaches 100 m at A = 95.5/4.8838 =
/// 19.554 m. Gumbel, H = B − A ln(−ln(1 − 10⁻⁴)) = B + 9.21029 A: 100 m at A = 10.369 m (B = 4.5).
#[test]
fn a_storm_distribution_whose_10000_year_storm_exceeds_100_m_is_refused() {
    assert_eq!(MAX_STORM_HEIGHT_M, 100.0);
    let e = StormDistribution::weibull(1.2, 0.12, 4.5).unwrap_err();
    assert_eq!((e.quantity, e.value), ("shape", 0.12));
    assert!(e.to_string().contains("1.30e8 m"), "{e}");
    assert!(StormDistribution::weibull(19.55, 1.4, 4.5).is_ok());
    assert_eq!(StormDistribution::weibull(19.56, 1.4, 4.5).unwrap_err().quantity, "shape");
    assert!(StormDistribution::gumbel(4.5, 10.36).is_ok());
    assert_eq!(StormDistribution::gumbel(4.5, 10.38).unwrap_err().quantity, "scale_m");
    // The scenario names the key; the example (10 000-year storm 10.4 m) is accepted.
    let shape = DESIGN.replacen("storm_shape = 1.4 ", "storm_shape = 0.12 ", 1);
    assert_eq!(key_of(&shape), "[design] storm_shape");
    let w = StormDistribution::weibull(1.2, 1.4, 4.5).unwrap();
    assert!((w.quantile_m(1.0 - 1e-4) - (4.5 + 1.2 * 4.8838)).abs() < 1e-3);
}

/// Item 5: `[fragility] significant_heights_m` containing 1e-300 gave a Goda safety factor of
/// 1.5e301; the heights start at a millimetre, as `[waves] significant_height_m`.
#[test]
fn fragility_height_1e_300_is_refused_as_a_wave_height() {
    let text =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/fragility.toml")).unwrap();
    let from = "significant_heights_m = [7.0,";
    assert!(text.contains(from));
    let bad = text.replacen(from, "significant_heights_m = [1e-300, 7.0,", 1);
    let sc = scenario(&bad);
    let e = sc.fragility_for("a test").unwrap_err();
    assert_eq!(e.key(), Some("[fragility] significant_heights_m[0]"));
    assert!(e.to_string().contains("= 1e-300: must be a finite number ≥ 0.001"), "{e}");
    let ok = text.replacen(from, "significant_heights_m = [0.001, 7.0,", 1);
    assert!(scenario(&ok).fragility_for("a test").is_ok());
}

/// Item 7: `dt_s = 1e-23` with adaptive steps blamed `dt_min_s`, which the file did not give, with
/// an empty range printed in full decimals; `dt_s` itself is named now, with the bound in short form.
#[test]
fn adaptive_dt_1e_23_names_dt_s_and_no_message_prints_a_long_number() {
    let m = message_of(&DESIGN.replacen("dt_s = 1e-3 ", "dt_s = 1e-23 ", 1));
    assert!(m.starts_with("`[solver] dt_s` = 1e-23: must be at least 1e-9 (s) with adaptive stepping"), "{m}");
    // Each refusal prints its numbers short: no run of more than 17 digits (an f64's shortest form).
    let long_run = |m: &str| m.split(|c: char| !c.is_ascii_digit()).map(str::len).max().unwrap_or(0);
    let size = include_str!("../../../examples/size_breakwater.toml");
    let size = scenario(&size.replacen("tolerance_m = 0.25", "tolerance_m = 1e-9", 1));
    let cases = [
        message_of(&DESIGN.replacen("dt_s = 1e-3 ", "dt_s = 1e-23 ", 1)),
        size.size_for("a test").unwrap_err().to_string(),
        message_of(&DESIGN.replacen("e100_kpa = 3.5e5", "e100_kpa = 3.5e5\nky_kn_per_m = 1e-200", 1)),
    ];
    for m in &cases {
        assert!(long_run(m) <= 17, "{m}");
    }
    assert!(cases[1].contains("> 1.4e-5 and ≤ 14 (m"), "{}", cases[1]);
    assert_eq!(caisson::fmt_number(3.071000000000001e-6), "3.071e-6");
    assert_eq!(
        (caisson::fmt_value(1e9), caisson::fmt_value(250000.0), caisson::fmt_value(8.24e200)),
        ("1e9".into(), "250000".into(), "8.24e200".into())
    );
}
