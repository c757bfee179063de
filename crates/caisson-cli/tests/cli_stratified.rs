//! `[design] sampling = "stratified"` (issue 35, item 3; docs/design.md, "Stratified sampling"):
//! the sample depends only on the seed and the life index, so a stratified run gives the same
//! outputs, byte for byte, on 1 and 2 threads and from shards merged; its lives are the lives of a
//! plain run of the same indices; its `lives.csv` carries each life's stratum and weight, whose
//! weighted mean is design.json's E|S|; and a bad value of the key is refused.

mod support;

use std::path::Path;
use support::{caisson, design_text, refused, s, site, write};

const OUTPUTS: [&str; 5] = ["design.json", "lives.csv", "histogram.svg", "exceedance.svg", "heel_pressure.svg"];

/// `caisson design FILE --out DIR [extra]`, expected to succeed.
fn design(file: &Path, dir: &Path, extra: &[&str]) {
    let o = caisson().args(["design", s(file), "--out", s(dir)]).args(extra).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

fn json(dir: &Path) -> serde_json::Value {
    serde_json::from_slice(&std::fs::read(dir.join("design.json")).unwrap()).unwrap()
}

/// The rows of lives.csv by column name.
fn csv_rows(dir: &Path) -> (Vec<String>, Vec<Vec<String>>) {
    let text = std::fs::read_to_string(dir.join("lives.csv")).unwrap();
    let mut lines = text.lines();
    let header: Vec<String> = lines.next().unwrap().split(',').map(String::from).collect();
    (header, lines.map(|l| l.split(',').map(String::from).collect()).collect())
}

#[test]
fn a_stratified_run_is_the_same_on_any_thread_count_and_from_shards() {
    let dir = tempfile::tempdir().unwrap();
    let file = write(dir.path(), "d.toml", &design_text(3000, 5, "sampling = \"stratified\""));
    let (one, two, a, b, merged) = ["one", "two", "a", "b", "merged"].map(|n| dir.path().join(n)).into();
    design(&file, &one, &["--threads", "1"]);
    design(&file, &two, &["--threads", "2"]);
    design(&file, &a, &["--life-range", "1700..3000", "--threads", "2"]);
    design(&file, &b, &["--life-range", "0..1700", "--threads", "1"]);
    let o = caisson().arg("merge").arg(&file).args([s(&a), s(&b), "--out", s(&merged)]).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let mut compared = 0;
    for name in OUTPUTS {
        let x = std::fs::read(one.join(name)).unwrap();
        assert!(x == std::fs::read(two.join(name)).unwrap(), "{name}: 1 and 2 threads differ");
        assert!(x == std::fs::read(merged.join(name)).unwrap(), "{name}: the merged shards differ");
        compared += 2;
    }
    assert_eq!(compared, 10);
    let j = json(&one);
    let sampling = &j["sampling"];
    assert_eq!(sampling["method"], "stratified");
    assert_eq!(sampling["pool_lives"], 3000);
    assert_eq!(j["lives"], 3000);
    let simulated = sampling["simulated_lives"].as_u64().unwrap() as usize;
    // About 4.7 % of the lives (the fractions of the strata times their shares of the pool:
    // 141 of 3000).
    assert!((100..500).contains(&simulated), "{simulated} lives simulated");
    let strata = sampling["strata"].as_array().unwrap();
    assert_eq!(strata.len(), 6);
    let pool: u64 = strata.iter().map(|h| h["pool_lives"].as_u64().unwrap()).sum();
    assert_eq!(pool, 3000);
    let (header, rows) = csv_rows(&one);
    assert_eq!(rows.len(), simulated);
    assert_eq!(&header[header.len() - 2..], ["stratum", "weight"]);
    // E|S| (capped) by hand from lives.csv: Σ w_i |S_i| with a failed life at the limit.
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let limit = j["failure_sliding_m"].as_f64().unwrap();
    let (mut by_hand, mut weights, mut p_failed, mut failed_lives) = (0.0, 0.0, 0.0, 0);
    for r in &rows {
        let failed =
            ["failed_by_sliding", "failed_by_rotation", "failed_by_heel_pressure"].iter().any(|c| r[col(c)] != "0");
        let m: f64 = r[col("sliding_m")].parse::<f64>().unwrap().abs();
        let w: f64 = r[col("weight")].parse().unwrap();
        by_hand += w * if failed { limit } else { m };
        weights += w;
        if failed {
            (p_failed, failed_lives) = (p_failed + w, failed_lives + 1);
        }
    }
    assert!((weights - 1.0).abs() < 1e-9, "the weights sum to {weights}");
    let e = j["dynamic"]["expected_sliding_m"].as_f64().unwrap();
    assert!((by_hand - e).abs() <= 1e-9 * e.max(1e-9), "E|S| {e} m, by hand {by_hand} m");
    // The failed-lives warning counts the simulated lives and gives the weighted P(failure) (Σ w
    // over the failed lives), not their raw share.
    let warned: Vec<&serde_json::Value> =
        j["warnings"].as_array().unwrap().iter().filter(|w| w["code"] == "failed-lives").collect();
    assert_eq!(warned.len(), usize::from(failed_lives > 0), "{:?}", j["warnings"]);
    if let Some(w) = warned.first() {
        let p = w["numbers"]["failure_probability"].as_f64().unwrap();
        assert!((p - p_failed).abs() < 1e-9, "warned P(failure) {p}, by hand {p_failed}");
        assert!((p - failed_lives as f64 / simulated as f64).abs() > 1e-3, "the raw share of the sample: {p}");
        let text = w["message"].as_str().unwrap();
        assert!(
            text.starts_with(&format!("{failed_lives} of {simulated} simulated lives of a stratified sample")),
            "{text}"
        );
    }
}

/// A simulated life of a stratified run is the life of a plain run of the same index: the same
/// row of lives.csv (but the stratum and the weight).
#[test]
fn a_sampled_life_is_the_plain_runs_life() {
    let dir = tempfile::tempdir().unwrap();
    let strat = write(dir.path(), "s.toml", &design_text(400, 9, "sampling = \"stratified\""));
    let plain = write(dir.path(), "p.toml", &design_text(400, 9, ""));
    let (sd, pd) = (dir.path().join("s"), dir.path().join("p"));
    design(&strat, &sd, &[]);
    design(&plain, &pd, &[]);
    let (_, sampled) = csv_rows(&sd);
    let (_, all) = csv_rows(&pd);
    assert!(!sampled.is_empty());
    for r in &sampled {
        let i: usize = r[0].parse().unwrap();
        assert_eq!(&r[..r.len() - 2], &all[i][..], "life {i}");
    }
}

#[test]
fn a_bad_sampling_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let file = write(dir.path(), "d.toml", &design_text(10, 1, "sampling = \"importance\""));
    refused(&["design", s(&file)], &["[design] sampling", "\"importance\"", "\"plain\"", "\"stratified\""]);
}

