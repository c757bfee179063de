//! `caisson size`: the same answer on any thread count, a required width monotone in the allowed
//! sliding, the comparison widths, and keyed errors for `[size]`.

mod support;

use serde_json::Value;
use support::{caisson, refused, sizing_text, write};

/// The sizing of the tests: [`sizing_text`] over 8-30 m with `criterion`.
fn size_text(criterion: &str) -> String {
    sizing_text(&format!("range_m = [8.0, 30.0]\n{criterion}\ntolerance_m = 0.5\ncurve_points = 4"))
}

fn sized(dir: &std::path::Path, criterion: &str, threads: &str) -> (Vec<u8>, Value) {
    let f = write(dir, "s.toml", &size_text(criterion));
    let o = caisson().args(["size", f.to_str().unwrap(), "--json", "--threads", threads]).output().unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let j: Value = serde_json::from_slice(&o.stdout).expect("JSON on stdout");
    (o.stdout, j)
}

fn width(j: &Value, model: &str) -> f64 {
    assert_eq!(j[model]["status"], "found", "{model}: {}", j[model]);
    j[model]["width_m"].as_f64().unwrap()
}

#[test]
fn the_answer_does_not_depend_on_the_thread_count() {
    let dir = tempfile::tempdir().unwrap();
    let (one, j) = sized(dir.path(), "expected_sliding_m = 0.05", "1");
    let (two, _) = sized(dir.path(), "expected_sliding_m = 0.05", "2");
    assert_eq!(one, two, "size.json must not depend on the thread count");
    // The search: 4 grid widths, then bisection to 0.5 m; no width twice; every candidate ran
    // the 12 lives; the required width meets the criterion and the one below the bracket not.
    let cands = j["candidates"].as_array().unwrap();
    assert!(cands.len() >= 4, "{}", cands.len());
    let widths: Vec<f64> = cands.iter().map(|c| c["width_m"].as_f64().unwrap()).collect();
    assert!(widths.windows(2).all(|w| w[0] < w[1]), "sorted, no width twice: {widths:?}");
    assert_eq!(j["lives_simulated"].as_u64(), Some(12 * cands.len() as u64));
    let w = width(&j, "dynamic");
    let b = j["dynamic"]["bracket_m"].as_array().unwrap();
    let (lo, hi) = (b[0].as_f64().unwrap(), b[1].as_f64().unwrap());
    assert!(hi == w && hi - lo <= 0.5, "bracket {lo}..{hi}, width {w}");
    let at = |x: f64| cands.iter().find(|c| c["width_m"].as_f64() == Some(x)).unwrap();
    assert_eq!(at(hi)["dynamic_meets"], true);
    assert_eq!(at(lo)["dynamic_meets"], false);
    assert!(at(hi)["dynamic"]["expected_sliding_m"].as_f64().unwrap() <= 0.05);
    // Goda's conventional width under H_max (here Goda's breaking-limited 13.451 m,
    // tests/verify_goda_design.rs): both factors reach 1.2 there (sliding governs, 18.81 m, to 1 mm), and
    // the heel pressure there is above the 500 kPa allowed.
    let g = &j["goda"];
    assert_eq!(g["status"], "found");
    assert_eq!(g["governs"], "sliding");
    assert_eq!(g["design_wave"]["rule"], "goda-breaking-limited");
    assert!((g["design_wave"]["design_height_m"].as_f64().unwrap() - 13.451).abs() < 1e-3, "{g}");
    let gw = g["width_m"].as_f64().unwrap();
    assert!((gw - 18.81).abs() < 0.01, "{gw}");
    assert_eq!(g["at_width"]["width_m"].as_f64(), Some(gw));
    assert!(g["at_width"]["sliding_safety_factor"].as_f64().unwrap() >= 1.2);
    assert!(g["at_width"]["overturning_safety_factor"].as_f64().unwrap() >= 1.2);
    assert_eq!(g["heel_pressure_above_allowable"], true);
    let codes: Vec<&str> = j["warnings"].as_array().unwrap().iter().map(|w| w["code"].as_str().unwrap()).collect();
    assert!(codes.contains(&"heel-pressure-above-allowable"), "{codes:?}");
    // The 8 m candidate would tip under the design wave: its overturning factor is below 1.
    assert!(at(8.0)["goda_overturning_safety_factor"].as_f64().unwrap() < 1.0);
    assert!(codes.contains(&"overturning-under-design-wave"), "{codes:?}");
}

