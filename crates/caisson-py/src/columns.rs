//! A table of flattened report rows: a serde `Serializer` that walks one report struct (nested
//! structs and maps, scalars and `Option`s, no sequences) and writes each scalar to its column,
//! named by the keys on its path joined by "." (`goda.horizontal_force_kn_per_m`). Every row must
//! have the same keys in the same order (checked). Numbers go to float or integer columns
//! (`None` as NaN), strings and booleans to their own.
//!
//! Used for the spectrum's points (`caisson.loads.evaluate` has a hand-written table,
//! `loads_table.rs`, without serde's walk). Speed: the first row fixes the
//! columns ([`Layout`]); the values then go into one numpy array of `columns × rows` 64-bit
//! slots allocated by numpy (which asks for huge pages: a page fault per 2 MB, not per 4 kB), a
//! float or an integer straight into its slot after a check of its key by pointer, and each
//! column reaches Python as a view of its row of that array, without a copy.

use numpy::{PyArray1, PyArray2, PyArrayMethods};
use pyo3::prelude::*;
use serde::ser::{self, Serialize};
use std::borrow::Cow;

/// What a column holds, and how its 64-bit slots encode it.
#[derive(Debug, Clone, PartialEq)]
enum Kind {
    /// No value seen yet but nulls (slots unwritten).
    Null,
    /// `f64` bits; null is NaN.
    Float,
    /// `i64` bits.
    Int,
    /// 0 false, 1 true, [`NULL_BOOL`] null.
    Bool,
    /// Codes into the column's distinct values ([`NULL_CODE`]: null): few distinct strings.
    Str(Vec<String>),
}

const NULL_BOOL: u64 = 2;
const NULL_CODE: u64 = u32::MAX as u64;

enum Cell<'a> {
    Null,
    Float(f64),
    Int(i64),
    Bool(bool),
    Str(&'a str),
}

/// The columns of a table: names, the key each is checked against, and their kinds in the first
/// row.
#[derive(Debug, Clone, Default)]
pub struct Layout {
    names: Vec<String>,
    leaves: Vec<&'static str>,
    kinds: Vec<Kind>,
}

impl Layout {
    /// The columns of a table whose first row is `row`.
    pub fn of<T: Serialize>(row: &T) -> Result<Layout, String> {
        let mut c = Columns { fixed: false, ..Columns::default() };
        c.push_row(row)?;
        Ok(c.layout)
    }

    /// How many columns.
    pub fn len(&self) -> usize {
        self.names.len()
    }
}

/// The table being built: `rows` rows of the columns of `layout` in `data`, column `j` in
/// `data[j * capacity ..][.. capacity]`.
#[derive(Debug, Default)]
pub struct Columns<'d> {
    layout: Layout,
    /// Whether the columns are fixed (after [`Layout::of`]); before, a row makes them.
    fixed: bool,
    data: &'d mut [u64],
    capacity: usize,
    rows: usize,
    pos: usize,
    /// The keys from the row to this value: kept while making the layout only (for the names).
    path: Vec<Cow<'static, str>>,
    /// The key of this value (a struct field's or enum variant's name, [`ANY_KEY`] in a map).
    leaf: &'static str,
    /// How many keys lead to this value.
    depth: usize,
    /// Per column once the layout is fixed: its key and its kind ([`FAST_FLOAT`], ...) for the
    /// fast paths.
    fast: Vec<(&'static str, u8)>,
    /// The index in `data` of this value's slot.
    at: usize,
}

const FAST_FLOAT: u8 = 0;
const FAST_INT: u8 = 1;
const FAST_BOOL: u8 = 2;
const FAST_STR: u8 = 3;
const FAST_NULL: u8 = 4;

fn fast_code(kind: &Kind) -> u8 {
    match kind {
        Kind::Float => FAST_FLOAT,
        Kind::Int => FAST_INT,
        Kind::Bool => FAST_BOOL,
        Kind::Str(_) => FAST_STR,
        Kind::Null => FAST_NULL,
    }
}

impl<'d> Columns<'d> {
    /// A table of at most `data.len() / layout.len()` rows of the columns of `layout`.
    pub fn new(layout: Layout, data: &'d mut [u64]) -> Self {
        let capacity = if layout.len() == 0 { 0 } else { data.len() / layout.len() };
        let fast = layout.leaves.iter().zip(&layout.kinds).map(|(&leaf, kind)| (leaf, fast_code(kind))).collect();
        Columns { layout, fixed: true, data, capacity, fast, ..Columns::default() }
    }

