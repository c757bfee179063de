//! `[waves] breaking_load` through every command that loads waves (docs/waves.md, docs/model.md
//! §5.5): each report records the rule (`model.breaking_load`, or `breaking_load.rule` in
//! `caisson loads`), and `"goda-takahashi"` without `[water] berm_width_m` is refused by each with
//! exit code 2 and an `Error:` naming the key and what to add.

mod support;

use serde_json::Value;
use support::{caisson_within, design_text, refused, s, site, write};

/// `text` with `breaking_load = "{rule}"` in `[waves]` (none: the profile's default) and `water`
/// in `[water]`.
fn with_rule(text: &str, rule: Option<&str>, water: &str) -> String {
    let text = match rule {
        Some(rule) => site::with(text, "waves", &format!("breaking_load = \"{rule}\"")),
        None => text.to_string(),
    };
    if water.is_empty() {
        text
    } else {
        site::with(&text, "water", water)
    }
}

fn json(args: &[&str]) -> Value {
    let o = caisson_within(120).args(args).arg("--json").output().unwrap();
    assert!(o.status.success(), "{args:?}: {}", String::from_utf8_lossy(&o.stderr));
    serde_json::from_slice(&o.stdout).unwrap()
}

/// The scenarios of each command: a regular train, the small design (also the fragility and
/// sizing tables, short), and the PARI breaking campaign.
fn scenarios(rule: Option<&str>, water: &str) -> Vec<(&'static str, String)> {
    let design = design_text(2, 1, "");
    let regular = site::with(
        &site::without(&design, "design", &[]),
        "waves",
        "kind = \"regular\"\nheight_m = 12.0\nwaves = 2\nrealizations = 1",
    );
    let regular = site::without(&regular, "waves", &["significant_height_m"]);
    let fragility = format!(
        "{}[fragility]\nsignificant_heights_m = [7.0, 9.0]\nstorms = 2\nstorm_duration_h = 0.1\n",
        site::without(&design, "design", &[])
    );
    let size = site::with(
        &site::with(&design, "design", "life_years = 2\nstorm_duration_h = 0.1"),
        "caisson",
        "unit_length_m = 20.0\nwall_thickness_m = 0.5\nslab_thickness_m = 0.8\npartition_thickness_m = 0.2\ncells_across = 4\ncells_along = 4\ncap_height_m = 2.0",
    );
    let size = format!(
        "{}[size]\nrange_m = [15.0, 25.0]\nexpected_sliding_m = 0.3\nlives = 2\ncurve_points = 2\ntolerance_m = 5.0\n",
        site::without(&size, "caisson", &["weight_in_water_kn"])
    );
    let campaign = std::fs::read_to_string(support::example("pari_breaking_campaign.toml")).unwrap();
    let campaign = campaign.replace("realizations = 10", "realizations = 1");
    [
        ("loads", regular.clone()),
        ("run", regular),
        ("design", design),
        ("fragility", fragility),
        ("size", size),
        ("campaign", campaign),
    ]
    .into_iter()
    .map(|(c, t)| (c, with_rule(&t, rule, water)))
    .collect()
}

#[test]
fn every_report_records_the_breaking_load_and_goda_takahashi_needs_the_berm() {
    let dir = tempfile::tempdir().unwrap();
    let mut checked = 0;
    for rule in ["cuomo-2010", "goda-takahashi", "none"] {
        for (command, text) in scenarios(Some(rule), "berm_width_m = 10.0") {
            let p = write(dir.path(), &format!("{command}_{rule}.toml"), &text);
            let j = json(&[command, s(&p)]);
            let recorded = if command == "loads" { &j["breaking_load"]["rule"] } else { &j["model"]["breaking_load"] };
            assert_eq!(recorded.as_str(), Some(rule), "{command}: {j}");
            checked += 1;
        }
    }
    assert_eq!(checked, 18);
    // Without the berm: refused by every command, before any output.
    for (command, text) in scenarios(Some("goda-takahashi"), "") {
        assert!(!text.contains("berm_width_m"), "{command}: the test's scenario has no berm");
        let p = write(dir.path(), &format!("{command}_refused.toml"), &text);
        refused(
            &[command, s(&p)],
            &["[water] berm_width_m", "breaking_load = \"goda-takahashi\"", "add `berm_width_m`"],
        );
    }
    // A run without waves records none.
    let run = json(&["run", &support::example("table5_triangle.toml")]);
    assert!(run["model"].get("breaking_load").is_none(), "{}", run["model"]);
}

/// The default rule (`goda-takahashi`, B_M = 0 without `[water] berm_width_m`) on a high mound
/// (d = 9 m at a 20 m toe: the design wave breaks at the wall and a berm of 0.12 L would make
/// Takahashi's α_I exceed α2) warns `impulsive-coefficient-without-berm` in the report of every
/// command that reads the design wave, the sizing included (its width varies; the warning does
/// not depend on it); on the design example's low mound no command does.
#[test]
fn every_command_warns_of_the_default_rule_without_a_berm_on_a_high_mound() {
    let dir = tempfile::tempdir().unwrap();
    let code = "impulsive-coefficient-without-berm";
    let codes = |j: &Value| -> Vec<String> {
        // A report without warnings has no `warnings` key.
        j["warnings"]
            .as_array()
            .map_or_else(Vec::new, |w| w.iter().map(|w| w["code"].as_str().unwrap().to_string()).collect())
    };
    let mut checked = 0;
    for (water, warns) in [("depth_at_wall_m = 9.0", true), ("", false)] {
        for (command, text) in scenarios(None, water) {
            if command == "campaign" {
                continue; // the PARI flume: its own site, not the high mound
            }
            assert!(!text.contains("breaking_load"), "{command}: the default rule");
            let p = write(dir.path(), &format!("{command}_{warns}.toml"), &text);
            let j = json(&[command, s(&p)]);
            assert_eq!(codes(&j).iter().any(|c| c == code), warns, "{command}, {water:?}: {:?}", codes(&j));
            checked += 1;
        }
    }
    assert_eq!(checked, 10);
}
