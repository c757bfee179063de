//! Issue 37 (hardening, third round), through the binary: each finding's reproducer ends in exit 2
//! naming its key, or in a finished run whose outputs are finite and whose shards merge and resume;
//! and the remaining messages say what is wrong. The library's side:
//! `crates/caisson/tests/regress_bounded_inputs.rs`.

mod support;

use std::path::Path;
use support::{caisson, caisson_within, design_text, example, refused, s, workspace_root, write};

/// The longest run of digits in `text` (a number written out in full has hundreds).
fn longest_digits(text: &str) -> usize {
    text.split(|c: char| !c.is_ascii_digit()).map(str::len).max().unwrap_or(0)
}

/// Every data row of a `lives.csv` with every field a finite number; returns the rows.
fn finite_rows(dir: &Path) -> usize {
    let text = std::fs::read_to_string(dir.join("lives.csv")).unwrap();
    let mut rows = 0;
    for line in text.lines().skip(1) {
        for field in line.split(',') {
            let v: f64 = field.parse().unwrap_or(f64::NAN);
            assert!(v.is_finite(), "`{field}` in {line}");
        }
        rows += 1;
    }
    rows
}

fn example_text(name: &str) -> String {
    std::fs::read_to_string(example(name)).unwrap()
}

/// `text` with `from` replaced once by `to` (`from` must be there).
fn edited(text: &str, from: &str, to: &str) -> String {
    assert!(text.contains(from), "`{from}` is in the text");
    text.replacen(from, to, 1)
}

/// The example `name` with `from` replaced once by `to`, written to `dir` under its own name.
fn example_with(dir: &Path, name: &str, from: &str, to: &str) -> std::path::PathBuf {
    write(dir, name, &edited(&example_text(name), from, to))
}

/// Item 1, the issue's reproducer: the design example with untruncated errors and a friction COV
/// of 0.25. Life 4278 meets a storm whose friction multiplier is drawn below 0 (the full run of
/// 5000 lives ended in `internal error: ... expected_sliding_uncapped_m is inf`, and a shard of it
/// wrote `inf` to lives.csv and `null` to its checkpoint): the shard now finishes with finite
/// numbers, and resuming it reads its own checkpoint back.
#[test]
fn the_design_example_with_untruncated_friction_errors_writes_finite_shards_it_can_read_back() {
    let dir = tempfile::tempdir().unwrap();
    let text = edited(
        &example_text("design_breakwater.toml"),
        "tidal_range_m = 2.0",
        "tidal_range_m = 2.0\nerror_truncated = false\nfriction_cov = 0.25",
    );
    let file = write(dir.path(), "d.toml", &text);
    let shard = dir.path().join("shard");
    caisson_within(120).args(["design", s(&file), "--life-range", "4278..4279", "--out", s(&shard)]).assert().success();
    assert_eq!(finite_rows(&shard), 1);
    let csv = std::fs::read_to_string(shard.join("lives.csv")).unwrap();
    // Its rigid block slid without (almost) any friction: far beyond the failure limit, finitely.
    let rigid: f64 = csv.lines().nth(1).unwrap().split(',').nth(5).unwrap().parse().unwrap();
    assert!(rigid > 1e3, "{csv}");
    let checkpoint = std::fs::read_to_string(shard.join("checkpoint.jsonl")).unwrap();
    assert!(!checkpoint.contains("null") && !checkpoint.contains("inf"), "{checkpoint}");
    caisson_within(120)
        .args(["design", s(&file), "--life-range", "4278..4279", "--resume", "--out", s(&shard)])
        .assert()
        .success();
    assert_eq!(std::fs::read_to_string(shard.join("lives.csv")).unwrap(), csv, "the resumed shard is the same");
}

