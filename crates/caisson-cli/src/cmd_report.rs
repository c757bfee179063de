//! `caisson report SCENARIO... --out DIR [--threads N] [--no-pdf]`: a calculation note
//! (docs/report.md). Each scenario is computed by the library as its own commands compute it —
//! Goda's static check as `caisson loads`, the lives as `caisson design`, the sizing as `caisson
//! size`, the storms as `caisson fragility` — and the note is written from the same report
//! structs those commands serialize (`report_html.rs`), so its numbers are theirs by construction.
//!
//! Files: `DIR/report.html`, one self-contained page (figures inline as SVG, styles inline, no
//! script, no link, nothing fetched), and `DIR/report.pdf` (A4) printed from it by a headless
//! Chromium where one is found (`CAISSON_CHROMIUM`, else `chromium`, `chromium-browser`,
//! `google-chrome` on the PATH); otherwise a note says the PDF was skipped.
//!
//! Several scenarios are set side by side ([`crate::report_html`], "Alternatives"): their
//! differences in E|S| and P(failure) are paired life by life where the alternatives share the
//! seed and the number of lives (common random numbers: life i meets the same storms in each).

use crate::cli::ReportArgs;
use crate::input_err;
use crate::output::{check_out_dir, ensure_dir, progress, with_threads, write_atomic};
use crate::report_html::{self, Alternative, DesignPart, OneWave, SizePart};
use anyhow::{Context, Result};
use caisson::analysis::conventional::static_check;
use caisson::analysis::lifetime::StormOutcome;
use caisson::analysis::rigid::RigidBlock;
use caisson::analysis::run as engine;
use caisson::drive::design::{DesignOptions, Designer};
use caisson::drive::size::{Hooks, Sizer};
use caisson::loads::risetime::load_rng;
use caisson::report::loads::LoadsReport;
use caisson::report::ModelReport;
use caisson::scenario::{self, Scenario};
use std::path::{Path, PathBuf};
use std::time::Duration;

/// The longest a headless Chromium may take to print the note.
const PRINT_TIMEOUT: Duration = Duration::from_secs(120);

pub fn run(args: ReportArgs) -> Result<()> {
    check_out_dir(Some(&args.out))?;
    // Held to the end: a second run into the same --out is refused at once.
    let _out_lock = crate::output::OutLock::acquire(&args.out, "report")?;
    // Every file read and checked before any computing.
    let mut scenarios = Vec::new();
    for path in &args.scenarios {
        scenarios.push((path.clone(), scenario::load(path).map_err(input_err)?));
    }
    let mut alternatives = Vec::new();
    for (path, sc) in &scenarios {
        alternatives.push(alternative(path, sc, args.threads)?);
    }
    let date = report_html::utc_date(now_s());
    let html = report_html::render(&alternatives, &date);
    ensure_dir(&args.out)?;
    let html_path = args.out.join("report.html");
    write_atomic(&html_path, html.as_bytes())?;
    let pdf = if args.no_pdf {
        crate::sayln!("report.pdf not printed (--no-pdf)");
        false
    } else {
        match chromium() {
            Some(browser) => {
                print_pdf(&browser, &html_path, &args.out.join("report.pdf"))?;
                true
            }
            None => {
                crate::sayln!(
                    "Note: report.pdf skipped: no headless Chromium found (set CAISSON_CHROMIUM or put chromium on the PATH); print report.html from a browser instead"
                );
                false
            }
        }
    };
    crate::output::tidy_out_dir(&args.out, "report", &[])?;
    crate::sayln!("Wrote report.html{} to {}", if pdf { " and report.pdf" } else { "" }, args.out.display());
    Ok(())
}

/// Seconds since 1970 of the note's date: `SOURCE_DATE_EPOCH` if set (a reproducible note), else now.
fn now_s() -> i64 {
    if let Some(s) = std::env::var("SOURCE_DATE_EPOCH").ok().and_then(|s| s.trim().parse::<i64>().ok()) {
        return s;
    }
    std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_secs() as i64)
}

/// The leading comment of a scenario file: its lines up to the first blank one, as the note's
/// title (the file name where it has none).
fn leading_comment(path: &Path) -> String {
    let text = std::fs::read_to_string(path).unwrap_or_default();
    let mut lines = Vec::new();
    for line in text.lines() {
        let Some(rest) = line.trim_start().strip_prefix('#') else { break };
        let rest = rest.trim();
        if rest.is_empty() {
            break;
        }
        lines.push(rest.to_string());
    }
    lines.join(" ")
}