    /// Append one report as a row.
    pub fn push_row<T: Serialize>(&mut self, row: &T) -> Result<(), String> {
        if self.fixed && self.rows >= self.capacity {
            return Err(format!("the table is full ({} rows)", self.capacity));
        }
        self.pos = 0;
        self.at = self.rows;
        self.leaf = "";
        self.depth = 0;
        self.path.clear();
        row.serialize(&mut *self).map_err(|e| e.0)?;
        if self.pos != self.layout.len() {
            return Err(format!("row {} has {} values, the first row {}", self.rows, self.pos, self.layout.len()));
        }
        self.rows += 1;
        Ok(())
    }

    /// Serialize `v` under the key `key` (the path is kept while making the layout only).
    #[inline(always)]
    fn under<T: ?Sized + Serialize>(&mut self, key: Cow<'static, str>, leaf: &'static str, v: &T) -> R {
        self.leaf = leaf;
        self.depth += 1;
        if self.fixed {
            v.serialize(&mut *self)?;
        } else {
            self.path.push(key);
            v.serialize(&mut *self)?;
            self.path.pop();
        }
        self.depth -= 1;
        Ok(())
    }

    /// Whether this value's key is that of the first row's value at the same position. A struct
    /// field's name is a `&'static str` of the derived code: the same pointer is the same key.
    #[inline(always)]
    fn same_key(&self) -> bool {
        match self.layout.leaves.get(self.pos) {
            Some(&first) => std::ptr::eq(first, self.leaf) || first == self.leaf,
            None => false,
        }
    }

    /// Write `bits` to this value's slot if its column is of kind `fast` and its key is this
    /// value's (by pointer); false otherwise (then [`Self::cell`] decides).
    #[inline(always)]
    fn put_fast(&mut self, fast: u8, bits: u64) -> bool {
        match (self.fast.get(self.pos), self.data.get_mut(self.at)) {
            (Some(&(key, f)), Some(slot)) if f == fast && std::ptr::eq(key, self.leaf) => {
                *slot = bits;
                self.pos += 1;
                self.at += self.capacity;
                true
            }
            _ => false,
        }
    }

    /// A float (`None`: NaN): straight into a float column, else [`Self::cell`].
    #[inline(always)]
    fn float(&mut self, x: Option<f64>) -> R {
        if self.put_fast(FAST_FLOAT, x.unwrap_or(f64::NAN).to_bits()) {
            return Ok(());
        }
        if x.is_none() && self.put_fast(FAST_NULL, 0) {
            // A column with no value yet: its slots are written when one comes.
            return Ok(());
        }
        self.cell(x.map_or(Cell::Null, Cell::Float))
    }

    /// A whole number: straight into an integer column, else [`Self::cell`].
    #[inline(always)]
    fn int(&mut self, x: i64) -> R {
        if self.put_fast(FAST_INT, x as u64) {
            return Ok(());
        }
        self.cell(Cell::Int(x))
    }

    /// A boolean: straight into a boolean column, else [`Self::cell`].
    #[inline(always)]
    fn boolean(&mut self, b: bool) -> R {
        if self.put_fast(FAST_BOOL, b as u64) {
            return Ok(());
        }
        self.cell(Cell::Bool(b))
    }

    /// Text: its code into a text column (a value seen before), else [`Self::cell`].
    #[inline(always)]
    fn text(&mut self, x: &str) -> R {
        if let (Some(&(key, FAST_STR)), Some(Kind::Str(values))) =
            (self.fast.get(self.pos), self.layout.kinds.get(self.pos))
        {
            if std::ptr::eq(key, self.leaf) {
                if let Some(code) = values.iter().position(|v| v == x) {
                    if self.put_fast(FAST_STR, code as u64) {
                        return Ok(());
                    }
                }
            }
        }
        self.cell(Cell::Str(x))
    }

