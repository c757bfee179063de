//! Command-line definitions (clap). Thin: the counts are bounded here (a finite allowed range for
//! every numeric option, refused by the parser with an `Error:` naming the option); everything
//! that needs the scenario is validated in the command modules.

use clap::{Args, Parser, Subcommand};
use std::path::PathBuf;

/// Most worker threads `--threads` accepts (0: one per core).
pub const MAX_THREADS: usize = caisson::MAX_THREADS;
/// Most lives `--lives` accepts: the cap of `[design] lives`.
pub const MAX_LIVES: usize = caisson::scenario::design::MAX_LIVES;

/// A whole number from `lo` to `hi`, or a message that gives the range.
fn whole_in(s: &str, lo: usize, hi: usize) -> Result<usize, String> {
    match s.trim().parse::<u64>() {
        Ok(n) if (lo as u64..=hi as u64).contains(&n) => Ok(n as usize),
        _ => Err(format!("must be a whole number from {lo} to {hi}")),
    }
}

/// `--threads`: 0 (one per core) to [`MAX_THREADS`].
fn threads(s: &str) -> Result<usize, String> {
    whole_in(s, 0, MAX_THREADS).map_err(|e| format!("{e} (0: one per core)"))
}

/// `--lives`: 1 to [`MAX_LIVES`], as `[design] lives`.
fn lives(s: &str) -> Result<usize, String> {
    whole_in(s, 1, MAX_LIVES).map_err(|e| format!("{e}, as `[design] lives`"))
}

/// `--life-range START..END`: whole numbers, START < END ≤ [`MAX_LIVES`] (END exclusive).
fn life_range(s: &str) -> Result<std::ops::Range<usize>, String> {
    let bad = || {
        format!(
            "must be START..END, whole numbers with START < END ≤ {MAX_LIVES} (END exclusive: 0..100 is lives 0 to 99)"
        )
    };
    let (a, b) = s.trim().split_once("..").ok_or_else(bad)?;
    let (a, b) = (a.trim().parse::<u64>().map_err(|_| bad())?, b.trim().parse::<u64>().map_err(|_| bad())?);
    if a < b && b <= MAX_LIVES as u64 {
        Ok(a as usize..b as usize)
    } else {
        Err(bad())
    }
}

#[derive(Parser, Debug)]
#[command(
    name = "caisson",
    version,
    about = "Dynamic sliding of caisson breakwaters under breaking and non-breaking waves"
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Run a scenario through the dynamic model and summarise the response.
    Run(RunArgs),
    /// Sweep the rise time of the scenario's triangular pulse: amplification Ψ and sliding vs t_r/T0.
    Spectrum(SpectrumArgs),
    /// Wave loads for the scenario's waves: Goda, Sainflou, impact, safety factors, histories.
    Loads(LoadsArgs),
    /// Run a grid of test conditions (heights × weights × regimes), many wave trains each.
    Campaign(CampaignArgs),
    /// Regenerate the validation report (validation.md and figures) against the seed paper.
    Validation(ValidationArgs),
    /// Lifetime Monte Carlo of performance-based design: expected sliding, percentiles, exceedance.
    Design(DesignArgs),
    /// Fragility curves: P(storm sliding > limit) against H1/3 at the structure, lognormal fits.
    Fragility(FragilityArgs),
    /// Sizing: the smallest caisson width whose lifetime sliding meets the `[size]` criterion.
    Size(SizeArgs),
    /// Merge the shards of a design run (`design --life-range`) into the outputs of one run.
    Merge(MergeArgs),
    /// A calculation note (report.html, and report.pdf where Chromium is found) of one scenario,
    /// or of several side by side.
    Report(ReportArgs),
}

#[derive(Args, Debug)]
pub struct ReportArgs {
    /// Scenario files (TOML); two or more are set side by side as alternatives.
    #[arg(required = true, value_name = "SCENARIO")]
    pub scenarios: Vec<PathBuf>,
    /// Write report.html (and report.pdf) here.
    #[arg(long, value_name = "DIR", required = true)]
    pub out: PathBuf,
    /// Worker threads (0: one per core). Results do not depend on it.
    #[arg(long, default_value_t = 0, value_parser = threads)]
    pub threads: usize,
    /// Do not print the PDF even where Chromium is found.
    #[arg(long)]
    pub no_pdf: bool,
}

#[derive(Args, Debug)]
pub struct RunArgs {
    /// Scenario file (TOML).
    pub scenario: PathBuf,
    /// Print the summary as JSON instead of text.
    #[arg(long)]
    pub json: bool,
    /// Write summary.json, history.csv, springs.csv and SVG plots into this directory.
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    /// Worker threads for wave-train realizations (0: one per core). Results do not depend on it.
    #[arg(long, default_value_t = 0, value_parser = threads)]
    pub threads: usize,
}

