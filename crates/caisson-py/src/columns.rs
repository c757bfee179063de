//! A table of flattened report rows: a serde `Serializer` that walks one report struct (nested
//! structs and maps, scalars and `Option`s, no sequences) and appends each scalar to its column,
//! named by the keys on its path joined by "." (`goda.horizontal_force_kn_per_m`). Every row must
//! have the same keys in the same order (checked). Numbers go to float or integer columns
//! (`None` as NaN), strings and booleans to their own.

use numpy::PyArray1;
use pyo3::prelude::*;
use serde::ser::{self, Serialize};
use std::borrow::Cow;

#[derive(Debug)]
enum Col {
    /// No value seen yet but this many nulls.
    Null(usize),
    Float(Vec<f64>),
    Int(Vec<i64>),
    Bool(Vec<Option<bool>>),
    /// Codes into the column's distinct values (`u32::MAX`: null): few distinct strings.
    Str(Vec<u32>, Vec<String>),
}

enum Cell<'a> {
    Null,
    Float(f64),
    Int(i64),
    Bool(bool),
    Str(&'a str),
}

impl Col {
    fn push(&mut self, c: Cell<'_>) -> Result<(), String> {
        match (&mut *self, c) {
            (Col::Null(n), Cell::Null) => *n += 1,
            (Col::Null(n), c) => {
                let n = *n;
                *self = match c {
                    Cell::Float(v) => Col::Float(std::iter::repeat_n(f64::NAN, n).chain([v]).collect()),
                    Cell::Int(v) => {
                        if n > 0 {
                            Col::Float(std::iter::repeat_n(f64::NAN, n).chain([v as f64]).collect())
                        } else {
                            Col::Int(vec![v])
                        }
                    }
                    Cell::Bool(v) => Col::Bool(std::iter::repeat_n(None, n).chain([Some(v)]).collect()),
                    Cell::Str(v) => {
                        Col::Str(std::iter::repeat_n(u32::MAX, n).chain([0]).collect(), vec![v.to_string()])
                    }
                    Cell::Null => unreachable!(),
                }
            }
            (Col::Float(v), Cell::Float(x)) => v.push(x),
            (Col::Float(v), Cell::Int(x)) => v.push(x as f64),
            (Col::Float(v), Cell::Null) => v.push(f64::NAN),
            (Col::Int(v), Cell::Int(x)) => v.push(x),
            (Col::Int(v), Cell::Float(x)) => {
                let mut f: Vec<f64> = v.iter().map(|&i| i as f64).collect();
                f.push(x);
                *self = Col::Float(f);
            }
            (Col::Int(v), Cell::Null) => {
                let mut f: Vec<f64> = v.iter().map(|&i| i as f64).collect();
                f.push(f64::NAN);
                *self = Col::Float(f);
            }
            (Col::Bool(v), Cell::Bool(x)) => v.push(Some(x)),
            (Col::Bool(v), Cell::Null) => v.push(None),
            (Col::Str(codes, values), Cell::Str(x)) => {
                let code = match values.iter().position(|v| v == x) {
                    Some(i) => i,
                    None => {
                        values.push(x.to_string());
                        values.len() - 1
                    }
                };
                codes.push(code as u32);
            }
            (Col::Str(codes, _), Cell::Null) => codes.push(u32::MAX),
            _ => return Err("a column changes type between rows".into()),
        }
        Ok(())
    }
}

/// The table being built.
#[derive(Debug, Default)]
pub struct Columns {
    names: Vec<String>,
    leaves: Vec<String>,
    cols: Vec<Col>,
    rows: usize,
    pos: usize,
    path: Vec<Cow<'static, str>>,
}

impl Columns {
    /// Append one report as a row.
    pub fn push_row<T: Serialize>(&mut self, row: &T) -> Result<(), String> {
        self.pos = 0;
        row.serialize(&mut *self).map_err(|e| e.0)?;
        if self.pos != self.cols.len() {
            return Err(format!("row {} has {} values, the first row {}", self.rows, self.pos, self.cols.len()));
        }
        self.rows += 1;
        Ok(())
    }

    fn cell(&mut self, c: Cell<'_>) -> Result<(), Error> {
        let leaf = self.path.last().map(|c| c.as_ref()).unwrap_or("");
        if self.rows == 0 {
            self.names.push(self.path.join("."));
            self.leaves.push(leaf.to_string());
            self.cols.push(Col::Null(0));
        } else if leaf != ANY_KEY && self.leaves.get(self.pos).map(String::as_str) != Some(leaf) {
            return Err(Error(format!(
                "row {} has key `{}` where the first row has another",
                self.rows,
                self.path.join(".")
            )));
        }
        self.cols[self.pos].push(c).map_err(Error)?;
        self.pos += 1;
        Ok(())
    }

