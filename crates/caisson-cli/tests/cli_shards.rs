//! Sharded design runs (issue 10 item 2): `caisson design --life-range START..END` shards merged
//! by `caisson merge` give what one process gives, byte for byte in every output file; merge
//! refuses overlaps, gaps, shards of another scenario or results version and edited or torn
//! lines, naming the shard; a shard resumes like a whole run.

mod support;

use std::path::{Path, PathBuf};
use support::{caisson, design_text, refused, s, write};

/// The output files of a design run (the checkpoint is compared apart: its lines are in the order
/// the lives finished).
const OUTPUTS: [&str; 5] = ["design.json", "lives.csv", "histogram.svg", "exceedance.svg", "heel_pressure.svg"];

/// `caisson design FILE --life-range RANGE --out DIR [extra]`, expected to succeed.
fn shard(file: &Path, range: &str, dir: &Path, extra: &[&str]) {
    caisson().args(["design", s(file), "--life-range", range, "--out", s(dir)]).args(extra).assert().success();
}

/// `caisson merge FILE SHARDS --out DIR [--json]`: its stdout.
fn merge(file: &Path, shards: &[&Path], out: &Path) -> Vec<u8> {
    let o = caisson().arg("merge").arg(file).args(shards).args(["--json", "--out", s(out)]).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    o.stdout
}

/// Every output file of `a` and `b` is byte-identical, and their checkpoints hold the same header
/// and lines (sorted). Returns how many files were compared.
fn assert_same_outputs(a: &Path, b: &Path) -> usize {
    for name in OUTPUTS {
        let (x, y) = (std::fs::read(a.join(name)).unwrap(), std::fs::read(b.join(name)).unwrap());
        assert!(x == y, "{name} differs between {a:?} and {b:?}");
    }
    let lines = |p: &Path| {
        let text = std::fs::read_to_string(p.join("checkpoint.jsonl")).unwrap();
        let mut l: Vec<String> = text.lines().map(String::from).collect();
        let header = l.remove(0);
        l.sort();
        (header, l)
    };
    assert_eq!(lines(a), lines(b), "checkpoints of {a:?} and {b:?}");
    OUTPUTS.len() + 1
}

/// The data rows of a lives.csv.
fn rows(dir: &Path) -> Vec<String> {
    std::fs::read_to_string(dir.join("lives.csv")).unwrap().lines().skip(1).map(String::from).collect()
}

/// Three shards (7, 9 and 8 lives) and one run of all 24 lives, in `dir`.
struct Setup {
    file: PathBuf,
    full: PathBuf,
    parts: [PathBuf; 3],
    full_json: Vec<u8>,
}

fn setup(dir: &Path) -> Setup {
    let file = write(dir, "d.toml", &design_text(24, 3, ""));
    let full = dir.join("full");
    let o = caisson().args(["design", s(&file), "--json", "--threads", "2", "--out", s(&full)]).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let parts = [dir.join("a"), dir.join("b"), dir.join("c")];
    // Run out of order, on different thread counts.
    shard(&file, "16..24", &parts[2], &["--threads", "2"]);
    shard(&file, "0..7", &parts[0], &["--threads", "1"]);
    shard(&file, "7..16", &parts[1], &[]);
    Setup { file, full, parts, full_json: o.stdout }
}

#[test]
fn three_shards_in_any_order_merge_to_one_process_byte_for_byte() {
    let dir = tempfile::tempdir().unwrap();
    let st = setup(dir.path());
    let [a, b, c] = [&st.parts[0], &st.parts[1], &st.parts[2]].map(|p| p.as_path());
    // A shard writes its checkpoint and lives.csv with the lives' own indices, no statistics.
    for p in [a, b, c] {
        assert!(p.join("checkpoint.jsonl").exists() && !p.join("design.json").exists(), "{p:?}");
    }
    assert!(rows(b)[0].starts_with("7,") && rows(b).len() == 9, "{:?}", rows(b));
    let joined: Vec<String> = [a, b, c].iter().flat_map(|p| rows(p)).collect();
    assert_eq!(joined, rows(&st.full), "the shards' rows are the rows of one run");
    let mut compared = 0;
    for (k, order) in [[c, a, b], [b, c, a]].iter().enumerate() {
        let out = dir.path().join(format!("merged{k}"));
        let json = merge(&st.file, order, &out);
        assert!(json == st.full_json, "merge --json differs from design --json");
        compared += assert_same_outputs(&st.full, &out);
    }
    assert_eq!(compared, 12);
    // Further merges: two shards merged first (--lives 16), then with the third.
    let ab = dir.path().join("ab");
    caisson().args(["merge", s(&st.file), s(a), s(b), "--lives", "16", "--out", s(&ab)]).assert().success();
    let out = dir.path().join("again");
    merge(&st.file, &[c, &ab.join("checkpoint.jsonl")], &out);
    assert_eq!(assert_same_outputs(&st.full, &out), 6);
    // The merged checkpoint resumes as a finished run: nothing to do, the same outputs.
    let resumed = caisson().args(["design", s(&st.file), "--json", "--resume", "--out", s(&out)]).output().unwrap();
    assert!(resumed.status.success(), "{}", String::from_utf8_lossy(&resumed.stderr));
    assert!(resumed.stdout == st.full_json);
    assert_eq!(assert_same_outputs(&st.full, &out), 6);
}

