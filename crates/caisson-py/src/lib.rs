//! `caisson._core`: the Python extension of the `caisson` package (a thin layer over the library).
//!
//! Every function here takes a validated [`CoreScenario`], calls one library driver with the GIL
//! released, and hands back either the JSON text of the library's report struct (the one the CLI
//! prints, so the keys and the numbers are the CLI's) or columns of numbers (numpy arrays) that
//! the Python package assembles into pandas and xarray objects. There is no physics here.
//!
//! Threads: a parallel driver runs on a local rayon pool of `threads` workers (0: one per core),
//! never on the global pool. Progress: the driver counts finished items; the calling thread wakes
//! every 0.1 s (GIL released), and when the count moved it takes the GIL and calls
//! `progress(done, total)`.

mod columns;
mod loads_table;

use caisson::analysis::campaign::run_campaign;
use caisson::analysis::conventional::{static_check, DesignWave, StaticCheck};
use caisson::analysis::fragility::{fit_lognormal as fit, run_fragility};
use caisson::analysis::lifetime::{LifeColumn, StormOutcome, LIFE_COLUMNS};
use caisson::analysis::run::{run as run_engine, run_observed, History};
use caisson::analysis::spectrum::{estimated_steps, sweep, MAX_STEPS, RATIO_RANGE};
use caisson::analysis::train::run_realizations;
use caisson::analysis::work::{self, Advice, Budget, Histories, WorkEstimate};
use caisson::drive::design::{DesignOptions, Designer};
use caisson::drive::size::{Hooks, SizeError, Sizer};
use caisson::dynamics::{Observer, StepView};
use caisson::foundation::DampingMode;
use caisson::loads::series::{ForceSeries, MAX_SAMPLES};
use caisson::loads::{LoadSpec, WaveForce};
use caisson::report::campaign::CampaignReport;
use caisson::report::checkpoint::{read_design, CheckpointError, DesignCheckpoint, Merge, MergeError};
use caisson::report::fragility::FragilityReport;
use caisson::report::loads::LoadsReport;
use caisson::report::run::RunReport;
use caisson::report::spectrum::SpectrumReport;
use caisson::report::train::TrainRunReport;
use caisson::scenario::design::MAX_LIVES;
use caisson::scenario::{Scenario, ScenarioError as LibError, MAX_MAGNITUDE};
use caisson::waves::{breaking, dispersion, surf_zone};
use numpy::{PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray1};
use pyo3::create_exception;
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::ops::ControlFlow;
use std::path::Path;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::Duration;

create_exception!(
    caisson,
    ScenarioError,
    PyValueError,
    "Bad scenario input: `str(e)` is the CLI's message; `.key` the file key (`\"[caisson] width_m\"`), `.value` the value as written, `.allowed` what is allowed (each may be None)."
);
create_exception!(
    caisson,
    FitError,
    PyValueError,
    "The counts do not determine a lognormal fit: `.reason` (\"no-exceedance\", \"all-exceed\", \"separated\", \"at-bounds\") and the message."
);
create_exception!(
    caisson,
    RunError,
    PyRuntimeError,
    "A run failed (Newton-Raphson did not converge): the CLI's message."
);

/// A Python `ScenarioError` with its attributes.
fn scenario_error(
    py: Python<'_>,
    message: String,
    key: Option<String>,
    value: Option<String>,
    allowed: Option<String>,
) -> PyErr {
    let e = ScenarioError::new_err(message);
    let v = e.value(py);
    let _ = v.setattr("key", key);
    let _ = v.setattr("value", value);
    let _ = v.setattr("allowed", allowed);
    e
}

/// The table and key of line `line` (1-based) of TOML `text`: `"[table] key"`, `"[table]"` for a
/// table header, or `"key"` before any table.
fn key_at_line(text: &str, line: usize) -> Option<String> {
    let lines: Vec<&str> = text.lines().collect();
    let here = lines.get(line.checked_sub(1)?)?.trim();
    let header = |l: &str| {
        let l = l.trim();
        (l.starts_with('[')).then(|| l.trim_start_matches('[').split(']').next().unwrap_or("").trim().to_string())
    };
    if let Some(h) = header(here) {
        return Some(format!("[{h}]"));
    }
    let key = here.split('=').next()?.trim().trim_matches('"').to_string();
    if key.is_empty() || !here.contains('=') {
        return None;
    }
    match lines[..line - 1].iter().rev().find_map(|l| header(l)) {
        Some(t) => Some(format!("[{t}] {key}")),
        None => Some(key),
    }
}

/// A library scenario error as a Python `ScenarioError` (message = the CLI's words after `Error: `).
fn lib_error(py: Python<'_>, e: LibError, text: Option<&str>) -> PyErr {
    let message = e.to_string();
    match e {
        LibError::OutOfRange { key, value, allowed } => {
            scenario_error(py, message, Some(key), Some(value), Some(allowed))
        }
        LibError::Missing { key, hint } => scenario_error(py, message, Some(key), None, Some(hint)),
        LibError::WrongType { key, expected, got, .. } => {
            // The value as written: `"20"`, `2.5`, `a list`.
            let value = got.strip_prefix("the string ").unwrap_or(&got).trim_end_matches(" in the list").to_string();
            scenario_error(py, message, Some(key), Some(value), Some(format!("must be {expected}")))
        }
        LibError::Syntax { line, .. } => {
            let key = text.and_then(|t| key_at_line(t, line));
            scenario_error(py, message, key, None, None)
        }
        LibError::Series { path, .. } => {
            scenario_error(py, message, Some("[load] file".into()), Some(path.display().to_string()), None)
        }
        LibError::Read { .. } | LibError::Conflict { .. } => scenario_error(py, message, None, None, None),
    }
}

fn run_error(e: impl std::fmt::Display) -> PyErr {
    RunError::new_err(e.to_string())
}

/// A validated scenario (the library's `Scenario`). Immutable; the Python `caisson.Scenario`
/// keeps the TOML text beside it (pickling, `to_dict`, `replace`).
#[pyclass(frozen, module = "caisson._core")]
struct CoreScenario {
    sc: Scenario,
}

#[pymethods]
impl CoreScenario {
    /// Parse and validate TOML `text`; `name` names it in messages, `base_dir` resolves relative
    /// file names (a force series).
    #[new]
    fn new(py: Python<'_>, text: &str, name: &str, base_dir: &str) -> PyResult<Self> {
        // The CLI's limit on a scenario file, for text too.
        let max = caisson::scenario::MAX_SCENARIO_BYTES;
        if text.len() as u64 > max {
            let message = format!(
                "the scenario text is {} bytes, larger than {} MiB, the most a scenario file may be",
                text.len(),
                max >> 20
            );
            return Err(scenario_error(
                py,
                message,
                None,
                Some(format!("{} bytes", text.len())),
                Some(format!("at most {} MiB", max >> 20)),
            ));
        }
        Scenario::from_toml(text, Path::new(name), Path::new(base_dir))
            .map(|sc| CoreScenario { sc })
            .map_err(|e| lib_error(py, e, Some(text)))
    }
    #[getter]
    fn has_load(&self) -> bool {
        self.sc.load.is_some()
    }
    #[getter]
    fn has_waves(&self) -> bool {
        self.sc.waves.is_some()
    }
    #[getter]
    fn has_campaign(&self) -> bool {
        self.sc.has_campaign_table()
    }
    #[getter]
    fn has_design(&self) -> bool {
        self.sc.design.is_some()
    }
    #[getter]
    fn has_fragility(&self) -> bool {
        self.sc.has_fragility_table()
    }
    /// Simulated time of a `[load]` run, s.
    #[getter]
    fn duration_s(&self) -> f64 {
        self.sc.duration_s
    }
    /// Lives of `[design]` (None without it).
    #[getter]
    fn design_lives(&self) -> Option<usize> {
        self.sc.design.as_ref().map(|d| d.lives)
    }

    /// `[design] lives = "auto"`: its target relative error (`design_lives` is then the budget).
    #[getter]
    fn design_target_relative_error(&self) -> Option<f64> {
        self.sc.design.as_ref().and_then(|d| d.auto).map(|a| a.target_relative_error)
    }
    /// The typed parameters as the library holds them (SI), JSON text (for inspection only).
    fn structure_json(&self) -> PyResult<String> {
        serde_json::to_string(self.sc.structure()).map_err(|e| PyRuntimeError::new_err(e.to_string()))
    }
}

/// The text of the scenario file `path`, read as the CLI reads it (at most 1 MiB, a regular
/// file: never a FIFO or a device read for ever).
#[pyfunction]
fn read_scenario(py: Python<'_>, path: &str) -> PyResult<String> {
    py.detach(|| caisson::scenario::read_text(Path::new(path))).map_err(|e| lib_error(py, e, None))
}

/// JSON text of a report by the library's one encoder (as the CLI prints it): a non-finite number
/// is an internal error naming its path.
fn report_json<T: serde::Serialize>(report: &T, what: &str) -> PyResult<String> {
    caisson::report::to_json_text(report, what).map_err(|e| PyRuntimeError::new_err(format!("internal error: {e}")))
}