#[derive(Args, Debug)]
pub struct DesignArgs {
    /// Design file (TOML): a wave scenario with a `[design]` table.
    pub scenario: PathBuf,
    /// Print the results as JSON.
    #[arg(long)]
    pub json: bool,
    /// Write design.json, lives.csv, histogram.svg, exceedance.svg and the checkpoint here.
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    /// Worker threads (0: one per core). Results do not depend on it.
    #[arg(long, default_value_t = 0, value_parser = threads)]
    pub threads: usize,
    /// Override `[design] lives` (1 to 10000000): exactly N lives, `lives = "auto"` off.
    #[arg(long, value_parser = lives)]
    pub lives: Option<usize>,
    /// Run only lives START..END (END exclusive) as a shard: its checkpoint and lives.csv in
    /// --out, no statistics; `caisson merge` joins the shards. Instead of --lives.
    #[arg(long, value_name = "START..END", value_parser = life_range, conflicts_with_all = ["lives", "json"], requires = "out")]
    pub life_range: Option<std::ops::Range<usize>>,
    /// Complete an interrupted run from its checkpoint (identical results).
    #[arg(long)]
    pub resume: bool,
    /// Checkpoint file (default DIR/checkpoint.jsonl with --out; none otherwise).
    #[arg(long, value_name = "FILE")]
    pub checkpoint: Option<PathBuf>,
    /// Brute force for comparison: no screen, fixed time step dt_s.
    #[arg(long)]
    pub brute_force: bool,
    /// Stop after this many lives (to exercise --resume).
    #[arg(long, hide = true)]
    pub stop_after: Option<usize>,
}

#[derive(Args, Debug)]
pub struct SizeArgs {
    /// Sizing file (TOML): a design scenario (`[design]`) with a `[size]` table and the caisson's
    /// construction.
    pub scenario: PathBuf,
    /// Print the results as JSON.
    #[arg(long)]
    pub json: bool,
    /// Write size.json, candidates.csv, design_curve.svg and the checkpoint here.
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    /// Worker threads (0: one per core). Results do not depend on it.
    #[arg(long, default_value_t = 0, value_parser = threads)]
    pub threads: usize,
    /// Complete an interrupted run from DIR/size_checkpoint.jsonl (identical results).
    #[arg(long)]
    pub resume: bool,
}

#[derive(Args, Debug)]
pub struct MergeArgs {
    /// Design file (TOML) the shards were run from: its statistics settings, warnings and plot title.
    pub scenario: PathBuf,
    /// The shards: each the --out directory of a `caisson design --life-range` run (its
    /// checkpoint.jsonl) or a checkpoint file.
    #[arg(required = true, value_name = "SHARD")]
    pub shards: Vec<PathBuf>,
    /// Write design.json, lives.csv, histogram.svg, exceedance.svg and the merged checkpoint here.
    #[arg(long, value_name = "DIR", required = true)]
    pub out: PathBuf,
    /// The lives the shards must cover, 0..N (default `[design] lives`; 1 to 10000000).
    #[arg(long, value_parser = lives)]
    pub lives: Option<usize>,
    /// Print the results as JSON.
    #[arg(long)]
    pub json: bool,
}

#[derive(Args, Debug)]
pub struct FragilityArgs {
    /// Fragility file (TOML): an irregular-wave scenario with a `[fragility]` table.
    pub scenario: PathBuf,
    /// Print the results as JSON.
    #[arg(long)]
    pub json: bool,
    /// Write fragility.json, fragility.csv and fragility.svg into this directory.
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    /// Worker threads (0: one per core). Results do not depend on it.
    #[arg(long, default_value_t = 0, value_parser = threads)]
    pub threads: usize,
}

#[derive(Args, Debug)]
pub struct ValidationArgs {
    /// Directory for validation.md (figures go to DIR/figures).
    #[arg(long, value_name = "DIR", default_value = "docs")]
    pub out: PathBuf,
}

#[derive(Args, Debug)]
pub struct CampaignArgs {
    /// Campaign file (TOML): a wave scenario with a `[campaign]` table.
    pub campaign: PathBuf,
    /// Print the results as JSON.
    #[arg(long)]
    pub json: bool,
    /// Write campaign.json, campaign.csv and SVG plots into this directory.
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    /// Worker threads (0: one per core). Results do not depend on it.
    #[arg(long, default_value_t = 0, value_parser = threads)]
    pub threads: usize,
    /// Override the foundation's damping_mode for every condition ("total" or "elastic").
    #[arg(long, value_name = "MODE")]
    pub damping_mode: Option<String>,
}

#[derive(Args, Debug)]
pub struct SpectrumArgs {
    /// Scenario file (TOML) with a `[load] kind = "triangle"` table.
    pub scenario: PathBuf,
    /// Range of t_r/T0 as FROM:TO:COUNT (logarithmically spaced).
    #[arg(long, value_name = "FROM:TO:COUNT", default_value = "0.05:5:60")]
    pub tr_over_t0: String,
    /// Print the table as JSON.
    #[arg(long)]
    pub json: bool,
    /// Write spectrum.csv, spectrum.json and spectrum.svg into this directory.
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
}

#[derive(Args, Debug)]
pub struct LoadsArgs {
    /// Scenario file (TOML) with `[caisson]`, `[water]` and `[waves]` tables.
    pub scenario: PathBuf,
    /// Print the quantities as JSON.
    #[arg(long)]
    pub json: bool,
    /// Also generate the force time history of a train of waves (needs --out).
    #[arg(long)]
    pub history: bool,
    /// Number of waves in the generated history (1 to 1030: at most 500000 rows).
    #[arg(long, default_value_t = 5)]
    pub waves: usize,
    /// Seed of the random generator (rise times).
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Directory for the history CSV and SVG.
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
}
