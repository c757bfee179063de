//! Issue 13 item 5, rough edges a new user hit: SVGs of any run under 1 MB (decimated lines),
//! `run --out` histories streamed (the same bytes as the whole-history writer), files of an
//! earlier run in a reused `--out` removed or named, and values of the wrong kind explained in
//! engineering words.

mod support;

use caisson::analysis::run::{run, History};
use caisson::scenario;
use std::path::Path;
use support::*;

fn files(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> =
        std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    v.sort();
    v
}

fn run_ok(args: &[&str]) -> String {
    let o = caisson().args(args).output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    assert_eq!(o.status.code(), Some(0), "{args:?}: {err}");
    err
}

/// Every SVG that the commands write for the bundled examples is under 1 MB (fifteen_waves'
/// springs.svg was 7.2 MB, `loads --history --waves 1030` 17.5 MB).
#[test]
fn every_svg_of_the_bundled_examples_is_under_a_megabyte() {
    let dir = tempfile::tempdir().unwrap();
    let out = |name: &str| dir.path().join(name).to_str().unwrap().to_string();
    let runs = [
        "table5_triangle.toml",
        "table5_series.toml",
        "fifteen_waves.toml",
        "prototype_breaking_wave.toml",
        "pari_breaking_loads.toml",
        "pari_nonbreaking_loads.toml",
        "breakwater_impact.toml",
    ];
    for (k, ex) in runs.iter().enumerate() {
        run_ok(&["run", &example(ex), "--out", &out(&format!("run{k}"))]);
    }
    run_ok(&["spectrum", &example("table5_triangle.toml"), "--out", &out("spectrum")]);
    run_ok(&["loads", &example("pari_breaking_loads.toml"), "--history", "--out", &out("loads")]);
    // The longest history `loads` writes (1030 waves, 500 000 rows).
    run_ok(&[
        "loads",
        &example("pari_breaking_loads.toml"),
        "--history",
        "--waves",
        "1030",
        "--out",
        &out("loads1030"),
    ]);
    run_ok(&["campaign", &example("pari_nonbreaking_campaign.toml"), "--out", &out("campaign")]);
    let mut checked = Vec::new();
    for sub in std::fs::read_dir(dir.path()).unwrap() {
        for f in std::fs::read_dir(sub.unwrap().path()).unwrap() {
            let p = f.unwrap().path();
            if p.extension().is_some_and(|e| e == "svg") {
                let size = std::fs::metadata(&p).unwrap().len();
                assert!(size < 1_000_000, "{}: {size} bytes", p.display());
                assert!(size > 10_000, "{}: {size} bytes, a plot with its lines", p.display());
                checked.push((p, size));
            }
        }
    }
    // run: 3 per [load] example (3), 4 per wave-train example of several waves (2), 3 per train of
    // one wave (2: no cumulative sliding to draw); spectrum 1, loads 2, campaign 2.
    assert_eq!(checked.len(), 3 * 3 + 4 * 2 + 3 * 2 + 1 + 2 + 2, "{checked:?}");
    for one_wave in ["run3", "run6"] {
        assert!(
            !dir.path().join(one_wave).join("sliding.svg").exists(),
            "{one_wave}: a one-wave run draws no cumulative sliding"
        );
    }
    // The largest of them before: fifteen_waves' springs.svg, now a few hundred kB.
    let fifteen = checked.iter().find(|(p, _)| p.ends_with("run2/springs.svg")).unwrap().1;
    assert!(fifteen < 500_000, "{fifteen}");
}

/// The histories written row by row are, byte for byte, what the whole-history writer made from
/// the library's `History` (the format of every earlier version: `{}` for times and forces in kN,
/// `{:e}` for displacements).
#[test]
fn streamed_histories_are_the_whole_history_files() {
    let dir = tempfile::tempdir().unwrap();
    let mut compared = 0;
    for ex in ["table5_triangle.toml", "table5_series.toml"] {
        let out = dir.path().join(ex);
        run_ok(&["run", &example(ex), "--out", out.to_str().unwrap()]);
        let sc = scenario::load(Path::new(&example(ex))).unwrap();
        let h = run(sc.structure(), sc.load.as_ref().unwrap(), sc.duration_s, true).unwrap().history.unwrap();
        assert!(h.len() > 500, "{} rows", h.len());
        assert_eq!(std::fs::read_to_string(out.join("history.csv")).unwrap(), history_csv(&h), "{ex}");
        assert_eq!(std::fs::read_to_string(out.join("springs.csv")).unwrap(), springs_csv(&h), "{ex}");
        compared += 2;
    }
    assert_eq!(compared, 4);
}

