//! Run state as text: the checkpoint codec of every resumable command (`caisson design`, `caisson
//! size`, Python's `Design`) and the rules of merging the shards of a design run. Text in, typed
//! values out: the front-ends own the files, the locks and the flushing (docs/design.md,
//! "Checkpoint" and "Sharding").
//!
//! **Format.** A header line (JSON: the format number, the fingerprint of what every record
//! depends on, the tool and results versions; a design checkpoint also the range of lives the
//! run was asked for and whether it ran by brute force), then one JSON line per finished record
//! (a life, or a sizing candidate), each ending with `"check"`: the FNV-1a of the header line, a
//! newline and the record's JSON ([`line_check`]). A line edited, copied from another checkpoint
//! or spliced onto another header fails its check. A last line without its newline was cut short
//! (the run stopped while writing it): it is reported, not read.
//!
//! **Rules of a reader** ([`read_design`], [`read_size`]): the header must be of this format and
//! results version and carry the fingerprint the reader expects; every complete line must pass
//! its check and hold a record, and no record may appear twice. The refusals are typed
//! ([`CheckpointError`]); the front-end words them with the file's name and what to do.
//!
//! **Merging** ([`Merge`]): shards join into lives 0..N only if every life is in exactly one
//! shard and none is at or beyond N; otherwise [`MergeError`] says which life and which shards.

use crate::analysis::lifetime::StormOutcome;
use crate::analysis::sizing::Candidate;
use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::io::BufRead;
use std::ops::Range;

/// The design checkpoint format written: 2 added the check of every life line (format 1 had
/// none); 3 adds the range of lives and `brute_force` to the header (for shards and merging).
pub const DESIGN_FORMAT: u32 = 3;
/// The sizing checkpoint format written.
pub const SIZE_FORMAT: u32 = 1;
/// The longest line a reader keeps (a life line is about 400 bytes; a header less).
pub const MAX_LINE_BYTES: usize = 64 * 1024;

/// The first line of a design checkpoint.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DesignHeader {
    pub caisson_design_checkpoint: u32,
    pub fingerprint: String,
    /// The lives the run that wrote the header was asked for, `life_start..life_end` (end
    /// exclusive; `0..lives` for a whole run). A resumed run may ask for others: the life lines
    /// say which lives the checkpoint holds.
    pub life_start: usize,
    pub life_end: usize,
    /// Whether the lives were run by brute force (part of the fingerprint too).
    pub brute_force: bool,
    pub caisson_version: String,
    pub results_version: u32,
}

impl DesignHeader {
    /// The header this build writes.
    pub fn new(fingerprint: String, lives: &Range<usize>, brute_force: bool) -> Self {
        DesignHeader {
            caisson_design_checkpoint: DESIGN_FORMAT,
            fingerprint,
            life_start: lives.start,
            life_end: lives.end,
            brute_force,
            caisson_version: crate::VERSION.to_string(),
            results_version: crate::RESULTS_VERSION,
        }
    }

    /// The lives the run was asked for.
    pub fn range(&self) -> Range<usize> {
        self.life_start..self.life_end
    }

    /// The header as its line (without the newline).
    pub fn line(&self) -> String {
        serde_json::to_string(self).expect("a header serializes")
    }
}

/// The first line of a sizing checkpoint.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SizeHeader {
    pub caisson_size_checkpoint: u32,
    pub fingerprint: String,
    pub caisson_version: String,
    pub results_version: u32,
}

impl SizeHeader {
    /// The header this build writes.
    pub fn new(fingerprint: String) -> Self {
        SizeHeader {
            caisson_size_checkpoint: SIZE_FORMAT,
            fingerprint,
            caisson_version: crate::VERSION.to_string(),
            results_version: crate::RESULTS_VERSION,
        }
    }

    /// The header as its line (without the newline).
    pub fn line(&self) -> String {
        serde_json::to_string(self).expect("a header serializes")
    }
}

/// A life as a design checkpoint holds it.
#[derive(Serialize, Deserialize)]
struct LifeLine {
    life: usize,
    #[serde(flatten)]
    outcome: StormOutcome,
}

/// The key that ends every record line: `,"check":"<16 hex digits>"}`.
const CHECK_KEY: &str = ",\"check\":\"";
const CHECK_TAIL_LEN: usize = CHECK_KEY.len() + 16 + 2;

