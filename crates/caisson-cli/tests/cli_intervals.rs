//! Issue 35, item 1: every Monte Carlo statistic of `design.json` and `size.json` with its
//! precision, checked against hand formulas computed here from the lives the run wrote
//! (`lives.csv`), not with the library's estimators:
//!
//! * a mean's standard error is the sample standard deviation of the lives' values (n − 1 in the
//!   denominator) over √n, its interval the mean ± 1.959964 standard errors;
//! * a probability k/n has the Wilson (1927) score interval
//!   (p̂ + z²/2n ± z √(p̂(1 − p̂)/n + z²/4n²)) / (1 + z²/n);
//! * a percentile's interval is the pair of order statistics (l, u) with l the largest rank whose
//!   binomial distribution function F(l − 1) ≤ 0.025 and u the smallest with F(u − 1) ≥ 0.975.

mod support;

use serde_json::Value;
use support::{caisson, example, write};

/// z = Φ⁻¹(0.975) (tables: 1.959963984540054).
const Z: f64 = 1.959_963_984_540_054;

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

fn pair(v: &Value) -> [f64; 2] {
    let a = v.as_array().unwrap_or_else(|| panic!("not a [low, high] pair: {v}"));
    assert_eq!(a.len(), 2, "{v}");
    [num(&a[0]), num(&a[1])]
}

fn close(got: f64, want: f64, what: &str) {
    // The library sums in another order: agreement to 1e-12 relative (1e-15 absolute at 0).
    assert!((got - want).abs() <= 1e-12 * want.abs() + 1e-15, "{what}: {got} vs by hand {want}");
}

/// Mean and s/√n of `xs`, two passes.
fn mean_se(xs: &[f64]) -> (f64, f64) {
    let n = xs.len() as f64;
    let mean = xs.iter().sum::<f64>() / n;
    let var = xs.iter().map(|x| (x - mean) * (x - mean)).sum::<f64>() / (n - 1.0);
    (mean, (var / n).sqrt())
}

fn wilson(k: usize, n: usize) -> [f64; 2] {
    let (p, n) = (k as f64 / n as f64, n as f64);
    let centre = p + Z * Z / (2.0 * n);
    let half = Z * (p * (1.0 - p) / n + Z * Z / (4.0 * n * n)).sqrt();
    let d = 1.0 + Z * Z / n;
    [((centre - half) / d).max(0.0), ((centre + half) / d).min(1.0)]
}

/// The ranks (1-based) of the order-statistic interval of the q-quantile of n values, from the
/// binomial pmf in logarithms: ln C(n, r) as a sum of logarithms.
fn ranks(n: usize, q: f64) -> (usize, usize) {
    let ln_pmf = |r: usize| {
        let ln_c: f64 = (1..=r).map(|i| ((n - r + i) as f64 / i as f64).ln()).sum();
        ln_c + r as f64 * q.ln() + (n - r) as f64 * (1.0 - q).ln()
    };
    let (mut cdf, mut lower, mut upper) = (0.0, 0, 0);
    for r in 0..=n {
        cdf += ln_pmf(r).exp();
        if cdf <= 0.025 {
            lower = r + 1;
        }
        if cdf >= 0.975 {
            upper = r + 1;
            break;
        }
    }
    (lower, upper)
}