/// Item 1 on the small design, where nearly half the storms are frictionless (bias −0.9, COV 1,
/// untruncated): the run finishes with finite statistics, and two shards merge (and a stopped run
/// resumes) to its outputs byte for byte.
#[test]
fn frictionless_storms_finish_finite_and_their_shards_merge_and_resume() {
    let dir = tempfile::tempdir().unwrap();
    let file = write(
        dir.path(),
        "d.toml",
        &design_text(6, 3, "error_truncated = false\nfriction_bias = -0.9\nfriction_cov = 1.0"),
    );
    let full = dir.path().join("full");
    let o = caisson().args(["design", s(&file), "--json", "--out", s(&full)]).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let json: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let uncapped = json["rigid_block"]["expected_sliding_uncapped_m"].as_f64().unwrap();
    assert!(uncapped.is_finite() && uncapped > 1e3, "{uncapped}");
    assert_eq!(finite_rows(&full), 6);
    let (a, b, merged) = (dir.path().join("a"), dir.path().join("b"), dir.path().join("merged"));
    for (range, d) in [("0..4", &a), ("4..6", &b)] {
        caisson().args(["design", s(&file), "--life-range", range, "--out", s(d)]).assert().success();
    }
    caisson().args(["merge", s(&file), s(&a), s(&b), "--out", s(&merged)]).assert().success();
    let resumed = dir.path().join("resumed");
    caisson().args(["design", s(&file), "--stop-after", "2", "--threads", "1", "--out", s(&resumed)]).assert().code(1);
    caisson().args(["design", s(&file), "--resume", "--out", s(&resumed)]).assert().success();
    for name in ["design.json", "lives.csv"] {
        let want = std::fs::read(full.join(name)).unwrap();
        assert!(std::fs::read(merged.join(name)).unwrap() == want, "merged {name}");
        assert!(std::fs::read(resumed.join(name)).unwrap() == want, "resumed {name}");
    }
}

/// Item 1: `[waves] rigid_block_mu = 6e-301` slid the block 4.7e299 m, exit 0.
#[test]
fn rigid_block_mu_6e_301_exits_2_naming_the_key() {
    let dir = tempfile::tempdir().unwrap();
    let text = edited(
        &example_text("design_breakwater.toml"),
        "period_s = 12.8\n",
        "period_s = 12.8\nrigid_block_mu = 6e-301\n",
    );
    let f = write(dir.path(), "d.toml", &text);
    refused(&["design", s(&f), "--lives", "2"], &["`[waves] rigid_block_mu` = 6e-301", "between 1e-6 and 2"]);
}

/// Item 3: the foundation's keys without bounds reached the solver: NaN residuals (exit 1) or a
/// settlement of 8.24e200 m printed in 200 digits (exit 0). Each is refused naming its key, in
/// short numbers, under every command the issue named.
#[test]
fn foundation_keys_beyond_their_ranges_exit_2_naming_the_key_under_every_command() {
    let dir = tempfile::tempdir().unwrap();
    for csv in ["forces_example.csv", "fifteen_waves.csv"] {
        std::fs::copy(workspace_root().join("examples").join(csv), dir.path().join(csv)).unwrap();
    }
    let soil = "e100_kpa = 3.5e5";
    let cases = [
        ("fifteen_waves.toml", "run", "reference_stress_kpa = 1e-300", "[foundation] reference_stress_kpa"),
        ("fragility.toml", "fragility", "kx_kn_per_m = 5e-324", "[foundation] kx_kn_per_m"),
        ("size_breakwater.toml", "size", "kx_kn_per_m = 5e-324", "[foundation] kx_kn_per_m"),
        ("table5_triangle.toml", "run", "ky_kn_per_m = 1e300", "[foundation] ky_kn_per_m"),
        ("table5_triangle.toml", "run", "damping_kns_per_m = 1e300", "[foundation] damping_kns_per_m"),
        ("table5_triangle.toml", "run", "ky_kn_per_m = 1e-200", "[foundation] ky_kn_per_m"),
    ];
    for (name, cmd, line, key) in cases {
        let f = example_with(dir.path(), name, soil, &format!("{soil}\n{line}"));
        let named = format!("`{key}` = ");
        let mut needles = vec![named.as_str()];
        if !key.ends_with("reference_stress_kpa") {
            needles.push("per metre of caisson length");
        }
        let err = refused(&[cmd, s(&f)], &needles);
        assert!(longest_digits(&err) <= 17, "{err}");
    }
}

/// Item 4: a 1 m wide, 24.5 m tall caisson (the example's weight): life 1898 met a wave that
/// rotated it 0.18 rad, where the engine stopped converging, and every life ran before the run
/// failed (exit 1, with advice about `dt_s`). The life now ends there, failed by rotation.
#[test]
fn a_slender_caisson_finishes_its_lives_failed_by_rotation() {
    let dir = tempfile::tempdir().unwrap();
    let f = example_with(dir.path(), "design_breakwater.toml", "width_m = 20.0", "width_m = 1.0");
    let shard = dir.path().join("shard");
    caisson_within(120).args(["design", s(&f), "--life-range", "1898..1900", "--out", s(&shard)]).assert().success();
    assert_eq!(finite_rows(&shard), 2);
    let csv = std::fs::read_to_string(shard.join("lives.csv")).unwrap();
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    let column = |name: &str| header.iter().position(|h| *h == name).unwrap_or_else(|| panic!("no {name}"));
    let (rotation, by_rotation) = (column("max_rotation_rad"), column("failed_by_rotation"));
    let mut checked = 0;
    for line in csv.lines().skip(1) {
        let cells: Vec<&str> = line.split(',').collect();
        let max_rotation_rad: f64 = cells[rotation].parse().unwrap();
        assert!(max_rotation_rad > 0.01 && cells[by_rotation] == "1", "failed by rotation: {line}");
        checked += 1;
    }
    assert_eq!(checked, 2);
}

