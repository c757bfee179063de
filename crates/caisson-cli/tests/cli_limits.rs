//! Regression tests of issue 12 (hardening): every option and input that could make a command
//! run without end or grow without bound is refused up front with an `Error:` that gives the
//! limit (and the estimate); `loads` refuses non-finite output. Each test is named after its
//! finding.

mod support;

use support::*;

#[test]
fn spectrum_tr_over_t0_5e_324_1e_9_and_1e300_are_refused_at_once() {
    for range in ["5e-324:1:3", "1e-9:1e-8:3", "1e300:1e301:3", "0.0001:1:3", "1:2000:3"] {
        refused(&["spectrum", &example("table5_triangle.toml"), "--tr-over-t0", range], &["--tr-over-t0", "0.001"]);
    }
}

#[test]
fn spectrum_sweep_over_the_step_budget_is_refused_with_the_estimate() {
    let err = refused(
        &["spectrum", &example("table5_triangle.toml"), "--tr-over-t0", "0.001:0.002:2000"],
        &["time steps", "at most 1e8"],
    );
    assert!(err.contains("2.89e8"), "the estimate is given: {err}");
}

#[test]
fn threads_99999999999_and_5000_are_refused_naming_the_option() {
    let cases: [(&str, String); 4] = [
        ("run", example("pari_breaking_loads.toml")),
        ("campaign", example("pari_breaking_campaign.toml")),
        ("design", example("design_breakwater.toml")),
        ("fragility", example("fragility.toml")),
    ];
    for (cmd, file) in &cases {
        for n in ["99999999999", "5000", "257", "x"] {
            refused(&[cmd, file, "--threads", n], &["--threads", "0 to 256"]);
        }
    }
}

#[test]
fn lives_1000000000_is_refused_like_the_file_cap() {
    for n in ["1000000000", "10000001", "0"] {
        refused(&["design", &example("design_breakwater.toml"), "--lives", n], &["--lives", "1 to 10000000"]);
    }
}

#[test]
fn loads_history_waves_100000_is_refused_before_computing() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let err = refused(
        &[
            "loads",
            &example("pari_breaking_loads.toml"),
            "--history",
            "--waves",
            "100000",
            "--out",
            out.to_str().unwrap(),
        ],
        &["--waves 100000", "rows", "1 to 1030"],
    );
    assert!(err.contains("48500000"), "the estimate is given: {err}");
    assert!(!out.exists(), "nothing written");
}

#[test]
fn loads_history_checks_out_before_computing() {
    let dir = tempfile::tempdir().unwrap();
    let file = write(dir.path(), "a-file", "not a directory");
    refused(
        &["loads", &example("pari_breaking_loads.toml"), "--history", "--out", file.to_str().unwrap()],
        &["--out", "not a directory"],
    );
    // Under a file: the directory cannot be created, said before computing.
    let below = file.join("sub");
    refused(
        &["loads", &example("pari_breaking_loads.toml"), "--history", "--out", below.to_str().unwrap()],
        &["--out", "cannot be created"],
    );
}

#[test]
fn loads_with_weight_1e305_kn_refuses_non_finite_output() {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(example("pari_breaking_loads.toml")).unwrap();
    let start = text.find("weight_in_water_kn").expect("the example gives the weight");
    let end = start + text[start..].find('\n').unwrap();
    let f = write(dir.path(), "heavy.toml", &format!("{}weight_in_water_kn = 1e305{}", &text[..start], &text[end..]));
    for json in [true, false] {
        let mut args = vec!["loads", f.to_str().unwrap()];
        if json {
            args.push("--json");
        }
        let o = caisson().args(&args).output().unwrap();
        let (out, err) = (String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
        assert_eq!(o.status.code(), Some(2), "non-finite loads must not exit 0: {out}");
        // Refused at validation (a weight beyond any caisson names its key); the loads' own
        // finite-value check stays behind it for numbers that pass validation.
        assert!(
            err.starts_with("Error:")
                && (err.contains("not finite numbers (loads.") || err.contains("[caisson] weight_in_water_kn")),
            "{err}"
        );
        assert!(!out.contains("null") && !out.contains("NaN") && !out.contains("inf"), "{out}");
    }
}

#[cfg(unix)]
#[test]
fn series_file_that_never_ends_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(example("table5_triangle.toml")).unwrap();
    let start = text.find("[load]").unwrap();
    let end = start + text[start..].find("[solver]").unwrap();
    let f = write(
        dir.path(),
        "zero.toml",
        &format!("{}[load]\nkind = \"series\"\nfile = \"/dev/zero\"\n\n{}", &text[..start], &text[end..]),
    );
    refused(&["run", f.to_str().unwrap()], &["/dev/zero", "128 MiB"]);
}

