//! `caisson fragility`: the JSON contract of docs/fragility.md, probabilities that rise with the
//! wave height, thread-count determinism, the output files, the shipped example, and keyed errors
//! for `[fragility]` (exit code 2, `Error:` naming the key, nothing written).

mod support;

use serde_json::Value;
use std::path::Path;
use support::{caisson, site, write};

/// The prototype caisson of examples/fragility.toml made lighter (W' = 5000 kN/m instead of
/// 6200: Goda's static sliding safety factor about 0.85 once the waves reach the breaking limit
/// at the wall), with storms of 0.1 h (28 waves). The heights are 3 m apart: at 3 and 6 m no wave
/// can slide the caisson (every storm is screened or slides by millimetres), at 12 and 15 m every
/// storm has several waves at the breaking limit, each sliding it by centimetres, and only 9 m is
/// in the transition. The probabilities then rise from 0 to 1 with H1/3 by far more than the
/// sampling noise of 8 storms (seeds 1-6 all give non-decreasing counts), so the test does not
/// depend on a lucky seed. The storms carry no load-model or friction errors (`errors = false`):
/// a storm drawn with a low force factor may slide less than 5 cm at 15 m, which would blur the
/// 0-to-1 rise this test counts on (the errors have tests of their own in `analysis::fragility`).
fn base() -> String {
    let site = site::without(site::SMALL_DESIGN, "design", &[]);
    let site = site::with(&site, "caisson", "weight_in_water_kn = 5000.0");
    site::with(
        &site,
        "fragility",
        "significant_heights_m = [3.0, 6.0, 9.0, 12.0, 15.0]\nstorms = 8\nlimits_m = [0.05, 0.2]\nstorm_duration_h = 0.1\nseed = 1\nerrors = false",
    )
}

/// `base()` with one exact piece of text replaced (panics if it is not there).
fn edit(from: &str, to: &str) -> String {
    let base = base();
    assert!(base.contains(from), "test bug: `{from}` is not in the base file");
    base.replacen(from, to, 1)
}

fn run_json(dir: &Path, text: &str, threads: &str) -> (String, Value) {
    let f = write(dir, "fragility.toml", text);
    let out = caisson().args(["fragility", f.to_str().unwrap(), "--json", "--threads", threads]).output().unwrap();
    assert!(out.status.success(), "stderr:\n{}", String::from_utf8_lossy(&out.stderr));
    let s = String::from_utf8(out.stdout).unwrap();
    let v = serde_json::from_str(&s).unwrap();
    (s, v)
}

fn finite(v: &Value, what: &str) -> f64 {
    let x = v.as_f64().unwrap_or_else(|| panic!("{what} is not a number: {v}"));
    assert!(x.is_finite(), "{what} = {x}");
    x
}