/// Item 4: `storm_shape` from 0.1 put the 50-year storm near 10⁵ m; such a tail is refused.
#[test]
fn a_storm_shape_of_0_12_exits_2_naming_the_key() {
    let dir = tempfile::tempdir().unwrap();
    let f = example_with(dir.path(), "design_breakwater.toml", "storm_shape = 1.4 ", "storm_shape = 0.12 ");
    let err = refused(&["design", s(&f)], &["`[design] storm_shape` = 0.12", "10 000-year storm", "1.30e8 m"]);
    assert!(longest_digits(&err) <= 17, "{err}");
}

/// Item 5: `[fragility] significant_heights_m` containing 1e-300 gave a safety factor of 1.5e301.
#[test]
fn a_fragility_height_of_1e_300_exits_2_naming_the_key() {
    let dir = tempfile::tempdir().unwrap();
    let f = example_with(
        dir.path(),
        "fragility.toml",
        "significant_heights_m = [7.0,",
        "significant_heights_m = [1e-300, 7.0,",
    );
    refused(&["fragility", s(&f)], &["`[fragility] significant_heights_m[0]` = 1e-300", "≥ 0.001"]);
}

/// Item 6: control characters in a campaign title made both SVG plots invalid XML (exit 0) and
/// reached the terminal raw: the title is refused where it enters.
#[test]
fn a_campaign_title_with_control_characters_exits_2_naming_the_key() {
    let dir = tempfile::tempdir().unwrap();
    let text = example_text("pari_breaking_campaign.toml");
    let title = "title = \"PARI breaking tests (seed Table 4, d = 0.4 m)\"";
    let f = write(dir.path(), "c.toml", &edited(&text, title, "title = \"PARI\\u001b[31m red\\ttab\""));
    let err = refused(&["campaign", s(&f)], &["`[campaign] title`", "control characters"]);
    assert!(!err.contains('\u{1b}') && !err.contains('\t'), "shown escaped: {err:?}");
}

/// Item 7: a stray `[campaign]` made `run` and `spectrum` answer "a campaign runs wave trains…",
/// a stray `[size]` "missing key `[design]`": each table is read by its command only.
#[test]
fn a_stray_campaign_or_size_table_is_for_its_command_only() {
    let dir = tempfile::tempdir().unwrap();
    let table5 = example_text("table5_triangle.toml");
    let campaign = write(dir.path(), "c.toml", &format!("{table5}\n[campaign]\nheights_m = [0.1]\n"));
    caisson().args(["run", s(&campaign)]).assert().success();
    caisson().args(["spectrum", s(&campaign), "--tr-over-t0", "0.5:2:3"]).assert().success();
    refused(&["campaign", s(&campaign)], &["remove the [load] table"]);
    let size = write(dir.path(), "s.toml", &format!("{table5}\n[size]\nrange_m = [10.0, 30.0]\n"));
    caisson().args(["run", s(&size)]).assert().success();
    refused(&["size", s(&size)], &["missing key `[design]`", "a [size] table sizes a design"]);
}

/// Item 7: the messages of values far out of range: `dt_s = 1e-23` blamed `dt_min_s`, which the
/// file did not give, with an empty range in full decimals; `tolerance_m`'s bound printed as
/// 0.000003071000000000001; a series of 1e308 was "inf kN"; a 20-digit seed was "number too large
/// to fit in target type" without the range.
#[test]
fn out_of_range_values_are_named_with_their_bounds_in_short_numbers() {
    let dir = tempfile::tempdir().unwrap();
    let design = example_text("design_breakwater.toml");
    let f = write(dir.path(), "dt.toml", &edited(&design, "dt_s = 1e-3 ", "dt_s = 1e-23 "));
    refused(&["design", s(&f)], &["`[solver] dt_s` = 1e-23: must be at least 1e-9 (s) with adaptive stepping"]);
    let f = example_with(dir.path(), "size_breakwater.toml", "tolerance_m = 0.25", "tolerance_m = 3e-9");
    let err = refused(&["size", s(&f)], &["`[size] tolerance_m` = 3e-9", "> 1.4e-5 and ≤ 14 (m"]);
    assert!(longest_digits(&err) <= 17, "{err}");
    std::fs::write(dir.path().join("big.csv"), "time_s,fx_kn,fy_kn,moment_knm\n0,1e308,0,0\n1,0,0,0\n").unwrap();
    let series = edited(&example_text("table5_series.toml"), "file = \"forces_example.csv\"", "file = \"big.csv\"");
    let f = write(dir.path(), "series.toml", &series);
    let err = refused(&["run", s(&f)], &["big.csv: line 2: column `fx_kn` has `1e308`", "at most 1e300"]);
    assert!(!err.contains("inf"), "{err}");
    let f = write(dir.path(), "seed.toml", &edited(&design, "seed = 1\n", "seed = 99999999999999999999\n"));
    refused(&["design", s(&f)], &["`[design] seed` = 99999999999999999999", "at most 9223372036854775807"]);
    let f = write(dir.path(), "seed2.toml", &edited(&design, "seed = 1\n", "seed = -5\n"));
    refused(&["design", s(&f)], &["`[design] seed` = -5", "from 0 to 9223372036854775807"]);
}

