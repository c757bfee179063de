//! `caisson design FILE.toml [--json] [--out DIR] [--threads N] [--resume] [--brute-force]`: the
//! lifetime Monte Carlo of performance-based design (docs/model.md §6.4), lives in parallel, with a
//! checkpoint that keeps every finished life.
//!
//! **Checkpoint** (`DIR/checkpoint.jsonl`, or `--checkpoint FILE`): a header line with the
//! fingerprint of what every life depends on (the typed scenario, the screen and the stepping of
//! `--brute-force`; [`design_fingerprint`]) and the tool and results versions, then one JSON line
//! per finished life, written and flushed as each life ends. A run killed at any moment (Ctrl-C,
//! `kill`) leaves the lives it finished; a partly written last line is ignored. `--resume` reads
//! them, runs only the missing lives and reports exactly what an uninterrupted run reports (each
//! life depends only on the seed and its index; f64 values round-trip exactly through JSON).

use crate::cli::DesignArgs;
use crate::input_err;
use crate::output::{check_out_dir, ensure_dir, pretty, progress, report_json, with_threads, write_atomic};
use crate::plot::{panels, Panel, Series};
use anyhow::{Context, Result};
use caisson::analysis::lifetime::{run_lives, StormOutcome};
use caisson::dynamics::Stepping;
use caisson::report::design::{design_fingerprint, DesignReport};
use caisson::scenario;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::io::{BufRead, Write};
use std::ops::ControlFlow;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

#[derive(serde::Serialize, serde::Deserialize)]
struct Header {
    caisson_design_checkpoint: u32,
    fingerprint: String,
    lives: usize,
    caisson_version: String,
    results_version: u32,
}

#[derive(serde::Serialize, serde::Deserialize)]
struct LifeLine {
    life: usize,
    #[serde(flatten)]
    outcome: StormOutcome,
}

/// Lives already in a checkpoint (an input error if it belongs to another run).
fn read_checkpoint(path: &Path, fingerprint: &str) -> Result<BTreeMap<usize, StormOutcome>> {
    let file = std::fs::File::open(path)
        .map_err(|e| input_err(format!("--resume: cannot read the checkpoint {}: {e}", path.display())))?;
    let mut lines = std::io::BufReader::new(file).lines();
    let header: Header = lines.next().and_then(|l| l.ok()).and_then(|l| serde_json::from_str(&l).ok()).ok_or_else(|| {
        input_err(format!(
            "--resume: {} line 1 is not a caisson design checkpoint header (of results version {}); run without --resume to start again",
            path.display(),
            caisson::RESULTS_VERSION
        ))
    })?;
    if header.results_version != caisson::RESULTS_VERSION {
        return Err(input_err(format!(
            "--resume: the checkpoint {} holds results version {} (caisson {}), this caisson {} computes results version {}; its lives would not match: run without --resume to start again",
            path.display(),
            header.results_version,
            header.caisson_version,
            caisson::VERSION,
            caisson::RESULTS_VERSION
        )));
    }
    if header.fingerprint != fingerprint {
        return Err(input_err(format!(
            "--resume: the checkpoint {} was written for a different scenario or options (fingerprint {}, this run {}: the caisson, foundation, solver, waves, [design] life model or seed, or --brute-force differ); run without --resume to start again",
            path.display(),
            header.fingerprint,
            fingerprint
        )));
    }
    let mut done = BTreeMap::new();
    for line in lines {
        let Ok(line) = line else { break };
        // A line cut short by an interruption does not parse: it and anything after it are ignored.
        match serde_json::from_str::<LifeLine>(&line) {
            Ok(l) => {
                done.insert(l.life, l.outcome);
            }
            Err(_) => break,
        }
    }
    Ok(done)
}

fn lives_csv(lives: &[StormOutcome]) -> Result<Vec<u8>> {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record([
        "life",
        "sliding_m",
        "rigid_block_sliding_m",
        "max_storm_sliding_m",
        "waves",
        "simulated_waves",
        "screened_waves",
    ])?;
    for (i, l) in lives.iter().enumerate() {
        w.write_record(&[
            i.to_string(),
            format!("{:e}", l.sliding_m),
            format!("{:e}", l.rigid_block_sliding_m),
            format!("{:e}", l.max_storm_sliding_m),
            l.waves.to_string(),
            l.simulated.to_string(),
            l.screened.to_string(),
        ])?;
    }
    Ok(w.into_inner()?)
}

