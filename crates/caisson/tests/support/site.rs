//! The prototype site shared by the lifetime, design, checkpoint, shard, fragility and sizing
//! tests of both crates (the CLI's tests include this file by path) and the Python shard tests:
//! `tests/data/small_design.toml`, a prototype caisson 20 m wide in 20 m of water, light enough
//! (W' 4500 kN/m) that the largest waves of its short Weibull storms slide it, so that a life
//! takes milliseconds. A test states only what it changes, with [`with`] and [`without`]: the
//! rest of its scenario is this file's, line for line, so a text edit of a test still finds the
//! lines it replaces.

/// The text of `tests/data/small_design.toml` ([design] is its last table).
pub const SMALL_DESIGN: &str = include_str!("../data/small_design.toml");

/// The byte range of `[table]` in `text`: from its header to the next table's header (or the
/// end), or `None` if the table is not there.
fn table_range(text: &str, table: &str) -> Option<(usize, usize)> {
    let header = format!("[{table}]\n");
    let start = if text.starts_with(&header) { 0 } else { text.find(&format!("\n{header}"))? + 1 };
    let body = start + header.len();
    let end = text[body..].find("\n[").map_or(text.len(), |i| body + i + 1);
    Some((start, end))
}

/// `text` with the `key = value` lines of `lines` set in `[table]`: a key's line is replaced where
/// the table has it, else added at the table's end; a table `text` lacks is appended with them.
pub fn with(text: &str, table: &str, lines: &str) -> String {
    let mut out = text.to_string();
    if !out.ends_with('\n') {
        out.push('\n');
    }
    for line in lines.lines().filter(|l| !l.trim().is_empty()) {
        let key = line.split('=').next().expect("a `key = value` line").trim();
        let Some((start, end)) = table_range(&out, table) else {
            out.push_str(&format!("[{table}]\n{line}\n"));
            continue;
        };
        let found = out[start..end]
            .match_indices('\n')
            .map(|(i, _)| start + i + 1)
            .find(|&i| out[i..end].split('=').next().is_some_and(|k| k.trim() == key) && !out[i..end].starts_with('['));
        match found {
            Some(i) => {
                let eol = i + out[i..].find('\n').map_or(out.len() - i, |n| n + 1);
                out.replace_range(i..eol, &format!("{line}\n"));
            }
            None => out.insert_str(end, &format!("{line}\n")),
        }
    }
    out
}

/// `text` without the keys `keys` of `[table]`, or without the whole table if `keys` is empty.
/// A key or table that is not there is a mistake of the test: it panics.
pub fn without(text: &str, table: &str, keys: &[&str]) -> String {
    let (start, end) = table_range(text, table).unwrap_or_else(|| panic!("test bug: no [{table}] in the text"));
    if keys.is_empty() {
        return format!("{}{}", &text[..start], &text[end..]);
    }
    let mut body: Vec<&str> = text[start..end].lines().collect();
    for key in keys {
        let n = body.len();
        body.retain(|l| l.split('=').next().is_none_or(|k| k.trim() != *key) || l.starts_with('['));
        assert_eq!(body.len() + 1, n, "test bug: [{table}] {key} is not in the text once");
    }
    format!("{}{}\n{}", &text[..start], body.join("\n"), &text[end..])
}
