//! Property test over generated scenarios (issue 12): mutations of the bundled examples (numbers
//! scaled by 10^±k, signs flipped, 0, NaN/inf, the extremes of f64, a whole number beyond TOML's,
//! keys dropped; each number of a one-line list too), and of the examples with the keys they
//! leave at their defaults written out ([`EXAMPLES`]: the foundation given directly, the reference
//! stress, the rigid block's μ, untruncated friction errors, the climate, the sizing example;
//! issue 37). For each:
//!
//! * **in process** (thousands of cases, fast): `Scenario::from_toml` (and the `[campaign]`,
//!   `[fragility]` or `[size]` that only its command reads) either refuses with an error naming a
//!   key (`[table] key`) and printing no number in full ([`MAX_DIGITS_IN_A_ROW`]) or gives a
//!   scenario whose short run (at most
//!   [`SHORT_STEPS`] steps of `dt_s` of a `[load]` run, one wave of one realization of a wave
//!   train, the storm case of a design) succeeds with finite numbers; never a panic, never a
//!   failed run on a scenario that validation accepted, and each case within [`CASE_BUDGET`].
//! * **through the binary** (a smaller sample): `caisson run|loads|campaign|design|fragility
//!   --json` under a time limit ([`CHILD_TIMEOUT`], then it is killed) and an address-space limit
//!   ([`CHILD_MEMORY_KB`], `ulimit -v`): exit 0 with finite JSON, or exit 2 with `Error:` naming a
//!   key, and no message (nor warning) printing a number in full; never a panic (101), a signal, a
//!   hang or the memory limit.
//!
//! Size: `CAISSON_FUZZ_CASES` (default 8000) in-process cases and `CAISSON_FUZZ_BIN_CASES`
//! (default 80) binary cases; CI runs the defaults (20 to 30 s on 2 cores). To search longer:
//! `CAISSON_FUZZ_CASES=100000 CAISSON_FUZZ_BIN_CASES=2000 cargo test --release -p caisson-cli
//! --test cli_fuzz_scenarios -- --nocapture` (CONTRIBUTING.md). A failure is shrunk by proptest to
//! a minimal mutation list and printed with the scenario text and the seed. The cases come from
//! a fixed seed, so the suite checks the same cases on every run and cannot fail by chance; a
//! longer search sets `CAISSON_FUZZ_SEED=N` (any u64) to explore other cases, and a finding
//! becomes a named regression test (`crates/caisson/tests/verify_findings.rs`).
//!
//! Work-size keys (`duration_s`, `dt_s`, counts such as `waves`, `realizations`, `lives`) are
//! mutated like the others: before a binary case runs, its work is estimated in process as the
//! command estimates it (`caisson::analysis::work`). Over the budget, the binary must refuse it
//! (exit 2); within the budget but longer than a case may take ([`QUICK_CPU_S`] of estimated
//! CPU, [`QUICK_MEMORY_BYTES`]), it is counted and not run; otherwise it runs, and a run that
//! does not end within [`CHILD_TIMEOUT`] is a failure (of the command or of its estimate). The
//! fragility example runs in the binary sample with 5 storms per height instead of 100, and
//! `design` with `--lives 2`, so that most of their cases are quick.

use proptest::prelude::*;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// Most time steps of the in-process short run of a `[load]` scenario.
const SHORT_STEPS: f64 = 400.0;
/// Wall time allowed for one in-process case (validation + short run).
const CASE_BUDGET: Duration = Duration::from_secs(10);
/// Wall time allowed for one binary case before it is killed and the case fails.
const CHILD_TIMEOUT: Duration = Duration::from_secs(20);
/// Address space allowed for one binary case, KiB (1 GiB).
const CHILD_MEMORY_KB: u64 = 1 << 20;

fn examples_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

