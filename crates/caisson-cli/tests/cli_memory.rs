//! Issue 12: `caisson run --out` streams its histories: a long run takes the memory of a short
//! one. Its own test binary with one test, so that the peak resident memory of the processes it
//! starts (getrusage(RUSAGE_CHILDREN): the largest child waited for) is theirs alone.

mod support;

use support::*;

/// Peak resident set size of the children waited for so far, KiB (Linux reports KiB).
#[cfg(target_os = "linux")]
fn children_peak_kib() -> i64 {
    let mut usage: libc::rusage = unsafe { std::mem::zeroed() };
    // SAFETY: getrusage writes into the struct it is given.
    let rc = unsafe { libc::getrusage(libc::RUSAGE_CHILDREN, &mut usage) };
    assert_eq!(rc, 0, "getrusage");
    usage.ru_maxrss as i64
}

/// The table 5 caisson at dt = 1 ms for 1 s and for 100 s (4600 natural periods, 10⁵ history
/// rows, 86 MB of CSV): the long run may take at most 24 MiB more than the short one. Holding its
/// histories (as before the streaming) took about 100 MB more: 104 MB against 6 MB for the short
/// run, measured with /usr/bin/time; streamed, 8.4 MB. The bound is far from both, so the test is
/// not flaky.
#[cfg(target_os = "linux")]
#[test]
fn a_long_run_with_out_takes_the_memory_of_a_short_one() {
    let dir = tempfile::tempdir().unwrap();
    let base = std::fs::read_to_string(example("table5_triangle.toml")).unwrap();
    assert!(base.contains("duration_s = 0.6") && base.contains("dt_s = 1e-4"));
    let scenario = |name: &str, duration: &str| {
        let text = base.replacen("duration_s = 0.6", &format!("duration_s = {duration}"), 1).replacen(
            "dt_s = 1e-4",
            "dt_s = 1e-3",
            1,
        );
        write(dir.path(), name, &text)
    };
    let (short, long) = (scenario("short.toml", "1"), scenario("long.toml", "100"));
    let run = |toml: &std::path::Path, out: &str| -> usize {
        let out = dir.path().join(out);
        caisson().args(["run", toml.to_str().unwrap(), "--out", out.to_str().unwrap()]).assert().success();
        let rows = std::fs::read_to_string(out.join("history.csv")).unwrap().lines().count() - 1;
        let springs = std::fs::read_to_string(out.join("springs.csv")).unwrap().lines().count() - 1;
        assert_eq!(rows, springs, "the two files have the same rows");
        rows
    };
    let rows_short = run(&short, "short");
    let peak_short = children_peak_kib();
    let rows_long = run(&long, "long");
    let peak_long = children_peak_kib();
    // One row per ms (a few fall a step late and share it with the next: the sampling of History).
    assert!((990..=1001).contains(&rows_short), "{rows_short} rows");
    assert!((99_000..=100_001).contains(&rows_long), "{rows_long} rows");
    assert!(peak_short > 1000, "a measured peak: {peak_short} KiB");
    assert!(
        peak_long - peak_short < 24 * 1024,
        "the 100 s run peaked at {peak_long} KiB, the 1 s run at {peak_short} KiB"
    );
}