/// The payload a driver unwinds with when Python asked it to stop ([`Ctl::tick`]): caught by
/// [`drive`], never a panic (`resume_unwind` does not run the panic hook).
struct Cancelled;

/// What a job running under [`drive`] sees: the count of finished items and whether Python has
/// asked it to stop (a signal such as Ctrl-C, or an exception in the progress callback).
struct Ctl {
    done: AtomicUsize,
    cancel: AtomicBool,
}

impl Ctl {
    fn new() -> Self {
        Ctl { done: AtomicUsize::new(0), cancel: AtomicBool::new(false) }
    }
    /// One more item finished; unwinds with [`Cancelled`] if asked to stop.
    fn tick(&self) {
        self.count();
        self.check();
    }
    /// One more item finished.
    fn count(&self) {
        self.done.fetch_add(1, Ordering::Relaxed);
    }
    fn cancelled(&self) -> bool {
        self.cancel.load(Ordering::Relaxed)
    }
    /// Unwind with [`Cancelled`] if asked to stop (a cancellation point).
    fn check(&self) {
        if self.cancelled() {
            std::panic::resume_unwind(Box::new(Cancelled));
        }
    }
}

/// The threads a call may start: 0 (one per core) to [`caisson::MAX_THREADS`], as the CLI's
/// `--threads` (also `caisson._core.check_threads`, for the calls that start none).
#[pyfunction]
fn check_threads(py: Python<'_>, threads: usize) -> PyResult<()> {
    if threads > caisson::MAX_THREADS {
        let allowed = format!("a whole number from 0 (one per core) to {}", caisson::MAX_THREADS);
        return Err(scenario_error(
            py,
            format!("`threads` = {threads}: must be {allowed}"),
            Some("threads".into()),
            Some(threads.to_string()),
            Some(allowed),
        ));
    }
    Ok(())
}

/// Run `job` on a local pool of `threads` workers with the GIL released. The calling thread
/// wakes every 0.1 s: it runs Python's signal handlers (Ctrl-C raises `KeyboardInterrupt`) and
/// calls `progress(done, total)` (GIL held) when the count moved, and once at the end. A signal
/// or an exception of `progress` asks the job to stop ([`Ctl`]): the job's result so far (if it
/// returned one rather than unwinding) comes back with the error.
fn drive_keep<T: Send>(
    py: Python<'_>,
    threads: usize,
    total: usize,
    progress: Option<Py<PyAny>>,
    job: impl FnOnce(&Ctl) -> T + Send,
) -> PyResult<(Option<T>, Option<PyErr>)> {
    check_threads(py, threads)?;
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .map_err(|e| PyRuntimeError::new_err(format!("starting the worker threads: {e}")))?;
    let ctl = Ctl::new();
    let mut reported = usize::MAX;
    let mut poll = |n: usize, py: Python<'_>| -> PyResult<()> {
        py.check_signals()?;
        if let Some(progress) = &progress {
            if n != reported {
                reported = n;
                progress.call1(py, (n, total))?;
            }
        }
        Ok(())
    };
    let (result, stop) = py.detach(|| {
        std::thread::scope(|s| {
            let (tx, rx) = std::sync::mpsc::channel();
            let ctl = &ctl;
            let worker = s.spawn(move || {
                let out = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| pool.install(|| job(ctl))));
                let _ = tx.send(());
                out
            });
            let mut stop: Option<PyErr> = None;
            loop {
                let finished = rx.recv_timeout(Duration::from_millis(100)).is_ok();
                if stop.is_none() {
                    if let Err(e) = Python::attach(|py| poll(ctl.done.load(Ordering::Relaxed), py)) {
                        ctl.cancel.store(true, Ordering::Relaxed);
                        stop = Some(e);
                    }
                }
                if finished {
                    break;
                }
            }
            (worker.join(), stop)
        })
    });
    match result {
        Ok(Ok(t)) => Ok((Some(t), stop)),
        Ok(Err(payload)) if payload.is::<Cancelled>() => Ok((None, stop)),
        _ => Err(PyRuntimeError::new_err("internal error: a worker thread panicked")),
    }
}

/// [`drive_keep`] for a job whose partial result is of no use: its result, or the error that
/// stopped it.
fn drive<T: Send>(
    py: Python<'_>,
    threads: usize,
    total: usize,
    progress: Option<Py<PyAny>>,
    job: impl FnOnce(&Ctl) -> T + Send,
) -> PyResult<T> {
    match drive_keep(py, threads, total, progress, job)? {
        (_, Some(e)) => Err(e),
        (Some(t), None) => Ok(t),
        (None, None) => Err(PyRuntimeError::new_err("internal error: a job stopped without a reason")),
    }
}

/// The observer of a Python `run`: hands each step to the history (if kept) and is a
/// cancellation point ([`Ctl::check`]) every 4096 steps (a few milliseconds).
struct Watch<'a> {
    inner: Option<&'a mut History>,
    ctl: &'a Ctl,
    steps: u32,
}

impl Observer for Watch<'_> {
    fn observe(&mut self, view: &StepView<'_>) {
        if let Some(h) = self.inner.as_deref_mut() {
            h.observe(view);
        }
        self.steps = self.steps.wrapping_add(1);
        if self.steps.is_multiple_of(4096) {
            self.ctl.check();
        }
    }
    fn reads_springs(&self) -> bool {
        self.inner.as_deref().is_some_and(|h| h.reads_springs())
    }
}

/// Columns of a run history with the CLI's names and units (`history.csv`), and the springs.
fn history_columns<'py>(py: Python<'py>, h: &History) -> PyResult<(Bound<'py, PyDict>, Bound<'py, PyDict>)> {
    let d = PyDict::new(py);
    let kn = |v: &[f64]| v.iter().map(|x| x / 1e3).collect::<Vec<f64>>();
    d.set_item("time_s", PyArray1::from_slice(py, &h.t_s))?;
    d.set_item("ux_m", PyArray1::from_slice(py, &h.ux_m))?;
    d.set_item("uy_m", PyArray1::from_slice(py, &h.uy_m))?;
    d.set_item("theta_rad", PyArray1::from_slice(py, &h.theta_rad))?;
    d.set_item("vx_m_per_s", PyArray1::from_slice(py, &h.vx_m_per_s))?;
    d.set_item("fx_kn", PyArray1::from_vec(py, kn(&h.fx_n)))?;
    d.set_item("fy_kn", PyArray1::from_vec(py, kn(&h.fy_n)))?;
    d.set_item("moment_knm", PyArray1::from_vec(py, kn(&h.m_nm)))?;
    d.set_item("reaction_x_kn", PyArray1::from_vec(py, kn(&h.reaction_x_n)))?;
    d.set_item("reaction_y_kn", PyArray1::from_vec(py, kn(&h.reaction_y_n)))?;
    d.set_item("reaction_moment_knm", PyArray1::from_vec(py, kn(&h.reaction_m_nm)))?;
    d.set_item("sliding_resistance_kn", PyArray1::from_vec(py, kn(&h.sliding_resistance_n)))?;
    d.set_item("sliding_springs", PyArray1::from_slice(py, &h.sliding_springs))?;
    let n = h.springs();
    let rows = h.len();
    let pick = |offset: usize| -> Vec<Vec<f64>> {
        (0..rows)
            .map(|k| h.spring_forces_n[k * 2 * n + offset..k * 2 * n + offset + n].iter().map(|v| v / 1e3).collect())
            .collect()
    };
    let uy: Vec<Vec<f64>> = (0..rows).map(|k| h.spring_uy_m[k * n..(k + 1) * n].to_vec()).collect();
    let s = PyDict::new(py);
    let arr2 = |v: Vec<Vec<f64>>| -> PyResult<Bound<'py, PyArray2<f64>>> {
        if v.is_empty() {
            return PyArray1::from_vec(py, Vec::<f64>::new()).reshape([0, n]);
        }
        PyArray2::from_vec2(py, &v).map_err(|e| PyRuntimeError::new_err(e.to_string()))
    };
    s.set_item("x_m", PyArray1::from_slice(py, &h.spring_x_m))?;
    s.set_item("normal_kn", arr2(pick(0))?)?;
    s.set_item("shear_kn", arr2(pick(n))?)?;
    s.set_item("uy_m", arr2(uy)?)?;
    Ok((d, s))
}