/// The required width grows as the allowed sliding falls (common random numbers: the same lives
/// at every width and for every criterion), for both models. (S_a from 0.02 m: with results
/// version 9's draws these 12 lives need a rigid block wider than the 30 m of the range for
/// 0.01 m.)
#[test]
fn the_required_width_is_monotone_in_the_allowed_sliding() {
    let dir = tempfile::tempdir().unwrap();
    let mut widths = Vec::new();
    let mut last = (f64::INFINITY, f64::INFINITY);
    for s_a in [0.02, 0.05, 0.3, 1.0] {
        let (_, j) = sized(dir.path(), &format!("expected_sliding_m = {s_a}"), "2");
        let (d, r) = (width(&j, "dynamic"), width(&j, "rigid_block"));
        assert!(d <= last.0 && r <= last.1, "S_a {s_a}: {d}, {r} after {last:?}");
        last = (d, r);
        widths.push(last);
    }
    assert_eq!(widths.len(), 4);
    // (Since results version 10 a life that rotates beyond 0.01 rad fails and counts at B/4 in
    // E|S|: the dynamic width of S_a = 1 m is about 20 m, where the rigid block's is 15 m.)
    assert!(
        last.0 < widths[0].0 && last.1 < widths[0].1,
        "a larger allowed sliding must allow a narrower caisson: {widths:?}"
    );
}

#[test]
fn bad_size_input_is_named() {
    let dir = tempfile::tempdir().unwrap();
    let cases = [
        ("range_m = [8.0, 30.0]", "range_m = [30.0, 8.0]", "[size] range_m"),
        ("range_m = [8.0, 30.0]", "range_m = [8.0]", "[size] range_m"),
        ("expected_sliding_m = 0.05", "", "[size] expected_sliding_m"),
        ("expected_sliding_m = 0.05", "exceedance_sliding_m = 0.3", "[size] exceedance_probability"),
        ("expected_sliding_m = 0.05", "failure_probability = 1.5", "[size] failure_probability"),
        ("tolerance_m = 0.5", "tolerance_m = 0.0", "[size] tolerance_m"),
        ("curve_points = 4", "curve_points = 1", "[size] curve_points"),
        ("[size]", "[size]\nvariable = \"height_m\"", "[size] variable"),
        ("curve_points = 4", "curve_points = 4\nsliding_safety_factor = 0.9", "[size] sliding_safety_factor"),
        ("curve_points = 4", "curve_points = 4\noverturning_safety_factor = 11.0", "[size] overturning_safety_factor"),
        (
            "curve_points = 4",
            "curve_points = 4\nallowable_heel_pressure_kpa = 5.0",
            "[size] allowable_heel_pressure_kpa",
        ),
        ("curve_points = 4", "curve_points = 4\nheel_pressure_governs = 1", "heel_pressure_governs"),
    ];
    let mut n = 0;
    for (from, to, key) in cases {
        let text = size_text("expected_sliding_m = 0.05").replace(from, to);
        assert_ne!(text, size_text("expected_sliding_m = 0.05"), "{from} must be in the file");
        let f = write(dir.path(), "bad.toml", &text);
        refused(&["size", f.to_str().unwrap()], &[key]);
        n += 1;
    }
    assert_eq!(n, 12);
    // A caisson given by its weight cannot be sized by width: its weight would not follow.
    let text = size_text("expected_sliding_m = 0.05").replace("unit_length_m = 20.0\n", "").replace(
        "wall_thickness_m = 0.5\nslab_thickness_m = 0.8\npartition_thickness_m = 0.2\ncells_across = 4\ncells_along = 4\ncap_height_m = 2.0\n",
        "weight_in_water_kn = 6000.0\n",
    );
    assert!(text.contains("weight_in_water_kn") && !text.contains("wall_thickness_m"));
    let f = write(dir.path(), "weight.toml", &text);
    refused(&["size", f.to_str().unwrap()], &["construction", "weight_in_water_kn"]);
}

/// A sizing run keeps every finished width in `DIR/size_checkpoint.jsonl`; `--resume` reuses
/// them (a torn last line is cut away) and reports exactly what an uninterrupted run reports. An
/// edited line and a checkpoint of another search are refused, naming the line or the file.
#[test]
fn a_resumed_sizing_run_reports_the_same() {
    let dir = tempfile::tempdir().unwrap();
    let f = write(dir.path(), "s.toml", &size_text("expected_sliding_m = 0.05"));
    let out = dir.path().join("out");
    let run = |extra: &[&str]| {
        let mut args = vec!["size", f.to_str().unwrap(), "--out", out.to_str().unwrap(), "--threads", "2"];
        args.extend_from_slice(extra);
        let o = caisson().args(&args).output().unwrap();
        assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
        (String::from_utf8_lossy(&o.stdout).to_string(), std::fs::read(out.join("size.json")).unwrap())
    };
    let (_, full) = run(&[]);
    let cp = out.join("size_checkpoint.jsonl");
    let text = std::fs::read_to_string(&cp).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert!(lines.len() >= 6, "a header and the candidates: {}", lines.len());
    // Keep the header, two widths and half of the third (a run killed while writing it).
    let torn = format!("{}\n{}\n{}\n{}", lines[0], lines[1], lines[2], &lines[3][..lines[3].len() / 2]);
    std::fs::write(&cp, &torn).unwrap();
    let (said, resumed) = run(&["--resume"]);
    assert!(said.contains("(2 widths from the checkpoint)"), "{said}");
    assert_eq!(resumed, full, "the resumed run reports exactly the same");
    assert_eq!(std::fs::read_to_string(&cp).unwrap(), text, "the checkpoint is whole again");
    // An edited line.
    std::fs::write(&cp, text.replacen("\"lives\":12", "\"lives\":13", 1)).unwrap();
    refused(&["size", f.to_str().unwrap(), "--out", out.to_str().unwrap(), "--resume"], &["line 2", "check"]);
    // Another search (another criterion): another fingerprint.
    std::fs::write(&cp, &text).unwrap();
    let other = write(dir.path(), "other.toml", &size_text("expected_sliding_m = 0.3"));
    refused(&["size", other.to_str().unwrap(), "--out", out.to_str().unwrap(), "--resume"], &["another sizing run"]);
}

