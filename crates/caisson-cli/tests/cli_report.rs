//! `caisson report`: the calculation note's numbers are those of the JSON commands (`loads`,
//! `design`, `size`), alternatives side by side with paired differences, and the note in a real
//! browser (headless Chromium: printed to an A4 PDF, a screenshot, no console error, every
//! figure in the DOM). Without Chromium the browser test says it was skipped.

mod support;

use serde_json::Value;
use std::path::{Path, PathBuf};
use support::{caisson_within, example, s, write};

/// Every shown number of alternative `alt`: (JSON key, the text shown).
fn shown(html: &str, alt: usize) -> Vec<(String, String)> {
    let mut out = Vec::new();
    let marker = format!("data-key=\"{alt}:");
    let mut rest = html;
    while let Some(i) = rest.find(&marker) {
        rest = &rest[i + marker.len()..];
        let key_end = rest.find('"').unwrap();
        let key = rest[..key_end].to_string();
        let text_start = rest.find('>').unwrap() + 1;
        let text_end = text_start + rest[text_start..].find('<').unwrap();
        out.push((key, rest[text_start..text_end].to_string()));
    }
    out
}

/// A shown number and the half-unit of its last digit (how far rounding may move it).
fn parse(text: &str) -> (f64, f64) {
    let t = text.replace('−', "-");
    let decimals = t.split_once('.').map_or(0, |(_, d)| d.len());
    (t.parse().unwrap_or_else(|_| panic!("a number: {text:?}")), 0.5 * 10f64.powi(-(decimals as i32)))
}

/// The value at `path` (dots; array indices as numbers) of `json`.
fn at<'a>(json: &'a Value, path: &str) -> &'a Value {
    path.split('.').fold(json, |v, k| match k.parse::<usize>() {
        Ok(i) if v.is_array() => &v[i],
        _ => &v[k],
    })
}

/// Compare every shown number of alternative 0 whose key starts with one of `docs`' names with
/// that JSON document's value: equal to the digits shown (half a unit of the last digit, plus
/// 1e-9 relative for the binary-to-decimal round trip). Returns how many were compared.
fn compare(html: &str, docs: &[(&str, &Value)]) -> usize {
    let mut compared = 0;
    for (key, text) in shown(html, 0) {
        let Some((doc, path)) = key.split_once('.') else { continue };
        let Some((_, json)) = docs.iter().find(|(d, _)| *d == doc) else { continue };
        let expected = at(json, path).as_f64().unwrap_or_else(|| panic!("{key}: no number in the JSON"));
        let (value, half) = parse(&text);
        assert!(
            (value - expected).abs() <= half * (1.0 + 1e-9) + 1e-9 * expected.abs(),
            "{key}: the note shows {text}, the JSON holds {expected}"
        );
        compared += 1;
    }
    compared
}

/// The JSON document a command prints with --json.
fn json_of(args: &[&str], secs: u64) -> Value {
    let o = caisson_within(secs).args(args).output().unwrap();
    assert_eq!(o.status.code(), Some(0), "{args:?}: {}", String::from_utf8_lossy(&o.stderr));
    serde_json::from_slice(&o.stdout).expect("JSON on stdout")
}

/// `caisson report ARGS --out DIR`: the note's text.
fn report(scenarios: &[&str], out: &Path, pdf: bool, secs: u64) -> String {
    let mut args = vec!["report"];
    args.extend_from_slice(scenarios);
    args.extend(["--out", s(out)]);
    if !pdf {
        args.push("--no-pdf");
    }
    let o = caisson_within(secs).args(&args).env("SOURCE_DATE_EPOCH", "1796083200").output().unwrap();
    assert_eq!(o.status.code(), Some(0), "{args:?}: {}", String::from_utf8_lossy(&o.stderr));
    std::fs::read_to_string(out.join("report.html")).unwrap()
}

/// The embedded report struct `what` of alternative `alt`.
fn embedded(html: &str, alt: usize, what: &str) -> Value {
    let open = format!("<script type=\"application/json\" id=\"json-{alt}-{what}\">");
    let start = html.find(&open).unwrap_or_else(|| panic!("{what} embedded")) + open.len();
    let end = start + html[start..].find("</script>").unwrap();
    serde_json::from_str(&html[start..end].replace("<\\/", "</")).unwrap()
}