/// `caisson size` with a stratified `[design]`: the same lives at every width (their storms'
/// severity does not depend on the caisson), each candidate the stratified estimate of `caisson
/// design` at its width, and the same size.json on 1 and 2 threads.
#[test]
fn a_stratified_sizing_is_the_design_at_each_width() {
    let dir = tempfile::tempdir().unwrap();
    let keys = "range_m = [8.0, 30.0]\nexpected_sliding_m = 0.05\ntolerance_m = 2.0\ncurve_points = 3\nlives = 3000";
    let text = site::with(&support::sizing_text(keys), "design", "sampling = \"stratified\"");
    let file = write(dir.path(), "s.toml", &text);
    let size = |threads: &str| {
        let o = caisson().args(["size", s(&file), "--json", "--threads", threads]).output().unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        o.stdout
    };
    let one = size("1");
    assert!(one == size("2"), "size.json differs between 1 and 2 threads");
    let j: serde_json::Value = serde_json::from_slice(&one).unwrap();
    let candidates = j["candidates"].as_array().unwrap();
    let mut compared = 0;
    for c in candidates.iter().take(2) {
        let w = c["width_m"].as_f64().unwrap();
        let at = site::with(&site::without(&text, "caisson", &["width_m"]), "caisson", &format!("width_m = {w}"));
        let f = write(dir.path(), "w.toml", &at);
        let o = caisson().args(["design", s(&f), "--json", "--lives", "3000"]).output().unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let d: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        assert_eq!(d["sampling"]["pool_lives"], 3000);
        for (key, design_key) in [("expected_sliding_m", "expected_sliding_m"), ("failure_probability", "failure")] {
            let want = if design_key == "failure" {
                d["dynamic"]["failure"]["probability"].as_f64().unwrap()
            } else {
                d["dynamic"][design_key].as_f64().unwrap()
            };
            let got = c["dynamic"][key].as_f64().unwrap();
            assert!((got - want).abs() <= 1e-12 * want.abs().max(1e-12), "{w} m {key}: size {got}, design {want}");
            compared += 1;
        }
    }
    assert_eq!(compared, 4);
}