/// The bundled examples that are scenarios, and the command each is run with in the binary
/// sample; then the examples with keys they leave at their defaults written out (each edit
/// replaces its text once), so that those keys are mutated too: the foundation's numbers given
/// directly and the soil's reference stress, the rigid block's μ, untruncated friction errors, the
/// climate (`design_climate.toml`) and the sizing example (its `[size]` checked in process, its
/// `[design]` run by the binary).
const EXAMPLES: [(&str, &str); 16] = [
    ("table5_triangle.toml", "run"),
    ("table5_series.toml", "run"),
    ("fifteen_waves.toml", "run"),
    ("pari_breaking_loads.toml", "loads"),
    ("pari_nonbreaking_loads.toml", "run"),
    ("pari_breaking_campaign.toml", "campaign"),
    ("pari_nonbreaking_campaign.toml", "campaign"),
    ("design_breakwater.toml", "design"),
    ("fragility.toml", "fragility"),
    ("caisson_geometry.toml", "run"),
    ("table5_triangle.toml", "run"),
    ("fifteen_waves.toml", "run"),
    ("design_breakwater.toml", "design"),
    ("design_climate.toml", "design"),
    ("fragility.toml", "fragility"),
    ("size_breakwater.toml", "design"),
];

/// The edits of the example `EXAMPLES[i]` (none for the first ten).
fn edits(i: usize) -> &'static [(&'static str, &'static str)] {
    const DIRECT: &str = "e100_kpa = 3.5e5\nkx_kn_per_m = 1.511e5\nky_kn_per_m = 1.404e5\ndamping_kns_per_m = 598.0\nreference_stress_kpa = 100.0";
    match i {
        10 => &[("e100_kpa = 3.5e5", DIRECT)],
        11 => &[("e100_kpa = 3.5e5", "e100_kpa = 3.5e5\nreference_stress_kpa = 100.0")],
        12 => &[
            ("period_s = 12.8\n", "period_s = 12.8\nrigid_block_mu = 0.6\n"),
            (
                "tidal_range_m = 2.0",
                "tidal_range_m = 2.0\nerror_truncated = false\nfriction_bias = 0.0\nfriction_cov = 0.25",
            ),
        ],
        14 | 15 => &[(
            "e100_kpa = 3.5e5",
            "e100_kpa = 3.5e5\nkx_kn_per_m = 2.9e5\nky_kn_per_m = 2.7e5\ndamping_kns_per_m = 2e4",
        )],
        _ => &[],
    }
}

fn example_text(i: usize) -> String {
    let text = std::fs::read_to_string(examples_dir().join(EXAMPLES[i].0)).unwrap();
    edits(i).iter().fold(text, |t, (from, to)| {
        assert!(t.contains(from), "{}: `{from}` is in the text", EXAMPLES[i].0);
        t.replacen(from, to, 1)
    })
}

/// One mutation of a numeric `key = value` line (or of one number of a `key = [...]` list).
#[derive(Debug, Clone)]
enum Op {
    /// × 10^k.
    Scale(i32),
    Negate,
    Zero,
    /// `nan`, `inf`, `-inf`, 5e-324, 1.7976931348623157e308, 99999999999999999999 (a whole
    /// number beyond TOML's).
    Special(usize),
    Drop,
}

/// The special values of [`Op::Special`].
const SPECIALS: [&str; 6] = ["nan", "inf", "-inf", "5e-324", "1.7976931348623157e308", "99999999999999999999"];

fn op() -> impl Strategy<Value = Op> {
    prop_oneof![
        5 => (-4i32..=4).prop_map(Op::Scale),
        2 => (-12i32..=12).prop_map(Op::Scale),
        1 => prop_oneof![Just(-300i32), Just(-160), Just(160), Just(300)].prop_map(Op::Scale),
        2 => Just(Op::Negate),
        1 => Just(Op::Zero),
        2 => (0usize..SPECIALS.len()).prop_map(Op::Special),
        2 => Just(Op::Drop),
    ]
}

/// A number of the text: its (table, key, line index, value, element), `element` its index in a
/// one-line list of numbers `key = [a, b, ...]` (`None`: the line's value).
type Numeric = (String, String, usize, String, Option<usize>);

/// The numbers of a one-line list of numbers `[a, b, ...]`, or `None`.
fn number_list(v: &str) -> Option<Vec<&str>> {
    let inner = v.strip_prefix('[')?.strip_suffix(']')?;
    let items: Vec<&str> = inner.split(',').map(str::trim).filter(|x| !x.is_empty()).collect();
    (!items.is_empty() && items.iter().all(|x| x.parse::<f64>().is_ok())).then_some(items)
}