/// The note is one file that fetches nothing: no link, no external source, no executable script.
fn self_contained(html: &str) {
    for needle in ["<link", " src=", "href=\"http", "url(", "@import", "<script>", "<script src"] {
        assert!(!html.contains(needle), "the note must fetch nothing: it holds {needle:?}");
    }
    assert_eq!(html.matches("<script").count(), html.matches("<script type=\"application/json\"").count());
}

#[test]
fn the_design_note_shows_the_numbers_of_design_json_and_loads_json() {
    let dir = tempfile::tempdir().unwrap();
    let scenario = example("design_breakwater.toml");
    let html = report(&[&scenario], &dir.path().join("r"), false, 600);
    self_contained(&html);
    let design = json_of(&["design", &scenario, "--json"], 600);
    let loads = json_of(&["loads", &scenario, "--json"], 60);
    // The report structs themselves, embedded: equal to what the commands print.
    assert_eq!(embedded(&html, 0, "design"), design, "design.json");
    assert_eq!(embedded(&html, 0, "loads"), loads, "loads.json");
    let compared = compare(&html, &[("design", &design), ("loads", &loads)]);
    // Goda's sheet (16 values), the design wave (4), the inputs (4) and the lifetime table (20).
    assert!(compared >= 40, "{compared} numbers compared");
    for section in
        ["title-block", "inputs", "design-wave", "goda-sheet", "one-wave", "lifetime", "warnings", "references"]
    {
        assert!(html.contains(&format!("id=\"{section}\"")), "the section {section}");
    }
    assert!(!html.contains("id=\"required-width\""), "no sizing section without [size]");
    // The model choices, the breaking-load rule with its source, and the versions.
    assert!(
        html.contains("breaking_load <b>goda-takahashi</b>: Goda (2000) with Takahashi"),
        "the rule and its source"
    );
    assert!(html.contains(&format!("results version {}", caisson::RESULTS_VERSION)));
    assert!(html.contains("<td>2026-12-01</td>"), "the date of SOURCE_DATE_EPOCH");
    // Two figures: the one wave and the exceedance curve.
    assert_eq!(html.matches("<figure ").count(), 2);
}

#[test]
fn the_sizing_note_shows_the_numbers_of_size_json() {
    let dir = tempfile::tempdir().unwrap();
    let scenario = example("size_breakwater.toml");
    let html = report(&[&scenario], &dir.path().join("r"), false, 900);
    let size = json_of(&["size", &scenario, "--json"], 900);
    assert_eq!(embedded(&html, 0, "size"), size, "size.json");
    let compared = compare(&html, &[("size", &size)]);
    // The three widths and, per candidate, its width, E|S| and P(failure).
    let candidates = size["candidates"].as_array().unwrap().len();
    assert_eq!(compared, 3 + 3 * candidates, "{compared} numbers compared of {candidates} candidates");
    assert!(html.contains("id=\"required-width\"") && html.contains("id=\"fig-design-curve-size_breakwater\""));
}

#[test]
fn alternatives_are_set_side_by_side_with_paired_differences() {
    let dir = tempfile::tempdir().unwrap();
    // The comparison of two widths of examples/compare (B = 20 m and 24 m), and B = 20 m again.
    let (a, b) = (example("compare/width_20m.toml"), example("compare/width_24m.toml"));
    let same = write(dir.path(), "same.toml", &std::fs::read_to_string(&a).unwrap());
    let html = report(&[&a, &b, s(&same)], &dir.path().join("r"), false, 600);
    assert!(html.contains("id=\"comparison\"") && html.contains("id=\"paired-differences\""));
    let number = |alt: usize, key: &str| -> (f64, f64) {
        let (_, text) = shown(&html, alt).into_iter().find(|(k, _)| k == key).unwrap_or_else(|| panic!("{alt}:{key}"));
        parse(&text)
    };
    // The mean of the lives' differences is the difference of the means: to the digits shown.
    let (ea, ha) = number(0, "design.dynamic.expected_sliding_m");
    let (eb, hb) = number(1, "design.dynamic.expected_sliding_m");
    let (d, hd) = number(1, "difference.expected_sliding_m");
    assert!((d - (eb - ea)).abs() <= ha + hb + hd, "ΔE|S| {d} against {eb} − {ea}");
    let (pa, qa) = number(0, "design.dynamic.failure.probability");
    let (pb, qb) = number(1, "design.dynamic.failure.probability");
    let (dp, qd) = number(1, "difference.failure_probability");
    assert!((dp - (pb - pa)).abs() <= qa + qb + qd, "ΔP(failure) {dp} against {pb} − {pa}");
    // The same scenario twice: every life the same, the difference exactly 0 with a zero interval.
    assert_eq!(number(2, "difference.expected_sliding_m").0, 0.0);
    assert!(html.contains("<td>C − A</td><td class=\"n\"><span class=\"v\" data-key=\"2:difference.expected_sliding_m\">0.0000</span></td><td class=\"n\">0.0000 to 0.0000</td>"));
    assert!(html.contains("common random numbers"));
    // Each alternative's note follows in full.
    assert_eq!(html.matches("id=\"goda-sheet\"").count(), 3);
}