/// `caisson size` with a stratified `[design]` and `[size] lives = "auto"`: each candidate is
/// `caisson design` at its width with `[design] lives = "auto"` and the same target and budget —
/// the same batches of the pool, the same stopping boundary, the same weighted E|S| and
/// P(failure) — and size.json is the same on 1 and 2 threads and resumed from a checkpoint.
#[test]
fn a_stratified_auto_sizing_is_the_auto_design_at_each_width() {
    let dir = tempfile::tempdir().unwrap();
    let rule = "target_relative_error = 0.15\nmax_lives = 4000";
    let keys = format!("range_m = [8.0, 30.0]\nexpected_sliding_m = 0.05\ntolerance_m = 4.0\ncurve_points = 3\nlives = \"auto\"\n{rule}");
    let text = site::with(&support::sizing_text(&keys), "design", "sampling = \"stratified\"");
    let file = write(dir.path(), "s.toml", &text);
    let out = dir.path().join("out");
    let size = |args: &[&str]| {
        let o = caisson().args(["size", s(&file), "--json"]).args(args).output().unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        o.stdout
    };
    let one = size(&["--threads", "1", "--out", s(&out)]);
    assert!(one == size(&["--threads", "2"]), "size.json differs between 1 and 2 threads");
    let j: serde_json::Value = serde_json::from_slice(&one).unwrap();
    let candidates = j["candidates"].as_array().unwrap();
    assert!(candidates.len() >= 3, "{}", candidates.len());
    let mut compared = 0;
    let mut boundaries = std::collections::BTreeSet::new();
    for c in candidates.iter().take(3) {
        let w = c["width_m"].as_f64().unwrap();
        let at = site::with(&site::without(&text, "caisson", &["width_m"]), "caisson", &format!("width_m = {w}"));
        let at = site::with(&site::without(&at, "design", &["lives"]), "design", &format!("lives = \"auto\"\n{rule}"));
        let f = write(dir.path(), "w.toml", &at);
        let o = caisson().args(["design", s(&f), "--json"]).output().unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let d: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        let (p, q) = (&c["precision"], &d["precision"]);
        assert_eq!((p["lives"].as_u64(), p["met"].as_bool()), (q["lives"].as_u64(), q["met"].as_bool()), "{w} m");
        assert_eq!(d["sampling"]["pool_lives"].as_u64(), p["lives"].as_u64(), "{w} m");
        boundaries.insert(p["lives"].as_u64().unwrap());
        let pairs = [
            (c["dynamic"]["expected_sliding_m"].as_f64(), d["dynamic"]["expected_sliding_m"].as_f64()),
            (c["dynamic"]["failure_probability"].as_f64(), d["dynamic"]["failure"]["probability"].as_f64()),
            (p["expected_sliding_relative_error"].as_f64(), q["expected_sliding_relative_error"].as_f64()),
        ];
        for (got, want) in pairs {
            let (got, want) = (got.unwrap(), want.unwrap());
            // The same lives and weights summed in the same order: equal to rounding.
            assert!((got - want).abs() <= 1e-12 * want.abs().max(1e-12), "{w} m: size {got}, design {want}");
            compared += 1;
        }
    }
    assert_eq!(compared, 9);
    // The widths took different numbers of lives: the rule reads each width's own estimates.
    assert!(boundaries.len() >= 2, "every width stopped at {boundaries:?}: choose a target that tells them apart");
    // Resumed from a checkpoint holding the first two candidates: the same size.json.
    let cp = out.join("size_checkpoint.jsonl");
    let text = std::fs::read_to_string(&cp).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    std::fs::write(&cp, format!("{}\n{}\n{}\n", lines[0], lines[1], lines[2])).unwrap();
    assert!(size(&["--out", s(&out), "--resume"]) == one, "a resumed run reports the same");
}