/// Item 7: line ends. A checkpoint converted to CR LF was "not a life line"; a scenario with
/// carriage returns alone got the parser's bare "expected newline". (CR LF scenario and series
/// files are read as they are.)
#[test]
fn converted_line_ends_are_named_as_such() {
    let dir = tempfile::tempdir().unwrap();
    let file = write(dir.path(), "d.toml", &design_text(3, 3, ""));
    let out = dir.path().join("out");
    caisson().args(["design", s(&file), "--out", s(&out)]).assert().success();
    let cp = out.join("checkpoint.jsonl");
    std::fs::write(&cp, std::fs::read_to_string(&cp).unwrap().replace('\n', "\r\n")).unwrap();
    refused(&["design", s(&file), "--resume", "--out", s(&out)], &["line 1 ends in CR LF", "dos2unix"]);
    let table5 = example_text("table5_triangle.toml");
    let crlf = write(dir.path(), "crlf.toml", &table5.replace('\n', "\r\n"));
    caisson().args(["run", s(&crlf)]).assert().success();
    let cr = write(dir.path(), "cr.toml", &table5.replace('\n', "\r"));
    refused(&["run", s(&cr)], &["cr.toml line 1", "carriage return (CR) without a line feed"]);
}

/// Item 7: `merge` named a shard by the range in its header, which a `--resume` for other lives
/// leaves as it was: it names the lives the shard holds.
#[test]
fn merge_names_a_shard_by_the_lives_it_holds() {
    let dir = tempfile::tempdir().unwrap();
    let file = write(dir.path(), "d.toml", &design_text(10, 3, ""));
    let (a, b) = (dir.path().join("a"), dir.path().join("b"));
    caisson().args(["design", s(&file), "--life-range", "0..4", "--out", s(&a)]).assert().success();
    // Resumed for lives 4..8: the checkpoint holds 0..8, its header still says 0..4.
    caisson().args(["design", s(&file), "--life-range", "4..8", "--resume", "--out", s(&a)]).assert().success();
    caisson().args(["design", s(&file), "--life-range", "6..10", "--out", s(&b)]).assert().success();
    let merged = dir.path().join("m");
    refused(
        &["merge", s(&file), s(&a), s(&b), "--out", s(&merged)],
        &["life 6 is in two shards", "(holding lives 0..8)", "(holding lives 6..10)"],
    );
}

/// Item 7: Ctrl-C left a new, empty `--out` directory behind (and the parents it created).
#[cfg(unix)]
#[test]
fn ctrl_c_leaves_no_new_empty_out_directory() {
    use std::time::{Duration, Instant};
    let dir = tempfile::tempdir().unwrap();
    let long = example_with(dir.path(), "table5_triangle.toml", "duration_s = 0.6", "duration_s = 300");
    let parent = dir.path().join("new");
    let out = parent.join("out");
    let mut child = std::process::Command::new(assert_cmd::cargo::cargo_bin("caisson"))
        .args(["run", s(&long), "--out", s(&out)])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    // The directory exists once the run has taken its lock.
    let start = Instant::now();
    while !out.join(".caisson.lock").exists() {
        assert!(start.elapsed() < Duration::from_secs(30), "the run took its --out");
        std::thread::sleep(Duration::from_millis(10));
    }
    std::thread::sleep(Duration::from_millis(200));
    assert!(std::process::Command::new("kill").args(["-INT", &child.id().to_string()]).status().unwrap().success());
    let status = child.wait().unwrap();
    assert_eq!(status.code(), Some(130));
    assert!(
        !parent.exists(),
        "the run's new directories are gone: {:?}",
        std::fs::read_dir(dir.path()).unwrap().count()
    );
}