#[cfg(unix)]
#[test]
fn scenario_file_that_never_ends_is_refused_quickly_naming_the_file_and_the_limit() {
    let start = std::time::Instant::now();
    for cmd in ["run", "loads", "campaign", "design", "fragility", "spectrum"] {
        refused(&[cmd, "/dev/zero"], &["scenario file /dev/zero", "larger than 1 MiB"]);
    }
    // Each reads at most 1 MiB + 1 byte: far below a second even on a loaded machine (the limit
    // of `caisson()` is 60 s; without the limit /dev/zero is read until memory runs out).
    assert!(start.elapsed() < std::time::Duration::from_secs(30), "{:?}", start.elapsed());
}

#[test]
fn huge_scenario_and_series_files_are_refused_by_their_size_without_reading_them() {
    let dir = tempfile::tempdir().unwrap();
    // Sparse files: their size is all that is checked, so 1 TiB costs nothing.
    let sparse = |name: &str, len: u64| {
        let p = dir.path().join(name);
        std::fs::File::create(&p).unwrap().set_len(len).unwrap();
        p
    };
    let big = sparse("big.toml", 1 << 40);
    refused(&["run", big.to_str().unwrap()], &["big.toml", "larger than 1 MiB"]);
    // Just over the limit, as a file of text: refused too; at the limit it is read (and parsed).
    let over = write(dir.path(), "over.toml", &"#".repeat((1 << 20) + 1));
    refused(&["run", over.to_str().unwrap()], &["over.toml", "larger than 1 MiB"]);
    let at = write(dir.path(), "at.toml", &"#".repeat(1 << 20));
    let err = refused(&["run", at.to_str().unwrap()], &["at.toml"]);
    assert!(!err.contains("larger than"), "a file of 1 MiB is read (and found to have no [caisson]): {err}");
    let csv = sparse("forces.csv", 1 << 40);
    let text = std::fs::read_to_string(example("table5_triangle.toml")).unwrap();
    let start = text.find("[load]").unwrap();
    let end = start + text[start..].find("[solver]").unwrap();
    let f = write(
        dir.path(),
        "series.toml",
        &format!("{}[load]\nkind = \"series\"\nfile = \"forces.csv\"\n\n{}", &text[..start], &text[end..]),
    );
    refused(&["run", f.to_str().unwrap()], &[csv.file_name().unwrap().to_str().unwrap(), "larger than 128 MiB"]);
}

#[test]
fn wave_trains_of_40000_waves_obey_the_step_limit_under_adaptive_stepping() {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(example("pari_breaking_loads.toml")).unwrap();
    assert!(text.contains("[waves]"));
    // 40 000 waves of the example's period (about 3 s) at the first step of 1e-4 s: over 1e9 steps.
    let long = text.replacen("[waves]", "[waves]\nwaves = 40000\nrealizations = 1", 1);
    let long = strip_keys(&long, "[waves]", &["waves", "realizations"], 2);
    let f = write(dir.path(), "long.toml", &long);
    refused(&["run", f.to_str().unwrap()], &["dt_s", "at most 1e9"]);
}

