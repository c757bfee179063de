//! `[size] lives = "auto"` (issue 35, item 2): each candidate width runs its lives in batches of
//! 500 until its own E|S| and P(failure) meet `target_relative_error`, at most `max_lives`; the
//! same size.json on 1 and 2 threads and on resume; each candidate says how many lives it took
//! and whether its target was met, and a candidate whose budget ran out is warned about.

mod support;

use serde_json::Value;
use support::{caisson_within, refused, sizing_text, write};

/// The sizing of `cli_size.rs` (a prototype caisson by its construction, short heavy storms) with
/// `[size] lives = "auto"` and `extra`.
fn size_text(extra: &str) -> String {
    sizing_text(&format!(
        "range_m = [8.0, 30.0]\nfailure_probability = 0.2\ntolerance_m = 4.0\ncurve_points = 3\nlives = \"auto\"\n{extra}"
    ))
}

fn sized(f: &std::path::Path, args: &[&str]) -> (Vec<u8>, String) {
    let o = caisson_within(300).args(["size", f.to_str().unwrap(), "--json"]).args(args).output().unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    (o.stdout, String::from_utf8_lossy(&o.stderr).to_string())
}

/// Target 0.1, budget 1000: every candidate stops at a batch boundary (500 or the budget
/// 1000) where its verdict is met, or at 1000 not met (and warned about); the lives simulated are
/// the candidates' own; one and two threads and a resumed run give the same size.json.
#[test]
fn auto_candidates_take_the_lives_they_need_on_any_thread_count() {
    let dir = tempfile::tempdir().unwrap();
    let f = write(dir.path(), "s.toml", &size_text("target_relative_error = 0.1\nmax_lives = 1000"));
    let (one, err) = sized(&f, &["--threads", "1"]);
    let (two, _) = sized(&f, &["--threads", "2"]);
    assert!(one == two, "size.json must not depend on the thread count");
    let j: Value = serde_json::from_slice(&one).unwrap();
    assert_eq!((j["target_relative_error"].as_f64(), j["lives_per_candidate"].as_u64()), (Some(0.1), Some(1000)));
    let cands = j["candidates"].as_array().unwrap();
    assert!(cands.len() >= 3, "{}", cands.len());
    let mut total = 0;
    let mut not_met = 0;
    for c in cands {
        let p = &c["precision"];
        let k = p["lives"].as_u64().unwrap();
        total += k;
        let met = p["met"].as_bool().unwrap();
        assert!([500, 1000].contains(&k), "a batch boundary: {k}");
        assert!(met || k == 1000, "stopped before the budget only when met: {p}");
        if met {
            assert!(p["expected_sliding_relative_error"].as_f64().unwrap() <= 0.1, "{p}");
        } else {
            not_met += 1;
        }
        // The rule read the candidate's own statistics: SE/E|S| of its dynamic model.
        let d = &c["dynamic"];
        let rel = d["expected_sliding_standard_error_m"].as_f64().unwrap() / d["expected_sliding_m"].as_f64().unwrap();
        assert!((p["expected_sliding_relative_error"].as_f64().unwrap() - rel).abs() <= 1e-12 * rel, "{p}");
    }
    assert_eq!(j["lives_simulated"].as_u64(), Some(total));
    let warned = j["warnings"].as_array().unwrap().iter().filter(|w| w["code"] == "precision-not-met").count();
    assert_eq!(warned, not_met, "one warning per candidate short of the target");
    assert_eq!(err.matches("took its whole budget").count(), not_met.min(1), "{err}");

    // Resumed from a checkpoint holding the first two candidates: the same size.json.
    let out = dir.path().join("out");
    let o = caisson_within(300)
        .args(["size", f.to_str().unwrap(), "--json", "--out", out.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(o.status.success());
    let cp = out.join("size_checkpoint.jsonl");
    let text = std::fs::read_to_string(&cp).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    std::fs::write(&cp, format!("{}\n{}\n{}\n", lines[0], lines[1], lines[2])).unwrap();
    let (resumed, _) = sized(&f, &["--out", out.to_str().unwrap(), "--resume"]);
    assert!(resumed == one, "a resumed run reports the same");
}

/// `[size] lives = "many"` and `target_relative_error = 0` are refused naming the key (exit 2).
#[test]
fn bad_size_auto_keys_are_refused_naming_the_key() {
    let dir = tempfile::tempdir().unwrap();
    let f = write(dir.path(), "a.toml", &size_text("").replace("lives = \"auto\"", "lives = \"many\""));
    refused(&["size", f.to_str().unwrap()], &["[size] lives", "\"many\"", "\"auto\""]);
    let f = write(dir.path(), "b.toml", &size_text("target_relative_error = 0"));
    refused(&["size", f.to_str().unwrap()], &["[size] target_relative_error", "0"]);
}