/// A force series from numpy columns (s, kN, kN, kN·m), checked as the CSV reader checks it.
fn series_from(py: Python<'_>, t_s: &[f64], fx_kn: &[f64], fy_kn: &[f64], moment_knm: &[f64]) -> PyResult<ForceSeries> {
    let n = t_s.len();
    let bad = |key: &str, value: String, allowed: &str| {
        scenario_error(
            py,
            format!("`{key}` = {value}: {allowed}"),
            Some(key.to_string()),
            Some(value),
            Some(allowed.to_string()),
        )
    };
    if n > MAX_SAMPLES {
        return Err(bad(
            "t_s",
            format!("{n} samples"),
            &format!("at most {MAX_SAMPLES} samples (what the largest series file holds)"),
        ));
    }
    for (name, v) in [("fx_kn", fx_kn), ("fy_kn", fy_kn), ("moment_knm", moment_knm)] {
        if v.len() != n {
            return Err(bad(name, format!("{} values", v.len()), &format!("must have one value per time ({n})")));
        }
        // Beyond 1e300 kN a value overflows once converted to N, as in a scenario file.
        if let Some((i, x)) = v.iter().enumerate().find(|(_, x)| !(x.is_finite() && x.abs() <= MAX_MAGNITUDE)) {
            return Err(bad(
                name,
                format!("{x:e} (sample {i})"),
                &format!("must be a finite number of magnitude at most {MAX_MAGNITUDE:e}"),
            ));
        }
    }
    if n < 2 {
        return Err(bad("t_s", format!("{n} samples"), "at least 2 samples are needed"));
    }
    for i in 0..n {
        if !t_s[i].is_finite() || (i > 0 && t_s[i] <= t_s[i - 1]) {
            return Err(bad("t_s", format!("{} (sample {i})", t_s[i]), "times must be finite and strictly increasing"));
        }
    }
    let f =
        (0..n).map(|i| WaveForce { fx_n: fx_kn[i] * 1e3, fy_n: fy_kn[i] * 1e3, m_nm: moment_knm[i] * 1e3 }).collect();
    Ok(ForceSeries::from_samples(t_s.to_vec(), f))
}

/// What to change to lower each kind of work, in the words of the Python API (the CLI's
/// [`Advice`] names its options).
const RUN_LOAD: Advice = Advice {
    steps: "shorten the run (`duration_s=`, `[load] duration_s`) or raise `[solver] dt_s`",
    waves: "",
    memory:
        "pass history=False, shorten the run or raise `[solver] output_interval_s` (the histories are returned whole)",
    disk: "",
};
const RUN_WAVES: Advice = Advice {
    steps: "lower `[waves] waves` or `[waves] realizations`, or raise `[solver] dt_max_s` or `error_tolerance_m`",
    waves: "lower `[waves] waves` or `[waves] realizations`",
    memory: "lower `[waves] waves` or `[waves] realizations` (every wave is kept for the summary)",
    disk: "",
};
const CAMPAIGN: Advice = Advice {
    steps: "lower `[waves] waves` or `[waves] realizations` or the number of `[campaign]` conditions, or raise `[solver] dt_max_s` or `error_tolerance_m`",
    waves: "lower `[waves] waves` or `[waves] realizations` or the number of `[campaign]` conditions",
    memory: "lower `[waves] waves` or `[waves] realizations` or the number of `[campaign]` conditions (every wave is kept in the report)",
    disk: "",
};
const DESIGN: Advice = Advice {
    steps: "simulate fewer lives at a time (`indices=`: shard them over tasks, docs/python.md), lower `[design] life_years` or `storm_duration_h`, or raise `[solver] dt_max_s`",
    waves: "simulate fewer lives at a time (`indices=`: shard them over tasks, docs/python.md), or lower `[design] life_years` or `storm_duration_h`",
    memory: "simulate fewer lives at a time (`indices=`)",
    disk: "",
};
const LOADS: Advice = Advice {
    steps: "",
    waves: "evaluate fewer waves per call (in chunks)",
    memory: "evaluate fewer waves per call (in chunks: the table holds about 600 bytes per wave)",
    disk: "",
};
const FRAGILITY: Advice = Advice {
    steps: "lower `[fragility] storms`, the number of `[fragility] significant_heights_m` or `[fragility] storm_duration_h`, or raise `[solver] dt_max_s`",
    waves: "lower `[fragility] storms`, the number of `[fragility] significant_heights_m` or `[fragility] storm_duration_h`",
    memory: "lower `[fragility] storms` or the number of `[fragility] significant_heights_m`",
    disk: "",
};

/// Refuse `e` over [`Budget::DEFAULT`] as the CLI does (docs/cli.md, Limits), with its words and
/// `command` named: a `ScenarioError` whose `.value` is the estimate and `.allowed` the limit.
fn check_work(py: Python<'_>, command: &str, e: &WorkEstimate, advice: &Advice) -> PyResult<()> {
    let b = Budget::DEFAULT;
    match (e.refusal(&b, command, advice), e.excess(&b)) {
        (Some(message), Some((resource, estimate, limit))) => {
            let (value, allowed) = match resource {
                work::Resource::Steps => {
                    (format!("{estimate:.2e} time steps"), format!("at most {limit:.0e} time steps"))
                }
                work::Resource::Waves => (format!("{estimate:.2e} waves"), format!("at most {limit:.0e} waves")),
                work::Resource::Memory => (
                    format!("{} held", work::describe_bytes(estimate)),
                    format!("at most {} held", work::describe_bytes(limit)),
                ),
                work::Resource::Disk => (
                    format!("{} written", work::describe_bytes(estimate)),
                    format!("at most {} written", work::describe_bytes(limit)),
                ),
            };
            Err(scenario_error(py, message, None, Some(value), Some(allowed)))
        }
        _ => probe_memory(command, e.memory_bytes),
    }
}

/// Refuse with `MemoryError` work whose `bytes` held cannot be had now (an address-space limit,
/// `ulimit -v`, or a small machine): a reservation of that size is tried and given back before
/// the work starts, so that an allocation failing later (which aborts the interpreter, or
/// panics in numpy) is unlikely.
fn probe_memory(command: &str, bytes: f64) -> PyResult<()> {
    if bytes < (64 << 20) as f64 {
        return Ok(());
    }
    let mut v: Vec<u8> = Vec::new();
    match v.try_reserve_exact(bytes as usize) {
        Ok(()) => Ok(()),
        Err(_) => Err(pyo3::exceptions::PyMemoryError::new_err(format!(
            "{command} would hold about {} in memory, which cannot be had now (an address-space limit or a small machine): ask for less at a time",
            work::describe_bytes(bytes)
        ))),
    }
}

/// The estimate of `what` ("run", "campaign", "design", "fragility") on `sc` as the Python entry
/// point makes it: `lives` for a design (default `[design] lives`), `history` and `duration_s`
/// for a `[load]` run. Returns the estimate, the advice and the entry point's name.
fn estimate_of(
    py: Python<'_>,
    sc: &Scenario,
    what: &str,
    lives: Option<usize>,
    history: bool,
    duration_s: Option<f64>,
) -> PyResult<(WorkEstimate, &'static Advice, &'static str)> {
    let lib = |e| lib_error(py, e, None);
    match what {
        "run" if sc.load.is_some() || duration_s.is_some() || sc.waves.is_none() => {
            let d = duration_s.unwrap_or(sc.duration_s);
            let h = if history { Histories::Held } else { Histories::None };
            Ok((py.detach(|| work::run(sc.structure(), d, h)), &RUN_LOAD, "caisson.run"))
        }
        "run" => {
            let case = sc.train_case().map_err(lib)?;
            Ok((py.detach(|| work::train(&case, Histories::None)), &RUN_WAVES, "caisson.run"))
        }
        "campaign" => {
            let c = sc.campaign().map_err(lib)?;
            Ok((py.detach(|| work::campaign(&c.setups, true)), &CAMPAIGN, "caisson.campaign"))
        }
        "design" => {
            let run = Designer::new(sc, "Design", DesignOptions { lives, brute_force: false }).map_err(lib)?;
            Ok((py.detach(|| run.estimate(run.design.lives)), &DESIGN, "Design.simulate_lives"))
        }
        "fragility" => {
            let p = sc.fragility_for("Fragility").map_err(lib)?;
            let case = sc.storm_case(true).map_err(lib)?;
            Ok((py.detach(|| work::fragility(&case, p)), &FRAGILITY, "Fragility.run"))
        }
        other => Err(scenario_error(
            py,
            format!("`what` = {other:?}: must be \"run\", \"campaign\", \"design\" or \"fragility\""),
            Some("what".into()),
            Some(other.into()),
            Some("\"run\", \"campaign\", \"design\" or \"fragility\"".into()),
        )),
    }
}

/// The budget of the long entry points, JSON text (`caisson.BUDGET`).
#[pyfunction]
fn budget_json() -> PyResult<String> {
    serde_json::to_string(&Budget::DEFAULT).map_err(|e| PyRuntimeError::new_err(e.to_string()))
}