#[test]
fn waves_times_realizations_is_bounded() {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(example("pari_breaking_loads.toml")).unwrap();
    let many = text.replacen("[waves]", "[waves]\nwaves = 1000\nrealizations = 100000", 1);
    let many = strip_keys(&many, "[waves]", &["waves", "realizations"], 2);
    let f = write(dir.path(), "many.toml", &many);
    refused(&["run", f.to_str().unwrap()], &["[waves] realizations", "at most 10000000"]);
}

/// Remove the lines `key = ...` of `table` after its first `keep` lines (so that the keys just
/// inserted at its top replace the example's own).
fn strip_keys(text: &str, table: &str, keys: &[&str], keep: usize) -> String {
    let mut out = Vec::new();
    let mut in_table = false;
    let mut seen = 0;
    for line in text.lines() {
        if line.starts_with('[') {
            in_table = line.trim() == table;
            seen = 0;
        } else if in_table {
            seen += 1;
            let key = line.split('=').next().unwrap_or("").trim();
            if seen > keep && keys.contains(&key) {
                continue;
            }
        }
        out.push(line);
    }
    out.join("\n") + "\n"
}

#[test]
fn dt_s_1e156_with_a_rise_time_of_5e158_is_refused() {
    // Found by tests/cli_fuzz_scenarios.rs: the run started, with times of 1e155 s, and failed with a
    // Newton-Raphson message (exit 1) instead of naming the key.
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(example("table5_triangle.toml")).unwrap();
    let huge = text
        .replacen("rise_time_s = 0.05", "rise_time_s = 5e158", 1)
        .replacen("duration_s = 0.6", "duration_s = 1e160", 1)
        .replacen("dt_s = 1e-4", "dt_s = 1e156", 1);
    let f = write(dir.path(), "huge.toml", &huge);
    refused(&["run", f.to_str().unwrap()], &["[solver] dt_s", "at most 1 (s)"]);
    let f = write(
        dir.path(),
        "two.toml",
        &text.replacen("dt_s = 1e-4", "dt_s = 2.0", 1).replacen("duration_s = 0.6", "duration_s = 60", 1),
    );
    refused(&["run", f.to_str().unwrap()], &["[solver] dt_s", "at most 1 (s)"]);
}

/// The example `name` with `from` replaced by `to` (which must be there), written to `dir`.
fn variant(dir: &std::path::Path, name: &str, edits: &[(&str, &str)]) -> std::path::PathBuf {
    let mut text = std::fs::read_to_string(example(name)).unwrap();
    for (from, to) in edits {
        assert!(text.contains(from), "{name} has `{from}`");
        text = text.replacen(from, to, 1);
    }
    write(dir, name, &text)
}

/// `run --out` streams its histories to disk, so they are counted as bytes written, not held:
/// ten million rows were refused as "10.2 GiB held in memory" although the run holds none of
/// them. They are refused now by the disk budget (10 GiB written), with the rows and what to
/// change.
#[test]
fn run_of_ten_million_history_rows_is_refused_by_its_disk_estimate_not_memory() {
    let dir = tempfile::tempdir().unwrap();
    let f = variant(dir.path(), "table5_triangle.toml", &[("duration_s = 0.6", "duration_s = 10000")]);
    let out = dir.path().join("out");
    let err = refused(
        &["run", f.to_str().unwrap(), "--out", out.to_str().unwrap()],
        &[
            "of time histories written to disk",
            "10000001 history rows written",
            "the budget is 10.0 GiB written",
            "[solver] output_interval_s",
            "without --out",
        ],
    );
    assert!(err.contains("about 10.2 GiB") && !err.contains("held in memory"), "the estimate is given: {err}");
    assert!(!out.exists(), "nothing written");
    // Without --out nothing is written or held: the same run is within the budget (it is not run
    // here: 1e8 steps).
}