/// The check of a record line: FNV-1a of the header line, a newline and the record's JSON.
pub fn line_check(header_line: &str, body: &str) -> String {
    let mut bytes = Vec::with_capacity(header_line.len() + 1 + body.len());
    bytes.extend_from_slice(header_line.as_bytes());
    bytes.push(b'\n');
    bytes.extend_from_slice(body.as_bytes());
    format!("{:016x}", super::fnv1a_64(&bytes))
}

/// A record (a JSON object) as a line under `header_line`, newline included, `"check"` last.
fn encode_line<T: Serialize>(header_line: &str, record: &T) -> String {
    let body = serde_json::to_string(record).expect("a record serializes");
    let check = line_check(header_line, &body);
    format!("{}{CHECK_KEY}{check}\"}}\n", &body[..body.len() - 1])
}

/// Why a complete line is not a record of its checkpoint.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum LineError {
    /// Not of the form `{...,"check":"<16 hex digits>"}`.
    #[error("is not a record line of a caisson checkpoint")]
    Malformed,
    /// Its check is not that of the header and the line.
    #[error("does not match its check: it was edited, or it comes from another checkpoint")]
    CheckMismatch,
    /// It passes its check but its JSON is not a record of this kind (serde's words).
    #[error("is not a record: {0}")]
    NotARecord(String),
}

/// A complete line (without its newline) back to its record, or why it is refused.
fn decode_line<T: DeserializeOwned>(header_line: &str, line: &str) -> Result<T, LineError> {
    let cut =
        line.len().checked_sub(CHECK_TAIL_LEN).filter(|&c| line.is_char_boundary(c)).ok_or(LineError::Malformed)?;
    let (head, tail) = line.split_at(cut);
    let check = tail.strip_prefix(CHECK_KEY).and_then(|t| t.strip_suffix("\"}")).ok_or(LineError::Malformed)?;
    let body = format!("{head}}}");
    if line_check(header_line, &body) != check {
        return Err(LineError::CheckMismatch);
    }
    serde_json::from_str(&body).map_err(|e| LineError::NotARecord(e.to_string()))
}

/// A finished life as a design checkpoint line, newline included.
pub fn life_line(header_line: &str, life: usize, outcome: &StormOutcome) -> String {
    encode_line(header_line, &LifeLine { life, outcome: *outcome })
}

/// A design checkpoint line (without its newline) back to its life.
pub fn parse_life_line(header_line: &str, line: &str) -> Result<(usize, StormOutcome), LineError> {
    decode_line::<LifeLine>(header_line, line).map(|l| (l.life, l.outcome))
}

/// A sizing candidate as a checkpoint line, newline included.
pub fn candidate_line(header_line: &str, c: &Candidate) -> String {
    encode_line(header_line, c)
}

/// A sizing checkpoint line (without its newline) back to its candidate.
pub fn parse_candidate_line(header_line: &str, line: &str) -> Result<Candidate, LineError> {
    decode_line(header_line, line)
}

/// The text of a whole design checkpoint: `header`, then `lives` in the order given.
pub fn design_text<'a>(header: &DesignHeader, lives: impl IntoIterator<Item = (usize, &'a StormOutcome)>) -> String {
    let header_line = header.line();
    let mut text = format!("{header_line}\n");
    for (i, o) in lives {
        text.push_str(&life_line(&header_line, i, o));
    }
    text
}

/// Why a line of a checkpoint is refused.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum LineFault {
    #[error("is {len} bytes long, longer than any record line ({MAX_LINE_BYTES} bytes at most): the file is damaged")]
    TooLong { len: u64 },
    #[error("is not UTF-8 text")]
    NotUtf8,
    /// Ends in CR LF: the file was converted to Windows line ends after caisson wrote it.
    #[error("ends in CR LF (Windows line ends): the file was converted after caisson wrote it (an editor, a transfer in text mode); convert it back to LF line ends (`dos2unix`)")]
    CrLf,
    #[error("{0}")]
    Refused(LineError),
    /// A life (or a width) that an earlier line holds.
    #[error("repeats {what} (already on line {first_line})")]
    Repeats { what: String, first_line: usize },
}