/// The work estimate of `what` on `sc` (`caisson.estimate`): JSON text of the estimate's fields,
/// `weighted_steps`, the `budget`, and `over_budget` (the first resource over it, or null) with
/// the `refusal` the entry point would raise (or null).
#[pyfunction]
#[pyo3(signature = (sc, what, lives=None, history=true, duration_s=None))]
fn estimate(
    py: Python<'_>,
    sc: &CoreScenario,
    what: &str,
    lives: Option<usize>,
    history: bool,
    duration_s: Option<f64>,
) -> PyResult<String> {
    let (e, advice, command) = estimate_of(py, &sc.sc, what, lives, history, duration_s)?;
    let b = Budget::DEFAULT;
    let mut v = serde_json::to_value(&e).map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
    let m = v.as_object_mut().expect("an estimate is an object");
    m.insert("weighted_steps".into(), e.weighted_steps().into());
    m.insert("budget".into(), serde_json::to_value(b).map_err(|e| PyRuntimeError::new_err(e.to_string()))?);
    m.insert(
        "over_budget".into(),
        serde_json::to_value(e.excess(&b).map(|x| x.0)).map_err(|e| PyRuntimeError::new_err(e.to_string()))?,
    );
    m.insert("refusal".into(), e.refusal(&b, command, advice).into());
    Ok(v.to_string())
}

type Series<'py> =
    (PyReadonlyArray1<'py, f64>, PyReadonlyArray1<'py, f64>, PyReadonlyArray1<'py, f64>, PyReadonlyArray1<'py, f64>);

/// One dynamic run of the scenario's `[load]`, or of the force series `series` (t_s, fx_kn,
/// fy_kn, moment_knm) for `duration_s` (default: to the last sample). Returns the `summary.json`
/// text, the history columns and the springs.
#[pyfunction]
#[pyo3(signature = (sc, series=None, duration_s=None, history=true))]
#[allow(clippy::type_complexity)]
fn run_load<'py>(
    py: Python<'py>,
    sc: &CoreScenario,
    series: Option<Series<'py>>,
    duration_s: Option<f64>,
    history: bool,
) -> PyResult<(String, Option<(Bound<'py, PyDict>, Bound<'py, PyDict>)>)> {
    let sc = &sc.sc;
    let own;
    let (load, duration) = match series {
        Some((t, fx, fy, m)) => {
            let s = series_from(py, t.as_slice()?, fx.as_slice()?, fy.as_slice()?, m.as_slice()?)?;
            let d = duration_s.unwrap_or_else(|| s.last_time_s());
            own = LoadSpec::Series(s);
            // The bound of a `[load]` on the weight, as the CLI checks a series file.
            sc.check_load(&own).map_err(|e| lib_error(py, e, None))?;
            (&own, d)
        }
        None => {
            let load = sc.load.as_ref().ok_or_else(|| {
                scenario_error(
                    py,
                    "missing key `[load]`: a single run needs a [load] table (kind = \"triangle\", \"static\" or \"series\") or a force series (t_s=, fx_kn=, fy_kn=, moment_knm=)".into(),
                    Some("[load]".into()),
                    None,
                    None,
                )
            })?;
            (load, duration_s.unwrap_or(sc.duration_s))
        }
    };
    if !(duration.is_finite() && duration > 0.0) {
        return Err(scenario_error(
            py,
            format!("`duration_s` = {}: must be a finite number > 0 (s)", caisson::fmt_value(duration)),
            Some("duration_s".into()),
            Some(caisson::fmt_value(duration)),
            Some("must be a finite number > 0 (s)".into()),
        ));
    }
    sc.solver().check_run(duration).map_err(|e| {
        let (allowed, value) = (e.allowed.describe(1.0, ""), caisson::fmt_value(e.value));
        scenario_error(
            py,
            format!("`[solver] {}` = {value}: {allowed}", e.quantity),
            Some(format!("[solver] {}", e.quantity)),
            Some(value),
            Some(allowed),
        )
    })?;
    let h = if history { Histories::Held } else { Histories::None };
    check_work(py, "caisson.run", &py.detach(|| work::run(sc.structure(), duration, h)), &RUN_LOAD)?;
    let structure = sc.structure();
    let (summary, held) = drive(py, 1, 1, None, |ctl| {
        let mut held = history.then(|| {
            let samples = (duration / structure.solver.output_interval_s).ceil() as usize + 1;
            let (c, f) = (&structure.caisson, &structure.foundation);
            let x = f.spring_positions(c.width_m);
            History::new(structure.solver.output_interval_s, samples, x, c.weight_in_water_n, f.mu_static)
        });
        let mut watch = Watch { inner: held.as_mut(), ctl, steps: 0 };
        run_observed(structure, load, duration, Some(&mut watch)).map(|summary| (summary, held))
    })?
    .map_err(run_error)?;
    let result = caisson::analysis::run::RunResult { summary, history: held };
    let json = report_json(&RunReport::new(sc.structure(), load, &result.summary), "summary")?;
    let cols = match &result.history {
        Some(h) => Some(history_columns(py, h)?),
        None => None,
    };
    Ok((json, cols))
}

/// The shock spectrum of the scenario's triangular `[load]` at the ratios t_r/T0 `tr_over_t0`
/// (any order; each in [`RATIO_RANGE`], at most [`MAX_STEPS`] time steps in all): the
/// `caisson spectrum --json` report without its points as JSON text, and the points as columns
/// (names and numpy arrays, in the order of `spectrum.csv`), one row per ratio in the order given.
#[pyfunction]
#[pyo3(signature = (sc, tr_over_t0, threads=1, progress=None))]
fn spectrum(
    py: Python<'_>,
    sc: &CoreScenario,
    tr_over_t0: PyReadonlyArray1<'_, f64>,
    threads: usize,
    progress: Option<Py<PyAny>>,
) -> PyResult<(String, Vec<String>, Vec<Py<PyAny>>)> {
    let sc = &sc.sc;
    let base = match &sc.load {
        Some(LoadSpec::Triangle(base)) => *base,
        other => {
            let value = match other {
                None => None,
                Some(LoadSpec::Static(_)) => Some("\"static\"".to_string()),
                Some(_) => Some("\"series\"".to_string()),
            };
            let key = if value.is_some() { "[load] kind" } else { "[load]" };
            return Err(scenario_error(
                py,
                "caisson.spectrum needs `[load] kind = \"triangle\"` (its peak forces are swept over rise times)"
                    .into(),
                Some(key.into()),
                value,
                Some("kind = \"triangle\"".into()),
            ));
        }
    };
    let ratios = tr_over_t0.as_slice()?.to_vec();
    let (lo, hi) = RATIO_RANGE;
    let allowed = format!("finite numbers from {lo} to {hi}, at least one");
    let bad = |value: String, message: String| {
        scenario_error(py, message, Some("tr_over_t0".into()), Some(value), Some(allowed.clone()))
    };
    if ratios.is_empty() {
        return Err(bad("an empty array".into(), format!("`tr_over_t0` is empty: give {allowed}")));
    }
    if let Some((i, x)) = ratios.iter().enumerate().find(|(_, x)| !(x.is_finite() && (lo..=hi).contains(*x))) {
        return Err(bad(
            x.to_string(),
            format!("`tr_over_t0` = {x} (element {i}): must be a finite number from {lo} to {hi}"),
        ));
    }
    let steps = estimated_steps(sc.structure(), &ratios);
    if steps.is_nan() || steps > MAX_STEPS {
        return Err(bad(
            format!("{} ratios", ratios.len()),
            format!(
                "`tr_over_t0`: the sweep would take about {steps:.2e} time steps (T0 = {:.4} s, [solver] dt_s = {} s); at most {MAX_STEPS:.0e}: raise the smallest ratio, lower the largest or give fewer",
                sc.structure().model().natural_period_s(),
                sc.solver().dt_s
            ),
        ));
    }
    let structure = sc.structure();
    let points = drive(py, threads, ratios.len(), progress, |ctl| sweep(structure, base, &ratios, &|| ctl.tick()))?
        .map_err(run_error)?;
    let report = SpectrumReport::new(structure, &base, &points);
    report_json(&report, "spectrum")?; // refuses a non-finite number anywhere, as the CLI does
    let points = &report.points;
    let (names, cols) = columns::build(py, points.len(), &points[0], |table| -> Result<(), String> {
        points.iter().try_for_each(|p| table.push_row(p))
    })?
    .map_err(PyRuntimeError::new_err)?;
    let mut head = serde_json::to_value(&report).map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
    head.as_object_mut().map(|m| m.remove("points"));
    Ok((report_json(&head, "spectrum")?, names, cols))
}

/// The wave-train realizations of a `[waves]` scenario: the wave-train `summary.json` text.
#[pyfunction]
#[pyo3(signature = (sc, threads=1, progress=None))]
fn run_trains(py: Python<'_>, sc: &CoreScenario, threads: usize, progress: Option<Py<PyAny>>) -> PyResult<String> {
    let case = sc.sc.train_case().map_err(|e| lib_error(py, e, None))?;
    check_work(py, "caisson.run", &py.detach(|| work::train(&case, Histories::None)), &RUN_WAVES)?;
    let total = case.waves.train.realizations;
    let summary =
        drive(py, threads, total, progress, |ctl| run_realizations(&case, &|| ctl.tick()))?.map_err(run_error)?;
    report_json(&TrainRunReport::new(case.structure, case.waves, &summary), "summary")
}