/// Every number of `text`: each line `key = <number>` and each number of a line `key = [...]`.
fn numeric_lines(text: &str) -> Vec<Numeric> {
    let mut table = String::new();
    let mut out = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let l = line.split('#').next().unwrap_or("").trim();
        if l.starts_with('[') {
            table = l.to_string();
            continue;
        }
        let Some((k, v)) = l.split_once('=') else { continue };
        let v = v.trim();
        if v.parse::<f64>().is_ok() {
            out.push((table.clone(), k.trim().to_string(), i, v.to_string(), None));
        } else if let Some(items) = number_list(v) {
            for (j, x) in items.iter().enumerate() {
                out.push((table.clone(), k.trim().to_string(), i, x.to_string(), Some(j)));
            }
        }
    }
    out
}

/// Apply `ops` (each on line `sel % n` of the numeric lines). Returns the text and a description
/// of what was changed.
fn mutate(text: &str, ops: &[(usize, Op)]) -> (String, Vec<String>) {
    let nums = numeric_lines(text);
    let mut lines: Vec<Option<String>> = text.lines().map(|l| Some(l.to_string())).collect();
    let mut what = Vec::new();
    for (sel, op) in ops {
        let (table, key, i, v, element) = &nums[sel % nums.len()];
        let Some(current) = lines[*i].clone() else { continue };
        let value = current.split_once('=').map(|(_, v)| v.split('#').next().unwrap_or("").trim().to_string());
        let value = value.unwrap_or_else(|| v.clone());
        if let Some(j) = element {
            // One number of a list: mutated as a number (dropped from the list by `Drop`).
            let Some(items) = number_list(&value) else { continue };
            let Some(&x) = items.get(*j) else { continue };
            let (new, _) = mutate(&format!("[t]\nk = {x}\n"), &[(0, op.clone())]);
            let new = new.lines().nth(1).and_then(|l| l.strip_prefix("k = ")).map(str::to_string);
            let mut list: Vec<String> = items.iter().map(|s| s.to_string()).collect();
            match &new {
                Some(n) => list[*j] = n.clone(),
                None => {
                    list.remove(*j);
                }
            }
            what.push(format!("{table} {key}[{j}]: {x} -> {}", new.as_deref().unwrap_or("(dropped)")));
            lines[*i] = Some(format!("{key} = [{}]", list.join(", ")));
            continue;
        }
        let integer = value.parse::<i64>().is_ok();
        let x: f64 = value.parse().unwrap_or(0.0);
        let new = match op {
            Op::Drop => None,
            Op::Scale(k) if integer => {
                let n: i64 = value.parse().unwrap();
                Some(if *k >= 0 {
                    n.saturating_mul(10i64.saturating_pow(*k as u32)).to_string()
                } else {
                    (n / 10i64.saturating_pow((-*k) as u32)).to_string()
                })
            }
            Op::Scale(k) => Some(format!("{:e}", x * 10f64.powi(*k))),
            Op::Negate if integer => Some(format!("{}", -value.parse::<i64>().unwrap())),
            Op::Negate => Some(format!("{:e}", -x)),
            Op::Zero => Some(if integer { "0".into() } else { "0.0".into() }),
            Op::Special(s) => Some(SPECIALS[*s].to_string()),
        };
        what.push(format!("{table} {key}: {value} -> {}", new.as_deref().unwrap_or("(dropped)")));
        lines[*i] = new.map(|n| format!("{key} = {n}"));
    }
    (lines.into_iter().flatten().collect::<Vec<_>>().join("\n") + "\n", what)
}

/// Whether an error message names a key of the file: `[table] key` (or the table), or the line
/// of a TOML type error with its text (`line 48, column 14: ... (in `life_years = nan`)`).
fn names_a_key(msg: &str) -> bool {
    (msg.contains('[') && msg.contains(']')) || (msg.contains(" line ") && msg.contains("(in `"))
}

/// The most digits in a row a message may print: a 20-digit whole number given in the file is shown
/// as given; a number printed in full (1e-300 written out: 300 digits) is a defect of the message.
const MAX_DIGITS_IN_A_ROW: usize = 20;