/// Why a checkpoint cannot be used.
#[derive(Debug, thiserror::Error)]
pub enum CheckpointError {
    #[error("{0}")]
    Io(#[from] std::io::Error),
    /// A header of another format (and the version that wrote it, if it says).
    #[error("the checkpoint is of format {format} (caisson {caisson_version})")]
    Format { format: u64, caisson_version: String },
    /// Line 1 is not a header of this kind.
    #[error("line 1 is not a checkpoint header")]
    NotAHeader,
    #[error("the checkpoint holds results version {results_version} (caisson {caisson_version})")]
    ResultsVersion { results_version: u32, caisson_version: String },
    /// Written for other parameters than the reader's.
    #[error("the checkpoint was written for other parameters (fingerprint {found}, expected {expected})")]
    Fingerprint { found: String, expected: String },
    /// Line `line` (1-based) is refused.
    #[error("line {line} {fault}")]
    Line { line: usize, fault: LineFault },
}

/// What is read from a design checkpoint.
#[derive(Debug, Clone, PartialEq)]
pub struct DesignCheckpoint {
    /// The header line as written (the lines' checks depend on it).
    pub header_line: String,
    pub header: DesignHeader,
    pub lives: BTreeMap<usize, StormOutcome>,
    /// Length of the header and the complete lines, bytes: a torn last line starts here.
    pub complete_len: u64,
    /// Bytes of a last line cut short (0: none).
    pub torn_bytes: u64,
}

/// Read one line of `r` (through its `\n`) into `buf`, keeping at most `max + 1` bytes of it (a
/// longer line is counted, not kept): (the line's length in bytes, whether it ends with `\n`).
pub fn read_line_limited(r: &mut impl BufRead, buf: &mut Vec<u8>, max: usize) -> std::io::Result<(u64, bool)> {
    buf.clear();
    let mut len = 0u64;
    loop {
        let chunk = r.fill_buf()?;
        if chunk.is_empty() {
            return Ok((len, false));
        }
        let (take, done) = match chunk.iter().position(|&b| b == b'\n') {
            Some(i) => (i + 1, true),
            None => (chunk.len(), false),
        };
        let room = (max + 1).saturating_sub(buf.len()).min(take);
        buf.extend_from_slice(&chunk[..room]);
        len += take as u64;
        r.consume(take);
        if done {
            return Ok((len, true));
        }
    }
}

/// The header line of `r` (and the bytes read), parsed as `H` of format `format` (the key
/// `format_key`), results version and fingerprint checked ([`CheckpointError`]).
fn read_header<H: DeserializeOwned>(
    r: &mut impl BufRead,
    format_key: &str,
    format: u32,
    expected: &dyn Fn(&H) -> String,
    versions: fn(&H) -> (u32, &str, &str),
) -> Result<(String, H, u64), CheckpointError> {
    let mut buf = Vec::new();
    let (_, complete) = read_line_limited(r, &mut buf, MAX_LINE_BYTES)?;
    let complete = complete && buf.len() <= MAX_LINE_BYTES;
    let header_line = std::str::from_utf8(&buf).unwrap_or("").trim_end_matches('\n').to_string();
    if complete && header_line.ends_with('\r') {
        return Err(CheckpointError::Line { line: 1, fault: LineFault::CrLf });
    }
    let value = serde_json::from_str::<serde_json::Value>(&header_line).ok().filter(|_| complete);
    // A header of another format names its format if it has one.
    if let Some(f) = value.as_ref().and_then(|v| v.get(format_key)?.as_u64()).filter(|&f| f != format as u64) {
        let caisson_version = value
            .as_ref()
            .and_then(|v| v.get("caisson_version")?.as_str().map(String::from))
            .unwrap_or_else(|| "?".into());
        return Err(CheckpointError::Format { format: f, caisson_version });
    }
    let header: H = serde_json::from_str(&header_line).ok().filter(|_| complete).ok_or(CheckpointError::NotAHeader)?;
    let (results_version, caisson_version, fingerprint) = versions(&header);
    if results_version != crate::RESULTS_VERSION {
        return Err(CheckpointError::ResultsVersion { results_version, caisson_version: caisson_version.into() });
    }
    let want = expected(&header);
    if fingerprint != want {
        return Err(CheckpointError::Fingerprint { found: fingerprint.to_string(), expected: want });
    }
    Ok((header_line, header, buf.len() as u64))
}

/// The complete lines after the header, each as text with its 1-based number; a last line
/// without its newline is torn: `on_torn(bytes)` and the end.
fn for_each_line(
    r: &mut impl BufRead,
    mut on_line: impl FnMut(usize, &str, u64) -> Result<(), LineFault>,
) -> Result<u64, CheckpointError> {
    let mut buf = Vec::new();
    for n in 2.. {
        let (len, complete) = read_line_limited(r, &mut buf, MAX_LINE_BYTES)?;
        if len == 0 {
            break;
        }
        if !complete {
            // The run stopped while writing this line (or a crash left a tail of NUL bytes).
            return Ok(len);
        }
        let line = |fault| CheckpointError::Line { line: n, fault };
        if len > MAX_LINE_BYTES as u64 {
            return Err(line(LineFault::TooLong { len }));
        }
        let text = std::str::from_utf8(&buf[..buf.len() - 1]).map_err(|_| line(LineFault::NotUtf8))?;
        if text.ends_with('\r') {
            return Err(line(LineFault::CrLf));
        }
        on_line(n, text, buf.len() as u64).map_err(line)?;
    }
    Ok(0)
}

/// Read a design checkpoint from `r`: a header of this format and results version whose
/// fingerprint is `expected(header)`, then every complete line a life of it, each life once;
/// `on_life` is called once per life read (module docs).
pub fn read_design(
    mut r: impl BufRead,
    expected: &dyn Fn(&DesignHeader) -> String,
    on_life: &dyn Fn(),
) -> Result<DesignCheckpoint, CheckpointError> {
    let (header_line, header, len) =
        read_header(&mut r, "caisson_design_checkpoint", DESIGN_FORMAT, expected, |h: &DesignHeader| {
            (h.results_version, &h.caisson_version, &h.fingerprint)
        })?;
    let mut cp = DesignCheckpoint { header_line, header, lives: BTreeMap::new(), complete_len: len, torn_bytes: 0 };
    let mut line_of: BTreeMap<usize, usize> = BTreeMap::new();
    cp.torn_bytes = for_each_line(&mut r, |n, text, bytes| {
        let (life, outcome) = parse_life_line(&cp.header_line, text).map_err(LineFault::Refused)?;
        if let Some(first_line) = line_of.insert(life, n) {
            return Err(LineFault::Repeats { what: format!("life {life}"), first_line });
        }
        cp.lives.insert(life, outcome);
        cp.complete_len += bytes;
        on_life();
        Ok(())
    })?;
    Ok(cp)
}

/// What is read from a sizing checkpoint: the header line and the finished candidates in the
/// order they were written.
#[derive(Debug, Clone, PartialEq)]
pub struct SizeCheckpoint {
    pub header_line: String,
    pub candidates: Vec<Candidate>,
}

/// Read a sizing checkpoint from `r` whose fingerprint must be `fingerprint`; a torn last line is
/// left out (module docs).
pub fn read_size(mut r: impl BufRead, fingerprint: &str) -> Result<SizeCheckpoint, CheckpointError> {
    let (header_line, _, _) = read_header(
        &mut r,
        "caisson_size_checkpoint",
        SIZE_FORMAT,
        &|_: &SizeHeader| fingerprint.to_string(),
        |h: &SizeHeader| (h.results_version, &h.caisson_version, &h.fingerprint),
    )?;
    let mut candidates: Vec<Candidate> = Vec::new();
    let mut line_of: Vec<usize> = Vec::new();
    for_each_line(&mut r, |n, text, _| {
        let c = parse_candidate_line(&header_line, text).map_err(LineFault::Refused)?;
        if let Some(k) = candidates.iter().position(|d| d.width_m == c.width_m) {
            return Err(LineFault::Repeats { what: format!("the width {} m", c.width_m), first_line: line_of[k] });
        }
        candidates.push(c);
        line_of.push(n);
        Ok(())
    })?;
    Ok(SizeCheckpoint { header_line, candidates })
}

/// Why shards do not merge into lives 0..N (shards numbered in the order given).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum MergeError {
    /// Shard `shard` holds `life` (the smallest such), at or beyond the `lives` to merge.
    #[error("shard {shard} holds life {life}, beyond the lives to merge, 0..{lives}")]
    Beyond { shard: usize, life: usize, lives: usize },
    /// `life` is in shards `first` and `second`.
    #[error("life {life} is in two shards: {first} and {second}")]
    Overlap { life: usize, first: usize, second: usize },
    /// Lives `start..end` (the first missing range) are in no shard: `missing` lives in `gaps`
    /// ranges in all; `incomplete`: a shard that was run for some of them.
    #[error("lives {start}..{end} are in no shard ({missing} lives missing in {gaps} gaps)")]
    Missing { start: usize, end: usize, missing: usize, gaps: usize, incomplete: Option<usize> },
}