/// `caisson loads --json` text of the scenario's wave.
#[pyfunction]
fn loads_report(py: Python<'_>, sc: &CoreScenario) -> PyResult<String> {
    let sc = &sc.sc;
    let ws = sc.waves_for("`caisson loads`").map_err(|e| lib_error(py, e, None))?;
    let check = static_check(sc.structure(), ws).map_err(|e| regime_error(py, e))?;
    // Refused as `caisson loads` refuses it: an input error naming the number that is not finite.
    let report = LoadsReport::of_structure(sc.structure(), ws, &check, None)
        .map_err(|e| scenario_error(py, e.to_string(), None, Some(e.0.path.clone()), None))?;
    report_json(&report, "loads")
}

fn regime_error(py: Python<'_>, e: caisson::loads::regime::RegimeError) -> PyErr {
    scenario_error(py, e.to_string(), Some("[waves] regime".into()), None, None)
}

/// The `caisson loads --json` quantities of many waves (heights and periods of equal length) as
/// columns: (flattened key names, values) ([`loads_table`]). Keys are joined by "."
/// (`goda.horizontal_force_kn_per_m`). `threads`: 1 this thread, 0 one per core, n a local pool.
#[pyfunction]
#[pyo3(signature = (sc, heights_m, periods_s, threads=1))]
fn loads_columns<'py>(
    py: Python<'py>,
    sc: &CoreScenario,
    heights_m: PyReadonlyArray1<'py, f64>,
    periods_s: PyReadonlyArray1<'py, f64>,
    threads: usize,
) -> PyResult<loads_table::Table> {
    let sc = &sc.sc;
    let ws = sc.waves_for("caisson.loads.evaluate").map_err(|e| lib_error(py, e, None))?;
    let (h, t) = (heights_m.as_slice()?, periods_s.as_slice()?);
    if h.len() != t.len() {
        return Err(PyValueError::new_err("heights_m and periods_s must have the same length"));
    }
    for (key, v) in [("heights_m", h), ("periods_s", t)] {
        if let Some(x) = v.iter().find(|x| !(x.is_finite() && **x > 0.0)) {
            return Err(scenario_error(
                py,
                format!("`{key}` = {x}: must be a finite number > 0"),
                Some(key.into()),
                Some(x.to_string()),
                Some("must be a finite number > 0".into()),
            ));
        }
    }
    check_threads(py, threads)?;
    let (w, mu) = (sc.caisson().weight_in_water_n, sc.foundation().mu_static);
    let e = work::loads_table(h.len(), loads_table::bytes_per_row(ws, w, mu));
    check_work(py, "caisson.loads.evaluate", &e, &LOADS)?;
    loads_table::build(py, ws, w, mu, h, t, threads)?
        .map_err(|(_, e)| scenario_error(py, e, Some("[waves] regime".into()), None, None))
}

/// Linear wavelength L(T, h), m, element-wise.
#[pyfunction]
fn wavelength_m<'py>(
    py: Python<'py>,
    period_s: PyReadonlyArray1<'py, f64>,
    depth_m: PyReadonlyArray1<'py, f64>,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let (t, d) = (period_s.as_slice()?, depth_m.as_slice()?);
    Ok(PyArray1::from_vec(py, t.iter().zip(d).map(|(&t, &d)| dispersion::wavelength_m(t, d)).collect()))
}

/// Breaker height H_b(h, T), m, element-wise, by criterion 0 Miche, 1 Goda (a, slope), 2 McCowan (gamma).
#[pyfunction]
fn breaker_height_m<'py>(
    py: Python<'py>,
    criterion: u8,
    depth_m: PyReadonlyArray1<'py, f64>,
    period_s: PyReadonlyArray1<'py, f64>,
    slope: PyReadonlyArray1<'py, f64>,
    coefficient: f64,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let (d, t, s) = (depth_m.as_slice()?, period_s.as_slice()?, slope.as_slice()?);
    let out = (0..d.len())
        .map(|i| match criterion {
            0 => breaking::miche_breaker_height_m(d[i], t[i]),
            1 => breaking::goda_breaker_height_m(d[i], t[i], s[i], coefficient),
            _ => coefficient * d[i],
        })
        .collect();
    Ok(PyArray1::from_vec(py, out))
}

/// Goda's surf-zone H1/3 and H_max at depth h (docs/model.md §3.3), m, element-wise.
#[pyfunction]
#[allow(clippy::type_complexity)]
fn surf_zone_heights<'py>(
    py: Python<'py>,
    h0_m: PyReadonlyArray1<'py, f64>,
    period_s: PyReadonlyArray1<'py, f64>,
    depth_m: PyReadonlyArray1<'py, f64>,
    slope: PyReadonlyArray1<'py, f64>,
) -> PyResult<(Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<f64>>)> {
    let (h, t, d, s) = (h0_m.as_slice()?, period_s.as_slice()?, depth_m.as_slice()?, slope.as_slice()?);
    let z: Vec<surf_zone::SurfZoneHeights> =
        (0..h.len()).map(|i| surf_zone::goda_surf_zone(h[i], t[i], d[i], s[i])).collect();
    Ok((
        PyArray1::from_vec(py, z.iter().map(|z| z.h13_m).collect()),
        PyArray1::from_vec(py, z.iter().map(|z| z.hmax_m).collect()),
    ))
}

/// The `[campaign]` of the scenario run in parallel: `campaign.json` text (with every realization).
#[pyfunction]
#[pyo3(signature = (sc, title, damping_mode=None, threads=1, progress=None))]
fn campaign(
    py: Python<'_>,
    sc: &CoreScenario,
    title: &str,
    damping_mode: Option<&str>,
    threads: usize,
    progress: Option<Py<PyAny>>,
) -> PyResult<String> {
    let mut scen = sc.sc.clone();
    if let Some(m) = damping_mode {
        let mode = match m {
            "total" => DampingMode::Total,
            "elastic" => DampingMode::Elastic,
            _ => {
                return Err(scenario_error(
                    py,
                    format!("`damping_mode` = \"{m}\": must be \"total\" or \"elastic\""),
                    Some("damping_mode".into()),
                    Some(m.into()),
                    Some("\"total\" or \"elastic\"".into()),
                ))
            }
        };
        scen = scen.with_foundation(|f| f.damping_mode = Some(mode)).map_err(|e| lib_error(py, e, None))?;
    }
    let mut c = scen.campaign().map_err(|e| lib_error(py, e, None))?;
    if scen.campaign.as_ref().is_some_and(|s| s.title.is_none()) {
        c.title = title.to_string();
    }
    check_work(py, "caisson.campaign", &py.detach(|| work::campaign(&c.setups, true)), &CAMPAIGN)?;
    let total = c.setups.iter().map(|s| s.waves.train.realizations).sum();
    let results =
        drive(py, threads, total, progress, |ctl| run_campaign(&c.setups, &|| ctl.tick()))?.map_err(run_error)?;
    report_json(&CampaignReport::new(&c, &results, true), "campaign")
}

/// The design run of the scenario's `[design]` (`lives`: how many, if not `[design] lives`), its
/// refusal as Python raises it.
fn designer<'a>(py: Python<'_>, sc: &'a Scenario, lives: Option<usize>) -> PyResult<Designer<'a>> {
    Designer::new(sc, "Design", DesignOptions { lives, brute_force: false }).map_err(|e| lib_error(py, e, None))
}

/// The lives `indices` of the scenario's `[design]` (any subset, any order): columns sorted by
/// life index, `life` and then the columns of `lives.csv` ([`LIFE_COLUMNS`]).
#[pyfunction]
#[pyo3(signature = (sc, indices, threads=1, progress=None))]
fn design_lives<'py>(
    py: Python<'py>,
    sc: &CoreScenario,
    indices: Vec<usize>,
    threads: usize,
    progress: Option<Py<PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let run = designer(py, &sc.sc, None)?;
    let total = indices.len();
    // The lives asked for, not the scenario's count (a shard costs its own lives).
    let (e, advice, command) = estimate_of(py, &sc.sc, "design", Some(total), true, None)?;
    check_work(py, command, &e, advice)?;
    let (lives, stop) = drive_keep(py, threads, total, progress, |ctl| {
        run.run(&indices, &|_, _| {
            // Stopped (Ctrl-C): the lives in progress finish and are kept, as the CLI keeps them.
            if ctl.cancelled() {
                return ControlFlow::Break(());
            }
            ctl.count();
            ControlFlow::Continue(())
        })
    })?;
    let lives = match lives {
        Some(r) => r.map_err(|e| run_error(format!("{e}: {}", e.source)))?,
        None => Vec::new(),
    };
    let d = lives_columns(py, &lives)?;
    if let Some(e) = stop {
        // `e.lives`: the columns of the lives finished before the stop.
        let _ = e.value(py).setattr("lives", &d);
        return Err(e);
    }
    Ok(d)
}