/// The headless Chromium of the machine, if any (as `caisson report` finds it).
fn chromium() -> Option<PathBuf> {
    if let Some(p) = std::env::var_os("CAISSON_CHROMIUM").filter(|p| !p.is_empty()) {
        return Some(PathBuf::from(p));
    }
    let path = std::env::var_os("PATH")?;
    std::env::split_paths(&path)
        .flat_map(|d| ["chromium", "chromium-browser", "google-chrome"].map(|n| d.join(n)))
        .find(|p| p.is_file())
}

/// Run the headless browser on `html` with `args`; its stdout and stderr.
fn browse(browser: &Path, profile: &Path, html: &Path, args: &[&str]) -> (String, String) {
    let url = format!("file://{}", std::fs::canonicalize(html).unwrap().display());
    let o = std::process::Command::new(browser)
        .args(["--headless", "--no-sandbox", "--disable-gpu", "--enable-logging=stderr", "--v=0"])
        .arg(format!("--user-data-dir={}", profile.display()))
        .args(args)
        .arg(url)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    (String::from_utf8_lossy(&o.stdout).into_owned(), String::from_utf8_lossy(&o.stderr).into_owned())
}

/// The pages of a PDF and their MediaBoxes, read from its page objects.
fn pdf_pages(pdf: &[u8]) -> (usize, Vec<String>) {
    let text = String::from_utf8_lossy(pdf);
    let pages = text.matches("/Type /Page").count() - text.matches("/Type /Pages").count();
    let boxes = text.match_indices("/MediaBox [").map(|(i, _)| text[i + 11..].split(']').next().unwrap().to_string());
    (pages, boxes.collect())
}

#[test]
fn the_note_opens_in_a_real_browser_prints_to_a4_and_has_every_figure() {
    let Some(browser) = chromium() else {
        eprintln!("skipped: no headless Chromium (set CAISSON_CHROMIUM or install chromium; .ci/run installs it)");
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("r");
    let html = report(&[&example("design_breakwater.toml")], &out, true, 600);
    // The PDF printed by `caisson report`: A4 (595 × 842 pt) on every page, 3 to 12 pages.
    let pdf = std::fs::read(out.join("report.pdf")).unwrap();
    assert!(pdf.starts_with(b"%PDF"));
    let (pages, boxes) = pdf_pages(&pdf);
    assert!((3..=12).contains(&pages), "{pages} pages");
    assert_eq!(boxes.len(), pages, "a MediaBox per page: {boxes:?}");
    for b in &boxes {
        let v: Vec<f64> = b.split_whitespace().map(|x| x.parse().unwrap()).collect();
        assert!(v.len() == 4 && (v[2] - 595.0).abs() < 1.0 && (v[3] - 842.0).abs() < 1.0, "not A4: {b}");
    }
    let profile = dir.path().join("profile");
    // The DOM as the browser built it: every figure there with its SVG.
    let (dom, log) = browse(&browser, &profile, &out.join("report.html"), &["--dump-dom"]);
    let figures = html.matches("<figure ").count();
    assert_eq!(figures, 2);
    assert_eq!(dom.matches("<figure ").count(), figures, "every figure in the DOM");
    assert!(dom.matches("<svg").count() >= figures, "every figure's SVG in the DOM");
    let errors: Vec<&str> =
        log.lines().filter(|l| l.contains("CONSOLE") || l.contains("Uncaught") || l.contains("ERR_FILE")).collect();
    assert!(errors.is_empty(), "console errors: {errors:?}");
    // A screenshot of the first screen.
    let shot = dir.path().join("shot.png");
    let (_, log) = browse(
        &browser,
        &profile,
        &out.join("report.html"),
        &[&format!("--screenshot={}", shot.display()), "--window-size=900,1200"],
    );
    let png = std::fs::read(&shot).unwrap();
    assert!(png.starts_with(b"\x89PNG") && png.len() > 10_000, "a screenshot of {} bytes", png.len());
    assert!(!log.contains("Uncaught"), "{log}");
}

#[test]
fn without_a_browser_the_note_is_written_and_the_pdf_skipped() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("r");
    let f = write(dir.path(), "d.toml", &support::design_text(20, 1, ""));
    let o = caisson_within(300)
        .args(["report", s(&f), "--out", s(&out)])
        .env("CAISSON_CHROMIUM", dir.path().join("no-such-browser"))
        .output()
        .unwrap();
    // A browser that cannot start: an error naming it, the HTML written.
    assert_eq!(o.status.code(), Some(1), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stderr).contains("no-such-browser"));
    assert!(out.join("report.html").is_file() && !out.join("report.pdf").exists());
    let o = caisson_within(300)
        .args(["report", s(&f), "--out", s(&out)])
        .env("PATH", "")
        .env("CAISSON_CHROMIUM", "")
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stdout).contains("report.pdf skipped"));
}

