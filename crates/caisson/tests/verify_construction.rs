//! A caisson given by its construction (`[caisson] wall_thickness_m`, ...; docs/model.md §8.4):
//! the bundled example's numbers are the worked example checked by hand, a change of width
//! rebuilds the weight in water, mass, centre of gravity and inertia (and what follows from
//! them), and the two routes to the weight exclude each other.

use caisson::scenario::{Scenario, ScenarioError};
use caisson::G_M_PER_S2;
use std::path::Path;

const EXAMPLE: &str = include_str!("../../../examples/caisson_geometry.toml");

fn parse(text: &str) -> Result<Scenario, ScenarioError> {
    Scenario::from_toml(text, Path::new("t.toml"), Path::new("."))
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// `EXAMPLE` with `from` replaced by `to` (which must be there).
fn edited(from: &str, to: &str) -> String {
    assert!(EXAMPLE.contains(from), "{from}");
    EXAMPLE.replacen(from, to, 1)
}

#[test]
fn the_example_is_the_worked_example_of_the_docs() {
    let sc = parse(EXAMPLE).unwrap();
    let c = sc.caisson();
    // docs/model.md §8.4: m = 829 434.88 kg/m, W' = 9.81 × 541 034.88 N/m, y_G = 9.9317 m,
    // I_G = 5.6440e7 kg·m²/m.
    assert!(rel(c.mass_kg, 829_434.88) < 1e-12, "{}", c.mass_kg);
    assert!(rel(c.weight_in_water_n, G_M_PER_S2 * 541_034.88) < 1e-12, "{}", c.weight_in_water_n);
    assert!(rel(c.cog_height_m, 9.931_712) < 1e-7, "{}", c.cog_height_m);
    assert!(rel(c.inertia_cog_kg_m2, 5.644_017_6e7) < 1e-7, "{}", c.inertia_cog_kg_m2);
    assert!(sc.caisson_spec().construction().is_some());
}

#[test]
fn a_wider_caisson_gets_its_own_weight_mass_and_inertia() {
    // dW'/dB = 259 211.592 N/m per metre of width for the example (docs/model.md §8.4); the
    // soil-derived foundation and the wave site follow the rebuilt caisson.
    let sc = parse(EXAMPLE).unwrap();
    let (w20, k20) = (sc.caisson().weight_in_water_n, sc.foundation().stiffness.kx_n_per_m);
    let mut n = 0;
    for b in [16.0, 18.0, 22.0, 26.0] {
        let wide = sc.clone().with_caisson(|c| *c = c.with_width_m(b)).unwrap();
        let c = wide.caisson();
        assert!(
            (c.weight_in_water_n - w20 - 259_211.592 * (b - 20.0)).abs() < 1e-6,
            "B = {b}: {}",
            c.weight_in_water_n
        );
        assert_eq!(c.width_m, b);
        // Wider: heavier, stiffer (the soil's stiffness follows the weight), more inertia.
        assert_eq!(c.mass_kg > sc.caisson().mass_kg, b > 20.0);
        assert_eq!(c.inertia_cog_kg_m2 > sc.caisson().inertia_cog_kg_m2, b > 20.0);
        assert_ne!(wide.foundation().stiffness.kx_n_per_m, k20);
        assert_eq!(wide.waves.as_ref().unwrap().model.site.width_m, b);
        n += 1;
    }
    assert_eq!(n, 4);
    // Too narrow for its walls and partitions (2 × 0.5 + 3 × 0.2 = 1.6 m): the width is named.
    let e = sc.clone().with_caisson(|c| c.width_m = 1.5).unwrap_err();
    assert_eq!(e.key(), Some("[caisson] width_m"), "{e}");
    assert!(e.to_string().contains("1.6 m"), "{e}");
}

#[test]
fn both_routes_to_the_weight_are_an_error_naming_both_keys() {
    let mut n = 0;
    for (line, key) in [
        ("weight_in_water_kn = 5300.0", "[caisson] weight_in_water_kn"),
        ("mass_kg = 8.3e5", "[caisson] mass_kg"),
        ("cog_height_m = 10.0", "[caisson] cog_height_m"),
        ("inertia_kg_m2 = 5.6e7", "[caisson] inertia_kg_m2"),
    ] {
        let e = parse(&edited("[caisson]\n", &format!("[caisson]\n{line}\n"))).unwrap_err();
        let msg = e.to_string();
        assert!(matches!(e, ScenarioError::Conflict { .. }), "{msg}");
        assert!(msg.contains(key) && msg.contains("[caisson] wall_thickness_m"), "{msg}");
        n += 1;
    }
    assert_eq!(n, 4);
    // Any key of the construction is the construction route (here the first one given).
    let w = "weight_in_water_kn = 5300.0\nfill_density_kg_per_m3 = 2000.0\n";
    let text = format!("[caisson]\nwidth_m = 20.0\nheight_m = 20.0\nbase_depth_m = 14.0\n{w}");
    let msg = parse(&text).unwrap_err().to_string();
    assert!(msg.contains("[caisson] weight_in_water_kn") && msg.contains("[caisson] fill_density_kg_per_m3"), "{msg}");
}

#[test]
fn incomplete_or_misfit_constructions_name_their_key() {
    let cases = [
        ("wall_thickness_m = 0.5    # outer walls\n", "", "[caisson] wall_thickness_m"),
        ("slab_thickness_m = 0.8    # base slab\n", "", "[caisson] slab_thickness_m"),
        ("partition_thickness_m = 0.2\n", "", "[caisson] partition_thickness_m"),
        ("cells_across = 4", "cells_across = 0", "[caisson] cells_across"),
        ("cells_along = 4", "cells_along = 101", "[caisson] cells_along"),
        ("wall_thickness_m = 0.5", "wall_thickness_m = 10.0", "[caisson] width_m"),
        ("unit_length_m = 20.0", "unit_length_m = 1.6", "[caisson] unit_length_m"),
        ("unit_length_m = 20.0 ", "# ", "[caisson] length_m"),
        ("cap_height_m = 2.0", "cap_height_m = 19.5", "[caisson] height_m"),
        ("cap_height_m = 2.0", "cap_height_m = -1.0", "[caisson] cap_height_m"),
        (
            "concrete_density_kg_per_m3 = 2450.0",
            "concrete_density_kg_per_m3 = 2.45",
            "[caisson] concrete_density_kg_per_m3",
        ),
        ("fill_density_kg_per_m3 = 2000.0", "fill_density_kg_per_m3 = nan", "[caisson] fill_density_kg_per_m3"),
        (
            "fill_density_above_water_kg_per_m3 = 1800.0",
            "fill_density_above_water_kg_per_m3 = 1.8e4",
            "[caisson] fill_density_above_water_kg_per_m3",
        ),
    ];
    for (from, to, key) in cases {
        let e = parse(&edited(from, to)).unwrap_err();
        assert_eq!(e.key(), Some(key), "{from} -> {to}: {e}");
    }
    // Partitions with a single cell do nothing: an error, not ignored.
    let one = edited("cells_across = 4", "cells_across = 1").replacen("cells_along = 4", "cells_along = 1", 1);
    let msg = parse(&one).unwrap_err().to_string();
    assert!(msg.contains("[caisson] partition_thickness_m"), "{msg}");
    assert!(parse(&one.replacen("partition_thickness_m = 0.2\n", "", 1)).is_ok());
    // A construction that floats (empty cells): named, not a negative weight.
    let empty = edited("fill_density_kg_per_m3 = 2000.0", "fill_density_kg_per_m3 = 0.0").replacen(
        "fill_density_above_water_kg_per_m3 = 1800.0",
        "fill_density_above_water_kg_per_m3 = 0.0",
        1,
    );
    let e = parse(&empty).unwrap_err();
    assert_eq!(e.key(), Some("[caisson] concrete_density_kg_per_m3"), "{e}");
    assert!(e.to_string().contains("floats"), "{e}");
}

/// A campaign gives each condition's weight in water, which would replace the construction: the
/// campaign refuses it (the scenario's other commands do not read `[campaign]`).
#[test]
fn a_campaign_that_sets_weights_refuses_a_construction() {
    let text = format!("{EXAMPLE}\n[campaign]\nheights_m = [6.0]\nweights_in_water_kn = [5000.0]\n");
    let msg = parse(&text).unwrap().campaign().unwrap_err().to_string();
    assert!(msg.contains("[campaign]") && msg.contains("[caisson]") && msg.contains("wall_thickness_m"), "{msg}");
}