    /// (names, numpy arrays or lists) for Python.
    pub fn into_python(self, py: Python<'_>) -> PyResult<(Vec<String>, Vec<Py<PyAny>>)> {
        let rows = self.rows;
        let cols = self
            .cols
            .into_iter()
            .map(|c| -> PyResult<Py<PyAny>> {
                Ok(match c {
                    Col::Null(_) => PyArray1::from_vec(py, vec![f64::NAN; rows]).into_any().unbind(),
                    Col::Float(v) => PyArray1::from_vec(py, v).into_any().unbind(),
                    Col::Int(v) => PyArray1::from_vec(py, v).into_any().unbind(),
                    Col::Bool(v) if v.iter().all(Option::is_some) => {
                        PyArray1::from_vec(py, v.into_iter().map(|b| b.unwrap_or(false)).collect()).into_any().unbind()
                    }
                    Col::Bool(v) => v.into_pyobject(py)?.into_any().unbind(),
                    Col::Str(codes, values) => {
                        (PyArray1::from_vec(py, codes), values).into_pyobject(py)?.into_any().unbind()
                    }
                })
            })
            .collect::<PyResult<_>>()?;
        Ok((self.names, cols))
    }
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

/// The path element of a map key after the first row (not compared).
const ANY_KEY: &str = "\u{0}";

fn unsupported(what: &str) -> Error {
    Error(format!("a report row cannot hold {what}"))
}

impl<'a> ser::Serializer for &'a mut Columns {
    type Ok = ();
    type Error = Error;
    type SerializeSeq = ser::Impossible<(), Error>;
    type SerializeTuple = ser::Impossible<(), Error>;
    type SerializeTupleStruct = ser::Impossible<(), Error>;
    type SerializeTupleVariant = ser::Impossible<(), Error>;
    type SerializeMap = MapRow<'a>;
    type SerializeStruct = Self;
    type SerializeStructVariant = Self;

    fn serialize_bool(self, v: bool) -> R {
        self.cell(Cell::Bool(v))
    }
    fn serialize_i8(self, v: i8) -> R {
        self.cell(Cell::Int(v as i64))
    }
    fn serialize_i16(self, v: i16) -> R {
        self.cell(Cell::Int(v as i64))
    }
    fn serialize_i32(self, v: i32) -> R {
        self.cell(Cell::Int(v as i64))
    }
    fn serialize_i64(self, v: i64) -> R {
        self.cell(Cell::Int(v))
    }
    fn serialize_u8(self, v: u8) -> R {
        self.cell(Cell::Int(v as i64))
    }
    fn serialize_u16(self, v: u16) -> R {
        self.cell(Cell::Int(v as i64))
    }
    fn serialize_u32(self, v: u32) -> R {
        self.cell(Cell::Int(v as i64))
    }
    fn serialize_u64(self, v: u64) -> R {
        self.cell(Cell::Int(i64::try_from(v).map_err(|_| unsupported("an integer above 2^63"))?))
    }
    fn serialize_f32(self, v: f32) -> R {
        self.cell(Cell::Float(v as f64))
    }
    fn serialize_f64(self, v: f64) -> R {
        self.cell(Cell::Float(v))
    }
    fn serialize_char(self, v: char) -> R {
        self.cell(Cell::Str(&v.to_string()))
    }
    fn serialize_str(self, v: &str) -> R {
        self.cell(Cell::Str(v))
    }
    fn serialize_bytes(self, _: &[u8]) -> R {
        Err(unsupported("bytes"))
    }
    fn serialize_none(self) -> R {
        self.cell(Cell::Null)
    }
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
        self.cell(Cell::Str(variant))
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
        self.path.push(Cow::Borrowed(variant));
        v.serialize(&mut *self)?;
        self.path.pop();
        Ok(())
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

impl ser::SerializeStruct for &mut Columns {
    type Ok = ();
    type Error = Error;
    fn serialize_field<T: ?Sized + Serialize>(&mut self, key: &'static str, v: &T) -> R {
        // The plausibility warnings are a list per report, not a column: `loads.report` has them.
        if key == "warnings" && self.path.is_empty() {
            return Ok(());
        }
        self.path.push(Cow::Borrowed(key));
        v.serialize(&mut **self)?;
        self.path.pop();
        Ok(())
    }
    fn end(self) -> R {
        Ok(())
    }
}

impl ser::SerializeStructVariant for &mut Columns {
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
pub struct MapRow<'a> {
    table: &'a mut Columns,
    key: Option<String>,
}

impl ser::SerializeMap for MapRow<'_> {
    type Ok = ();
    type Error = Error;
    fn serialize_key<T: ?Sized + Serialize>(&mut self, key: &T) -> R {
        if self.table.rows > 0 {
            // The keys are those of the first row (checked by their count at the end of the row).
            self.key = None;
            return Ok(());
        }
        let v = serde_json::to_value(key).map_err(|e| Error(e.to_string()))?;
        self.key = Some(v.as_str().map(str::to_string).ok_or_else(|| unsupported("a map with non-string keys"))?);
        Ok(())
    }
    fn serialize_value<T: ?Sized + Serialize>(&mut self, v: &T) -> R {
        self.table.path.push(match self.key.take() {
            Some(k) => Cow::Owned(k),
            None => Cow::Borrowed(ANY_KEY),
        });
        v.serialize(&mut *self.table)?;
        self.table.path.pop();
        Ok(())
    }
    fn end(self) -> R {
        Ok(())
    }
}