/// The design example over 400 lives: every interval of `design.json` of the dynamic model
/// against the hand formulas on `lives.csv` (|S| of each life; a failed life, by any mode, at the
/// 5 m limit for the capped statistics), and the text prints E|S| with the digits its interval
/// supports.
#[test]
fn design_intervals_are_the_hand_formulas_on_lives_csv() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let o = caisson()
        .args(["design", &example("design_breakwater.toml"), "--lives", "400", "--out", out.to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let text = String::from_utf8_lossy(&o.stdout).to_string();
    let j: Value = serde_json::from_str(&std::fs::read_to_string(out.join("design.json")).unwrap()).unwrap();
    let mut reader = csv::Reader::from_path(out.join("lives.csv")).unwrap();
    let header = reader.headers().unwrap().clone();
    let col = |name: &str| header.iter().position(|h| h == name).unwrap_or_else(|| panic!("no column {name}"));
    let (s, fs, fr, fh) =
        (col("sliding_m"), col("failed_by_sliding"), col("failed_by_rotation"), col("failed_by_heel_pressure"));
    let mut lives: Vec<(f64, bool)> = Vec::new();
    for row in reader.records() {
        let row = row.unwrap();
        let failed = [fs, fr, fh].iter().any(|&c| row[c].parse::<u8>().unwrap() != 0);
        lives.push((row[s].parse::<f64>().unwrap().abs(), failed));
    }
    let n = lives.len();
    assert_eq!(n, 400);
    let limit = num(&j["failure_sliding_m"]);
    assert_eq!(limit, 5.0);
    let failures = lives.iter().filter(|l| l.1).count();
    assert!(failures >= 10, "the example fails some lives ({failures}): the test needs them");
    let d = &j["dynamic"];

    // Means: capped, as simulated, per year, the surviving lives.
    let capped: Vec<f64> = lives.iter().map(|&(m, f)| if f { limit } else { m }).collect();
    let uncapped: Vec<f64> = lives.iter().map(|l| l.0).collect();
    let surviving: Vec<f64> = lives.iter().filter(|l| !l.1).map(|l| l.0).collect();
    let years = num(&j["life_years"]);
    let mut checked = 0;
    for (values, group, key, scale) in [
        (&capped, d, "expected_sliding", 1.0),
        (&uncapped, d, "expected_sliding_uncapped", 1.0),
        (&capped, d, "expected_sliding_per_year", years),
        (&surviving, &d["surviving"], "expected_sliding", 1.0),
    ] {
        let (mean, se) = mean_se(values);
        let (mean, se) = (mean / scale, se / scale);
        close(num(&group[format!("{key}_m")]), mean, key);
        close(num(&group[format!("{key}_standard_error_m")]), se, key);
        let ci = pair(&group[format!("{key}_ci95_m")]);
        close(ci[0], mean - Z * se, key);
        close(ci[1], mean + Z * se, key);
        checked += 1;
    }
    assert_eq!(checked, 4);

    // Probabilities: failure, by mode, every P(|S| > s).
    let f = &d["failure"];
    assert_eq!(f["lives"].as_u64(), Some(failures as u64));
    let ci = pair(&f["probability_ci95"]);
    let want = wilson(failures, n);
    close(ci[0], want[0], "P(failure) low");
    close(ci[1], want[1], "P(failure) high");
    for mode in ["by_sliding", "by_rotation", "by_heel_pressure"] {
        let k = f[mode]["lives"].as_u64().unwrap() as usize;
        let ci = pair(&f[mode]["probability_ci95"]);
        let want = wilson(k, n);
        close(ci[0], want[0], mode);
        close(ci[1], want[1], mode);
    }
    let exceedance = d["exceedance_probability"].as_array().unwrap();
    assert!(exceedance.len() >= 3, "{exceedance:?}");
    for e in exceedance {
        let t = num(&e["threshold_m"]);
        let k = lives.iter().filter(|&&(m, f)| f || m > t).count();
        close(num(&e["probability"]), k as f64 / n as f64, "P(|S| > s)");
        let ci = pair(&e["ci95"]);
        let want = wilson(k, n);
        close(ci[0], want[0], "P(|S| > s) low");
        close(ci[1], want[1], "P(|S| > s) high");
    }

    // The heel pressure's exceedance of q_a: Wilson on the lives' largest heel pressure.
    let h = &d["heel_pressure_exceedance"];
    let q_a = num(&h["allowable_kpa"]);
    let mut heel = csv::Reader::from_path(out.join("lives.csv")).unwrap();
    let q = col("max_heel_pressure_kpa");
    let k = heel.records().filter(|r| r.as_ref().unwrap()[q].parse::<f64>().unwrap() > q_a).count();
    assert_eq!(h["lives"].as_u64(), Some(k as u64));
    let ci = pair(&h["ci95"]);
    let want = wilson(k, n);
    close(ci[0], want[0], "P(q_heel > q_a) low");
    close(ci[1], want[1], "P(q_heel > q_a) high");

    // Percentiles: order statistics of the capped |S|.
    let mut sorted = capped.clone();
    sorted.sort_by(f64::total_cmp);
    for (name, q) in [("p5", 0.05), ("p50", 0.50), ("p95", 0.95), ("p99", 0.99)] {
        let (l, u) = ranks(n, q);
        let ci = &d["percentiles_ci95_m"][name];
        assert_eq!(num(&ci[0]), sorted[l - 1], "{name}: rank {l}");
        assert_eq!(num(&ci[1]), sorted[u - 1], "{name}: rank {u}");
        let p = num(&d["percentiles_m"][name]);
        assert!(num(&ci[0]) <= p && p <= num(&ci[1]), "{name}: {p} outside {ci}");
    }
    // By hand for 400 lives at the median (exact sums of C(400, r) / 2^400): F(179) = 0.02012,
    // F(180) = 0.02552 → l = 180; F(219) = 0.97448, F(220) = 0.97988 → u = 221.
    assert_eq!(ranks(400, 0.5), (180, 221));

    // The text: E|S| ± the interval's half-width, both to its first significant digit.
    let (mean, se) = mean_se(&capped);
    let half = Z * se;
    let decimals = (-half.log10().floor()) as usize;
    let want = format!("{mean:.decimals$} ± {half:.decimals$} m");
    let line = text.lines().find(|l| l.starts_with("expected sliding E|S|")).expect("the E|S| line");
    assert!(line.contains(&want), "{line:?} should show {want:?}");
}

/// A short sizing run: each candidate's intervals in `size.json` (E|S| ± 1.96 SE, Wilson for
/// P(failure) from its lives) and the same numbers in candidates.csv.
#[test]
fn size_candidates_carry_their_intervals_in_json_and_csv() {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(example("size_breakwater.toml")).unwrap();
    let text = support::site::with(&text, "size", "lives = 40\nrange_m = [18.0, 24.0]\ncurve_points = 3");
    let f = write(dir.path(), "s.toml", &text);
    let out = dir.path().join("out");
    let o = caisson().args(["size", f.to_str().unwrap(), "--out", out.to_str().unwrap()]).output().unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let j: Value = serde_json::from_str(&std::fs::read_to_string(out.join("size.json")).unwrap()).unwrap();
    let n = j["lives_per_candidate"].as_u64().unwrap() as usize;
    assert_eq!(n, 40);
    let cands = j["candidates"].as_array().unwrap();
    let mut reader = csv::Reader::from_path(out.join("candidates.csv")).unwrap();
    let header = reader.headers().unwrap().clone();
    let rows: Vec<csv::StringRecord> = reader.records().map(|r| r.unwrap()).collect();
    assert_eq!(rows.len(), cands.len());
    assert!(cands.len() >= 3, "{}", cands.len());
    let cell = |row: &csv::StringRecord, name: &str| -> f64 {
        row[header.iter().position(|h| h == name).unwrap_or_else(|| panic!("no column {name}"))].parse().unwrap()
    };
    for (c, row) in cands.iter().zip(&rows) {
        for model in ["dynamic", "rigid_block"] {
            let m = &c[model];
            for key in ["expected_sliding", "expected_sliding_uncapped"] {
                let (mean, se) = (num(&m[format!("{key}_m")]), num(&m[format!("{key}_standard_error_m")]));
                let ci = pair(&m[format!("{key}_ci95_m")]);
                close(ci[0], mean - Z * se, key);
                close(ci[1], mean + Z * se, key);
                assert_eq!(cell(row, &format!("{model}_{key}_ci95_low_m")), ci[0]);
                assert_eq!(cell(row, &format!("{model}_{key}_ci95_high_m")), ci[1]);
            }
            let p = num(&m["failure_probability"]);
            let k = (p * n as f64).round() as usize;
            assert_eq!(k as f64 / n as f64, p, "a share of 40 lives");
            let ci = pair(&m["failure_probability_ci95"]);
            let want = wilson(k, n);
            close(ci[0], want[0], "P(failure) low");
            close(ci[1], want[1], "P(failure) high");
            assert_eq!(cell(row, &format!("{model}_failure_probability_ci95_low")), ci[0]);
            assert_eq!(cell(row, &format!("{model}_failure_probability_ci95_high")), ci[1]);
        }
    }
}
