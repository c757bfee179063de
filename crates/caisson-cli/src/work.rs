//! The work budget of the commands that can run long (docs/cli.md, "Limits"): `run`, `campaign`,
//! `design`, `size` and `fragility` estimate their work with [`caisson::analysis::work`] before they
//! start and refuse a run over [`Budget::DEFAULT`] with an input error (exit 2) that gives the
//! estimate, the limit and what to change (the options and keys of the CLI, [`Advice`]); a long
//! run within the budget says its estimate on stderr. `merge` simulates nothing and is not
//! estimated.

use crate::input_err;
use anyhow::Result;
use caisson::analysis::work::{self, Advice, Budget, Histories, WorkEstimate};
use caisson::scenario::Scenario;

pub const RUN_LOAD: Advice = Advice {
    steps: "shorten `[load] duration_s` or raise `[solver] dt_s`",
    waves: "",
    memory: "shorten `[load] duration_s`",
    disk: "raise `[solver] output_interval_s` (fewer history rows; the summary's peaks still use every step), shorten `[load] duration_s`, or run without --out",
};

pub const RUN_WAVES: Advice = Advice {
    steps: "lower `[waves] waves` or `[waves] realizations`, or raise `[solver] dt_max_s` or `error_tolerance_m`",
    waves: "lower `[waves] waves` or `[waves] realizations`",
    memory: "lower `[waves] waves` or `[waves] realizations` (every wave is kept for the summary)",
    disk: "raise `[solver] output_interval_s` (fewer history rows of realization 0), lower `[waves] waves`, or run without --out",
};

pub const CAMPAIGN: Advice = Advice {
    steps: "lower `[waves] waves` or `[waves] realizations` or the number of `[campaign]` conditions, or raise `[solver] dt_max_s` or `error_tolerance_m`",
    waves: "lower `[waves] waves` or `[waves] realizations` or the number of `[campaign]` conditions",
    memory: "lower `[waves] waves` or `[waves] realizations` or the number of `[campaign]` conditions, or run without --out (campaign.json keeps every wave)",
    disk: "",
};

pub const DESIGN: Advice = Advice {
    steps: "lower --lives (or `[design] lives` or, with lives = \"auto\", `[design] max_lives`, or the lives of --life-range), `[design] life_years` or `[design] storm_duration_h`, or raise `[solver] dt_max_s` (with --brute-force, `[solver] dt_s`)",
    waves: "lower --lives (or `[design] lives` or, with lives = \"auto\", `[design] max_lives`, or the lives of --life-range), `[design] life_years` or `[design] storm_duration_h`",
    memory: "lower --lives (or `[design] lives` or, with lives = \"auto\", `[design] max_lives`, or the lives of --life-range)",
    disk: "",
};

pub const SIZE: Advice = Advice {
    steps: "lower `[size] lives` (with \"auto\", `[size] max_lives`), `[size] curve_points` or `[design] life_years`, raise `[size] tolerance_m` or narrow `[size] range_m`",
    waves: "lower `[size] lives` (with \"auto\", `[size] max_lives`), `[size] curve_points` or `[design] life_years`, raise `[size] tolerance_m` or narrow `[size] range_m`",
    memory: "lower `[size] lives`",
    disk: "",
};

pub const FRAGILITY: Advice = Advice {
    steps: "lower `[fragility] storms`, the number of `[fragility] significant_heights_m` or `[fragility] storm_duration_h`, or raise `[solver] dt_max_s`",
    waves: "lower `[fragility] storms`, the number of `[fragility] significant_heights_m` or `[fragility] storm_duration_h`",
    memory: "lower `[fragility] storms` or the number of `[fragility] significant_heights_m`",
    disk: "",
};

/// Refuse `e` if it is over the budget (naming `command`'s keys from `advice`); otherwise the
/// note to print on stderr when the run starts if it is long ([`say`]).
pub fn check(command: &str, e: &WorkEstimate, advice: &Advice) -> Result<Option<String>> {
    let b = Budget::DEFAULT;
    if let Some(refusal) = e.refusal(&b, &format!("caisson {command}"), advice) {
        return Err(input_err(refusal));
    }
    Ok(e.note(&b))
}

/// Print the note of [`check`], if any, as the run starts (after every input check, so that an
/// input error stays the first line on stderr).
pub fn say(note: Option<String>) {
    if let Some(n) = note {
        eprintln!("{n}");
    }
}

/// The estimate of `caisson run` on `sc` (a `[load]` run or wave trains), `out`: with --out (its
/// time histories streamed to files).
pub fn run_estimate(sc: &Scenario, out: bool) -> Option<(WorkEstimate, &'static Advice)> {
    let histories = if out { Histories::Streamed } else { Histories::None };
    if sc.load.is_some() {
        Some((work::run(sc.structure(), sc.duration_s, histories), &RUN_LOAD))
    } else {
        sc.train_case().ok().map(|case| (work::train(&case, histories), &RUN_WAVES))
    }
}

/// [`check`] of `caisson run` on `sc`.
pub fn check_run(sc: &Scenario, out: bool) -> Result<Option<String>> {
    match run_estimate(sc, out) {
        Some((e, advice)) => check("run", &e, advice),
        None => Ok(None),
    }
}