/// `merge FILE SHARDS --out DIR` refused with every needle; DIR is not created.
fn merge_refused(file: &Path, shards: &[&Path], out: &Path, needles: &[&str]) {
    let mut args = vec!["merge", s(file)];
    args.extend(shards.iter().map(|p| s(p)));
    args.extend(["--out", s(out)]);
    refused(&args, needles);
    assert!(!out.exists(), "nothing written");
}

#[test]
fn merge_refuses_overlaps_gaps_and_foreign_or_edited_shards_and_says_which() {
    let dir = tempfile::tempdir().unwrap();
    let st = setup(dir.path());
    let [a, b, c] = [&st.parts[0], &st.parts[1], &st.parts[2]].map(|p| p.as_path());
    let out = dir.path().join("out");
    let mut cases = 0;
    // Overlap: lives 5..12 are in a (0..7) and in o (5..12): the first is named, with both shards.
    let o = dir.path().join("o");
    shard(&st.file, "5..12", &o, &[]);
    let o_name = format!("shard {}", o.display());
    let a_name = format!("shard {} (holding lives 0..7)", a.display());
    merge_refused(&st.file, &[a, &o, b, c], &out, &["life 5 is in two shards", &a_name, &o_name, "5..12"]);
    cases += 1;
    // Gaps: a missing middle shard, and a missing last one (the file's 24 lives).
    merge_refused(&st.file, &[a, c], &out, &["lives 7..16 are in no shard", "9 lives", "0..24"]);
    merge_refused(&st.file, &[a, b], &out, &["lives 16..24 are in no shard", "--life-range 16..24"]);
    cases += 2;
    // Another scenario (another seed): another fingerprint.
    let g = write(dir.path(), "g.toml", &design_text(24, 4, ""));
    let foreign = dir.path().join("foreign");
    shard(&g, "7..16", &foreign, &[]);
    let f_name = format!("shard {}", foreign.display());
    merge_refused(&st.file, &[a, &foreign, c], &out, &[&f_name, "different scenario", "fingerprint"]);
    cases += 1;
    // Another results version (the header edited; its lines then fail their checks too).
    let copy = |name: &str, from: &Path| {
        let to = dir.path().join(name);
        std::fs::create_dir(&to).unwrap();
        std::fs::copy(from.join("checkpoint.jsonl"), to.join("checkpoint.jsonl")).unwrap();
        to
    };
    let old = copy("old", b);
    let text = std::fs::read_to_string(old.join("checkpoint.jsonl")).unwrap();
    let v = caisson::RESULTS_VERSION;
    let edited = text.replacen(&format!("\"results_version\":{v}"), &format!("\"results_version\":{}", v - 1), 1);
    assert_ne!(edited, text);
    std::fs::write(old.join("checkpoint.jsonl"), edited).unwrap();
    let old_name = format!("shard {}", old.display());
    merge_refused(&st.file, &[a, &old, c], &out, &[&old_name, &format!("results version {}", v - 1)]);
    cases += 1;
    // An edited life line (its waves count), the check kept.
    let ed = copy("edited", b);
    let mut l: Vec<String> =
        std::fs::read_to_string(ed.join("checkpoint.jsonl")).unwrap().lines().map(String::from).collect();
    l[3] = l[3].replacen("\"waves\":", "\"waves\":1", 1);
    std::fs::write(ed.join("checkpoint.jsonl"), l.iter().map(|x| format!("{x}\n")).collect::<String>()).unwrap();
    let ed_name = format!("shard {}", ed.display());
    merge_refused(&st.file, &[a, &ed, c], &out, &[&ed_name, "line 4", "does not match its check"]);
    cases += 1;
    // A torn last line (a shard killed while writing).
    let torn = copy("torn", b);
    let text = std::fs::read_to_string(torn.join("checkpoint.jsonl")).unwrap();
    std::fs::write(torn.join("checkpoint.jsonl"), &text[..text.len() - 40]).unwrap();
    merge_refused(&st.file, &[a, &torn, c], &out, &["cut short", "--life-range 7..16 --resume"]);
    cases += 1;
    // A shard still being written: its lock holds the id of a running process (this test's).
    let lock = b.join("checkpoint.jsonl.lock");
    std::fs::write(&lock, format!("{}\n", std::process::id())).unwrap();
    merge_refused(&st.file, &[a, b, c], &out, &["being written by a running", "wait for it to end"]);
    std::fs::remove_file(&lock).unwrap();
    cases += 1;
    // Lives beyond the lives to merge, and a shard given twice.
    let n16 = ["merge", s(&st.file), s(a), s(b), s(c), "--lives", "16", "--out", s(&out)];
    refused(&n16, &["holds life 16", "beyond the lives to merge, 0..16", "--lives 16"]);
    merge_refused(&st.file, &[a, b, &b.join("checkpoint.jsonl"), c], &out, &["given twice"]);
    cases += 2;
    assert_eq!(cases, 10);
}

