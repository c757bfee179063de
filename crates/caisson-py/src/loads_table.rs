//! The table of `caisson.loads.evaluate`: the `caisson loads --json` values of many waves, one
//! column per key, written by [`LoadsReport::columns`] (no serde walk) straight into numpy arrays:
//! numbers into one `f64` array of columns × rows (null: NaN), flags into one `bool` array, text
//! as `i32` codes into the column's distinct values (in the order of first appearance) for a
//! pandas Categorical. Each column reaches Python as a row view of its array, without a copy.
//!
//! The rows are filled with the GIL released, on the calling thread (`threads = 1`) or in
//! contiguous blocks on a local rayon pool; the codes of each block are renumbered into the
//! distinct values of the whole table in block order, so the table is the same on any number of
//! threads.

use caisson::analysis::conventional::{DesignWave, StaticCheck};
use caisson::analysis::site::WaveSetup;
use caisson::report::loads::{ColumnSink, LoadsReport};
use numpy::{PyArray2, PyArrayMethods};
use pyo3::prelude::*;

/// What a column holds.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Kind {
    Number = 0,
    Flag = 1,
    Text = 2,
}

/// The columns, from one report (they do not depend on the values).
#[derive(Default)]
struct Layout(Vec<(&'static str, Kind)>);

impl ColumnSink for Layout {
    fn number(&mut self, name: &'static str, _: Option<f64>) {
        self.0.push((name, Kind::Number));
    }
    fn flag(&mut self, name: &'static str, _: bool) {
        self.0.push((name, Kind::Flag));
    }
    fn text(&mut self, name: &'static str, _: &'static str) {
        self.0.push((name, Kind::Text));
    }
}

impl Layout {
    fn count(&self, kind: Kind) -> usize {
        self.0.iter().filter(|c| c.1 == kind).count()
    }
}

/// A block of rows: its slice of every column, and the distinct text values of its rows.
struct Block<'a> {
    first_row: usize,
    numbers: Vec<&'a mut [f64]>,
    flags: Vec<&'a mut [bool]>,
    codes: Vec<&'a mut [i32]>,
    texts: Vec<Vec<&'static str>>,
    /// The row being written and the next column of each [`Kind`].
    row: usize,
    at: [usize; 3],
}

impl ColumnSink for Block<'_> {
    #[inline(always)]
    fn number(&mut self, _: &'static str, x: Option<f64>) {
        self.numbers[self.at[0]][self.row] = x.unwrap_or(f64::NAN);
        self.at[0] += 1;
    }
    #[inline(always)]
    fn flag(&mut self, _: &'static str, b: bool) {
        self.flags[self.at[1]][self.row] = b;
        self.at[1] += 1;
    }
    #[inline(always)]
    fn text(&mut self, _: &'static str, s: &'static str) {
        let values = &mut self.texts[self.at[2]];
        // A few distinct values per column, almost always the same `&'static str`.
        let code = match values.iter().position(|v| std::ptr::eq(*v, s) || *v == s) {
            Some(i) => i,
            None => {
                values.push(s);
                values.len() - 1
            }
        };
        self.codes[self.at[2]][self.row] = code as i32;
        self.at[2] += 1;
    }
}

impl Block<'_> {
    /// The rows of the waves (`heights_m[i]`, `periods_s[i]`) of this block; the first error
    /// with its row.
    fn fill(
        &mut self,
        ws: &WaveSetup,
        w: f64,
        mu: f64,
        h: &[f64],
        t: &[f64],
        ctl: &crate::Ctl,
    ) -> Result<(), (usize, String)> {
        let rows = self.numbers.first().map_or(0, |c| c.len());
        let (h, t) = (&h[self.first_row..][..rows], &t[self.first_row..][..rows]);
        for (row, (&h, &t)) in h.iter().zip(t).enumerate() {
            if row.is_multiple_of(1024) {
                ctl.check();
            }
            let check = StaticCheck::new(ws, DesignWave::with_height(ws, h, t), w, mu, ws.regime())
                .map_err(|e| (self.first_row + row, e.to_string()))?;
            (self.row, self.at) = (row, [0; 3]);
            LoadsReport::new(ws, &check, w, mu).columns(self);
        }
        Ok(())
    }
}

/// `columns` (each of `rows` slots) cut into blocks of `block` rows: `out[b][j]` is column `j`'s
/// slice of block `b`.
fn cut<T>(columns: &mut [T], rows: usize, block: usize, blocks: usize) -> Vec<Vec<&mut [T]>> {
    let mut out: Vec<Vec<&mut [T]>> = (0..blocks).map(|_| Vec::new()).collect();
    if rows > 0 {
        for column in columns.chunks_mut(rows) {
            for (b, part) in column.chunks_mut(block).enumerate() {
                out[b].push(part);
            }
        }
    }
    out
}

/// A table for Python: column names, and per column a numpy array (numbers, flags) or
/// (codes, distinct values) (text).
pub type Table = (Vec<String>, Vec<Py<PyAny>>);

/// Bytes a row of the table takes (its numbers, flags and text codes; about 600 bytes, which is
/// the peak measured per wave of `loads.evaluate` with its DataFrame): the memory bound of
/// `loads.evaluate` (`caisson::analysis::work::loads_table`).
pub fn bytes_per_row(ws: &WaveSetup, weight_in_water_n: f64, mu: f64) -> f64 {
    let (w, mut layout) = (weight_in_water_n, Layout::default());
    if let Ok(c) = StaticCheck::new(ws, DesignWave::of(ws), w, mu, ws.regime()) {
        LoadsReport::new(ws, &c, w, mu).columns(&mut layout);
    }
    let (n, f, c) = (layout.count(Kind::Number), layout.count(Kind::Flag), layout.count(Kind::Text));
    (8 * n.max(1) + f + 4 * c) as f64
}

