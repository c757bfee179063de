//! `caisson design FILE.toml [--json] [--out DIR] [--threads N] [--resume] [--brute-force]`: the
//! lifetime Monte Carlo of performance-based design (PHYSICS.md §6.4), lives in parallel, with a
//! checkpoint that keeps every finished life.
//!
//! **Checkpoint** (`DIR/checkpoint.jsonl`, or `--checkpoint FILE`): a header line with the run's
//! fingerprint (the scenario text and the options that change results), then one JSON line per
//! finished life, written and flushed as each life ends. A run killed at any moment (Ctrl-C,
//! `kill`) leaves the lives it finished; a partly written last line is ignored. `--resume` reads
//! them, runs only the missing lives and reports exactly what an uninterrupted run reports (each
//! life depends only on the seed and its index; f64 values round-trip exactly through JSON).

use crate::cli::DesignArgs;
use crate::cmd_run::check_finite;
use crate::input_err;
use crate::output::{ensure_dir, write_atomic};
use crate::plot::{panels, Panel, Series};
use crate::train_out::set_threads;
use anyhow::{Context, Result};
use caisson::analysis::lifetime::{life_statistics, simulate_life, LifeStatistics, StormOutcome, Structure};
use caisson::scenario::design::validate_design;
use caisson::scenario::waves::validate_waves;
use caisson::scenario::{parse_str, validate, Stepping};
use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;
use serde_json::{json, Value};
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::io::{BufRead, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

#[derive(serde::Serialize, serde::Deserialize)]
struct Header {
    caisson_design_checkpoint: u32,
    fingerprint: String,
    lives: usize,
}

#[derive(serde::Serialize, serde::Deserialize)]
struct LifeLine {
    life: usize,
    #[serde(flatten)]
    outcome: StormOutcome,
}

/// Lives already in a checkpoint (errors if it belongs to another run).
fn read_checkpoint(path: &Path, fingerprint: &str) -> Result<BTreeMap<usize, StormOutcome>> {
    let file = std::fs::File::open(path)
        .map_err(|e| input_err(format!("--resume: cannot read the checkpoint {}: {e}", path.display())))?;
    let mut lines = std::io::BufReader::new(file).lines();
    let header: Header =
        lines.next().and_then(|l| l.ok()).and_then(|l| serde_json::from_str(&l).ok()).ok_or_else(|| {
            input_err(format!("--resume: {} line 1 is not a caisson design checkpoint header", path.display()))
        })?;
    if header.fingerprint != fingerprint {
        return Err(input_err(format!(
            "--resume: the checkpoint {} was written for a different scenario or options (lives, seed, --brute-force); run without --resume to start again",
            path.display()
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

fn stats_json(s: &LifeStatistics, years: usize) -> Value {
    json!({
        "expected_sliding_m": s.mean_m,
        "expected_sliding_per_year_m": s.mean_m / years as f64,
        "percentiles_m": s.percentiles_m.iter().map(|(p, v)| (format!("p{}", *p as u32), json!(v))).collect::<serde_json::Map<_, _>>(),
        "exceedance_probability": s.exceedance.iter().map(|(t, p)| json!({"threshold_m": t, "probability": p})).collect::<Vec<_>>(),
    })
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
    let text = std::fs::read_to_string(&args.scenario)
        .map_err(|e| input_err(format!("cannot read scenario file {}: {e}", args.scenario.display())))?;
    let file = parse_str(&text, &args.scenario).map_err(input_err)?;
    let base = args.scenario.parent().unwrap_or(Path::new("."));
    let mut sc = validate(&file, base).map_err(input_err)?;
    let ws = validate_waves(&file, &sc.caisson).map_err(input_err)?;
    let mut spec = validate_design(&file).map_err(input_err)?;
    if let Some(n) = args.lives {
        if n == 0 {
            return Err(input_err("--lives 0: must be at least 1"));
        }
        spec.lives = n;
    }
    if args.brute_force {
        // Brute force: every wave through the dynamic model at the fixed step dt_s.
        spec.screen = false;
        sc.solver.stepping = Stepping::Fixed;
    }
    if let Some(dir) = &args.out {
        if dir.exists() && !dir.is_dir() {
            return Err(input_err(format!("--out {}: exists and is not a directory", dir.display())));
        }
    }
    let checkpoint: Option<PathBuf> =
        args.checkpoint.clone().or_else(|| args.out.as_ref().map(|d| d.join("checkpoint.jsonl")));
    if args.resume && checkpoint.is_none() {
        return Err(input_err(
            "--resume needs the checkpoint: give --out DIR (DIR/checkpoint.jsonl) or --checkpoint FILE",
        ));
    }
    set_threads(args.threads)?;
    let structure = Structure {
        caisson: &sc.caisson,
        foundation: &sc.foundation,
        solver: sc.solver,
        model: &ws.model,
        rigid_block_mu: ws.rigid_block_mu.unwrap_or(sc.foundation.mu_static),
        screen: spec.screen,
    };
    let fingerprint = format!("{text}\n--lives {} --brute-force {}", spec.lives, args.brute_force);
    let mut done = if args.resume {
        read_checkpoint(checkpoint.as_ref().expect("checked"), &fingerprint)?
    } else {
        BTreeMap::new()
    };
    done.retain(|&i, _| i < spec.lives);
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
                writeln!(
                    f,
                    "{}",
                    serde_json::to_string(&Header {
                        caisson_design_checkpoint: 1,
                        fingerprint: fingerprint.clone(),
                        lives: spec.lives
                    })?
                )?;
                f
            };
            f.flush()?;
            Some(Mutex::new(f))
        }
        None => None,
    };
    let todo: Vec<usize> = (0..spec.lives).filter(|i| !done.contains_key(i)).collect();
    let pb = ProgressBar::new(spec.lives as u64);
    pb.set_style(
        ProgressStyle::with_template("lives [{bar:40}] {pos}/{len}, {elapsed} elapsed, ~{eta} left")
            .expect("template")
            .progress_chars("=> "),
    );
    pb.set_position(done.len() as u64);
    let finished_now = AtomicUsize::new(0);
    let stop_after = args.stop_after.unwrap_or(usize::MAX);
    let results: Vec<Option<(usize, StormOutcome)>> = todo
        .par_iter()
        .map(|&i| -> Result<Option<(usize, StormOutcome)>> {
            if finished_now.load(Ordering::SeqCst) >= stop_after {
                return Ok(None);
            }
            let o = simulate_life(&structure, &spec.life, spec.seed, i).with_context(|| format!("life {i} failed"))?;
            if let Some(w) = &writer {
                let line = serde_json::to_string(&LifeLine { life: i, outcome: o })?;
                let mut f = w.lock().expect("checkpoint lock");
                writeln!(f, "{line}")?;
                f.flush()?;
            }
            finished_now.fetch_add(1, Ordering::SeqCst);
            pb.inc(1);
            Ok(Some((i, o)))
        })
        .collect::<Result<_>>()?;
    pb.finish_and_clear();
    for (i, o) in results.into_iter().flatten() {
        done.insert(i, o);
    }
    if done.len() < spec.lives {
        anyhow::bail!(
            "stopped after {} of {} lives (--stop-after); the finished lives are in {}; run again with --resume to complete",
            done.len(),
            spec.lives,
            checkpoint.as_ref().map_or("no checkpoint".into(), |p| p.display().to_string())
        );
    }
    let lives: Vec<StormOutcome> = done.into_values().collect();
    let dynamic: Vec<f64> = lives.iter().map(|l| l.sliding_m).collect();
    let rigid: Vec<f64> = lives.iter().map(|l| l.rigid_block_sliding_m).collect();
    let sd = life_statistics(&dynamic, &spec.thresholds_m);
    let sr = life_statistics(&rigid, &spec.thresholds_m);
    let waves: u64 = lives.iter().map(|l| l.waves).sum();
    let simulated: u64 = lives.iter().map(|l| l.simulated).sum();
    let screened: u64 = lives.iter().map(|l| l.screened).sum();
    let years = spec.life.life_years;
    let json = json!({
        "lives": spec.lives,
        "life_years": years,
        "seed": spec.seed,
        "screen": spec.screen,
        "dynamic": stats_json(&sd, years),
        "rigid_block": stats_json(&sr, years),
        "rigid_block_mu": structure.rigid_block_mu,
        "waves": waves,
        "simulated_waves": simulated,
        "screened_waves": screened,
        "screened_share": screened as f64 / waves.max(1) as f64,
    });
    check_finite(&json, "design")?;
    if args.json {
        crate::sayln!("{}", serde_json::to_string_pretty(&json)?);
    } else {
        let mut t = String::new();
        let _ = writeln!(
            t,
            "{} lives of {years} years (seed {}), {} waves, {} through the dynamic model, {:.4} % screened{}",
            spec.lives,
            spec.seed,
            waves,
            simulated,
            100.0 * screened as f64 / waves.max(1) as f64,
            if spec.screen { "" } else { " (screen off)" }
        );
        let _ = writeln!(t);
        let _ = writeln!(
            t,
            "                                  dynamic model   rigid block (Shimosako, μ = {})",
            structure.rigid_block_mu
        );
        let _ = writeln!(t, "expected sliding over the life   {:>10.4} m    {:>10.4} m", sd.mean_m, sr.mean_m);
        let _ = writeln!(
            t,
            "expected sliding per year        {:>10.5} m    {:>10.5} m",
            sd.mean_m / years as f64,
            sr.mean_m / years as f64
        );
        for ((p, a), (_, b)) in sd.percentiles_m.iter().zip(&sr.percentiles_m) {
            let _ = writeln!(t, "{:>3.0} % percentile                  {:>10.4} m    {:>10.4} m", p, a, b);
        }
        for ((th, a), (_, b)) in sd.exceedance.iter().zip(&sr.exceedance) {
            let _ = writeln!(t, "P(sliding > {:<5} m)             {:>10.4}      {:>10.4}", th, a, b);
        }
        crate::say!("{t}");
    }
    if let Some(dir) = &args.out {
        ensure_dir(dir)?;
        write_atomic(&dir.join("design.json"), serde_json::to_string_pretty(&json)?.as_bytes())?;
        write_atomic(&dir.join("lives.csv"), &lives_csv(&lives)?)?;
        let title = args.scenario.file_stem().and_then(|s| s.to_str()).unwrap_or("design");
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
