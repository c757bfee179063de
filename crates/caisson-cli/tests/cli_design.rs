//! `caisson design`: JSON contract, thread-count determinism, checkpoint and resume (after
//! `--stop-after` and after a real kill), and keyed errors for `[design]`.

mod support;

use serde_json::Value;
use support::write;

/// The time limit of one command (runs of many lives on a loaded machine).
fn caisson() -> assert_cmd::Command {
    support::caisson_within(120)
}

/// The small design (`crates/caisson/tests/data/small_design.toml`, seed 3) with `lives` lives and `extra`.
fn design_text(lives: usize, extra: &str) -> String {
    support::design_text(lives, 3, extra)
}

fn json_of(out: &[u8]) -> Value {
    serde_json::from_slice(out).expect("JSON on stdout")
}

#[test]
fn json_has_the_documented_keys_and_is_the_same_on_any_thread_count() {
    let dir = tempfile::tempdir().unwrap();
    let f = write(dir.path(), "d.toml", &design_text(12, ""));
    let one = caisson()
        .args(["design", f.to_str().unwrap(), "--json", "--threads", "1"])
        .assert()
        .success()
        .get_output()
        .stdout
        .clone();
    let two = caisson()
        .args(["design", f.to_str().unwrap(), "--json", "--threads", "2"])
        .assert()
        .success()
        .get_output()
        .stdout
        .clone();
    assert_eq!(one, two, "results must not depend on the thread count");
    let j = json_of(&one);
    for model in ["dynamic", "rigid_block"] {
        let m = &j[model];
        assert!(m["expected_sliding_m"].as_f64().unwrap() >= 0.0);
        assert!(
            (m["expected_sliding_per_year_m"].as_f64().unwrap() - m["expected_sliding_m"].as_f64().unwrap() / 5.0)
                .abs()
                < 1e-15
        );
        let p = &m["percentiles_m"];
        let (p5, p50, p95, p99) = (
            p["p5"].as_f64().unwrap(),
            p["p50"].as_f64().unwrap(),
            p["p95"].as_f64().unwrap(),
            p["p99"].as_f64().unwrap(),
        );
        assert!(p5 <= p50 && p50 <= p95 && p95 <= p99);
        let ex = m["exceedance_probability"].as_array().unwrap();
        let thresholds: Vec<f64> = ex.iter().map(|e| e["threshold_m"].as_f64().unwrap()).collect();
        assert_eq!(thresholds, vec![0.03, 0.1, 0.3, 1.0, 3.0]);
        let probs: Vec<f64> = ex.iter().map(|e| e["probability"].as_f64().unwrap()).collect();
        assert!(probs.windows(2).all(|w| w[1] <= w[0]) && probs.iter().all(|p| (0.0..=1.0).contains(p)));
    }
    let share = j["screened_share"].as_f64().unwrap();
    assert!((0.0..=1.0).contains(&share));
    assert_eq!(
        j["waves"].as_u64().unwrap(),
        j["simulated_waves"].as_u64().unwrap() + j["screened_waves"].as_u64().unwrap(),
        "every wave is either simulated or screened"
    );
    // The test is not vacuous: some life slides.
    assert!(j["dynamic"]["expected_sliding_m"].as_f64().unwrap() > 0.0);
    // Failure (default limit B/4 = 5 m), surviving lives and direction.
    assert_eq!(j["failure_sliding_m"].as_f64(), Some(5.0));
    for model in ["dynamic", "rigid_block"] {
        let (f, s) = (&j[model]["failure"], &j[model]["surviving"]);
        let failed = f["lives"].as_u64().unwrap();
        assert_eq!(failed + s["lives"].as_u64().unwrap(), 12, "{model}: every life fails or survives");
        assert!((f["probability"].as_f64().unwrap() - failed as f64 / 12.0).abs() < 1e-15);
        // The modes cover the failed lives (a life may fail by both); the rigid block never
        // rotates; the capped E|S| stays within the sliding limit.
        let (by_s, by_r) = (f["by_sliding"]["lives"].as_u64().unwrap(), f["by_rotation"]["lives"].as_u64().unwrap());
        assert!(by_s.max(by_r) <= failed && by_s + by_r >= failed, "{model}: {f}");
        assert!(model == "dynamic" || by_r == 0);
        assert!(j[model]["expected_sliding_m"].as_f64().unwrap() <= 5.0);
        assert!(j[model]["expected_sliding_uncapped_m"].as_f64().unwrap() >= 0.0);
    }
    assert_eq!(j["failure_rotation_rad"].as_f64(), Some(0.01));
    assert!(j.get("lives_end_at_failure").is_none() && j.get("failure_heel_pressure_kpa").is_none());
    let d = &j["dynamic"];
    let net = d["expected_shoreward_sliding_m"].as_f64().unwrap() - d["expected_seaward_sliding_m"].as_f64().unwrap();
    assert!((net - d["expected_net_sliding_m"].as_f64().unwrap()).abs() < 1e-12, "net = shoreward − seaward");
    assert!(d["expected_max_excursion_m"].as_f64().unwrap() >= d["expected_net_sliding_m"].as_f64().unwrap());
    for key in ["seaward_lives", "rocking_waves", "large_rotation_waves", "large_rotation_lives"] {
        assert!(d[key].is_u64(), "dynamic.{key}");
    }
}