#[test]
fn json_contract_and_probabilities_rising_with_height() {
    let dir = tempfile::tempdir().unwrap();
    let (_, v) = run_json(dir.path(), &base(), "0");
    for key in ["period_s", "storm_duration_h", "hmax_ratio", "rigid_block_mu"] {
        finite(&v[key], key);
    }
    assert_eq!(v["scenario"], "fragility.toml");
    assert_eq!(v["waves_per_storm"], 28);
    assert_eq!(v["storms"], 8);
    assert_eq!(v["seed"], 1);
    assert_eq!(v["limits_m"], serde_json::json!([0.05, 0.2]));
    assert_eq!(v["failure_rotation_rad"], 0.01);
    finite(&v["design_wave"]["goda_sliding_safety_factor"], "design_wave.goda_sliding_safety_factor");
    let levels = v["levels"].as_array().unwrap();
    assert_eq!(levels.len(), 5);
    let mut previous = [[0.0_f64; 2]; 2];
    for (i, l) in levels.iter().enumerate() {
        assert_eq!(finite(&l["significant_height_m"], "height"), [3.0, 6.0, 9.0, 12.0, 15.0][i]);
        // Goda's design-wave H_max: at most 1.8 H1/3, and inside the surf zone of the 20 m toe
        // (H1/3 ≥ 9 m here) the breaking limit, below 1.7 H1/3.
        let (h13, hmax) = ([3.0, 6.0, 9.0, 12.0, 15.0][i], finite(&l["hmax_m"], "hmax_m"));
        let low = if h13 >= 9.0 { 1.0 } else { 1.7 };
        let high = if h13 >= 9.0 { 1.7 } else { 1.8 };
        assert!(hmax > low * h13 && hmax <= high * h13 + 1e-12, "H1/3 {h13} m: H_max {hmax} m");
        for key in [
            "mean_sliding_m",
            "max_sliding_m",
            "mean_rigid_block_sliding_m",
            "max_rigid_block_sliding_m",
            "screened_share",
            "simulated_waves",
            "goda_sliding_safety_factor",
        ] {
            assert!(finite(&l[key], key) >= 0.0, "{key}");
        }
        assert_eq!(l["storms"], 8);
        assert_eq!(l["storm_sliding_m"].as_array().unwrap().len(), 8);
        assert_eq!(l["storm_rigid_block_sliding_m"].as_array().unwrap().len(), 8);
        let rotations: Vec<f64> =
            l["storm_max_rotation_rad"].as_array().unwrap().iter().map(|r| r.as_f64().unwrap()).collect();
        assert_eq!(rotations.len(), 8);
        let rotated = rotations.iter().filter(|&&r| r > 0.01).count() as u64;
        assert_eq!(l["rotation_failures"].as_u64(), Some(rotated));
        let ex = l["exceedance"].as_array().unwrap();
        assert_eq!(ex.len(), 2);
        for (j, e) in ex.iter().enumerate() {
            assert_eq!(finite(&e["limit_m"], "limit_m"), [0.05, 0.2][j]);
            for (m, model) in ["dynamic", "rigid_block"].iter().enumerate() {
                let p = finite(&e[format!("{model}_probability")], "probability");
                let k = e[format!("{model}_count")].as_u64().unwrap();
                assert!((0.0..=1.0).contains(&p));
                assert_eq!(p, k as f64 / 8.0);
                // The counts agree with the storm slidings (and, for the dynamic model, a storm
                // that rotated beyond the limit exceeds every limit).
                let key = if m == 0 { "storm_sliding_m" } else { "storm_rigid_block_sliding_m" };
                let by_hand = l[key]
                    .as_array()
                    .unwrap()
                    .iter()
                    .zip(&rotations)
                    .filter(|(s, &r)| s.as_f64().unwrap().abs() > [0.05, 0.2][j] || (m == 0 && r > 0.01))
                    .count() as u64;
                assert_eq!(k, by_hand);
                assert!(
                    p >= previous[m][j],
                    "P({model} > {}) falls from {} to {p} at level {i}",
                    [0.05, 0.2][j],
                    previous[m][j]
                );
                previous[m][j] = p;
            }
        }
    }
    // From none at the lowest height to all at the highest (the configuration is chosen so).
    assert_eq!(levels[0]["exceedance"][0]["dynamic_count"], 0);
    assert_eq!(levels[4]["exceedance"][0]["dynamic_count"], 8);
    let fits = v["fits"].as_array().unwrap();
    assert_eq!(fits.len(), 2);
    for f in fits {
        finite(&f["limit_m"], "limit_m");
        for model in ["dynamic", "rigid_block"] {
            let x = &f[model];
            if x["fitted"].as_bool().unwrap() {
                let median = finite(&x["median_m"], "median_m");
                assert!((3.0..=15.0).contains(&median), "median {median}");
                for key in ["beta", "ln_median_se", "beta_se"] {
                    assert!(finite(&x[key], key) > 0.0);
                }
                finite(&x["log_likelihood"], "log_likelihood");
                // The 95 % intervals hold their estimate (an open end is null).
                for (key, value) in [("median_ci95_m", median), ("beta_ci95", finite(&x["beta"], "beta"))] {
                    let [lo, hi] = [0, 1].map(|i| x[key][i].as_f64());
                    assert_eq!(x[key].as_array().map(Vec::len), Some(2), "{key}: {}", x[key]);
                    assert!(lo.is_none_or(|lo| lo < value) && hi.is_none_or(|hi| value < hi), "{key}: {}", x[key]);
                }
            } else {
                let reason = x["reason"].as_str().unwrap();
                assert!(["no-exceedance", "all-exceed", "separated", "at-bounds"].contains(&reason), "{reason}");
                assert!(!x["message"].as_str().unwrap().is_empty());
            }
        }
    }
}

#[test]
fn results_do_not_depend_on_the_thread_count() {
    let dir = tempfile::tempdir().unwrap();
    let (one, _) = run_json(dir.path(), &base(), "1");
    let (two, _) = run_json(dir.path(), &base(), "2");
    assert_eq!(one, two);
}

#[test]
fn out_writes_json_csv_and_svg() {
    let dir = tempfile::tempdir().unwrap();
    let f = write(dir.path(), "fragility.toml", &base());
    let out = dir.path().join("out");
    let o = caisson().args(["fragility", f.to_str().unwrap(), "--out", out.to_str().unwrap()]).output().unwrap();
    assert!(o.status.success(), "stderr:\n{}", String::from_utf8_lossy(&o.stderr));
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(text.contains("P(S > 0.05 m)") && text.contains("Lognormal fits"), "{text}");
    let json: Value = serde_json::from_str(&std::fs::read_to_string(out.join("fragility.json")).unwrap()).unwrap();
    assert_eq!(json["levels"].as_array().unwrap().len(), 5);
    let csv = std::fs::read_to_string(out.join("fragility.csv")).unwrap();
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(lines.len(), 1 + 5 * 2, "a header and one row per (height, limit)");
    assert!(lines[0].starts_with(
        "significant_height_m,hmax_m,storms,limit_m,dynamic_count,dynamic_probability,dynamic_fitted_probability"
    ));
    assert!(!csv.contains("NaN") && !csv.to_lowercase().contains("inf"));
    let svg = std::fs::read_to_string(out.join("fragility.svg")).unwrap();
    assert!(svg.starts_with("<svg"));
    // One panel per limit, both models on it.
    for label in ["P(S &gt; 0.05 m)", "P(S &gt; 0.2 m)", "dynamic model: storms", "rigid block: storms"] {
        assert!(svg.contains(label), "no `{label}` in the plot");
    }
    let mut names: Vec<String> =
        std::fs::read_dir(&out).unwrap().map(|e| e.unwrap().file_name().into_string().unwrap()).collect();
    names.sort();
    assert_eq!(names, ["fragility.csv", "fragility.json", "fragility.svg"]);
}