    /// Any value: while making the layout, a new column; then into its column, whose kind may
    /// widen (no value yet → any, integers → floats, null → NaN or null).
    fn cell(&mut self, c: Cell<'_>) -> R {
        if !self.fixed {
            self.layout.names.push(self.path.join("."));
            self.layout.leaves.push(self.leaf);
            self.layout.kinds.push(match c {
                Cell::Null => Kind::Null,
                Cell::Float(_) => Kind::Float,
                Cell::Int(_) => Kind::Int,
                Cell::Bool(_) => Kind::Bool,
                Cell::Str(v) => Kind::Str(vec![v.to_string()]),
            });
            self.pos += 1;
            return Ok(());
        }
        if !self.same_key() {
            return Err(self.other_key());
        }
        let (j, rows, cap) = (self.pos, self.rows, self.capacity);
        let column = &mut self.data[j * cap..j * cap + rows + 1];
        let kind = &mut self.layout.kinds[j];
        let value = match (&mut *kind, c) {
            (Kind::Null, Cell::Null) => 0,
            (Kind::Null, c) => {
                // The rows before were null.
                let (new, fill, value) = match c {
                    Cell::Float(x) => (Kind::Float, f64::NAN.to_bits(), x.to_bits()),
                    Cell::Int(x) if rows == 0 => (Kind::Int, 0, x as u64),
                    Cell::Int(x) => (Kind::Float, f64::NAN.to_bits(), (x as f64).to_bits()),
                    Cell::Bool(b) => (Kind::Bool, NULL_BOOL, b as u64),
                    Cell::Str(v) => (Kind::Str(vec![v.to_string()]), NULL_CODE, 0),
                    Cell::Null => unreachable!(),
                };
                column[..rows].fill(fill);
                *kind = new;
                value
            }
            (Kind::Float, Cell::Float(x)) => x.to_bits(),
            (Kind::Float, Cell::Int(x)) => (x as f64).to_bits(),
            (Kind::Float, Cell::Null) => f64::NAN.to_bits(),
            (Kind::Int, Cell::Int(x)) => x as u64,
            (Kind::Int, c @ (Cell::Float(_) | Cell::Null)) => {
                for v in &mut column[..rows] {
                    *v = (*v as i64 as f64).to_bits();
                }
                *kind = Kind::Float;
                match c {
                    Cell::Float(x) => x.to_bits(),
                    _ => f64::NAN.to_bits(),
                }
            }
            (Kind::Bool, Cell::Bool(b)) => b as u64,
            (Kind::Bool, Cell::Null) => NULL_BOOL,
            (Kind::Str(values), Cell::Str(x)) => match values.iter().position(|v| v == x) {
                Some(i) => i as u64,
                None => {
                    values.push(x.to_string());
                    (values.len() - 1) as u64
                }
            },
            (Kind::Str(_), Cell::Null) => NULL_CODE,
            _ => return Err(Error(format!("row {rows}: column `{}` changes type between rows", self.layout.names[j]))),
        };
        column[rows] = value;
        self.fast[j].1 = fast_code(&self.layout.kinds[j]);
        self.pos += 1;
        self.at += self.capacity;
        Ok(())
    }

    #[cold]
    fn other_key(&self) -> Error {
        match self.layout.names.get(self.pos) {
            Some(first) => {
                Error(format!("row {} has key `{}` where the first row has `{first}`", self.rows, self.leaf))
            }
            None => Error(format!("row {} has more values than the first row ({})", self.rows, self.layout.len())),
        }
    }

    /// The layout with the kinds of every row.
    pub fn finish(self) -> Finished {
        Finished { layout: self.layout, rows: self.rows }
    }
}

/// A filled table, for [`into_python`].
pub struct Finished {
    layout: Layout,
    rows: usize,
}

/// A table for Python: column names and columns.
pub type Table = (Vec<String>, Vec<Py<PyAny>>);

/// Build a table of `rows` rows whose first row is `first`: `fill` pushes the rows (the GIL
/// released). Returns (names, columns) for Python, each column a numpy array (floats and
/// integers: views of one array, no copy), a list (booleans with nulls) or (codes, distinct
/// values) (strings, code 2^32 − 1 null); or the error of `fill`.
pub fn build<T, E, F>(py: Python<'_>, rows: usize, first: &T, fill: F) -> PyResult<Result<Table, E>>
where
    T: Serialize,
    E: Send,
    F: for<'d> FnOnce(&mut Columns<'d>) -> Result<(), E> + Send,
{
    let layout = Layout::of(first).map_err(pyo3::exceptions::PyRuntimeError::new_err)?;
    let width = layout.len();
    let arena = PyArray2::<u64>::zeros(py, [width, rows], false);
    let done = {
        let mut rw = arena.readwrite();
        let data = rw.as_slice_mut()?;
        py.detach(|| {
            let mut table = Columns::new(layout, data);
            fill(&mut table).map(|()| table.finish())
        })
    };
    let done = match done {
        Ok(d) => d,
        Err(e) => return Ok(Err(e)),
    };
    if done.rows != rows {
        return Err(pyo3::exceptions::PyRuntimeError::new_err(format!(
            "internal error: {} rows of {rows} filled",
            done.rows
        )));
    }
    into_python(py, &arena, done).map(Ok)
}