/// A history of a billion rows (1e5 s at output_interval_s = dt_s = 1e-4 s: the most steps a run
/// may take) would write about a terabyte: refused up front with the estimate, the limit and
/// what to change.
#[test]
fn run_out_of_a_billion_history_rows_is_refused_up_front() {
    let dir = tempfile::tempdir().unwrap();
    let f = variant(
        dir.path(),
        "table5_triangle.toml",
        &[("duration_s = 0.6", "duration_s = 1e5"), ("dt_s = 1e-4", "dt_s = 1e-4\noutput_interval_s = 1e-4")],
    );
    let out = dir.path().join("out");
    let err = refused(
        &["run", f.to_str().unwrap(), "--out", out.to_str().unwrap()],
        &["about 1.0 TiB of time histories written to disk", "1000000001 history rows written", "10.0 GiB written"],
    );
    assert!(err.contains("raise `[solver] output_interval_s`"), "{err}");
    assert!(!out.exists(), "nothing written");
}

/// Five million rows (5.1 GiB of CSV, formerly 5.2 GiB "held in memory", over the 4 GiB memory
/// budget) are within the budgets now: the run starts (its estimate says the bytes written and
/// none held) and is stopped with Ctrl-C, leaving no file.
#[cfg(unix)]
#[test]
fn run_out_of_five_million_history_rows_starts_and_counts_them_as_disk() {
    use std::io::BufRead;
    let dir = tempfile::tempdir().unwrap();
    // 5000 s at 5e-5 s: 1e8 steps, so the estimate is said; rows every 1 ms.
    let f = variant(
        dir.path(),
        "table5_triangle.toml",
        &[("duration_s = 0.6", "duration_s = 5000"), ("dt_s = 1e-4", "dt_s = 5e-5\noutput_interval_s = 1e-3")],
    );
    let out = dir.path().join("out");
    let mut child = std::process::Command::new(assert_cmd::cargo::cargo_bin("caisson"))
        .args(["run", f.to_str().unwrap(), "--out", out.to_str().unwrap()])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let mut stderr = std::io::BufReader::new(child.stderr.take().unwrap());
    let mut first = String::new();
    stderr.read_line(&mut first).unwrap();
    let sent = std::process::Command::new("kill").args(["-INT", &child.id().to_string()]).status().unwrap();
    assert!(sent.success());
    let mut rest = String::new();
    std::io::Read::read_to_string(&mut stderr, &mut rest).unwrap();
    let status = child.wait().unwrap();
    assert!(first.starts_with("Estimated work: about 1.0e8 time steps"), "{first}{rest}");
    assert!(
        first.contains("0.0 MiB held, 5.1 GiB written") && first.contains("5000001 history rows written"),
        "{first}"
    );
    assert_eq!(status.code(), Some(130), "{first}{rest}");
    assert!(!out.join("history.csv").exists() && temporaries(&out).is_empty(), "nothing kept");
}

#[test]
fn run_of_1000_realizations_of_10000_waves_is_refused_by_its_memory_estimate() {
    let dir = tempfile::tempdir().unwrap();
    let f =
        variant(dir.path(), "pari_breaking_loads.toml", &[("[waves]", "[waves]\nwaves = 10000\nrealizations = 1000")]);
    let err = refused(
        &["run", f.to_str().unwrap()],
        &["1000 realizations × 10000 waves", "held in memory", "the budget is 4.0 GiB", "[waves] waves"],
    );
    assert!(err.contains("about 19.1 GiB"), "the estimate is given: {err}");
}

#[test]
fn campaign_of_15_conditions_of_1000_realizations_of_10000_waves_is_refused_by_its_step_estimate() {
    let dir = tempfile::tempdir().unwrap();
    let f = variant(
        dir.path(),
        "pari_breaking_campaign.toml",
        &[("waves = 15 ", "waves = 10000 "), ("realizations = 10", "realizations = 1000")],
    );
    let err = refused(
        &["campaign", f.to_str().unwrap()],
        &["time steps of the dynamic model", "15 conditions", "the budget is 2e10 time steps", "[waves] waves"],
    );
    // 1.5e8 waves of 3.04 s at about 220 adaptive steps a second (the pilot's): about 1e11.
    assert!((5e10..2e11).contains(&estimate(&err)), "the estimate is given: {err}");
}