/// Whether `msg` prints a number in full (more than [`MAX_DIGITS_IN_A_ROW`] digits in a row).
fn prints_a_long_number(msg: &str) -> bool {
    msg.split(|c: char| !c.is_ascii_digit()).any(|d| d.len() > MAX_DIGITS_IN_A_ROW)
}

/// Refuse a non-finite number (null: serde_json's NaN) anywhere in `v`.
fn all_finite(v: &serde_json::Value) -> bool {
    use serde_json::Value;
    match v {
        Value::Null => false,
        Value::Number(n) => n.as_f64().is_some_and(f64::is_finite),
        Value::Array(a) => a.iter().all(all_finite),
        // A percentile's interval has an open end (null) where the lives are too few for it
        // (docs/design.md, "Intervals"); its other numbers are finite.
        Value::Object(m) => m.iter().all(|(k, v)| {
            if k == "percentiles_ci95_m" {
                v.as_object().is_some_and(|o| {
                    o.values()
                        .flat_map(|pair| pair.as_array().into_iter().flatten())
                        .all(|e| e.is_null() || all_finite(e))
                })
            } else {
                all_finite(v)
            }
        }),
        _ => true,
    }
}

/// The in-process check of one scenario text; Err describes the failure.
fn check_in_process(name: &str, text: &str) -> Result<&'static str, String> {
    use caisson::scenario::Scenario;
    let path = examples_dir().join(name);
    let refusal = |msg: String| {
        if !names_a_key(&msg) {
            Err(format!("error names no key: {msg}"))
        } else if prints_a_long_number(&msg) {
            Err(format!("error prints a number in full: {msg}"))
        } else {
            Ok("refused")
        }
    };
    let sc = match Scenario::from_toml(text, &path, &examples_dir()) {
        Err(e) => return refusal(e.to_string()),
        Ok(sc) => sc,
    };
    // The tables only their command reads are refused when it asks for them.
    let deferred = [
        sc.has_campaign_table().then(|| sc.campaign().err()).flatten(),
        sc.has_fragility_table().then(|| sc.fragility_for("a fragility run").err()).flatten(),
        text.contains("\n[size]").then(|| sc.size_for("a sizing run").err()).flatten(),
    ];
    if let Some(e) = deferred.into_iter().flatten().next() {
        return refusal(e.to_string());
    }
    if let Some(load) = &sc.load {
        let duration = sc.duration_s.min(SHORT_STEPS * sc.solver().dt_s);
        let r = caisson::analysis::run::run(sc.structure(), load, duration, false)
            .map_err(|e| format!("a validated [load] scenario failed to run: {e}"))?;
        let v = serde_json::to_value(&r.summary).unwrap();
        if !all_finite(&v) {
            return Err(format!("non-finite run summary: {v}"));
        }
        return Ok("ran");
    }
    if let Some(ws) = &sc.waves {
        if sc.design.is_some() || sc.fragility.is_some() {
            sc.storm_case(true).map_err(|e| format!("a validated design scenario has no storm case: {e}"))?;
            return Ok("storm case");
        }
        let mut one = ws.clone();
        one.train.waves = 1;
        one.train.realizations = 1;
        let case = caisson::analysis::train::TrainCase { structure: sc.structure(), waves: &one };
        let r = case.run(0, None).map_err(|e| format!("a validated wave scenario failed to run one wave: {e}"))?;
        let finite = [r.sliding_m, r.rigid_block_sliding_m, r.max_horizontal_reaction_n]
            .iter()
            .chain(r.waves.iter().map(|w| &w.sliding_m))
            .all(|x| x.is_finite());
        if !finite {
            return Err(format!("non-finite wave-train result: {r:?}"));
        }
        return Ok("ran a wave");
    }
    Ok("validated")
}

/// The seed of the generated cases: fixed, so that a run of the suite checks the same cases
/// every time and never fails by chance; `CAISSON_FUZZ_SEED` searches elsewhere.
fn fuzz_seed() -> u64 {
    std::env::var("CAISSON_FUZZ_SEED").ok().and_then(|v| v.parse().ok()).unwrap_or(20_261_123)
}

