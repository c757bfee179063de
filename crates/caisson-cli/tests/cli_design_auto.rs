//! `[design] lives = "auto"` (issue 35, item 2): lives in batches of 500 until the relative
//! standard errors of E|S| and P(failure) meet `target_relative_error`, at most `max_lives`. The
//! same lives and statistics with 1 and 2 threads, on resume, and from shards merged by `caisson
//! merge` (which applies the rule over the batches in order and refuses shards that do not reach
//! the stopping point); the budget running out is reported and warned; bad keys refused.

mod support;

use std::path::Path;
use support::{caisson_within, design_text, refused, s, write};

/// The output files of a design run, and its checkpoint.
const OUTPUTS: [&str; 6] =
    ["design.json", "lives.csv", "histogram.svg", "exceedance.svg", "heel_pressure.svg", "checkpoint.jsonl"];

/// The small design (seed 3) with `lives = "auto"` and the keys `extra` of `[design]`.
fn auto_text(extra: &str) -> String {
    let text = design_text(1, 3, "");
    assert!(text.contains("\nlives = 1\n"), "the small design's lives line");
    text.replace("\nlives = 1\n", &format!("\nlives = \"auto\"\n{extra}\n"))
}

/// `caisson design FILE ARGS`, expected to succeed: its stderr.
fn design(file: &Path, args: &[&str]) -> String {
    let o = caisson_within(300).args(["design", s(file)]).args(args).output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr).to_string();
    assert!(o.status.success(), "{args:?}: {err}");
    err
}

fn json(dir: &Path) -> serde_json::Value {
    serde_json::from_slice(&std::fs::read(dir.join("design.json")).unwrap()).unwrap()
}

/// Every output file of `a` and `b` byte-identical: the number compared.
fn assert_same(a: &Path, b: &Path) -> usize {
    for name in OUTPUTS {
        let (x, y) = (std::fs::read(a.join(name)).unwrap(), std::fs::read(b.join(name)).unwrap());
        assert!(x == y, "{name} differs between {a:?} and {b:?}");
    }
    OUTPUTS.len()
}

/// Target 0.03, budget 4000: the small design's lives fail often (P(failure) ≈ 0.38), so the
/// failures' relative error √((1 − p)/k) and E|S|'s reach 0.03 near 2000 lives — a stop past the
/// first batches, measured at 2000 (4 batches). One and two threads, a run stopped after 700
/// lives and resumed, and three shards (0..1200, 1200..1800, 1800..2500) merged give the same
/// files, byte for byte (6 files × 3 comparisons); the first two shards alone do not reach the
/// stopping point and are refused.
#[test]
fn auto_gives_the_same_lives_on_any_threads_resume_and_shards() {
    let dir = tempfile::tempdir().unwrap();
    let file = write(dir.path(), "auto.toml", &auto_text("target_relative_error = 0.03\nmax_lives = 4000"));
    let one = dir.path().join("one");
    design(&file, &["--threads", "1", "--out", s(&one)]);
    let j = json(&one);
    let p = &j["precision"];
    let k = p["lives"].as_u64().unwrap() as usize;
    assert_eq!(j["lives"].as_u64(), Some(k as u64));
    assert!(k.is_multiple_of(500) && k > 500 && k < 4000, "a stop at a batch boundary past the first: {k}");
    assert_eq!(
        (p["met"].as_bool(), p["max_lives"].as_u64(), p["batch_lives"].as_u64()),
        (Some(true), Some(4000), Some(500))
    );
    let (es, pf) =
        (p["expected_sliding_relative_error"].as_f64().unwrap(), p["failure_relative_error"].as_f64().unwrap());
    assert!(es <= 0.03 && pf <= 0.03, "{p}");
    // The rule's numbers are the report's: SE/E|S| and √((1 − p)/k) of its failures.
    let d = &j["dynamic"];
    let se = d["expected_sliding_standard_error_m"].as_f64().unwrap() / d["expected_sliding_m"].as_f64().unwrap();
    assert!((es - se).abs() < 1e-12 * se, "{es} {se}");
    let failed = d["failure"]["lives"].as_f64().unwrap();
    let by_hand = ((1.0 - failed / k as f64) / failed).sqrt();
    assert!((pf - by_hand).abs() < 1e-12, "{pf} {by_hand}");
    // lives.csv holds lives 0..k.
    let rows = std::fs::read_to_string(one.join("lives.csv")).unwrap().lines().count() - 1;
    assert_eq!(rows, k);

    let two = dir.path().join("two");
    let err = design(&file, &["--threads", "2", "--out", s(&two)]);
    assert!(!err.contains("Warning: the design run took its whole budget"), "{err}");
    let mut compared = assert_same(&one, &two);

    // Stopped after 700 lives (past the first boundary, before the stop), then resumed.
    let resumed = dir.path().join("resumed");
    let o = caisson_within(300)
        .args(["design", s(&file), "--threads", "2", "--stop-after", "700", "--out", s(&resumed)])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success() && err.contains("stopped after") && err.contains("--resume"), "{err}");
    design(&file, &["--threads", "2", "--resume", "--out", s(&resumed)]);
    compared += assert_same(&one, &resumed);

    // Shards of fixed ranges; the merge applies the rule.
    let shard = |range: &str, name: &str| {
        let d = dir.path().join(name);
        design(&file, &["--life-range", range, "--out", s(&d)]);
        d
    };
    let (a, b, c) = (shard("0..1200", "a"), shard("1200..1800", "b"), shard("1800..2500", "c"));
    let merged = dir.path().join("merged");
    refused(
        &["merge", s(&file), s(&a), s(&b), "--out", s(&merged)],
        &["lives = \"auto\"", "hold lives 0..1800", "do not reach the stopping point", "--life-range 1800.."],
    );
    let o = caisson_within(300).args(["merge", s(&file), s(&a), s(&b), s(&c), "--out", s(&merged)]).output().unwrap();
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(
        out.contains(&format!("is met at {k} lives"))
            && out.contains(&format!("{} lives beyond it not used", 2500 - k)),
        "{out}"
    );
    compared += assert_same(&one, &merged);
    assert_eq!(compared, 18);
}