/// `[design] lives = "auto"`: lives 0..k, k where the rule stops (the first batch boundary
/// where the target is met, or the budget `max_lives`; [`Designer::run_auto`]), as columns of
/// [`design_lives`]. Estimated and budgeted on the budget's lives.
#[pyfunction]
#[pyo3(signature = (sc, threads=1, progress=None))]
fn design_auto<'py>(
    py: Python<'py>,
    sc: &CoreScenario,
    threads: usize,
    progress: Option<Py<PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let run = designer(py, &sc.sc, None)?;
    if run.auto().is_none() {
        return Err(PyValueError::new_err(
            "the scenario's `[design] lives` is a number: simulate_auto needs `lives = \"auto\"` (simulate_lives runs a number of lives)",
        ));
    }
    let total = run.design.lives;
    let (e, advice, command) = estimate_of(py, &sc.sc, "design", Some(total), true, None)?;
    check_work(py, command, &e, advice)?;
    let done = std::collections::BTreeMap::new();
    let (ran, stop) = drive_keep(py, threads, total, progress, |ctl| {
        run.run_auto(&done, &|_, _| {
            if ctl.cancelled() {
                return ControlFlow::Break(());
            }
            ctl.count();
            ControlFlow::Continue(())
        })
    })?;
    let lives = match ran {
        Some(r) => match r.map_err(|e| run_error(format!("{e}: {}", e.source)))? {
            caisson::drive::design::AutoRun::Done { lives, sample, .. } => match sample {
                // A stratified design: its sample of lives 0..k.
                Some(s) => s.pool.indices().into_iter().zip(lives).collect(),
                None => lives.into_iter().enumerate().collect(),
            },
            caisson::drive::design::AutoRun::Stopped { computed } => computed,
        },
        None => Vec::new(),
    };
    let d = lives_columns(py, &lives)?;
    if let Some(e) = stop {
        let _ = e.value(py).setattr("lives", &d);
        return Err(e);
    }
    Ok(d)
}

/// The columns of `lives` (sorted by index): `life`, then [`LIFE_COLUMNS`].
fn lives_columns<'py>(py: Python<'py>, lives: &[(usize, StormOutcome)]) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("life", PyArray1::from_vec(py, lives.iter().map(|(i, _)| *i as u64).collect::<Vec<u64>>()))?;
    for (name, column) in LIFE_COLUMNS {
        match column {
            LifeColumn::Metres(f) | LifeColumn::Radians(f) | LifeColumn::Kilopascals(f) => {
                d.set_item(name, PyArray1::from_vec(py, lives.iter().map(|(_, o)| f(o)).collect()))?
            }
            LifeColumn::Count(f) => {
                d.set_item(name, PyArray1::from_vec(py, lives.iter().map(|(_, o)| f(o)).collect()))?
            }
        }
    }
    Ok(d)
}

/// The names of the columns of a life (after `life`), as `lives.csv` writes them.
#[pyfunction]
fn life_columns() -> Vec<&'static str> {
    LIFE_COLUMNS.iter().map(|(name, _)| *name).collect()
}

/// `design.json` text of the lives given as columns (every name of [`life_columns`], in life
/// order): metres and radians as floats, counts as whole numbers; `life` their indices (each
/// once, ascending). The lives are joined by the merge rules of `caisson merge`: lives 0..N with
/// N the largest index + 1, every one given ([`Merge`]): a gap is refused (`ValueError`).
///
/// A stratified design (`[design] sampling = "stratified"`) needs its sample of lives 0..`pool_lives`
/// ([`design_sample`]), every one given, and no other.
#[pyfunction]
#[pyo3(signature = (sc, columns, life, pool_lives=None))]
fn design_statistics(
    py: Python<'_>,
    sc: &CoreScenario,
    columns: Bound<'_, PyDict>,
    life: Vec<usize>,
    pool_lives: Option<usize>,
) -> PyResult<String> {
    let run = designer(py, &sc.sc, None)?;
    let mut rows: Vec<serde_json::Map<String, serde_json::Value>> = Vec::new();
    for (name, column) in LIFE_COLUMNS {
        let item = columns
            .get_item(name)?
            .ok_or_else(|| PyValueError::new_err(format!("the lives have no column `{name}`")))?;
        let values: Vec<serde_json::Value> = match column {
            LifeColumn::Metres(_) | LifeColumn::Radians(_) | LifeColumn::Kilopascals(_) => {
                item.extract::<Vec<f64>>()?.into_iter().map(serde_json::Value::from).collect()
            }
            LifeColumn::Count(_) => item.extract::<Vec<u64>>()?.into_iter().map(serde_json::Value::from).collect(),
        };
        if rows.is_empty() {
            rows.resize(values.len(), serde_json::Map::new());
        }
        if values.len() != rows.len() {
            return Err(PyValueError::new_err(format!(
                "column `{name}` has {} values where the others have {}",
                values.len(),
                rows.len()
            )));
        }
        for (row, v) in rows.iter_mut().zip(values) {
            row.insert(name.to_string(), v);
        }
    }
    let lives: Vec<StormOutcome> = rows
        .into_iter()
        .map(|r| serde_json::from_value(serde_json::Value::Object(r)))
        .collect::<Result<_, _>>()
        .map_err(|e| PyValueError::new_err(format!("a life's columns do not form an outcome: {e}")))?;
    if life.len() != lives.len() {
        return Err(PyValueError::new_err(format!(
            "`life` has {} values where the columns have {}",
            life.len(),
            lives.len()
        )));
    }
    if run.auto().is_some() {
        // `lives = "auto"`: the rule over the batch boundaries of the lives given, in order, as
        // `caisson merge` applies it (gaps beyond the stopping point do not matter).
        let given = life.len();
        let held: std::collections::BTreeMap<usize, StormOutcome> = life.into_iter().zip(lives).collect();
        if held.len() < given {
            return Err(PyValueError::new_err("a life appears more than once"));
        }
        return match py.detach(|| run.stopping_point(&held)) {
            Some(caisson::drive::design::Stopping::At(k, _, sample)) => {
                // The lives 0..k, or a stratified design's sample of them.
                let indices: Vec<usize> = sample.as_ref().map_or_else(|| (0..k).collect(), |s| s.pool.indices());
                let lives: Vec<StormOutcome> = indices.iter().map(|i| held[i]).collect();
                report_json(&run.report_sampled(&lives, sample.as_deref()), "design")
            }
            Some(caisson::drive::design::Stopping::NotReached { missing, last_boundary }) => Err(PyValueError::new_err(format!(
                "lives = \"auto\": the lives given hold lives 0..{missing} (of those the design simulates; life {missing} is not given), and the target relative error {} is met at no batch boundary up to {last_boundary}: they do not reach the stopping point; simulate more lives from {missing} (`Design.simulate_lives(range({missing}, END))`) and add them",
                run.auto().map_or(0.0, |a| a.target_relative_error)
            ))),
            None => Err(PyValueError::new_err("not lives = \"auto\"")),
        };
    }
    // A stratified design's pool: the Design's lives.
    let n = pool_lives.unwrap_or(run.design.lives);
    let sample = py.detach(|| run.sample(0..n));
    let lives = match &sample {
        Some(s) => sampled(life, lives, n, &s.pool.indices())?,
        None => merged(life, lives)?,
    };
    report_json(&run.report_sampled(&lives, sample.as_ref()), "design")
}

/// The lives a stratified design of `lives` lives simulates (`None` for a plain design: every
/// life), by the CLI's rule ([`Designer::sample`]).
#[pyfunction]
#[pyo3(signature = (sc, lives, threads=1))]
fn design_sample(py: Python<'_>, sc: &CoreScenario, lives: usize, threads: usize) -> PyResult<Option<Vec<usize>>> {
    let run = designer(py, &sc.sc, Some(lives))?;
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .map_err(|e| run_error(format!("starting the worker threads: {e}")))?;
    Ok(py.detach(|| pool.install(|| run.sample(0..lives))).map(|s| s.pool.indices()))
}

/// The sampled lives `wanted` of a stratified design of `n` lives, from lives (index, outcome):
/// each wanted life given, refused (`ValueError`) otherwise.
fn sampled(life: Vec<usize>, lives: Vec<StormOutcome>, n: usize, wanted: &[usize]) -> PyResult<Vec<StormOutcome>> {
    let mut merge = Merge::new(n);
    let refuse = |e: MergeError| {
        PyValueError::new_err(match e {
            MergeError::Missing { start, missing, .. } => format!(
                "life {start} of the stratified sample is missing ({missing} of its {} lives): simulate the sample's lives (`Design.simulate_lives()` simulates them all)",
                wanted.len()
            ),
            MergeError::Overlap { life, .. } => format!("life {life} appears more than once"),
            MergeError::Beyond { life, lives, .. } => format!("life {life} is beyond the lives 0..{lives}"),
        })
    };
    merge.add(None, life.into_iter().zip(lives)).map_err(refuse)?;
    merge.finish_sample(wanted).map_err(refuse)
}