fn cases(var: &str, default: u32) -> u32 {
    std::env::var(var).ok().and_then(|v| v.parse().ok()).unwrap_or(default)
}

fn mutations() -> impl Strategy<Value = (usize, Vec<(usize, Op)>)> {
    (0..EXAMPLES.len(), prop::collection::vec((0usize..1000, op()), 1..=3))
}

/// Run `check` on `cases` generated mutation lists of the examples as `base` gives them;
/// returns how many were checked.
fn run_cases(
    cases: u32,
    max_shrink_iters: u32,
    base: fn(usize) -> String,
    check: impl Fn(usize, &str, &[String]) -> Result<(), TestCaseError>,
) -> usize {
    use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
    use std::sync::atomic::{AtomicUsize, Ordering};
    let checked = AtomicUsize::new(0);
    let seed = fuzz_seed();
    let rng = TestRng::from_seed(RngAlgorithm::ChaCha, &[seed.to_le_bytes(); 4].concat());
    let config = Config { cases, max_shrink_iters, failure_persistence: None, ..Config::default() };
    let mut runner = TestRunner::new_with_rng(config, rng);
    let result = runner.run(&mutations(), |(ex, ops)| {
        let (text, what) = mutate(&base(ex), &ops);
        check(ex, &text, &what)?;
        checked.fetch_add(1, Ordering::Relaxed);
        Ok(())
    });
    if let Err(e) = result {
        panic!("{e} (CAISSON_FUZZ_SEED={seed})");
    }
    checked.into_inner()
}

#[test]
fn mutated_scenarios_are_refused_by_key_or_run_finite_in_process() {
    let n = cases("CAISSON_FUZZ_CASES", 8000);
    let start = Instant::now();
    let checked = run_cases(n, 200, example_text, |ex, text, what| {
        let t0 = Instant::now();
        let outcome = std::panic::catch_unwind(|| check_in_process(EXAMPLES[ex].0, text));
        let elapsed = t0.elapsed();
        match outcome {
            Err(_) => prop_assert!(false, "panic on {} with {what:?}", EXAMPLES[ex].0),
            Ok(Err(e)) => prop_assert!(false, "{} with {what:?}: {e}", EXAMPLES[ex].0),
            Ok(Ok(_)) => {}
        }
        prop_assert!(elapsed < CASE_BUDGET, "{} with {what:?} took {elapsed:?}", EXAMPLES[ex].0);
        Ok(())
    });
    println!("in process: {checked} scenarios checked in {:?}", start.elapsed());
    assert!(checked >= n as usize, "every generated case was checked: {checked} of {n}");
}

/// The start of the error of a binary case that was killed at [`CHILD_TIMEOUT`].
const TIMEOUT: &str = "no answer within";

/// Estimated CPU time of a binary case that is run, at most, s: within the budget but longer, a
/// case is counted and not run. A fifth of [`CHILD_TIMEOUT`], at [`S_PER_STEP`] and
/// [`S_PER_WAVE`]: about three times the measured costs (0.35 µs a step, 0.17 µs a drawn wave,
/// BENCHMARKS.md), so that a case run on a loaded machine still ends in time.
const QUICK_CPU_S: f64 = 4.0;
const S_PER_STEP: f64 = 1e-6;
const S_PER_WAVE: f64 = 5e-7;
/// Estimated memory of a binary case that is run, at most (a quarter of [`CHILD_MEMORY_KB`]).
const QUICK_MEMORY_BYTES: f64 = 256.0 * 1024.0 * 1024.0;

/// What to expect of a binary case, from its work estimated in process as the command does.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Plan {
    /// Over the budget: the binary must refuse it (exit 2, naming the budget).
    OverBudget,
    /// Within the budget but longer than a case may take: not run.
    Long,
    /// Run it (refused by validation, or quick).
    Run,
}