/// `[design] failure_sliding_m` below every life's excursion fails every life that slid: the
/// failure count follows the limit, and the warning says so.
#[test]
fn a_small_failure_limit_fails_the_lives_that_slide() {
    let dir = tempfile::tempdir().unwrap();
    let f = write(dir.path(), "d.toml", &design_text(12, "failure_sliding_m = 1e-9"));
    let out = dir.path().join("out");
    let o = caisson().args(["design", f.to_str().unwrap(), "--json", "--out", out.to_str().unwrap()]).output().unwrap();
    assert_eq!(o.status.code(), Some(0));
    let j = json_of(&o.stdout);
    let csv = std::fs::read_to_string(out.join("lives.csv")).unwrap();
    let mut rows = csv.lines();
    let header: Vec<&str> = rows.next().unwrap().split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap_or_else(|| panic!("no column {name}"));
    let moved =
        rows.filter(|r| r.split(',').nth(col("max_excursion_m")).unwrap().parse::<f64>().unwrap() > 1e-9).count();
    assert!(moved >= 1, "some life must move for the test to count anything");
    assert_eq!(j["dynamic"]["failure"]["lives"].as_u64(), Some(moved as u64));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains(&format!("Warning: {moved} of 12 lives failed")), "{err}");
    assert!(j["warnings"].as_array().unwrap().iter().any(|w| w["code"] == "failed-lives"));
}

#[test]
fn an_interrupted_run_resumes_to_the_identical_result() {
    let dir = tempfile::tempdir().unwrap();
    let f = write(dir.path(), "d.toml", &design_text(10, ""));
    let full = dir.path().join("full");
    let part = dir.path().join("part");
    let reference = caisson()
        .args(["design", f.to_str().unwrap(), "--json", "--out", full.to_str().unwrap()])
        .assert()
        .success()
        .get_output()
        .stdout
        .clone();
    // Stop after 3 lives: exit 1, the checkpoint keeps them, no results written.
    let out = caisson()
        .args([
            "design",
            f.to_str().unwrap(),
            "--json",
            "--threads",
            "1",
            "--stop-after",
            "3",
            "--out",
            part.to_str().unwrap(),
        ])
        .assert()
        .code(1)
        .get_output()
        .clone();
    assert!(String::from_utf8_lossy(&out.stderr).contains("--resume"));
    let cp = std::fs::read_to_string(part.join("checkpoint.jsonl")).unwrap();
    assert_eq!(cp.lines().count(), 1 + 3, "header + 3 lives");
    assert!(!part.join("design.json").exists());
    let resumed = caisson()
        .args(["design", f.to_str().unwrap(), "--json", "--resume", "--out", part.to_str().unwrap()])
        .assert()
        .success()
        .get_output()
        .stdout
        .clone();
    assert_eq!(resumed, reference, "resume must give exactly the uninterrupted result");
    assert_eq!(std::fs::read(part.join("lives.csv")).unwrap(), std::fs::read(full.join("lives.csv")).unwrap());
    // The ordered checkpoint: 3 lives read back and made again, 7 lines as this run wrote them.
    let (resumed_cp, full_cp) =
        (std::fs::read(part.join("checkpoint.jsonl")).unwrap(), std::fs::read(full.join("checkpoint.jsonl")).unwrap());
    assert_eq!(String::from_utf8_lossy(&full_cp).lines().count(), 1 + 10, "header + 10 lives");
    assert_eq!(resumed_cp, full_cp, "the resumed checkpoint is the uninterrupted one, byte for byte");
}