/// The table of the waves (`heights_m[i]`, `periods_s[i]`) (equal lengths, checked by the
/// caller) at the site and caisson of `ws`, on `threads` threads (1: this one; 0: one per core);
/// or the error of the first wave that has one, with its index.
pub fn build(
    py: Python<'_>,
    ws: &WaveSetup,
    weight_in_water_n: f64,
    mu: f64,
    heights_m: &[f64],
    periods_s: &[f64],
    threads: usize,
) -> PyResult<Result<Table, (usize, String)>> {
    let (w, rows) = (weight_in_water_n, heights_m.len());
    // The columns from the first wave (the scenario's own when there is none).
    let (h0, t0) = match (heights_m.first(), periods_s.first()) {
        (Some(&h), Some(&t)) => (h, t),
        _ => (ws.height_m(), ws.period_s()),
    };
    let first = match StaticCheck::new(ws, DesignWave::with_height(ws, h0, t0), w, mu, ws.regime()) {
        Ok(c) => LoadsReport::new(ws, &c, w, mu),
        Err(e) => return Ok(Err((0, e.to_string()))),
    };
    let mut layout = Layout::default();
    first.columns(&mut layout);
    let (n_num, n_flag, n_text) = (layout.count(Kind::Number), layout.count(Kind::Flag), layout.count(Kind::Text));

    let numbers = PyArray2::<f64>::zeros(py, [n_num, rows], false);
    let flags = PyArray2::<bool>::zeros(py, [n_flag, rows], false);
    let codes = PyArray2::<i32>::zeros(py, [n_text, rows], false);
    let texts = {
        let (mut nw, mut fw, mut cw) = (numbers.readwrite(), flags.readwrite(), codes.readwrite());
        let (nd, fd, cd) = (nw.as_slice_mut()?, fw.as_slice_mut()?, cw.as_slice_mut()?);
        let workers = match threads {
            0 => std::thread::available_parallelism().map_or(1, |n| n.get()),
            n => n,
        };
        // Blocks of at least 2048 rows, about 8 per thread (the regimes cost differently).
        let parts = if workers == 1 { 1 } else { 8 * workers };
        let block = rows.div_ceil(parts).max(2048).min(rows.max(1));
        let blocks = rows.div_ceil(block);
        let (mut nb, mut fb, mut cb) =
            (cut(nd, rows, block, blocks), cut(fd, rows, block, blocks), cut(cd, rows, block, blocks));
        let mut blocks: Vec<Block<'_>> = (0..blocks)
            .map(|b| Block {
                first_row: b * block,
                numbers: std::mem::take(&mut nb[b]),
                flags: std::mem::take(&mut fb[b]),
                codes: std::mem::take(&mut cb[b]),
                texts: vec![Vec::new(); n_text],
                row: 0,
                at: [0; 3],
            })
            .collect();
        let (h, t) = (heights_m, periods_s);
        // On `threads` workers (`crate::drive`: Ctrl-C stops it within 1024 rows of a block).
        let merged = crate::drive(py, threads, 0, None, |ctl| {
            use rayon::prelude::*;
            let errors: Vec<_> = blocks.par_iter_mut().map(|b| b.fill(ws, w, mu, h, t, ctl).err()).collect();
            // The first row's error, whatever the threads.
            match errors.into_iter().flatten().min_by_key(|e| e.0) {
                Some(e) => Err(e),
                None => Ok(merge_texts(&mut blocks, n_text)),
            }
        })?;
        match merged {
            Ok(texts) => texts,
            Err(e) => return Ok(Err(e)),
        }
    };

    let mut names = Vec::with_capacity(layout.0.len());
    let mut cols = Vec::with_capacity(layout.0.len());
    let mut at = [0; 3];
    for (name, kind) in layout.0 {
        names.push(name.to_string());
        cols.push(match kind {
            Kind::Number => numbers.get_item(at[0])?.unbind(),
            Kind::Flag => flags.get_item(at[1])?.unbind(),
            Kind::Text => (codes.get_item(at[2])?, &texts[at[2]]).into_pyobject(py)?.into_any().unbind(),
        });
        at[kind as usize] += 1;
    }
    Ok(Ok((names, cols)))
}

/// The distinct text values of the whole table per text column, in order of first appearance,
/// each block's codes renumbered into them.
fn merge_texts(blocks: &mut [Block<'_>], n_text: usize) -> Vec<Vec<&'static str>> {
    let mut all: Vec<Vec<&'static str>> = vec![Vec::new(); n_text];
    for b in blocks {
        for (j, local) in b.texts.iter().enumerate() {
            let to: Vec<i32> = local
                .iter()
                .map(|v| {
                    let i = all[j].iter().position(|a| a == v).unwrap_or_else(|| {
                        all[j].push(v);
                        all[j].len() - 1
                    });
                    i as i32
                })
                .collect();
            if to.iter().enumerate().any(|(i, &c)| c != i as i32) {
                for c in b.codes[j].iter_mut() {
                    *c = to[*c as usize];
                }
            }
        }
    }
    all
}