/// The plan of `caisson cmd` on `text` (module docs), and the estimate in words.
fn plan(name: &str, cmd: &str, text: &str) -> (Plan, String) {
    use caisson::analysis::work::{self, Budget, Histories};
    let Ok(sc) = caisson::scenario::Scenario::from_toml(text, &examples_dir().join(name), &examples_dir()) else {
        return (Plan::Run, "refused by validation".into());
    };
    let estimate = match cmd {
        "run" if sc.load.is_some() => Some(work::run(sc.structure(), sc.duration_s, Histories::None)),
        "run" => sc.train_case().ok().map(|c| work::train(&c, Histories::None)),
        "campaign" => sc.campaign().ok().map(|c| work::campaign(&c.setups, false)),
        "design" => sc.design.clone().and_then(|mut d| {
            d.lives = 2;
            let case = sc.storm_case(d.screen).ok()?;
            Some(work::design(&case, &d, sc.waves.as_ref()?))
        }),
        "fragility" => sc.fragility.as_ref().and_then(|p| Some(work::fragility(&sc.storm_case(true).ok()?, p))),
        _ => None,
    };
    let Some(e) = estimate else { return (Plan::Run, "no estimate".into()) };
    let words =
        format!("{:.2e} weighted steps, {:.2e} waves, {:.0} MB", e.weighted_steps(), e.waves, e.memory_bytes / 1e6);
    if e.excess(&Budget::DEFAULT).is_some() {
        (Plan::OverBudget, words)
    } else if e.weighted_steps() * S_PER_STEP + e.waves * S_PER_WAVE > QUICK_CPU_S
        || e.memory_bytes > QUICK_MEMORY_BYTES
    {
        (Plan::Long, words)
    } else {
        (Plan::Run, words)
    }
}

/// The examples as the binary sample mutates them: the fragility example with 5 storms per
/// height (100 take 6 s on 2 cores, too long for a case).
fn binary_base(i: usize) -> String {
    let text = example_text(i);
    if EXAMPLES[i].1 == "fragility" {
        assert!(text.contains("\nstorms = 100 "), "the fragility example sets 100 storms");
        text.replacen("\nstorms = 100 ", "\nstorms = 5 ", 1)
    } else {
        text
    }
}

/// Run the binary on `text` (written beside a copy of the examples' series file) under the time
/// and memory limits; Err describes the failure.
#[cfg(unix)]
fn check_binary(dir: &Path, cmd: &str, text: &str) -> Result<(i32, String), String> {
    use std::io::Read;
    let file = dir.join("case.toml");
    std::fs::write(&file, text).unwrap();
    let bin = assert_cmd::cargo::cargo_bin("caisson");
    let mut args: Vec<String> = vec![cmd.into(), file.to_str().unwrap().into(), "--json".into()];
    if cmd == "design" {
        args.extend(["--lives".into(), "2".into()]);
    }
    if cmd != "loads" {
        args.extend(["--threads".into(), "1".into()]);
    }
    let script = format!("ulimit -v {CHILD_MEMORY_KB}; exec \"$0\" \"$@\"");
    let mut child = std::process::Command::new("sh")
        .arg("-c")
        .arg(script)
        .arg(&bin)
        .args(&args)
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let mut stdout = child.stdout.take().unwrap();
    let reader = std::thread::spawn(move || {
        let mut s = Vec::new();
        let _ = stdout.read_to_end(&mut s);
        s
    });
    let start = Instant::now();
    let status = loop {
        if let Some(s) = child.try_wait().unwrap() {
            break s;
        }
        if start.elapsed() > CHILD_TIMEOUT {
            let _ = child.kill();
            let _ = child.wait();
            return Err(format!("{TIMEOUT} {CHILD_TIMEOUT:?} (killed)"));
        }
        std::thread::sleep(Duration::from_millis(5));
    };
    let out = reader.join().unwrap();
    let mut err = String::new();
    child.stderr.take().unwrap().read_to_string(&mut err).unwrap();
    match status.code() {
        Some(0) => {
            let v: serde_json::Value = serde_json::from_slice(&out).map_err(|e| format!("exit 0, no JSON: {e}"))?;
            // `loads` writes null for an absent value; its numbers are checked by the binary.
            if cmd != "loads" && !all_finite(&v) {
                return Err("exit 0 with a non-finite number in the JSON".into());
            }
            Ok((0, err))
        }
        Some(_) if prints_a_long_number(&err) => Err(format!("a message prints a number in full: {err}")),
        Some(2) if err.starts_with("Error:") && names_a_key(&err) => Ok((2, err)),
        Some(c) => Err(format!("exit {c}: {err}")),
        None => Err(format!("killed by a signal (memory limit {CHILD_MEMORY_KB} KiB?): {err}")),
    }
}