#[test]
fn a_killed_run_resumes_to_the_identical_result() {
    let dir = tempfile::tempdir().unwrap();
    // Longer lives so that the run is still going when it is killed.
    let text = design_text(120, "").replace("life_years = 5", "life_years = 20");
    let f = write(dir.path(), "d.toml", &text);
    let out = dir.path().join("out");
    let bin = assert_cmd::cargo::cargo_bin("caisson");
    let mut child = std::process::Command::new(&bin)
        .args(["design", f.to_str().unwrap(), "--json", "--threads", "2", "--out", out.to_str().unwrap()])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let cp = out.join("checkpoint.jsonl");
    let start = std::time::Instant::now();
    loop {
        let n = std::fs::read_to_string(&cp).map(|s| s.lines().count()).unwrap_or(0);
        if n >= 6 || start.elapsed().as_secs() > 60 {
            break;
        }
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
    child.kill().unwrap();
    let status = child.wait().unwrap();
    let lines = std::fs::read_to_string(&cp).unwrap().lines().count();
    if status.success() {
        // The machine finished before the kill landed: nothing to resume, but the check below holds.
        eprintln!("run finished before the kill");
    }
    assert!(lines >= 2, "the checkpoint keeps the finished lives");
    // Simulate a line cut by the kill, then resume.
    std::fs::OpenOptions::new()
        .append(true)
        .open(&cp)
        .and_then(|mut fh| std::io::Write::write_all(&mut fh, b"{\"life\": 39"))
        .unwrap();
    let resumed = caisson()
        .args(["design", f.to_str().unwrap(), "--json", "--resume", "--out", out.to_str().unwrap()])
        .assert()
        .success()
        .get_output()
        .stdout
        .clone();
    let reference =
        caisson().args(["design", f.to_str().unwrap(), "--json"]).assert().success().get_output().stdout.clone();
    assert_eq!(resumed, reference);
}

#[test]
fn resume_refuses_a_checkpoint_of_another_run() {
    let dir = tempfile::tempdir().unwrap();
    let f = write(dir.path(), "d.toml", &design_text(4, ""));
    let out = dir.path().join("out");
    caisson()
        .args(["design", f.to_str().unwrap(), "--stop-after", "1", "--threads", "1", "--out", out.to_str().unwrap()])
        .assert()
        .code(1);
    let g = write(dir.path(), "d.toml", &design_text(4, "").replace("seed = 3", "seed = 4"));
    let err = caisson()
        .args(["design", g.to_str().unwrap(), "--resume", "--out", out.to_str().unwrap()])
        .assert()
        .code(2)
        .get_output()
        .stderr
        .clone();
    let err = String::from_utf8_lossy(&err);
    assert!(err.starts_with("Error:") && err.contains("different scenario"), "{err}");
}

#[test]
fn bad_design_keys_are_named() {
    let dir = tempfile::tempdir().unwrap();
    let cases = [
        ("storm_distribution = \"weibull\"", "storm_distribution = \"frechet\"", "[design] storm_distribution"),
        ("storm_shape = 1.4", "storm_shape = -1.0", "[design] storm_shape"),
        ("storm_scale_m = 1.5", "storm_scale_m = 0.0", "[design] storm_scale_m"),
        ("storm_scale_m = 1.5\n", "", "[design] storm_scale_m"),
        ("lives = 4", "lives = 0", "[design] lives"),
        ("life_years = 5", "life_years = -2", "[design] life_years"),
        ("storm_duration_h = 0.2", "storm_duration_h = nan", "[design] storm_duration_h"),
        ("tidal_range_m = 2.0", "tidal_range_m = -1.0", "[design] tidal_range_m"),
        ("seed = 3", "seed = -3", "[design] seed"),
        ("seed = 3", "seed = 3\nwave_force_cov = 0.8", "[design] wave_force_cov"),
        ("seed = 3", "seed = 3\nthresholds_m = [0.2, -1.0]", "[design] thresholds_m[1]"),
        ("storm_distribution = \"weibull\"", "storm_distribution = \"gumbel\"", "[design] storm_shape"),
        ("seed = 3", "seed = 3\nfailure_sliding_m = 0.0", "[design] failure_sliding_m"),
        ("seed = 3", "seed = 3\nfailure_sliding_m = -2.0", "[design] failure_sliding_m"),
        ("seed = 3", "seed = 3\nfailure_rotation_rad = 0.0", "[design] failure_rotation_rad"),
        ("seed = 3", "seed = 3\nfailure_rotation_rad = 0.5", "[design] failure_rotation_rad"),
        ("seed = 3", "seed = 3\nfailure_rotation_rad = inf", "[design] failure_rotation_rad"),
        ("seed = 3", "seed = 3\ncontinue_after_failure = true", "[design] continue_after_failure"),
        ("seed = 3", "seed = 3\nallowable_heel_pressure_kpa = 0.0", "[design] allowable_heel_pressure_kpa"),
        ("seed = 3", "seed = 3\nfailure_heel_pressure_kpa = 2e4", "[design] failure_heel_pressure_kpa"),
        // 350 kN/m is below 0.2 of the 3536.5 kN/m of water the caisson displaces.
        ("weight_in_water_kn = 4500.0", "weight_in_water_kn = 350.0", "[caisson] weight_in_water_kn"),
        // 750 kN/m (0.21 of it) floats at 4 m of tide (ρ_w g B l R = 808 kN).
        ("tidal_range_m = 2.0", "tidal_range_m = 4.0", "[design] tidal_range_m"),
    ];
    for (from, to, key) in cases {
        let mut text = design_text(4, "").replace(from, to);
        if to == "tidal_range_m = 4.0" {
            text = text.replace("weight_in_water_kn = 4500.0", "weight_in_water_kn = 750.0");
        }
        let f = write(dir.path(), "bad.toml", &text);
        let out = dir.path().join("never");
        let o = caisson()
            .args(["design", f.to_str().unwrap(), "--out", out.to_str().unwrap()])
            .assert()
            .code(2)
            .get_output()
            .clone();
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.starts_with("Error:") && err.contains(key), "{to}: {err}");
        assert!(!out.exists(), "{to}: nothing may be written");
    }
}

/// A reader that goes away (`caisson … | head`) is not a panic: the command finishes, writes its
/// files and exits 0.
#[test]
fn a_closed_stdout_is_not_a_panic() {
    let dir = tempfile::tempdir().unwrap();
    let f = write(dir.path(), "d.toml", &design_text(6, ""));
    let out = dir.path().join("out");
    let mut child = std::process::Command::new(assert_cmd::cargo::cargo_bin("caisson"))
        .args(["design", f.to_str().unwrap(), "--json", "--out", out.to_str().unwrap()])
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take()); // close the reading end before anything is written
    let o = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success() && !err.contains("panicked"), "{:?}: {err}", o.status);
    assert!(out.join("design.json").exists());
}