/// Stratified sampling with `lives = "auto"` (target 0.2, budget 6000; the small design fails often, so the sample is no gain on it: 0.13 at 6000 lives): batch by batch each
/// batch's sample of the pool is simulated and the rule reads the weighted estimates. The same
/// files, byte for byte, with 1 and 2 threads, after a stop and a resume, and from two shards
/// merged (6 files × 3 comparisons); design.json's `precision` counts the pool (k, a batch
/// boundary), its `sampling` object the same pool, and lives.csv holds the sample only.
#[test]
fn stratified_auto_gives_the_same_lives_on_any_threads_resume_and_shards() {
    let dir = tempfile::tempdir().unwrap();
    let text = auto_text("target_relative_error = 0.2\nmax_lives = 6000\nsampling = \"stratified\"");
    let file = write(dir.path(), "auto.toml", &text);
    let one = dir.path().join("one");
    design(&file, &["--threads", "1", "--out", s(&one)]);
    let j = json(&one);
    let p = &j["precision"];
    let k = p["lives"].as_u64().unwrap() as usize;
    println!("stopped at {k} lives: {p}");
    assert!(k.is_multiple_of(500) && k > 500 && k < 6000 && p["met"] == true, "a stop past the first batch: {p}");
    assert_eq!((j["lives"].as_u64(), j["sampling"]["pool_lives"].as_u64()), (Some(k as u64), Some(k as u64)));
    let sampled = j["sampling"]["simulated_lives"].as_u64().unwrap() as usize;
    let rows = std::fs::read_to_string(one.join("lives.csv")).unwrap().lines().count() - 1;
    assert!(rows == sampled && sampled < k / 5, "{rows} rows, {sampled} simulated of {k}");
    let two = dir.path().join("two");
    design(&file, &["--threads", "2", "--out", s(&two)]);
    let mut compared = assert_same(&one, &two);
    let resumed = dir.path().join("resumed");
    let o = caisson_within(300)
        .args(["design", s(&file), "--threads", "2", "--stop-after", &(sampled / 2).to_string(), "--out", s(&resumed)])
        .output()
        .unwrap();
    assert!(!o.status.success(), "stopped after half the sample");
    design(&file, &["--threads", "2", "--resume", "--out", s(&resumed)]);
    compared += assert_same(&one, &resumed);
    let (a, b) = (dir.path().join("a"), dir.path().join("b"));
    design(&file, &["--life-range", "0..1000", "--out", s(&a)]);
    design(&file, &["--life-range", &format!("1000..{}", k + 500), "--out", s(&b)]);
    let merged = dir.path().join("merged");
    let o = caisson_within(300).args(["merge", s(&file), s(&a), s(&b), "--out", s(&merged)]).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    compared += assert_same(&one, &merged);
    assert_eq!(compared, 18);
}