/// No shard holds the life yet.
const NONE: u32 = u32::MAX;

/// Shards joining into lives 0..N: [`Merge::add`] each shard in turn, then [`Merge::finish`].
pub struct Merge {
    lives: Vec<StormOutcome>,
    owner: Vec<u32>,
    ran_for: Vec<Option<Range<usize>>>,
}

impl Merge {
    /// A merge of lives 0..`lives`.
    pub fn new(lives: usize) -> Self {
        Merge { lives: vec![StormOutcome::default(); lives], owner: vec![NONE; lives], ran_for: Vec::new() }
    }

    /// The range shard `k` was run for (its header), if known.
    pub fn ran_for(&self, k: usize) -> Option<&Range<usize>> {
        self.ran_for.get(k)?.as_ref()
    }

    /// Add the next shard: its lives (index, outcome; any order) and the range it was run for,
    /// if known. Refuses a life at or beyond N, then a life another shard holds.
    pub fn add(
        &mut self,
        ran_for: Option<Range<usize>>,
        lives: impl IntoIterator<Item = (usize, StormOutcome)>,
    ) -> Result<(), MergeError> {
        let k = self.ran_for.len();
        let n = self.lives.len();
        let mut lives: Vec<(usize, StormOutcome)> = lives.into_iter().collect();
        lives.sort_by_key(|(i, _)| *i);
        if let Some(&(life, _)) = lives.iter().find(|(i, _)| *i >= n) {
            return Err(MergeError::Beyond { shard: k, life, lives: n });
        }
        for (life, outcome) in lives {
            if self.owner[life] != NONE {
                return Err(MergeError::Overlap { life, first: self.owner[life] as usize, second: k });
            }
            self.owner[life] = k as u32;
            self.lives[life] = outcome;
        }
        self.ran_for.push(ran_for);
        Ok(())
    }