/// (names, numpy arrays or lists) for Python.
fn into_python(
    py: Python<'_>,
    arena: &Bound<'_, PyArray2<u64>>,
    t: Finished,
) -> PyResult<(Vec<String>, Vec<Py<PyAny>>)> {
    let rows = t.rows;
    let np = py.import("numpy")?;
    let (float64, int64) = (np.getattr("float64")?, np.getattr("int64")?);
    let mut cols = Vec::with_capacity(t.layout.len());
    for (j, kind) in t.layout.kinds.into_iter().enumerate() {
        let row = arena.get_item(j)?;
        let slots =
            || -> PyResult<Vec<u64>> { Ok(row.extract::<numpy::PyReadonlyArray1<u64>>()?.as_slice()?.to_vec()) };
        cols.push(match kind {
            Kind::Null => PyArray1::from_vec(py, vec![f64::NAN; rows]).into_any().unbind(),
            Kind::Float => row.call_method1("view", (&float64,))?.unbind(),
            Kind::Int => row.call_method1("view", (&int64,))?.unbind(),
            Kind::Bool => {
                let v = slots()?;
                if v.contains(&NULL_BOOL) {
                    let b: Vec<Option<bool>> = v.iter().map(|&x| (x != NULL_BOOL).then_some(x == 1)).collect();
                    b.into_pyobject(py)?.into_any().unbind()
                } else {
                    PyArray1::from_vec(py, v.iter().map(|&x| x == 1).collect::<Vec<bool>>()).into_any().unbind()
                }
            }
            Kind::Str(values) => {
                let codes: Vec<u32> = slots()?.into_iter().map(|x| x as u32).collect();
                (PyArray1::from_vec(py, codes), values).into_pyobject(py)?.into_any().unbind()
            }
        });
    }
    Ok((t.layout.names, cols))
}

#[derive(Debug)]
pub struct Error(String);

impl std::fmt::Display for Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}
impl std::error::Error for Error {}
impl ser::Error for Error {
    fn custom<T: std::fmt::Display>(msg: T) -> Self {
        Error(msg.to_string())
    }
}

type R = Result<(), Error>;

/// The key of every map value: map keys are read in the first row only (for the names), later a
/// map value matches the column at its position.
const ANY_KEY: &str = "\u{0}";

fn unsupported(what: &str) -> Error {
    Error(format!("a report row cannot hold {what}"))
}

impl<'a, 'd> ser::Serializer for &'a mut Columns<'d> {
    type Ok = ();
    type Error = Error;
    type SerializeSeq = ser::Impossible<(), Error>;
    type SerializeTuple = ser::Impossible<(), Error>;
    type SerializeTupleStruct = ser::Impossible<(), Error>;
    type SerializeTupleVariant = ser::Impossible<(), Error>;
    type SerializeMap = MapRow<'a, 'd>;
    type SerializeStruct = Self;
    type SerializeStructVariant = Self;