/// Everything the note shows of one scenario.
fn alternative(path: &Path, sc: &Scenario, threads: usize) -> Result<Alternative> {
    let file = path.file_name().and_then(|s| s.to_str()).unwrap_or("scenario").to_string();
    let name = path.file_stem().and_then(|s| s.to_str()).unwrap_or("scenario").to_string();
    let structure = sc.structure();
    let mut alt = Alternative {
        file,
        name,
        title: leading_comment(path),
        model: ModelReport::new(structure, sc.waves.as_ref()),
        caisson: *sc.caisson(),
        foundation: caisson::report::FoundationReport::from(&engine::FoundationSummary::new(
            sc.caisson(),
            sc.foundation(),
            &structure.model(),
        )),
        springs: sc.foundation().springs,
        loads: None,
        one_wave: None,
        one_wave_error: None,
        design: None,
        size: None,
        fragility: None,
    };
    let Some(ws) = sc.waves.as_ref() else { return Ok(alt) };
    // Goda's static check under the design wave, as `caisson loads` computes it.
    let check = static_check(structure, ws).map_err(input_err)?;
    alt.loads = Some(LoadsReport::of_structure(structure, ws, &check, None).map_err(input_err)?);
    // A wave the engine cannot follow is said in the note, not an error of the whole note.
    match one_wave(sc, ws, &check) {
        Ok(w) => alt.one_wave = Some(w),
        Err(e) => alt.one_wave_error = Some(format!("{e:#}")),
    }
    if sc.design.is_some() {
        let mut run = Designer::new(sc, "`caisson report`", DesignOptions::default()).map_err(input_err)?;
        // The note's curves and paired comparisons read every life, unweighted: a stratified
        // `[design]` runs plain here (the very lives of a plain run of its seed).
        run.design.sampling = caisson::analysis::lifetime::Sampling::Plain;
        let design = &run.design;
        let estimate = with_threads(threads, || run.estimate(design.lives))?;
        crate::work::say(crate::work::check("design", &estimate, &crate::work::DESIGN)?);
        let pb = progress(design.lives as u64, "lives", "");
        let indices: Vec<usize> = (0..design.lives).collect();
        let on_life = |_: usize, _: &StormOutcome| crate::interrupt::tick(&pb);
        let interrupted = || anyhow::Error::new(crate::Interrupted("interrupted (Ctrl-C); nothing was written".into()));
        let lives: Vec<StormOutcome> = if run.auto().is_some() {
            // `lives = "auto"`: the lives to the target, as `caisson design` runs them.
            let done = std::collections::BTreeMap::new();
            match with_threads(threads, || run.run_auto(&done, &on_life))?.context("the design run failed")? {
                caisson::drive::design::AutoRun::Done { lives, .. } => lives,
                caisson::drive::design::AutoRun::Stopped { .. } => return Err(interrupted()),
            }
        } else {
            let lives = with_threads(threads, || run.run(&indices, &on_life))?.context("the design run failed")?;
            if lives.len() < design.lives {
                return Err(interrupted());
            }
            lives.into_iter().map(|(_, o)| o).collect()
        };
        pb.finish_and_clear();
        let report = run.report(&lives);
        alt.design = Some(DesignPart { report, lives, params: design.clone() });
    }
    if sc.size.is_some() {
        let sizer = Sizer::new(sc, "`caisson report`").map_err(input_err)?;
        let estimate = sizer.estimate("`caisson report`").map_err(input_err)?;
        crate::work::say(crate::work::check("size", &estimate, &crate::work::SIZE)?);
        let pb = progress((sizer.candidates() * sizer.params.lives) as u64, "candidates", "lives");
        let mut width = |w: f64, _: bool| pb.set_message(format!("B = {w:.3} m"));
        let life = || crate::interrupt::tick(&pb);
        let mut candidate = |_: &caisson::analysis::sizing::Candidate| Ok(());
        let hooks = Hooks { width: &mut width, life: &life, candidate: &mut candidate };
        let report = with_threads(threads, || sizer.run(&[], hooks))?.map_err(|e| match e {
            caisson::drive::size::SizeError::Stopped { .. } => {
                anyhow::Error::new(crate::Interrupted("interrupted (Ctrl-C); nothing was written".into()))
            }
            caisson::drive::size::SizeError::Run { width_m, source } => {
                anyhow::Error::new(source).context(format!("the lives at the width {width_m} m"))
            }
            e => input_err(e),
        })?;
        pb.finish_and_clear();
        let svg = crate::cmd_size::design_curve_svg(&caption_of(&alt), &report)?;
        alt.size = Some(SizePart { report, svg });
    }
    if sc.has_fragility_table() {
        let params = sc.fragility_for("`caisson report`").map_err(input_err)?;
        let case = sc.storm_case(true).map_err(input_err)?;
        let estimate = caisson::analysis::work::fragility(&case, params);
        crate::work::say(crate::work::check("fragility", &estimate, &crate::work::FRAGILITY)?);
        let pb = progress((params.heights_m.len() * params.storms) as u64, "storms", "");
        let result =
            with_threads(threads, || caisson::analysis::fragility::run_fragility(&case, params, &|| pb.inc(1)))?
                .context("the fragility analysis failed")?;
        pb.finish_and_clear();
        let report = caisson::report::fragility::FragilityReport::new(&alt.file, structure, ws, params, &result);
        let svg = crate::cmd_fragility::fragility_svg(&caption_of(&alt), &result)?;
        alt.fragility = Some((report, svg));
    }
    Ok(alt)
}

