//! The work budget of the commands that can run long (docs/cli.md, "Limits"): `run`, `campaign`,
//! `design` and `fragility` estimate their work with [`caisson::analysis::work`] before they
//! start and refuse a run over [`Budget::DEFAULT`] with an input error (exit 2) that gives the
//! estimate, the limit and what to change; a long run within the budget says its estimate on
//! stderr.

use crate::input_err;
use anyhow::Result;
use caisson::analysis::work::{self, Budget, Resource, WorkEstimate};
use caisson::scenario::Scenario;

/// Runs estimated at this many steps or waves or more say their estimate (about half a minute).
const LONG: f64 = 1e8;

/// What to change to lower each kind of work, in the words of the command's keys and options.
pub struct Advice {
    pub steps: &'static str,
    pub waves: &'static str,
    pub memory: &'static str,
}

pub const RUN_LOAD: Advice = Advice {
    steps: "shorten `[load] duration_s` or raise `[solver] dt_s`",
    waves: "",
    memory: "shorten `[load] duration_s`, raise `[solver] output_interval_s`, or run without --out (its time histories are held whole)",
};

pub const RUN_WAVES: Advice = Advice {
    steps: "lower `[waves] waves` or `[waves] realizations`, or raise `[solver] dt_max_s` or `error_tolerance_m`",
    waves: "lower `[waves] waves` or `[waves] realizations`",
    memory: "lower `[waves] waves` or `[waves] realizations` (every wave is kept for the summary), or raise `[solver] output_interval_s` (the time histories of --out)",
};

pub const CAMPAIGN: Advice = Advice {
    steps: "lower `[waves] waves` or `[waves] realizations` or the number of `[campaign]` conditions, or raise `[solver] dt_max_s` or `error_tolerance_m`",
    waves: "lower `[waves] waves` or `[waves] realizations` or the number of `[campaign]` conditions",
    memory: "lower `[waves] waves` or `[waves] realizations` or the number of `[campaign]` conditions, or run without --out (campaign.json keeps every wave)",
};

pub const DESIGN: Advice = Advice {
    steps: "lower --lives (or `[design] lives`), `[design] life_years` or `[design] storm_duration_h`, or raise `[solver] dt_max_s` (with --brute-force, `[solver] dt_s`)",
    waves: "lower --lives (or `[design] lives`), `[design] life_years` or `[design] storm_duration_h`",
    memory: "lower --lives (or `[design] lives`)",
};

pub const FRAGILITY: Advice = Advice {
    steps: "lower `[fragility] storms`, the number of `[fragility] significant_heights_m` or `[fragility] storm_duration_h`, or raise `[solver] dt_max_s`",
    waves: "lower `[fragility] storms`, the number of `[fragility] significant_heights_m` or `[fragility] storm_duration_h`",
    memory: "lower `[fragility] storms` or the number of `[fragility] significant_heights_m`",
};

/// `bytes` in words (MB, GB: powers of 1024).
pub fn bytes(b: f64) -> String {
    const MIB: f64 = 1024.0 * 1024.0;
    if b >= 1024.0 * MIB {
        format!("{:.1} GiB", b / (1024.0 * MIB))
    } else {
        format!("{:.1} MiB", b / MIB)
    }
}

/// Refuse `e` if it is over the budget (naming `command`'s keys from `advice`); otherwise the
/// note to print on stderr when the run starts if it is long ([`say`]).
pub fn check(command: &str, e: &WorkEstimate, advice: &Advice) -> Result<Option<String>> {
    let b = Budget::DEFAULT;
    if let Some((resource, estimate, _)) = e.excess(&b) {
        let (what, limit, change) = match resource {
            Resource::Steps => (
                format!(
                    "about {estimate:.2e} time steps of the dynamic model ({}; {:.3e} s of loading at {}{})",
                    e.basis,
                    e.simulated_s,
                    e.steps_from.describe(),
                    if e.step_cost == 1.0 {
                        String::new()
                    } else {
                        format!(
                            "; {:.2e} steps, each of {:.3} steps on 10 springs, the budget's unit",
                            e.steps, e.step_cost
                        )
                    }
                ),
                format!("{:.0e} time steps", b.steps),
                advice.steps,
            ),
            Resource::Waves => {
                (format!("about {estimate:.2e} waves ({})", e.basis), format!("{:.0e} waves", b.waves), advice.waves)
            }
            Resource::Memory => (
                format!("about {} of results held in memory ({})", bytes(estimate), e.basis),
                bytes(b.memory_bytes),
                advice.memory,
            ),
        };
        return Err(input_err(format!(
            "`caisson {command}` would take {what}; the budget is {limit} (docs/cli.md, Limits): {change}"
        )));
    }
    Ok((e.weighted_steps() >= LONG || e.waves >= LONG).then(|| {
        format!(
            "Estimated work: about {:.1e} time steps and {:.1e} waves, {} held ({}); the budget is {:.0e} steps, {:.0e} waves, {}",
            e.weighted_steps(),
            e.waves,
            bytes(e.memory_bytes),
            e.basis,
            b.steps,
            b.waves,
            bytes(b.memory_bytes)
        )
    }))
}

/// Print the note of [`check`], if any, as the run starts (after every input check, so that an
/// input error stays the first line on stderr).
pub fn say(note: Option<String>) {
    if let Some(n) = note {
        eprintln!("{n}");
    }
}

/// The estimate of `caisson run` on `sc` (a `[load]` run or wave trains), `out`: with --out.
pub fn run_estimate(sc: &Scenario, out: bool) -> Option<(WorkEstimate, &'static Advice)> {
    if sc.load.is_some() {
        Some((work::run(sc.structure(), sc.duration_s, out), &RUN_LOAD))
    } else {
        sc.train_case().ok().map(|case| (work::train(&case, out), &RUN_WAVES))
    }
}

/// [`check`] of `caisson run` on `sc`.
pub fn check_run(sc: &Scenario, out: bool) -> Result<Option<String>> {
    match run_estimate(sc, out) {
        Some((e, advice)) => check("run", &e, advice),
        None => Ok(None),
    }
}