#[cfg(unix)]
#[test]
fn mutated_scenarios_through_the_binary_exit_0_finite_or_2_naming_a_key() {
    use std::sync::atomic::{AtomicUsize, Ordering};
    let n = cases("CAISSON_FUZZ_BIN_CASES", 80);
    let start = Instant::now();
    let (long, over) = (AtomicUsize::new(0), AtomicUsize::new(0));
    let checked = run_cases(n, 5, binary_base, |ex, text, what| {
        let (cmd, name) = (EXAMPLES[ex].1, EXAMPLES[ex].0);
        let (plan, estimate) = plan(name, cmd, text);
        if plan == Plan::Long {
            long.fetch_add(1, Ordering::Relaxed);
            return Ok(());
        }
        let dir = tempfile::tempdir().unwrap();
        // The series examples read their CSV relative to the scenario.
        for csv in ["forces_example.csv", "fifteen_waves.csv"] {
            std::fs::copy(examples_dir().join(csv), dir.path().join(csv)).unwrap();
        }
        match check_binary(dir.path(), cmd, text) {
            Ok((code, err)) if plan == Plan::OverBudget => {
                prop_assert!(
                    code == 2 && err.contains("the budget is"),
                    "caisson {cmd} on {name} with {what:?}: estimated over the budget ({estimate}) but exit {code}: {err}"
                );
                over.fetch_add(1, Ordering::Relaxed);
            }
            Ok(_) => {}
            Err(e) => prop_assert!(false, "caisson {cmd} on {name} with {what:?} (estimate {estimate}): {e}"),
        }
        Ok(())
    });
    println!(
        "through the binary: {checked} scenarios checked: {} refused over the work budget, {} within the budget but longer than a case may take (not run), in {:?}",
        over.into_inner(),
        long.into_inner(),
        start.elapsed()
    );
    assert!(checked >= n as usize, "every generated case was checked: {checked} of {n}");
}

/// The examples themselves pass both checks (the generator starts from valid scenarios).
#[test]
fn the_unmutated_examples_pass() {
    for (i, (name, _)) in EXAMPLES.iter().enumerate() {
        let r = check_in_process(name, &example_text(i));
        assert!(matches!(r, Ok(o) if o != "refused"), "{name}: {r:?}");
    }
}

/// Every numeric key of every example under every operation, once, in process; prints each
/// failure instead of stopping at the first (`cargo test --release -p caisson-cli --test
/// fuzz_scenarios -- --ignored --nocapture`): the map of what is left, for triage.
#[test]
#[ignore]
fn survey_every_key_and_operation() {
    let ops: Vec<Op> = [-300, -160, -12, -6, -3, -1, 1, 3, 6, 12, 160, 300]
        .into_iter()
        .map(Op::Scale)
        .chain([Op::Negate, Op::Zero, Op::Drop])
        .chain((0..5).map(Op::Special))
        .collect();
    let (mut total, mut failed) = (0, 0);
    for (ex, (name, _)) in EXAMPLES.iter().enumerate() {
        let text = example_text(ex);
        for sel in 0..numeric_lines(&text).len() {
            for op in &ops {
                let (t, what) = mutate(&text, &[(sel, op.clone())]);
                total += 1;
                let start = Instant::now();
                let r = std::panic::catch_unwind(|| check_in_process(name, &t));
                let dt = start.elapsed();
                let bad = match &r {
                    Err(_) => Some("PANIC".to_string()),
                    Ok(Err(e)) => Some(e.chars().take(160).collect()),
                    Ok(Ok(_)) if dt > CASE_BUDGET => Some(format!("slow {dt:?}")),
                    _ => None,
                };
                if let Some(b) = bad {
                    failed += 1;
                    println!("{name} {what:?}: {b}");
                }
            }
        }
    }
    println!("{failed} of {total} cases failed");
}