/// Lives (index, outcome) joined into lives 0..N, N the largest index + 1, by the merge rules of
/// `caisson merge` ([`Merge`]), refused (`ValueError`) in the words of the Python API.
fn merged(life: Vec<usize>, lives: Vec<StormOutcome>) -> PyResult<Vec<StormOutcome>> {
    let n = life.iter().max().map_or(0, |m| m + 1);
    let mut merge = Merge::new(n);
    let refuse = |e: MergeError| {
        PyValueError::new_err(match e {
            MergeError::Missing { start, end, missing, gaps, .. } => {
                let more = if gaps > 1 { format!(", {missing} lives missing in {gaps} gaps") } else { String::new() };
                format!(
                    "lives {start}..{end} are missing ({} lives{more}): the statistics of lives up to {} need every life 0..{n}, as `caisson merge` refuses a gap between shards; simulate them (`Design.simulate_lives(range({start}, {end}))`) and add them",
                    end - start,
                    n - 1
                )
            }
            MergeError::Overlap { life, .. } => format!("life {life} appears more than once"),
            MergeError::Beyond { life, lives, .. } => format!("life {life} is beyond the lives 0..{lives}"),
        })
    };
    merge.add(None, life.into_iter().zip(lives)).map_err(refuse)?;
    merge.finish().map_err(refuse)
}

/// The fingerprint of the design's lives (what every life depends on).
#[pyfunction]
fn design_fingerprint_of(py: Python<'_>, sc: &CoreScenario) -> PyResult<String> {
    Ok(designer(py, &sc.sc, None)?.fingerprint())
}

const SIZE: Advice = Advice {
    steps: "lower `[size] lives`, `[size] curve_points` or `[design] life_years`, raise `[size] tolerance_m` or narrow `[size] range_m`",
    waves: "lower `[size] lives`, `[size] curve_points` or `[design] life_years`, raise `[size] tolerance_m` or narrow `[size] range_m`",
    memory: "lower `[size] lives`",
    disk: "",
};

/// A sizing error as Python raises it: the scenario's as `ScenarioError`, a failed run as
/// `RunError`.
fn size_error(py: Python<'_>, e: SizeError) -> PyErr {
    match e {
        SizeError::Scenario(e) => lib_error(py, e, None),
        e @ SizeError::AtWidth { .. } => scenario_error(py, e.to_string(), None, None, None),
        SizeError::Run { width_m, source } => {
            run_error(format!("the lives at the width {width_m} m: {source}: {}", source.source))
        }
        e @ SizeError::NoConstruction(_) => scenario_error(py, e.to_string(), Some("[caisson]".into()), None, None),
        e => PyRuntimeError::new_err(e.to_string()),
    }
}

/// The scenario's sizing (`caisson size --json`): `size.json` text, by the library's driver.
#[pyfunction]
#[pyo3(signature = (sc, threads=1, progress=None))]
fn size(py: Python<'_>, sc: &CoreScenario, threads: usize, progress: Option<Py<PyAny>>) -> PyResult<String> {
    let sizer = Sizer::new(&sc.sc, "`caisson.size`").map_err(|e| size_error(py, e))?;
    let estimate = py.detach(|| sizer.estimate("`caisson.size`")).map_err(|e| size_error(py, e))?;
    check_work(py, "caisson.size", &estimate, &SIZE)?;
    let total = sizer.candidates() * sizer.params.lives;
    let report = drive(py, threads, total, progress, |ctl| {
        let life = || {
            ctl.count();
            if ctl.cancelled() {
                ControlFlow::Break(())
            } else {
                ControlFlow::Continue(())
            }
        };
        let hooks = Hooks { width: &mut |_, _| {}, life: &life, candidate: &mut |_| Ok(()) };
        sizer.run(&[], hooks)
    })?
    .map_err(|e| size_error(py, e))?;
    report_json(&report, "size")
}

/// A checkpoint's refusal as a `ValueError` naming the file (and the line).
fn checkpoint_error(name: &str, e: CheckpointError) -> PyErr {
    use caisson::report::checkpoint::{LineError, LineFault};
    let message = match e {
        CheckpointError::Fingerprint { found, expected } => format!(
            "{name} was written for a different scenario or options (fingerprint {found}, this design {expected}: the caisson, foundation, solver, waves, [design] life model or seed differ, or it was run with --brute-force)"
        ),
        CheckpointError::Line { line, fault: LineFault::Refused(LineError::Malformed | LineError::NotARecord(_)) } => {
            format!("{name} line {line} is not a life line of a caisson design checkpoint")
        }
        CheckpointError::Format { format, caisson_version } => format!(
            "{name} is of checkpoint format {format} (caisson {caisson_version}); this caisson reads format {}",
            caisson::report::checkpoint::DESIGN_FORMAT
        ),
        CheckpointError::ResultsVersion { results_version, caisson_version } => format!(
            "{name} holds results version {results_version} (caisson {caisson_version}); this caisson computes results version {}: its lives would not match",
            caisson::RESULTS_VERSION
        ),
        e => format!("{name}: {e}"),
    };
    PyValueError::new_err(message)
}

/// The lives of the design checkpoint `data` (the bytes of the file `name`) of the scenario's
/// `[design]`, read by the library's codec: the columns of [`design_lives`].
fn read_design_lives(sc: &Scenario, name: &str, data: &[u8]) -> PyResult<DesignCheckpoint> {
    let run =
        Designer::new(sc, "Design", DesignOptions::default()).map_err(|e| PyValueError::new_err(e.to_string()))?;
    let fingerprint = run.fingerprint();
    read_design(data, &|_| fingerprint.clone(), &|| {}).map_err(|e| checkpoint_error(name, e))
}

/// The lives of a `caisson design` checkpoint (`data`: the bytes of the file `name`) of the
/// scenario's `[design]`: columns sorted by life as [`design_lives`] returns them. A torn last
/// line is left out.
#[pyfunction]
fn read_design_checkpoint<'py>(
    py: Python<'py>,
    sc: &CoreScenario,
    name: &str,
    data: &[u8],
) -> PyResult<Bound<'py, PyDict>> {
    let cp = py.detach(|| read_design_lives(&sc.sc, name, data))?;
    let lives: Vec<(usize, StormOutcome)> = cp.lives.into_iter().collect();
    lives_columns(py, &lives)
}

/// The shards `files` ((name, bytes) of each checkpoint) of the scenario's design joined into
/// lives 0..`lives` by the rules of `caisson merge`: (`design.json` text, the lives' columns).
#[pyfunction]
fn merge_checkpoints<'py>(
    py: Python<'py>,
    sc: &CoreScenario,
    files: Vec<(String, Vec<u8>)>,
    lives: usize,
) -> PyResult<(String, Bound<'py, PyDict>)> {
    let mut merge = Merge::new(lives);
    let mut ranges: Vec<std::ops::Range<usize>> = Vec::new();
    let text = |r: &std::ops::Range<usize>| format!("{}..{}", r.start, r.end);
    for (name, data) in &files {
        let cp = py.detach(|| read_design_lives(&sc.sc, name, data))?;
        if cp.torn_bytes > 0 {
            return Err(PyValueError::new_err(format!(
                "shard {name} ends in a line cut short ({} bytes: the run stopped while writing it): complete the shard first (`caisson design --life-range {} --resume`)",
                cp.torn_bytes,
                text(&cp.header.range())
            )));
        }
        ranges.push(cp.header.range());
        merge.add(Some(cp.header.range()), cp.lives).map_err(|e| shard_error(&e, &files, &ranges, lives))?;
    }
    let all = merge.finish().map_err(|e| shard_error(&e, &files, &ranges, lives))?;
    let report = designer(py, &sc.sc, Some(lives))?.report(&all);
    let indexed: Vec<(usize, StormOutcome)> = all.into_iter().enumerate().collect();
    Ok((report_json(&report, "design")?, lives_columns(py, &indexed)?))
}

/// A refusal of the merge rules naming the shards (by file) and the lives they were run for.
fn shard_error(e: &MergeError, files: &[(String, Vec<u8>)], ranges: &[std::ops::Range<usize>], n: usize) -> PyErr {
    let shard = |k: usize| format!("shard {} (lives {}..{})", files[k].0, ranges[k].start, ranges[k].end);
    PyValueError::new_err(match *e {
        MergeError::Beyond { shard: k, life, .. } => {
            format!("{} holds life {life}, beyond the lives to merge, 0..{n} (the design's lives)", shard(k))
        }
        MergeError::Overlap { life, first, second } => format!(
            "life {life} is in two shards: {} and {}; shards must not overlap: give each life to one shard",
            shard(first),
            shard(second)
        ),
        MergeError::Missing { start, end, missing, gaps, incomplete } => {
            let more = if gaps > 1 { format!(", {missing} lives missing in {gaps} gaps") } else { String::new() };
            let hint = match incomplete {
                Some(k) => format!("{} is incomplete: complete it with --resume", shard(k)),
                None => format!("run them (`caisson design --life-range {start}..{end}`) and merge that shard too"),
            };
            format!(
                "lives {start}..{end} are in no shard ({} lives{more}; the merge needs lives 0..{n}): {hint}",
                end - start
            )
        }
    })
}

