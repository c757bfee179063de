//! The CSV exporter: a table is a list of serde rows whose field names are its columns, in order
//! (no header listed apart from its row). Numbers keep the notation each file has always had:
//! [`Sci`] writes `{:e}` (lengths, which span micrometres to metres), [`Plain`] writes `{}` (the
//! shortest text that reads back as the same number: forces in kN, counts, probabilities). An
//! `Option` that is `None` is an empty cell.
//!
//! `history.csv` and `springs.csv` are streamed row by row while the run steps
//! (`history_out`), without this exporter: their rows are written with no allocation, and
//! springs.csv has a column per spring.

use anyhow::Result;
use serde::{Serialize, Serializer};

/// A number written as `{:e}` (e.g. `1.2e-3`).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Sci(pub f64);

impl Serialize for Sci {
    fn serialize<S: Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        s.collect_str(&format_args!("{:e}", self.0))
    }
}

/// A number written as `{}` (Rust's shortest round-trip text: `0.25`, `1`, `2130.8`).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Plain(pub f64);

impl Serialize for Plain {
    fn serialize<S: Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        s.collect_str(&self.0)
    }
}

/// The CSV text of `rows`: a header of the row type's field names, then one line per row.
pub(crate) fn to_csv<R: Serialize>(rows: impl IntoIterator<Item = R>) -> Result<Vec<u8>> {
    let mut w = csv::Writer::from_writer(Vec::new());
    for r in rows {
        w.serialize(r)?;
    }
    Ok(w.into_inner()?)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Serialize)]
    struct Row {
        n: usize,
        name: &'static str,
        sci_m: Sci,
        plain_kn: Plain,
        maybe: Option<Plain>,
    }

    #[test]
    fn a_row_writes_its_field_names_then_each_notation() {
        let rows = [
            Row { n: 1, name: "breaking", sci_m: Sci(0.00125), plain_kn: Plain(2130.8), maybe: None },
            Row { n: 2, name: "non-breaking", sci_m: Sci(3.0), plain_kn: Plain(1.0), maybe: Some(Plain(0.25)) },
        ];
        let text = String::from_utf8(to_csv(rows).unwrap()).unwrap();
        assert_eq!(text, "n,name,sci_m,plain_kn,maybe\n1,breaking,1.25e-3,2130.8,\n2,non-breaking,3e0,1,0.25\n");
    }

    #[test]
    fn no_rows_is_an_empty_file() {
        // The header comes from the first row: a table without rows has no text at all, as
        // candidates.csv of a sizing that evaluated no width.
        assert!(to_csv(std::iter::empty::<Row>()).unwrap().is_empty());
    }
}