    #[inline(always)]
    fn serialize_bool(self, v: bool) -> R {
        self.boolean(v)
    }
    fn serialize_i8(self, v: i8) -> R {
        self.int(v as i64)
    }
    fn serialize_i16(self, v: i16) -> R {
        self.int(v as i64)
    }
    fn serialize_i32(self, v: i32) -> R {
        self.int(v as i64)
    }
    fn serialize_i64(self, v: i64) -> R {
        self.int(v)
    }
    fn serialize_u8(self, v: u8) -> R {
        self.int(v as i64)
    }
    fn serialize_u16(self, v: u16) -> R {
        self.int(v as i64)
    }
    #[inline(always)]
    fn serialize_u32(self, v: u32) -> R {
        self.int(v as i64)
    }
    fn serialize_u64(self, v: u64) -> R {
        self.int(i64::try_from(v).map_err(|_| unsupported("an integer above 2^63"))?)
    }
    fn serialize_f32(self, v: f32) -> R {
        self.float(Some(v as f64))
    }
    #[inline(always)]
    fn serialize_f64(self, v: f64) -> R {
        self.float(Some(v))
    }
    fn serialize_char(self, v: char) -> R {
        self.cell(Cell::Str(&v.to_string()))
    }
    fn serialize_str(self, v: &str) -> R {
        self.text(v)
    }
    fn serialize_bytes(self, _: &[u8]) -> R {
        Err(unsupported("bytes"))
    }
    #[inline(always)]
    fn serialize_none(self) -> R {
        self.float(None)
    }
    #[inline(always)]
    fn serialize_some<T: ?Sized + Serialize>(self, v: &T) -> R {
        v.serialize(self)
    }
    fn serialize_unit(self) -> R {
        self.cell(Cell::Null)
    }
    fn serialize_unit_struct(self, _: &'static str) -> R {
        self.cell(Cell::Null)
    }
    fn serialize_unit_variant(self, _: &'static str, _: u32, variant: &'static str) -> R {
        self.text(variant)
    }
    fn serialize_newtype_struct<T: ?Sized + Serialize>(self, _: &'static str, v: &T) -> R {
        v.serialize(self)
    }
    fn serialize_newtype_variant<T: ?Sized + Serialize>(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
        v: &T,
    ) -> R {
        self.under(Cow::Borrowed(variant), variant, v)
    }
    fn serialize_seq(self, _: Option<usize>) -> Result<Self::SerializeSeq, Error> {
        Err(unsupported("a list"))
    }
    fn serialize_tuple(self, _: usize) -> Result<Self::SerializeTuple, Error> {
        Err(unsupported("a tuple"))
    }
    fn serialize_tuple_struct(self, _: &'static str, _: usize) -> Result<Self::SerializeTupleStruct, Error> {
        Err(unsupported("a tuple"))
    }
    fn serialize_tuple_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Self::SerializeTupleVariant, Error> {
        Err(unsupported("a tuple"))
    }
    fn serialize_map(self, _: Option<usize>) -> Result<Self::SerializeMap, Error> {
        Ok(MapRow { table: self, key: None })
    }
    #[inline(always)]
    fn serialize_struct(self, _: &'static str, _: usize) -> Result<Self::SerializeStruct, Error> {
        Ok(self)
    }
    fn serialize_struct_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Self::SerializeStructVariant, Error> {
        Ok(self)
    }
}

impl ser::SerializeStruct for &mut Columns<'_> {
    type Ok = ();
    type Error = Error;
    #[inline(always)]
    fn serialize_field<T: ?Sized + Serialize>(&mut self, key: &'static str, v: &T) -> R {
        // The plausibility warnings are a list per report, not a column: `loads.report` has them.
        if self.depth == 0 && key == "warnings" {
            return Ok(());
        }
        self.under(Cow::Borrowed(key), key, v)
    }
    fn end(self) -> R {
        Ok(())
    }
}

impl ser::SerializeStructVariant for &mut Columns<'_> {
    type Ok = ();
    type Error = Error;
    fn serialize_field<T: ?Sized + Serialize>(&mut self, key: &'static str, v: &T) -> R {
        ser::SerializeStruct::serialize_field(self, key, v)
    }
    fn end(self) -> R {
        Ok(())
    }
}

/// A map (a struct with `#[serde(flatten)]` fields serializes as one): string keys only.
pub struct MapRow<'a, 'd> {
    table: &'a mut Columns<'d>,
    key: Option<String>,
}

impl ser::SerializeMap for MapRow<'_, '_> {
    type Ok = ();
    type Error = Error;
    fn serialize_key<T: ?Sized + Serialize>(&mut self, key: &T) -> R {
        if self.table.fixed {
            // The keys are those of the first row (checked by their count at the end of the row).
            self.key = None;
            return Ok(());
        }
        let v = serde_json::to_value(key).map_err(|e| Error(e.to_string()))?;
        self.key = Some(v.as_str().map(str::to_string).ok_or_else(|| unsupported("a map with non-string keys"))?);
        Ok(())
    }
    #[inline(always)]
    fn serialize_value<T: ?Sized + Serialize>(&mut self, v: &T) -> R {
        let key = self.key.take().map(Cow::Owned).unwrap_or(Cow::Borrowed(ANY_KEY));
        self.table.under(key, ANY_KEY, v)
    }
    fn end(self) -> R {
        Ok(())
    }
}