/// The scenario's `[fragility]`: `fragility.json` text (`name`: the scenario file's name).
#[pyfunction]
#[pyo3(signature = (sc, name, threads=1, progress=None))]
fn fragility(
    py: Python<'_>,
    sc: &CoreScenario,
    name: &str,
    threads: usize,
    progress: Option<Py<PyAny>>,
) -> PyResult<String> {
    let p = sc.sc.fragility_for("Fragility").map_err(|e| lib_error(py, e, None))?;
    let case = sc.sc.storm_case(true).map_err(|e| lib_error(py, e, None))?;
    let ws = sc.sc.waves_for("Fragility").map_err(|e| lib_error(py, e, None))?;
    check_work(py, "Fragility.run", &py.detach(|| work::fragility(&case, p)), &FRAGILITY)?;
    let total = p.heights_m.len() * p.storms;
    let r = drive(py, threads, total, progress, |ctl| run_fragility(&case, p, &|| ctl.tick()))?
        .map_err(|e| run_error(format!("{e}: {}", e.source)))?;
    report_json(&FragilityReport::new(name, sc.sc.structure(), ws, p, &r), "fragility")
}

/// Maximum-likelihood lognormal fit of `k` exceedances in `n` trials at intensities `im`:
/// (median, beta, ln_median_se, beta_se, log_likelihood, median_ci95, beta_ci95), the intervals
/// `[low, high]` with `None` for an open end, or `FitError`.
#[pyfunction]
#[allow(clippy::type_complexity)]
fn fit_lognormal(
    py: Python<'_>,
    im: Vec<f64>,
    k: Vec<u64>,
    n: Vec<u64>,
) -> PyResult<(f64, f64, f64, f64, f64, [Option<f64>; 2], [Option<f64>; 2])> {
    if im.len() != k.len() || k.len() != n.len() {
        return Err(PyValueError::new_err("im, k and n must have the same length"));
    }
    if let Some(x) = im.iter().find(|x| !(x.is_finite() && **x > 0.0)) {
        return Err(PyValueError::new_err(format!("im = {x}: intensities must be finite numbers > 0")));
    }
    if let Some(i) = (0..k.len()).find(|&i| k[i] > n[i]) {
        return Err(PyValueError::new_err(format!("k[{i}] = {} exceeds n[{i}] = {}", k[i], n[i])));
    }
    match py.detach(|| fit(&im, &k, &n)) {
        Ok(f) => Ok((f.median, f.beta, f.ln_median_se, f.beta_se, f.log_likelihood, f.median_ci95, f.beta_ci95)),
        Err(e) => {
            let err = FitError::new_err(e.to_string());
            let reason = serde_json::to_value(e).ok().and_then(|v| v.as_str().map(str::to_string));
            let _ = err.value(py).setattr("reason", reason);
            Err(err)
        }
    }
}

/// Benchmark helper (BENCHMARKS.md, not API): seconds per `run` of the scenario's `[load]` inside
/// Rust (the engine and the summary, no history), mean over `repeats` runs.
#[pyfunction]
fn _bench_run_s(py: Python<'_>, sc: &CoreScenario, repeats: usize) -> PyResult<f64> {
    let sc = &sc.sc;
    let load = sc.load.as_ref().ok_or_else(|| PyValueError::new_err("needs a [load]"))?;
    py.detach(|| {
        let t0 = std::time::Instant::now();
        for _ in 0..repeats.max(1) {
            let r = run_engine(sc.structure(), load, sc.duration_s, false).map_err(run_error)?;
            std::hint::black_box(RunReport::new(sc.structure(), load, &r.summary));
        }
        Ok(t0.elapsed().as_secs_f64() / repeats.max(1) as f64)
    })
}

/// Benchmark helper (BENCHMARKS.md, not API): seconds (wall clock) that the first phases of
/// [`loads_columns`] take inside Rust on `heights_m` at the scenario's period: 0 the model and
/// Goda's safety factors, 1 these and the report rows (not the columns).
#[pyfunction]
fn _bench_loads_s(py: Python<'_>, sc: &CoreScenario, heights_m: PyReadonlyArray1<'_, f64>, phase: u8) -> PyResult<f64> {
    let sc = &sc.sc;
    let ws = sc.waves_for("bench").map_err(|e| lib_error(py, e, None))?;
    let (w, mu) = (sc.caisson().weight_in_water_n, sc.foundation().mu_static);
    let (t, heights) = (ws.period_s(), heights_m.as_slice()?);
    py.detach(|| {
        let t0 = std::time::Instant::now();
        for &h in heights {
            let check = StaticCheck::new(ws, DesignWave::with_height(ws, h, t), w, mu, ws.regime())
                .map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
            if phase == 0 {
                std::hint::black_box(check.safety);
            } else {
                std::hint::black_box(LoadsReport::new(ws, &check, w, mu));
            }
        }
        Ok(t0.elapsed().as_secs_f64())
    })
}

/// `caisson.report`: the calculation note of the scenario files `scenarios` (several: side by
/// side) into `out` (report.html; report.pdf where a headless Chromium is found and `pdf`), by
/// the CLI's own exporter (`caisson report`, docs/report.md). Returns the files written.
#[pyfunction]
#[pyo3(signature = (scenarios, out, threads=0, pdf=true))]
fn report(py: Python<'_>, scenarios: Vec<String>, out: String, threads: usize, pdf: bool) -> PyResult<Vec<String>> {
    check_threads(py, threads)?;
    let args = caisson_cli::cli::ReportArgs {
        scenarios: scenarios.iter().map(std::path::PathBuf::from).collect(),
        out: std::path::PathBuf::from(&out),
        threads,
        no_pdf: !pdf,
    };
    py.detach(|| caisson_cli::cmd_report::run(args)).map_err(|e| {
        if e.downcast_ref::<caisson_cli::InputError>().is_some() {
            scenario_error(py, e.to_string(), None, None, None)
        } else {
            run_error(format!("{e:#}"))
        }
    })?;
    let dir = Path::new(&out);
    Ok(["report.html", "report.pdf"]
        .iter()
        .map(|f| dir.join(f))
        .filter(|p| p.is_file())
        .map(|p| p.display().to_string())
        .collect())
}

#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("ScenarioError", py.get_type::<ScenarioError>())?;
    m.add("FitError", py.get_type::<FitError>())?;
    m.add("RunError", py.get_type::<RunError>())?;
    m.add("VERSION", caisson::VERSION)?;
    m.add("RESULTS_VERSION", caisson::RESULTS_VERSION)?;
    m.add_class::<CoreScenario>()?;
    m.add_function(wrap_pyfunction!(run_load, m)?)?;
    m.add_function(wrap_pyfunction!(report, m)?)?;
    m.add_function(wrap_pyfunction!(run_trains, m)?)?;
    m.add_function(wrap_pyfunction!(spectrum, m)?)?;
    m.add_function(wrap_pyfunction!(loads_report, m)?)?;
    m.add_function(wrap_pyfunction!(loads_columns, m)?)?;
    m.add_function(wrap_pyfunction!(wavelength_m, m)?)?;
    m.add_function(wrap_pyfunction!(breaker_height_m, m)?)?;
    m.add_function(wrap_pyfunction!(surf_zone_heights, m)?)?;
    m.add_function(wrap_pyfunction!(campaign, m)?)?;
    m.add_function(wrap_pyfunction!(design_lives, m)?)?;
    m.add_function(wrap_pyfunction!(design_auto, m)?)?;
    m.add_function(wrap_pyfunction!(design_statistics, m)?)?;
    m.add_function(wrap_pyfunction!(design_sample, m)?)?;
    m.add_function(wrap_pyfunction!(life_columns, m)?)?;
    m.add_function(wrap_pyfunction!(design_fingerprint_of, m)?)?;
    m.add_function(wrap_pyfunction!(fragility, m)?)?;
    m.add_function(wrap_pyfunction!(size, m)?)?;
    m.add_function(wrap_pyfunction!(read_design_checkpoint, m)?)?;
    m.add_function(wrap_pyfunction!(merge_checkpoints, m)?)?;
    m.add_function(wrap_pyfunction!(fit_lognormal, m)?)?;
    m.add_function(wrap_pyfunction!(estimate, m)?)?;
    m.add_function(wrap_pyfunction!(read_scenario, m)?)?;
    m.add_function(wrap_pyfunction!(check_threads, m)?)?;
    m.add("MAX_THREADS", caisson::MAX_THREADS)?;
    m.add("MAX_SAMPLES", MAX_SAMPLES)?;
    m.add_function(wrap_pyfunction!(budget_json, m)?)?;
    m.add("MAX_LIVES", MAX_LIVES)?;
    m.add_function(wrap_pyfunction!(_bench_run_s, m)?)?;
    m.add_function(wrap_pyfunction!(_bench_loads_s, m)?)?;
    Ok(())
}