#[test]
fn design_of_ten_million_lives_is_refused_by_its_wave_estimate() {
    let err = refused(
        &["design", &example("design_breakwater.toml"), "--lives", "10000000"],
        &["10000000 lives × 50 years", "the budget is 2e10 waves", "--lives"],
    );
    assert!(err.contains("about 3.72e11 waves"), "the estimate is given: {err}");
}

#[test]
fn design_of_the_example_by_brute_force_is_refused_by_its_step_estimate() {
    // Every one of 1.9e8 waves at fixed steps of 1 ms: about 1.8e12 steps (BENCHMARKS.md: 69 h).
    let err = refused(
        &["design", &example("design_breakwater.toml"), "--brute-force"],
        &["time steps", "fixed steps of 0.001 s", "the budget is 2e10 time steps", "--brute-force"],
    );
    assert!((1e12..4e12).contains(&estimate(&err)), "the estimate is given: {err}");
}

#[test]
fn fragility_of_a_million_storms_per_height_is_refused_by_its_step_estimate() {
    let dir = tempfile::tempdir().unwrap();
    let f = variant(dir.path(), "fragility.toml", &[("storms = 100 ", "storms = 1000000 ")]);
    let err = refused(
        &["fragility", f.to_str().unwrap()],
        &[
            "9 heights × 1000000 storms × 563 waves",
            "simulated (screen pilot)",
            "the budget is 2e10 time steps",
            "[fragility] storms",
        ],
    );
    // 9e6 storms of 563 waves, 5 % simulated, at about 29 steps a second: about 1e11.
    assert!((5e10..1e12).contains(&estimate(&err)), "the estimate is given: {err}");
}

#[test]
fn a_long_design_run_says_its_estimate() {
    // 3000 lives: 1.1e8 waves, over the 1e8 at which the estimate is said; stopped after one life.
    let dir = tempfile::tempdir().unwrap();
    let o = caisson()
        .args(["design", &example("design_breakwater.toml"), "--lives", "3000", "--stop-after", "1"])
        .args(["--out", dir.path().join("out").to_str().unwrap()])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.starts_with("Estimated work: about "), "{err}");
    assert!(err.contains("e8 waves") && err.contains("3000 lives × 50 years"), "{err}");
    // A short run says nothing.
    let o = caisson().args(["design", &example("design_breakwater.toml"), "--lives", "2", "--json"]).output().unwrap();
    assert!(o.status.success());
    assert!(!String::from_utf8_lossy(&o.stderr).contains("Estimated work"));
}

/// Found by tests/cli_fuzz_scenarios.rs: the PARI breaking campaign on 1000 springs was estimated at
/// its 1.5e6 steps and took over 20 s where the estimate said 1.5 s: a step's cost grows with the
/// springs. A step on n springs counts (n + 10)/20 steps on 10 (50.5 for 1000), so the same
/// campaign with 100 realizations of 10 000 waves (1e10 steps) is refused on 1000 springs.
#[test]
fn campaign_on_1000_springs_counts_each_step_as_50_steps_on_10() {
    let dir = tempfile::tempdir().unwrap();
    let f = variant(
        dir.path(),
        "pari_breaking_campaign.toml",
        &[
            ("springs = 10", "springs = 1000"),
            ("waves = 15 ", "waves = 10000 "),
            ("realizations = 10", "realizations = 100"),
        ],
    );
    refused(
        &["campaign", f.to_str().unwrap()],
        &["time steps of the dynamic model", "each of 50.500 steps on 10 springs", "the budget is 2e10 time steps"],
    );
}