    /// The lives `wanted` (ascending: a stratified run's sample of 0..N) in index order, if every
    /// one is in a shard (the others the shards hold are left out); the missing range is of the
    /// wanted lives.
    pub fn finish_sample(mut self, wanted: &[usize]) -> Result<Vec<StormOutcome>, MergeError> {
        // The lives not wanted count as held, so that only the wanted ones can be missing.
        let mut needed = vec![false; self.owner.len()];
        for &i in wanted {
            needed[i] = true;
        }
        for (i, o) in self.owner.iter_mut().enumerate() {
            if !needed[i] && *o == NONE {
                *o = NONE - 1;
            }
        }
        let lives = self.finish()?;
        Ok(wanted.iter().map(|&i| lives[i]).collect())
    }

    /// Lives 0..N in index order, if every one is in a shard.
    pub fn finish(self) -> Result<Vec<StormOutcome>, MergeError> {
        let (owner, n) = (&self.owner, self.owner.len());
        if let Some(start) = owner.iter().position(|&o| o == NONE) {
            let end = owner[start..].iter().position(|&o| o != NONE).map_or(n, |e| start + e);
            let missing = owner.iter().filter(|&&o| o == NONE).count();
            let gaps = (0..n).filter(|&i| owner[i] == NONE && (i == 0 || owner[i - 1] != NONE)).count();
            let incomplete =
                self.ran_for.iter().position(|r| r.as_ref().is_some_and(|r| r.start < end && start < r.end));
            return Err(MergeError::Missing { start, end, missing, gaps, incomplete });
        }
        Ok(self.lives)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn life(s: f64) -> StormOutcome {
        StormOutcome { sliding_m: s, rigid_block_sliding_m: 2.0 * s, waves: 7, ..StormOutcome::default() }
    }

    fn checkpoint(lives: &[usize]) -> String {
        let h = DesignHeader::new("f00d".into(), &(0..10), false);
        let outcomes: Vec<(usize, StormOutcome)> = lives.iter().map(|&i| (i, life(i as f64 * 0.1))).collect();
        design_text(&h, outcomes.iter().map(|(i, o)| (*i, o)))
    }

    fn read(text: &str) -> Result<DesignCheckpoint, CheckpointError> {
        read_design(text.as_bytes(), &|_| "f00d".into(), &|| {})
    }

    /// Text out and back: every life bit for bit, the header as written; a torn last line is
    /// counted and not read.
    #[test]
    fn a_design_checkpoint_round_trips_and_a_torn_line_is_left_out() {
        let text = checkpoint(&[3, 0, 7]);
        let cp = read(&text).unwrap();
        assert_eq!(cp.lives.keys().copied().collect::<Vec<_>>(), [0, 3, 7]);
        assert_eq!(cp.lives[&7], life(0.7000000000000001));
        assert_eq!((cp.complete_len, cp.torn_bytes), (text.len() as u64, 0));
        assert_eq!(cp.header.range(), 0..10);
        let tail = "{\"life\":9,\"slid";
        let cp = read(&format!("{text}{tail}")).unwrap();
        assert_eq!((cp.lives.len(), cp.complete_len, cp.torn_bytes), (3, text.len() as u64, tail.len() as u64));
    }

    /// Each rule refuses with its typed error: another fingerprint, results version or format, an
    /// edited line (with its number), a repeated life.
    #[test]
    fn a_design_checkpoint_reader_refuses_by_rule() {
        let text = checkpoint(&[0, 1]);
        let other = read_design(text.as_bytes(), &|_| "beef".into(), &|| {}).unwrap_err();
        assert!(matches!(other, CheckpointError::Fingerprint { ref found, .. } if found == "f00d"), "{other}");
        let old = text.replacen(&format!("\"results_version\":{}", crate::RESULTS_VERSION), "\"results_version\":1", 1);
        assert!(matches!(read(&old).unwrap_err(), CheckpointError::ResultsVersion { results_version: 1, .. }));
        let format2 = text.replacen("\"caisson_design_checkpoint\":3", "\"caisson_design_checkpoint\":2", 1);
        assert!(matches!(read(&format2).unwrap_err(), CheckpointError::Format { format: 2, .. }));
        assert!(matches!(read("not json\n").unwrap_err(), CheckpointError::NotAHeader));
        let edited = text.replacen("\"waves\":7", "\"waves\":8", 1);
        let e = read(&edited).unwrap_err();
        assert!(matches!(e, CheckpointError::Line { line: 2, fault: LineFault::Refused(LineError::CheckMismatch) }));
        let lines: Vec<&str> = text.lines().collect();
        let repeated = format!("{}\n{}\n{}\n", lines[0], lines[1], lines[1]);
        let e = read(&repeated).unwrap_err();
        assert_eq!(e.to_string(), "line 3 repeats life 0 (already on line 2)");
        assert!(matches!(read(&format!("{}\nxyz\n", lines[0])).unwrap_err(), CheckpointError::Line { line: 2, .. }));
    }

    /// The merge rules: a life beyond N, a life in two shards, a gap (with the shard run for it).
    #[test]
    fn shards_merge_only_into_every_life_once() {
        let lives = |r: Range<usize>| r.map(|i| (i, life(i as f64))).collect::<Vec<_>>();
        let mut m = Merge::new(6);
        m.add(Some(0..3), lives(0..3)).unwrap();
        m.add(None, lives(3..6)).unwrap();
        let all = m.finish().unwrap();
        assert_eq!(all.iter().map(|o| o.sliding_m).collect::<Vec<_>>(), [0.0, 1.0, 2.0, 3.0, 4.0, 5.0]);

        let mut m = Merge::new(6);
        assert_eq!(m.add(None, lives(4..8)), Err(MergeError::Beyond { shard: 0, life: 6, lives: 6 }));
        let mut m = Merge::new(6);
        m.add(None, lives(0..3)).unwrap();
        assert_eq!(m.add(None, lives(2..4)), Err(MergeError::Overlap { life: 2, first: 0, second: 1 }));
        let mut m = Merge::new(10);
        m.add(Some(0..5), lives(0..2)).unwrap();
        m.add(Some(5..10), lives(5..8)).unwrap();
        let e = m.finish().unwrap_err();
        assert_eq!(e, MergeError::Missing { start: 2, end: 5, missing: 5, gaps: 2, incomplete: Some(0) });
    }
}