fn history_csv(h: &History) -> String {
    let mut s = String::from("time_s,ux_m,uy_m,theta_rad,vx_m_per_s,fx_kn,fy_kn,moment_knm,reaction_x_kn,reaction_y_kn,reaction_moment_knm,sliding_resistance_kn,sliding_springs\n");
    for k in 0..h.len() {
        s += &format!(
            "{},{:e},{:e},{:e},{:e},{},{},{},{},{},{},{},{}\n",
            h.t_s[k],
            h.ux_m[k],
            h.uy_m[k],
            h.theta_rad[k],
            h.vx_m_per_s[k],
            h.fx_n[k] / 1e3,
            h.fy_n[k] / 1e3,
            h.m_nm[k] / 1e3,
            h.reaction_x_n[k] / 1e3,
            h.reaction_y_n[k] / 1e3,
            h.reaction_m_nm[k] / 1e3,
            h.sliding_resistance_n[k] / 1e3,
            h.sliding_springs[k]
        );
    }
    s
}

fn springs_csv(h: &History) -> String {
    let n = h.springs();
    let mut cols = vec!["time_s".to_string()];
    cols.extend((1..=n).map(|i| format!("normal_{i}_kn")));
    cols.extend((1..=n).map(|i| format!("shear_{i}_kn")));
    cols.extend((1..=n).map(|i| format!("uy_{i}_m")));
    let mut s = cols.join(",") + "\n";
    for k in 0..h.len() {
        let mut row = vec![format!("{}", h.t_s[k])];
        row.extend(h.spring_forces_n[k * 2 * n..(k + 1) * 2 * n].iter().map(|v| format!("{}", v / 1e3)));
        row.extend(h.spring_uy_m[k * n..(k + 1) * n].iter().map(|v| format!("{v:e}")));
        s += &(row.join(",") + "\n");
    }
    s
}

/// A run that fails part-way (Newton-Raphson does not converge at the first step) leaves no
/// history file, no temporary file and no directory it created; in a directory of an earlier
/// run, that run's files stay as they were.
#[test]
fn a_failed_run_leaves_nothing_of_its_streamed_files() {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(example("table5_triangle.toml")).unwrap();
    let bad = write(
        dir.path(),
        "bad.toml",
        &text.replacen("dt_s = 1e-4", "dt_s = 1e-2\nmax_iterations = 1\nmax_substep_levels = 0", 1),
    );
    let nested = dir.path().join("new/out");
    let o = caisson().args(["run", bad.to_str().unwrap(), "--out", nested.to_str().unwrap()]).output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.contains("did not converge"), "{err}");
    assert!(!dir.path().join("new").exists(), "the directories it created are removed");
    let earlier = dir.path().join("earlier");
    run_ok(&["run", &example("table5_triangle.toml"), "--out", earlier.to_str().unwrap()]);
    let before: Vec<(String, Vec<u8>)> =
        files(&earlier).into_iter().map(|f| (f.clone(), std::fs::read(earlier.join(&f)).unwrap())).collect();
    assert_eq!(before.len(), 6);
    let o = caisson().args(["run", bad.to_str().unwrap(), "--out", earlier.to_str().unwrap()]).output().unwrap();
    assert_eq!(o.status.code(), Some(1));
    let after: Vec<(String, Vec<u8>)> =
        files(&earlier).into_iter().map(|f| (f.clone(), std::fs::read(earlier.join(&f)).unwrap())).collect();
    assert_eq!(before, after, "the earlier run's files are untouched, no temporary file is left");
}

/// A reused `--out`: the files of the command's own set that this run did not write are removed
/// (and said so); other commands' files and a design checkpoint are named in a `Warning:`; other
/// files are left alone and not named.
#[test]
fn files_of_an_earlier_run_are_removed_or_named() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let o = out.to_str().unwrap();
    // A wave-train run, then a [load] run: the trains' files go.
    run_ok(&["run", &example("pari_breaking_loads.toml"), "--out", o]);
    assert_eq!(files(&out).len(), 9, "{:?}", files(&out));
    write(&out, "notes.txt", "mine");
    let err = run_ok(&["run", &example("table5_triangle.toml"), "--out", o]);
    assert!(err.contains("Removed realizations.csv, waves.csv, sliding.svg from"), "{err}");
    assert!(!err.contains("notes.txt") && !err.contains("also holds"), "{err}");
    assert_eq!(
        files(&out),
        ["displacements.svg", "history.csv", "loads.svg", "notes.txt", "springs.csv", "springs.svg", "summary.json"]
    );
    // Another command into the same directory: the run's files are named, not removed; so is a
    // checkpoint (work to resume).
    write(&out, "checkpoint.jsonl", "{}\n");
    let err = run_ok(&["spectrum", &example("table5_triangle.toml"), "--tr-over-t0", "0.5:2:3", "--out", o]);
    let warning = err.lines().find(|l| l.contains("also holds")).unwrap_or_else(|| panic!("{err}"));
    assert!(warning.starts_with("Warning: "), "{warning}");
    for name in ["summary.json", "history.csv", "springs.csv", "loads.svg", "displacements.svg", "springs.svg"] {
        assert!(warning.contains(name), "{name}: {warning}");
    }
    assert!(
        warning.contains("(written by `caisson run`)")
            && warning.contains("checkpoint.jsonl (written by `caisson design`)")
    );
    assert!(!warning.contains("notes.txt") && !err.contains("Removed"), "{err}");
    assert_eq!(files(&out).len(), 7 + 1 + 3, "nothing removed: {:?}", files(&out));
    // `loads` with and then without --history: the history's files go, nothing else.
    let loads = dir.path().join("loads");
    let l = loads.to_str().unwrap();
    run_ok(&["loads", &example("pari_breaking_loads.toml"), "--history", "--out", l]);
    assert_eq!(files(&loads), ["loads.json", "wave_loads.csv", "wave_loads.svg"]);
    let err = run_ok(&["loads", &example("pari_breaking_loads.toml"), "--json", "--out", l]);
    assert!(err.contains("Removed wave_loads.csv, wave_loads.svg from"), "{err}");
    assert!(!err.contains("also holds"), "{err}");
    assert_eq!(files(&loads), ["loads.json"]);
    // The same command again: nothing to say.
    let err = run_ok(&["loads", &example("pari_breaking_loads.toml"), "--json", "--out", l]);
    assert!(!err.contains("Removed") && !err.contains("also holds"), "{err}");
}