/// The number after "would take about " in a refusal.
fn estimate(err: &str) -> f64 {
    let at = err.find("would take about ").expect("an estimate") + "would take about ".len();
    err[at..].split(' ').next().unwrap().parse().expect("a number")
}

/// A shard is estimated at its own lives: `--life-range 0..2` of a scenario of 10⁷ lives (whose
/// whole run is refused at 3.72e11 waves) runs, and `merge` (which simulates nothing) is never
/// refused by a simulation estimate: it joins the shards, or names the lives missing.
#[test]
fn design_shard_of_a_ten_million_life_scenario_is_estimated_at_its_own_lives() {
    let dir = tempfile::tempdir().unwrap();
    let f = variant(dir.path(), "design_breakwater.toml", &[("lives = 5000", "lives = 10000000")]);
    let f = f.to_str().unwrap();
    refused(&["design", f], &["10000000 lives × 50 years", "the budget is 2e10 waves", "--life-range"]);
    let (a, b) = (dir.path().join("a"), dir.path().join("b"));
    for (range, out) in [("0..2", &a), ("2..4", &b)] {
        let o = caisson().args(["design", f, "--life-range", range, "--out", out.to_str().unwrap()]).output().unwrap();
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(o.status.success(), "{range}: {err}");
        assert!(!err.contains("would take"), "{err}");
    }
    let merged = dir.path().join("merged");
    let (sa, sb, m) = (a.to_str().unwrap(), b.to_str().unwrap(), merged.to_str().unwrap());
    let err = refused(&["merge", f, sa, sb, "--out", m], &["lives 4..10000000 are in no shard"]);
    assert!(!err.contains("would take"), "{err}");
    let o = caisson().args(["merge", f, sa, sb, "--out", m, "--lives", "4"]).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(merged.join("design.json").exists());
}

/// The disk estimate of `run --out` against the files written: at least their bytes (an estimate
/// below them would let a run past the budget) and at most 35 % more (25 bytes a number against
/// the 19-21 measured), on two `[load]` runs and on wave trains (realization 0, adaptive steps).
/// Measured: 1.22 (`table5_triangle`), 1.31 (`fifteen_waves`), 1.74 (`pari_breaking_loads`: 1.32
/// before the sticking phases' error was held per unit step, results version 25, which shortens
/// steps that still fall within one output interval, so fewer rows are written than steps).
#[test]
fn the_disk_estimate_of_run_out_covers_the_csv_files_written() {
    use caisson::analysis::work::{self, Histories};
    let mut checked = 0;
    for name in ["table5_triangle.toml", "fifteen_waves.toml", "pari_breaking_loads.toml"] {
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("out");
        let o = caisson().args(["run", &example(name), "--out", out.to_str().unwrap()]).output().unwrap();
        assert!(o.status.success(), "{name}");
        let written: u64 =
            ["history.csv", "springs.csv"].iter().map(|f| std::fs::metadata(out.join(f)).unwrap().len()).sum();
        let sc = caisson::scenario::load(std::path::Path::new(&example(name))).unwrap();
        let e = match sc.load {
            Some(_) => work::run(sc.structure(), sc.duration_s, Histories::Streamed),
            None => work::train(&sc.train_case().unwrap(), Histories::Streamed),
        };
        // Adaptive steps (the wave trains) give a row a step where steps are longer than the
        // output interval: the rows are counted from the pilot's steps (within 15 %) as if none
        // fell within one interval, an upper bound: 2 (the budget's estimate errs on the safe side).
        let high = if sc.load.is_some() { 1.35 } else { 2.0 };
        let ratio = e.disk_bytes / written as f64;
        assert!((1.0..high).contains(&ratio), "{name}: estimated {} bytes, wrote {written}", e.disk_bytes);
        if sc.load.is_some() {
            assert_eq!(e.memory_bytes, 0.0, "{name}: streamed histories hold no memory");
        }
        checked += 1;
    }
    assert_eq!(checked, 3);
}