#[test]
fn a_shard_resumes_after_stop_after_and_merges_to_the_same_result() {
    let dir = tempfile::tempdir().unwrap();
    let st = setup(dir.path());
    let [a, _, c] = [&st.parts[0], &st.parts[1], &st.parts[2]].map(|p| p.as_path());
    let b = dir.path().join("b2");
    caisson()
        .args(["design", s(&st.file), "--life-range", "7..16", "--threads", "1", "--stop-after", "4"])
        .args(["--out", s(&b)])
        .assert()
        .code(1);
    assert!(!b.join("lives.csv").exists(), "a stopped shard writes no lives.csv");
    let kept = std::fs::read_to_string(b.join("checkpoint.jsonl")).unwrap().lines().count();
    assert_eq!(kept, 1 + 4, "header + 4 lives");
    // Merged before it is complete: refused, naming the shard and how to complete it.
    let out = dir.path().join("out");
    let cmd = format!("--life-range 7..16 --resume --out {}", b.display());
    merge_refused(&st.file, &[a, &b, c], &out, &["are in no shard", "is incomplete", &cmd]);
    shard(&st.file, "7..16", &b, &["--resume", "--threads", "2"]);
    assert_eq!(std::fs::read(b.join("lives.csv")).unwrap(), std::fs::read(st.parts[1].join("lives.csv")).unwrap());
    let json = merge(&st.file, &[a, &b, c], &out);
    assert!(json == st.full_json);
    assert_eq!(assert_same_outputs(&st.full, &out), 6);
}

#[test]
fn bad_life_ranges_are_refused_naming_the_option() {
    let dir = tempfile::tempdir().unwrap();
    let f = write(dir.path(), "d.toml", &design_text(4, 3, ""));
    let out = dir.path().join("out");
    let mut cases = 0;
    for bad in ["5..5", "7..3", "0..10000001", "3", "a..b", "-1..4", "1...4"] {
        refused(
            &["design", s(&f), &format!("--life-range={bad}"), "--out", s(&out)],
            &["--life-range", "START < END ≤ 10000000", "END exclusive"],
        );
        cases += 1;
    }
    // Not with --lives (a shard's lives are its range), nor --json (a shard has no statistics);
    // it needs --out.
    refused(&["design", s(&f), "--life-range", "0..2", "--lives", "4", "--out", s(&out)], &["--life-range", "--lives"]);
    refused(&["design", s(&f), "--life-range", "0..2", "--json", "--out", s(&out)], &["--life-range", "--json"]);
    refused(&["design", s(&f), "--life-range", "0..2"], &["--out"]);
    cases += 3;
    assert_eq!(cases, 10);
    assert!(!out.exists());
}