/// A budget too small for the target: the run stops at max_lives = 1000, says so in the text and
/// in design.json (met false) and warns (`precision-not-met`, stderr and `warnings`).
#[test]
fn a_budget_that_runs_out_is_reported_and_warned() {
    let dir = tempfile::tempdir().unwrap();
    let file = write(dir.path(), "auto.toml", &auto_text("target_relative_error = 0.01\nmax_lives = 1000"));
    let out = dir.path().join("out");
    let o = caisson_within(300).args(["design", s(&file), "--out", s(&out)]).output().unwrap();
    assert!(o.status.success());
    let (text, err) = (String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
    assert!(text.contains("lives to a target precision: 1000 lives") && text.contains("NOT met"), "{text}");
    assert!(err.contains("Warning: the design run took its whole budget of 1000 lives"), "{err}");
    let j = json(&out);
    assert_eq!((j["lives"].as_u64(), j["precision"]["met"].as_bool()), (Some(1000), Some(false)));
    let codes: Vec<&str> = j["warnings"].as_array().unwrap().iter().filter_map(|w| w["code"].as_str()).collect();
    assert!(codes.contains(&"precision-not-met"), "{codes:?}");
    // A fixed number of lives has no `precision`; --lives turns "auto" off.
    let fixed = dir.path().join("fixed");
    design(&file, &["--lives", "20", "--out", s(&fixed)]);
    let j = json(&fixed);
    assert_eq!((j["lives"].as_u64(), j.get("precision")), (Some(20), None));
}

/// Refused with `Error:` naming the key, exit 2 (5 cases): a word other than "auto", a target of
/// 0 and above 0.5, max_lives 0, and the keys of "auto" beside a number of lives.
#[test]
fn bad_auto_keys_are_refused_naming_the_key() {
    let dir = tempfile::tempdir().unwrap();
    let cases: [(String, &[&str]); 5] = [
        (
            design_text(1, 3, "").replace("\nlives = 1\n", "\nlives = \"many\"\n"),
            &["[design] lives", "\"many\"", "\"auto\""],
        ),
        (auto_text("target_relative_error = 0"), &["[design] target_relative_error", "0"]),
        (auto_text("target_relative_error = 0.6"), &["[design] target_relative_error", "0.6"]),
        (auto_text("max_lives = 0"), &["[design] max_lives", "whole number from 1"]),
        (design_text(10, 3, "target_relative_error = 0.05"), &["[design] target_relative_error", "lives = \"auto\""]),
    ];
    for (k, (text, needles)) in cases.iter().enumerate() {
        let file = write(dir.path(), &format!("bad{k}.toml"), text);
        refused(&["design", s(&file)], needles);
    }
}

/// The design example with `lives = "auto"` (the default target 0.05 and budget 100 000): it stops
/// at 5500 lives (measured: E|S| 4.8 %, P(failure) 4.9 %), the same files with 1 and 2 threads
/// and from two shards (0..3000 and 3000..6000) merged (6 files × 2 comparisons), the merge using
/// lives 0..5500 of the 6000 the shards hold.
#[test]
fn auto_on_the_design_example_with_threads_and_shards() {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(support::example("design_breakwater.toml")).unwrap();
    let lives_line = text.lines().find(|l| l.starts_with("lives = ")).expect("the example's lives");
    let file = write(dir.path(), "design_auto.toml", &text.replacen(lives_line, "lives = \"auto\"", 1));
    let (one, two) = (dir.path().join("one"), dir.path().join("two"));
    design(&file, &["--threads", "1", "--out", s(&one)]);
    design(&file, &["--threads", "2", "--out", s(&two)]);
    let j = json(&one);
    let p = &j["precision"];
    assert_eq!(
        (j["lives"].as_u64(), p["met"].as_bool(), p["max_lives"].as_u64()),
        (Some(5500), Some(true), Some(100_000))
    );
    assert_eq!(p["target_relative_error"].as_f64(), Some(0.05));
    let mut compared = assert_same(&one, &two);
    let (a, b) = (dir.path().join("a"), dir.path().join("b"));
    design(&file, &["--life-range", "0..3000", "--out", s(&a)]);
    design(&file, &["--life-range", "3000..6000", "--out", s(&b)]);
    let merged = dir.path().join("merged");
    let o = caisson_within(300).args(["merge", s(&file), s(&a), s(&b), "--out", s(&merged)]).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stdout)
        .contains("is met at 5500 lives (batches of 500); 500 lives beyond it not used"));
    compared += assert_same(&one, &merged);
    assert_eq!(compared, 12);
}