#[test]
fn the_comparison_of_two_breaking_load_rules_names_each_rule_and_pairs_them() {
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = (example("compare/breaking_goda_takahashi.toml"), example("compare/breaking_cuomo_2010.toml"));
    let html = report(&[&a, &b], &dir.path().join("r"), false, 600);
    // The rule of each, in the comparison table and in each title block, with its source.
    assert!(
        html.contains("<td class=\"n\">goda-takahashi</td><td class=\"n\">cuomo-2010</td>"),
        "the rules side by side"
    );
    assert!(html.contains("breaking_load <b>cuomo-2010</b>: Cuomo, Allsop, Bruce &amp; Pearson (2010)"));
    assert!(html.contains("breaking_load <b>goda-takahashi</b>: Goda (2000) with Takahashi"));
    assert_eq!(embedded(&html, 0, "design")["seed"], embedded(&html, 1, "design")["seed"]);
    assert!(html.contains("<td>paired</td>"), "the same seed and lives: paired");
}

#[test]
fn bad_input_is_refused_before_anything_is_written() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("r");
    let missing = dir.path().join("missing.toml");
    // A missing second scenario: refused (exit 2, naming it) before the first is computed.
    let err = support::refused(
        &["report", &example("design_breakwater.toml"), s(&missing), "--out", s(&out)],
        &["missing.toml"],
    );
    assert!(err.starts_with("Error:"), "{err}");
    assert!(!out.exists(), "nothing written");
    // A bad key of a scenario: its key named.
    let bad = write(dir.path(), "bad.toml", &support::design_text(20, 1, "").replace("mu_static = ", "mu_static = -"));
    support::refused(&["report", s(&bad), "--out", s(&out)], &["mu_static"]);
    // --out is required.
    support::refused(&["report", &example("design_breakwater.toml")], &["--out"]);
    assert!(!out.exists());
}

#[test]
fn the_fragility_note_shows_the_numbers_of_fragility_json() {
    let dir = tempfile::tempdir().unwrap();
    let scenario = example("fragility.toml");
    let html = report(&[&scenario], &dir.path().join("r"), false, 600);
    let fragility = json_of(&["fragility", &scenario, "--json"], 600);
    assert_eq!(embedded(&html, 0, "fragility"), fragility, "fragility.json");
    // θ and β of both models at each limit.
    let limits = fragility["limits_m"].as_array().unwrap().len();
    assert_eq!(compare(&html, &[("fragility", &fragility)]), 2 * 2 * limits);
    assert!(html.contains("id=\"fig-fragility-fragility\""));
    assert!(!html.contains("id=\"lifetime\""), "no [design]: no lifetime section");
}