/// A value of the wrong kind: exit 2 and a message that names the key, the kind it takes (with
/// its unit) and what was given; never serde's "invalid type: ..., expected f64".
#[test]
fn values_of_the_wrong_kind_are_explained() {
    let dir = tempfile::tempdir().unwrap();
    let table5 = std::fs::read_to_string(example("table5_triangle.toml")).unwrap();
    let design = std::fs::read_to_string(example("design_breakwater.toml")).unwrap();
    let fragility = std::fs::read_to_string(example("fragility.toml")).unwrap();
    let cases: &[(&str, &String, &str, &str, &[&str])] = &[
        // Numbers.
        (
            "run",
            &table5,
            "width_m = 0.78",
            "width_m = \"20\"",
            &["`[caisson] width_m` must be a number (m), got the string \"20\""],
        ),
        (
            "run",
            &table5,
            "e100_kpa = 3.5e5",
            "e100_kpa = \"3.5e5\"",
            &["`[foundation] e100_kpa` must be a number (kPa), got the string \"3.5e5\""],
        ),
        (
            "run",
            &table5,
            "peak_horizontal_kn = 12.0",
            "peak_horizontal_kn = true",
            &["`[load] peak_horizontal_kn` must be a number (kN), got true"],
        ),
        ("run", &table5, "dt_s = 1e-4", "dt_s = [1e-4]", &["`[solver] dt_s` must be a number (s), got a list"]),
        // Whole numbers.
        (
            "run",
            &table5,
            "springs = 10",
            "springs = 10.0",
            &["`[foundation] springs` must be a whole number, got 10.0"],
        ),
        (
            "design",
            &design,
            "lives = 5000",
            "lives = 2.5",
            &["`[design] lives` must be a whole number (or \"auto\": lives to `target_relative_error`), got 2.5"],
        ),
        (
            "fragility",
            &fragility,
            "storms = 100",
            "storms = \"100\"",
            &["`[fragility] storms` must be a whole number, got the string \"100\""],
        ),
        // Booleans.
        (
            "design",
            &design,
            "lives = 5000",
            "lives = 5000\nscreen = \"yes\"",
            &["`[design] screen` must be true or false", "got the string \"yes\""],
        ),
        (
            "run",
            &table5,
            "added_mass = true",
            "added_mass = 1",
            &["`[foundation] added_mass` must be true or false", "got 1"],
        ),
        // Text and lists.
        ("run", &table5, "kind = \"triangle\"", "kind = 3", &["`[load] kind` must be text in quotes, got 3"]),
        (
            "fragility",
            &fragility,
            "significant_heights_m = [7.0,",
            "significant_heights_m = [\"7\",",
            &["`[fragility] significant_heights_m` must be a list of numbers (m), got the string \"7\" in the list"],
        ),
    ];
    for (k, (cmd, base, from, to, needles)) in cases.iter().enumerate() {
        assert!(base.contains(from), "{from}");
        let p = write(dir.path(), &format!("case{k}.toml"), &base.replacen(from, to, 1));
        let err = refused(&[cmd, p.to_str().unwrap()], needles);
        let line =
            base.replacen(from, to, 1).lines().position(|l| l.starts_with(to.lines().last().unwrap())).unwrap() + 1;
        assert!(err.contains(&format!("case{k}.toml line {line}: ")), "{err}");
        assert!(!err.contains("invalid type") && !err.contains("expected f64"), "{err}");
    }
    assert_eq!(cases.len(), 11);
    // A table given as a value.
    let p = write(dir.path(), "table.toml", "caisson = 5\n");
    refused(&["run", p.to_str().unwrap()], &["`[caisson]` must be a table, got 5"]);
}