/// candidates.csv is size.json's candidates, flattened: a row per candidate, a column per number
/// (a model's under its prefix: `dynamic_p95_m` is `dynamic.p95_m`, `dynamic_impulsive_waves`
/// is `dynamic.impulsive.waves`, `dynamic_failure_probability_ci95_low` is
/// `dynamic.failure_probability_ci95[0]`; `heel_pressure_exceedance_probability` is
/// `heel_pressure_exceedance.probability`), each cell the JSON value exactly (`{:e}` round-trips
/// f64), an empty cell where the JSON has `null`.
#[test]
fn candidates_csv_is_the_json_candidates_flattened() {
    let dir = tempfile::tempdir().unwrap();
    let f = write(dir.path(), "s.toml", &size_text("expected_sliding_m = 0.05"));
    let out = dir.path().join("out");
    let o = caisson().args(["size", f.to_str().unwrap(), "--out", out.to_str().unwrap()]).output().unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let j: Value = serde_json::from_slice(&std::fs::read(out.join("size.json")).unwrap()).unwrap();
    let cands = j["candidates"].as_array().unwrap();
    let mut r = csv::Reader::from_path(out.join("candidates.csv")).unwrap();
    let header: Vec<String> = r.headers().unwrap().iter().map(String::from).collect();
    // 6 of the width, 12 of each model, 8 of its intervals and 8 of its impulsive waves (4 and
    // their intervals' ends), 4 of the heel pressure, 2 verdicts, 2 of the precision (empty: a
    // fixed number of lives).
    assert_eq!(header.len(), 68, "{header:?}");
    let (mut rows, mut cells, mut empty) = (0, 0, 0);
    for (row, c) in r.records().map(Result::unwrap).zip(cands) {
        for (name, cell) in header.iter().zip(row.iter()) {
            // A key of `obj`, an interval's end `…_ci95_low…` the first of `…_ci95…`.
            let flat = |obj: &Value, key: &str| {
                if key.contains("_ci95_low") {
                    obj[key.replace("_ci95_low", "_ci95")][0].clone()
                } else if key.contains("_ci95_high") {
                    obj[key.replace("_ci95_high", "_ci95")][1].clone()
                } else {
                    obj[key].clone()
                }
            };
            let model = |m: &str, rest: &str| match rest.strip_prefix("impulsive_") {
                Some(key) => flat(&c[m]["impulsive"], key),
                None => flat(&c[m], rest),
            };
            let want = match name.split_once('_') {
                Some((m @ "dynamic", rest)) if c.get(name).is_none() => model(m, rest),
                Some(("rigid", rest)) if c.get(name).is_none() => model("rigid_block", &rest["block_".len()..]),
                Some(("precision", key)) => c["precision"][key].clone(),
                _ => match name.strip_prefix("heel_pressure_exceedance_") {
                    Some("ci95_low") => c["heel_pressure_exceedance"]["ci95"][0].clone(),
                    Some("ci95_high") => c["heel_pressure_exceedance"]["ci95"][1].clone(),
                    Some(key) => c["heel_pressure_exceedance"][key].clone(),
                    None => c[name.as_str()].clone(),
                },
            };
            let may_be_null = name.starts_with("goda_") || name.starts_with("precision_");
            assert!(!want.is_null() || may_be_null, "{name}: no such number in the JSON");
            match want {
                Value::Null => {
                    assert_eq!(cell, "", "{name}");
                    empty += 1;
                }
                Value::Bool(b) => assert_eq!(cell, b.to_string(), "{name}"),
                v => assert_eq!(cell.parse::<f64>().ok(), v.as_f64(), "{name}: {cell} vs {v}"),
            }
            cells += 1;
        }
        rows += 1;
    }
    assert_eq!((rows, cells), (cands.len(), 68 * cands.len()), "every cell checked");
    // The heel pressure is undefined (null) at the narrow widths that would overturn (the resultant
    // outside the base).
    assert!(empty > 0, "an empty cell checked");
}