#[test]
fn the_shipped_example_runs_with_fewer_storms() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let text = std::fs::read_to_string(root.join("examples/fragility.toml")).unwrap();
    let fewer: String =
        text.lines().map(|l| if l.starts_with("storms = ") { "storms = 2" } else { l }).collect::<Vec<_>>().join("\n");
    assert_ne!(fewer, text.trim_end(), "the example's storms line changed; update this test");
    let dir = tempfile::tempdir().unwrap();
    let (_, v) = run_json(dir.path(), &fewer, "0");
    assert_eq!(v["levels"].as_array().unwrap().len(), 9);
    let sf = finite(&v["design_wave"]["goda_sliding_safety_factor"], "design SF");
    assert!(
        (1.15..1.3).contains(&sf),
        "the example's design wave should have a static sliding safety factor of about 1.2, not {sf}"
    );
}

/// Bad input: exit code 2, `Error:` naming `key`, no panic, nothing on stdout, `out` not created.
fn bad(text: &str, key: &str) {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "fragility.toml", text);
    let out = caisson().current_dir(dir.path()).args(["fragility", "fragility.toml", "--out", "out"]).output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).to_string();
    assert_eq!(out.status.code(), Some(2), "exit code for `{key}`; stderr:\n{stderr}");
    assert!(stderr.starts_with("Error:"), "{stderr}");
    assert!(stderr.contains(key), "`{key}` not named in:\n{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert!(out.stdout.is_empty(), "stdout: {}", String::from_utf8_lossy(&out.stdout));
    let names: Vec<_> = std::fs::read_dir(dir.path()).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(names, ["fragility.toml"], "something was written");
}

#[test]
fn bad_inputs_name_their_key_and_write_nothing() {
    let heights = "significant_heights_m = [3.0, 6.0, 9.0, 12.0, 15.0]";
    bad(&edit(heights, "significant_heights_m = [3.0, 9.0, 6.0]"), "[fragility] significant_heights_m[2]");
    bad(&edit(heights, "significant_heights_m = [3.0, -6.0]"), "[fragility] significant_heights_m[1]");
    bad(&edit(heights, "significant_heights_m = [3.0, 60.0]"), "[fragility] significant_heights_m[1]");
    bad(&edit(heights, "significant_heights_m = []"), "[fragility] significant_heights_m");
    bad(&edit(heights, ""), "[fragility] significant_heights_m");
    bad(&edit("storms = 8", "storms = 0"), "[fragility] storms");
    bad(&edit("storms = 8", "storms = 8\nfailure_rotation_rad = 0.0"), "[fragility] failure_rotation_rad");
    bad(&edit("storms = 8", "storms = 2.5"), "storms");
    bad(&edit("limits_m = [0.05, 0.2]", "limits_m = [0.05, -0.2]"), "[fragility] limits_m[1]");
    bad(&edit("limits_m = [0.05, 0.2]", "limits_m = [0.2, 0.05]"), "[fragility] limits_m[1]");
    bad(&edit("storm_duration_h = 0.1", "storm_duration_h = 0"), "[fragility] storm_duration_h");
    bad(&edit("storm_duration_h = 0.1", "storm_duration_h = 0.1\nperiod_s = nan"), "[fragility] period_s");
    bad(&edit("seed = 1", "seed = -1"), "[fragility] seed");
    bad(&edit("seed = 1", "seed = 1\nscreen = false"), "screen");
    bad(&base()[..base().find("[fragility]").unwrap()], "[fragility]");
    bad(
        &edit("kind = \"irregular\"\nsignificant_height_m = 7.5", "kind = \"regular\"\nheight_m = 7.5"),
        "[waves] kind",
    );
    bad(&edit("period_s = 12.8\n[solver]", "period_s = 12.8\nseed = 4\n[solver]"), "[waves] seed");
    bad(&edit("weight_in_water_kn = 5000.0", "weight_in_water_kn = -5000.0"), "[caisson] weight_in_water_kn");
    // A file that is not there.
    let dir = tempfile::tempdir().unwrap();
    let out = caisson().current_dir(dir.path()).args(["fragility", "nothere.toml"]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).starts_with("Error:"));
}