/// The caption line of a figure: site, caisson and version ([`report_html::caption`]).
fn caption_of(alt: &Alternative) -> String {
    report_html::caption(alt)
}

/// The design wave (H_D of Goda's check) through the dynamic model, once, beside the rigid block.
fn one_wave(
    sc: &Scenario,
    ws: &caisson::analysis::site::WaveSetup,
    check: &caisson::analysis::conventional::StaticCheck,
) -> Result<OneWave> {
    let records = ws.model.regular_records(&check.loads, 1, &mut load_rng(1));
    let train = ws.model.train(&records)?;
    let event = train.events()[0];
    let duration_s = event.end_s();
    let result = engine::run(sc.structure(), &train, duration_s, true)?;
    let block = RigidBlock::new(sc.caisson(), ws.model.site.rho_w, ws.rigid_block_mu(sc.foundation()));
    let history = result.history.expect("recorded");
    Ok(OneWave {
        height_m: records[0].height_m,
        period_s: records[0].period_s,
        rise_time_s: records[0].rise_time_s,
        duration_s,
        dynamic_sliding_m: result.summary.permanent_sliding_m,
        max_displacement_m: result.summary.max_horizontal_displacement_m,
        max_rotation_rad: result.summary.max_rotation_rad,
        max_reaction_kn: result.summary.max_horizontal_reaction_n / 1e3,
        rigid_block_sliding_m: block.wave_sliding_m(&event),
        rigid_block_mu: ws.rigid_block_mu(sc.foundation()),
        t_s: history.t_s,
        ux_m: history.ux_m,
        fx_kn: history.fx_n.iter().map(|f| f / 1e3).collect(),
        resistance_kn: history.sliding_resistance_n.iter().map(|f| f / 1e3).collect(),
    })
}

/// The headless Chromium to print with: `CAISSON_CHROMIUM`, else the first of the usual names on
/// the PATH.
pub(crate) fn chromium() -> Option<PathBuf> {
    if let Some(p) = std::env::var_os("CAISSON_CHROMIUM").filter(|p| !p.is_empty()) {
        return Some(PathBuf::from(p));
    }
    let path = std::env::var_os("PATH")?;
    for dir in std::env::split_paths(&path) {
        for name in ["chromium", "chromium-browser", "google-chrome", "google-chrome-stable"] {
            let p = dir.join(name);
            if p.is_file() {
                return Some(p);
            }
        }
    }
    None
}

/// Print `html` to `pdf` (A4, the page's own `@page` size) with the headless `browser`: into a
/// temporary file beside it, then written in place whole.
fn print_pdf(browser: &Path, html: &Path, pdf: &Path) -> Result<()> {
    let html_abs = std::fs::canonicalize(html).with_context(|| format!("reading {}", html.display()))?;
    let dir = pdf.parent().unwrap_or(Path::new("."));
    let scratch = Scratch(dir.join(format!(".caisson-chromium-{}", std::process::id())));
    let _ = std::fs::remove_dir_all(&scratch.0);
    std::fs::create_dir_all(&scratch.0)
        .with_context(|| format!("creating a scratch directory in {}", dir.display()))?;
    let printed = scratch.0.join("report.pdf");
    let mut child = std::process::Command::new(browser)
        .args(["--headless", "--no-sandbox", "--disable-gpu", "--no-pdf-header-footer"])
        .arg(format!("--user-data-dir={}", scratch.0.join("profile").display()))
        .arg(format!("--print-to-pdf={}", printed.display()))
        .arg(format!("file://{}", html_abs.display()))
        .stdin(std::process::Stdio::null())
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .with_context(|| format!("starting {}", browser.display()))?;
    let stderr = child.stderr.take();
    let reader = std::thread::spawn(move || {
        let mut s = String::new();
        if let Some(mut e) = stderr {
            let _ = std::io::Read::read_to_string(&mut e, &mut s);
        }
        s
    });
    let started = std::time::Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait()? {
            break status;
        }
        if started.elapsed() > PRINT_TIMEOUT {
            let _ = child.kill();
            let _ = child.wait();
            anyhow::bail!(
                "{} did not print the note within {} s; report.html is written (print it from a browser)",
                browser.display(),
                PRINT_TIMEOUT.as_secs()
            );
        }
        std::thread::sleep(Duration::from_millis(50));
    };
    let messages = reader.join().unwrap_or_default();
    let bytes = std::fs::read(&printed).ok().filter(|b| b.starts_with(b"%PDF"));
    match bytes {
        Some(bytes) if status.success() => write_atomic(pdf, &bytes),
        _ => anyhow::bail!(
            "{} could not print the note to PDF ({status}); report.html is written (print it from a browser): {}",
            browser.display(),
            messages.lines().rev().take(3).collect::<Vec<_>>().join(" / ")
        ),
    }
}

/// The browser's scratch directory (its profile and the printed file), removed on drop.
struct Scratch(PathBuf);

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}