/// Histogram of the life totals (dynamic and rigid block) and their exceedance curves.
fn plots(dir: &Path, title: &str, dynamic: &[f64], rigid: &[f64]) -> Result<()> {
    let max = dynamic.iter().chain(rigid).copied().fold(0.0, f64::max).max(1e-6);
    let bins = 40;
    let hist = |v: &[f64]| -> Vec<(f64, f64)> {
        let mut c = vec![0usize; bins];
        for &x in v {
            c[((x / max * bins as f64) as usize).min(bins - 1)] += 1;
        }
        let w = max / bins as f64;
        c.iter()
            .enumerate()
            .flat_map(|(i, &n)| {
                let y = n as f64 / v.len().max(1) as f64;
                [(i as f64 * w, y), ((i + 1) as f64 * w, y)]
            })
            .collect()
    };
    panels(
        &dir.join("histogram.svg"),
        &format!("{title}: sliding over the design life"),
        "total sliding (m)",
        &[Panel {
            y_label: "share of lives".into(),
            series: vec![
                Series::line("dynamic model", hist(dynamic)),
                Series::dashed("rigid block (Shimosako model)", hist(rigid)),
            ],
        }],
    )?;
    let exceed = |v: &[f64]| -> Vec<(f64, f64)> {
        let mut s = v.to_vec();
        s.sort_by(f64::total_cmp);
        let n = s.len().max(1) as f64;
        s.iter().enumerate().map(|(i, &x)| (x, 1.0 - i as f64 / n)).collect()
    };
    panels(
        &dir.join("exceedance.svg"),
        &format!("{title}: probability that the life's sliding exceeds S"),
        "S (m)",
        &[Panel {
            y_label: "P(sliding > S)".into(),
            series: vec![
                Series::line("dynamic model", exceed(dynamic)),
                Series::dashed("rigid block (Shimosako model)", exceed(rigid)),
            ],
        }],
    )
}

pub fn run(args: DesignArgs) -> Result<()> {
    let mut sc = scenario::load(&args.scenario).map_err(input_err)?;
    let mut design = sc.design_for("`caisson design`").map_err(input_err)?.clone();
    if let Some(n) = args.lives {
        if n == 0 {
            return Err(input_err("--lives 0: must be at least 1"));
        }
        design.lives = n;
    }
    if args.brute_force {
        // Brute force: every wave through the dynamic model at the fixed step dt_s.
        design.screen = false;
        let solver = caisson::dynamics::SolverParams { stepping: Stepping::Fixed, ..sc.solver() };
        sc = sc.with_solver(solver).map_err(input_err)?;
    }
    check_out_dir(args.out.as_deref())?;
    let checkpoint: Option<PathBuf> =
        args.checkpoint.clone().or_else(|| args.out.as_ref().map(|d| d.join("checkpoint.jsonl")));
    if args.resume && checkpoint.is_none() {
        return Err(input_err(
            "--resume needs the checkpoint: give --out DIR (DIR/checkpoint.jsonl) or --checkpoint FILE",
        ));
    }
    let case = sc.storm_case(design.screen).map_err(input_err)?;
    let fingerprint = design_fingerprint(&case, &design);
    let mut done = if args.resume {
        read_checkpoint(checkpoint.as_ref().expect("checked"), &fingerprint)?
    } else {
        BTreeMap::new()
    };
    done.retain(|&i, _| i < design.lives);
    let writer = match &checkpoint {
        Some(path) => {
            if let Some(parent) = path.parent().filter(|p| !p.as_os_str().is_empty()) {
                ensure_dir(parent)?;
            }
            let mut f = if args.resume {
                std::fs::OpenOptions::new()
                    .append(true)
                    .open(path)
                    .with_context(|| format!("opening the checkpoint {}", path.display()))?
            } else {
                let mut f = std::fs::File::create(path)
                    .with_context(|| format!("creating the checkpoint {}", path.display()))?;
                let header = Header {
                    caisson_design_checkpoint: 1,
                    fingerprint: fingerprint.clone(),
                    lives: design.lives,
                    caisson_version: caisson::VERSION.to_string(),
                    results_version: caisson::RESULTS_VERSION,
                };
                writeln!(f, "{}", serde_json::to_string(&header)?)?;
                f
            };
            f.flush()?;
            Some(Mutex::new(f))
        }
        None => None,
    };
    let todo: Vec<usize> = (0..design.lives).filter(|i| !done.contains_key(i)).collect();
    let pb = progress(design.lives as u64, "lives", "");
    pb.set_position(done.len() as u64);
    let finished_now = AtomicUsize::new(0);
    let stop_after = args.stop_after.unwrap_or(usize::MAX);
    let write_error: Mutex<Option<anyhow::Error>> = Mutex::new(None);
    let on_life = |i: usize, o: &StormOutcome| {
        if let Some(w) = &writer {
            let line = serde_json::to_string(&LifeLine { life: i, outcome: *o }).expect("a life serializes");
            let mut f = w.lock().expect("checkpoint lock");
            if let Err(e) = writeln!(f, "{line}").and_then(|_| f.flush()) {
                *write_error.lock().expect("error slot") =
                    Some(anyhow::Error::new(e).context("writing the checkpoint"));
                return ControlFlow::Break(());
            }
        }
        pb.inc(1);
        if finished_now.fetch_add(1, Ordering::SeqCst) + 1 >= stop_after {
            ControlFlow::Break(())
        } else {
            ControlFlow::Continue(())
        }
    };
    let results = with_threads(args.threads, || run_lives(&case, &design.life, design.seed, &todo, &on_life))?
        .context("the design run failed")?;
    pb.finish_and_clear();
    if let Some(e) = write_error.into_inner().expect("error slot") {
        return Err(e);
    }
    done.extend(results);
    if done.len() < design.lives {
        anyhow::bail!(
            "stopped after {} of {} lives (--stop-after); the finished lives are in {}; run again with --resume to complete",
            done.len(),
            design.lives,
            checkpoint.as_ref().map_or("no checkpoint".into(), |p| p.display().to_string())
        );
    }
    let lives: Vec<StormOutcome> = done.into_values().collect();
    let mut report = DesignReport::new(&design, case.rigid_block_mu, &lives);
    report.warnings = caisson::analysis::checks::structure_warnings(case.structure);
    crate::output::print_warnings(&report.warnings);
    let json = report_json(&report, "design")?;
    if args.json {
        crate::sayln!("{}", pretty(&json)?);
    } else {
        crate::say!("{}", design_text(&report));
    }
    if let Some(dir) = &args.out {
        ensure_dir(dir)?;
        write_atomic(&dir.join("design.json"), pretty(&json)?.as_bytes())?;
        write_atomic(&dir.join("lives.csv"), &lives_csv(&lives)?)?;
        let title = args.scenario.file_stem().and_then(|s| s.to_str()).unwrap_or("design");
        let dynamic: Vec<f64> = lives.iter().map(|l| l.sliding_m).collect();
        let rigid: Vec<f64> = lives.iter().map(|l| l.rigid_block_sliding_m).collect();
        plots(dir, title, &dynamic, &rigid)?;
        if !args.json {
            crate::sayln!(
                "\nWrote design.json, lives.csv, histogram.svg, exceedance.svg (and checkpoint.jsonl) to {}",
                dir.display()
            );
        }
    }
    Ok(())
}

/// The table of a design run.
fn design_text(r: &DesignReport) -> String {
    let years = r.life_years;
    let (sd, sr) = (&r.dynamic, &r.rigid_block);
    let mut t = String::new();
    let _ = writeln!(
        t,
        "{} lives of {years} years (seed {}), {} waves, {} through the dynamic model, {:.4} % screened{}",
        r.lives,
        r.seed,
        r.waves,
        r.simulated_waves,
        100.0 * r.screened_waves as f64 / r.waves.max(1) as f64,
        if r.screen { "" } else { " (screen off)" }
    );
    let _ = writeln!(t);
    let _ = writeln!(
        t,
        "                                  dynamic model   rigid block (Shimosako, μ = {})",
        r.rigid_block_mu
    );
    let _ = writeln!(
        t,
        "expected sliding over the life   {:>10.4} m    {:>10.4} m",
        sd.expected_sliding_m, sr.expected_sliding_m
    );
    let _ = writeln!(
        t,
        "expected sliding per year        {:>10.5} m    {:>10.5} m",
        sd.expected_sliding_m / years as f64,
        sr.expected_sliding_m / years as f64
    );
    let (pd, pr) = (&sd.percentiles_m, &sr.percentiles_m);
    for (p, a, b) in [(5.0, pd.p5, pr.p5), (50.0, pd.p50, pr.p50), (95.0, pd.p95, pr.p95), (99.0, pd.p99, pr.p99)] {
        let _ = writeln!(t, "{:>3.0} % percentile                  {:>10.4} m    {:>10.4} m", p, a, b);
    }
    for (a, b) in sd.exceedance_probability.iter().zip(&sr.exceedance_probability) {
        let _ = writeln!(
            t,
            "P(sliding > {:<5} m)             {:>10.4}      {:>10.4}",
            a.threshold_m, a.probability, b.probability
        );
    }
    t
}
