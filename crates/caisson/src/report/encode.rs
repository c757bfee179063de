//! One encoder for every report: [`to_json`] turns any report into JSON and refuses a non-finite
//! number, naming its path (`loads.safety.sliding`, `design.dynamic.percentiles_m.p95`). The CLI
//! prints and writes what it returns; the Python bindings hand its text to Python. So neither can
//! print a `NaN` that serde_json would have written as `null`, nor refuse what the other accepts.
//!
//! The check walks the report itself, not its JSON: serde_json writes NaN and ±∞ as `null`, which
//! is also how a report writes an absent value (`Option::None`, e.g. a width beyond the sizing
//! range), so only the report's own numbers tell the two apart.

use serde::Serialize;

/// A non-finite number in a report: its path (`size.candidates[3].dynamic.p95_m`) and value.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{path} is {value}")]
pub struct NotFinite {
    pub path: String,
    pub value: f64,
}

/// Refuse a non-finite number anywhere in `report` (`what` starts the path: `loads`).
pub fn check_finite<T: Serialize + ?Sized>(report: &T, what: &str) -> Result<(), NotFinite> {
    let mut path = vec![what.to_string()];
    report.serialize(finite::Check { path: &mut path })
}

/// `report` as JSON, refusing a non-finite number ([`check_finite`]; `what` names the report).
pub fn to_json<T: Serialize + ?Sized>(report: &T, what: &str) -> Result<serde_json::Value, NotFinite> {
    check_finite(report, what)?;
    // A report of plain structs, numbers and strings always serializes (string keys only).
    Ok(serde_json::to_value(report).expect("a report serializes to JSON"))
}

/// [`to_json`] as pretty text, keys sorted (what `--json` prints and the output files hold).
pub fn to_json_pretty<T: Serialize + ?Sized>(report: &T, what: &str) -> Result<String, NotFinite> {
    Ok(serde_json::to_string_pretty(&to_json(report, what)?).expect("JSON text"))
}

/// The report as compact JSON text with its keys in the struct's order (what the Python bindings
/// parse: a dict whose keys come in the order of the report, as the columns of a table of many
/// reports do), refusing a non-finite number ([`check_finite`]).
pub fn to_json_text<T: Serialize + ?Sized>(report: &T, what: &str) -> Result<String, NotFinite> {
    check_finite(report, what)?;
    Ok(serde_json::to_string(report).expect("a report serializes to JSON"))
}

/// A serde serializer that writes nothing and fails at the first non-finite f32 or f64, with the
/// path of the field (`loads.safety.heel_pressure_pa`).
mod finite {
    use serde::ser::{self, Serialize};

    pub use super::NotFinite;

    impl ser::Error for NotFinite {
        fn custom<T: std::fmt::Display>(msg: T) -> Self {
            // Only a report's own `Serialize` could fail this way (none does): the message as path.
            NotFinite { path: msg.to_string(), value: f64::NAN }
        }
    }

    type R = Result<(), NotFinite>;

    pub struct Check<'a> {
        pub path: &'a mut Vec<String>,
    }

    /// A sequence, tuple, map or struct: its elements are `[i]`, its fields `.name`.
    pub struct Compound<'a> {
        path: &'a mut Vec<String>,
        index: usize,
        key: Option<String>,
    }

    impl<'a> Check<'a> {
        fn compound(self) -> Result<Compound<'a>, NotFinite> {
            Ok(Compound { path: self.path, index: 0, key: None })
        }
    }

    impl Compound<'_> {
        fn visit<T: Serialize + ?Sized>(&mut self, step: String, v: &T) -> R {
            self.path.push(step);
            v.serialize(Check { path: &mut *self.path })?;
            self.path.pop();
            Ok(())
        }
        fn element<T: Serialize + ?Sized>(&mut self, v: &T) -> R {
            self.index += 1;
            self.visit(format!("[{}]", self.index - 1), v)
        }
    }

    /// `fn serialize_x(self, _: T) -> R { Ok(()) }` for each `serialize_x: T`: values that are
    /// always finite.
    macro_rules! finite_values {
        ($($method:ident: $t:ty),* $(,)?) => {
            $(fn $method(self, _: $t) -> R {
                Ok(())
            })*
        };
    }

    /// `fn serialize_x(self, _: A, ...) -> Result<Compound, _>` for each `serialize_x(A, ...)`:
    /// the values of a sequence, tuple, map or struct are checked one by one.
    macro_rules! opens_compound {
        ($a:lifetime; $($method:ident($($arg:ty),*)),* $(,)?) => {
            $(fn $method(self, $(_: $arg),*) -> Result<Compound<$a>, NotFinite> {
                self.compound()
            })*
        };
    }

    impl<'a> ser::Serializer for Check<'a> {
        type Ok = ();
        type Error = NotFinite;
        type SerializeSeq = Compound<'a>;
        type SerializeTuple = Compound<'a>;
        type SerializeTupleStruct = Compound<'a>;
        type SerializeTupleVariant = Compound<'a>;
        type SerializeMap = Compound<'a>;
        type SerializeStruct = Compound<'a>;
        type SerializeStructVariant = Compound<'a>;

        fn serialize_f64(self, v: f64) -> R {
            if v.is_finite() {
                Ok(())
            } else {
                Err(NotFinite { path: self.path.concat(), value: v })
            }
        }
        fn serialize_f32(self, v: f32) -> R {
            self.serialize_f64(v as f64)
        }
        finite_values!(
            serialize_bool: bool, serialize_i8: i8, serialize_i16: i16, serialize_i32: i32, serialize_i64: i64,
            serialize_u8: u8, serialize_u16: u16, serialize_u32: u32, serialize_u64: u64, serialize_char: char,
            serialize_str: &str, serialize_bytes: &[u8], serialize_unit_struct: &'static str,
        );
        fn serialize_none(self) -> R {
            Ok(())
        }
        fn serialize_unit(self) -> R {
            Ok(())
        }
        fn serialize_unit_variant(self, _: &'static str, _: u32, _: &'static str) -> R {
            Ok(())
        }
        fn serialize_some<T: Serialize + ?Sized>(self, v: &T) -> R {
            v.serialize(self)
        }
        fn serialize_newtype_struct<T: Serialize + ?Sized>(self, _: &'static str, v: &T) -> R {
            v.serialize(self)
        }
        fn serialize_newtype_variant<T: Serialize + ?Sized>(
            self,
            _: &'static str,
            _: u32,
            variant: &'static str,
            v: &T,
        ) -> R {
            self.compound()?.visit(format!(".{variant}"), v)
        }
        opens_compound!('a;
            serialize_seq(Option<usize>), serialize_tuple(usize), serialize_tuple_struct(&'static str, usize),
            serialize_tuple_variant(&'static str, u32, &'static str, usize), serialize_map(Option<usize>),
            serialize_struct(&'static str, usize), serialize_struct_variant(&'static str, u32, &'static str, usize),
        );
    }

    /// The sequence-like traits (elements `[i]`) and the struct-like ones (fields `.name`).
    macro_rules! compound {
        ($($trait:ident :: $method:ident),*; $($struct_trait:ident),*) => {
            $(impl ser::$trait for Compound<'_> {
                type Ok = ();
                type Error = NotFinite;
                fn $method<T: Serialize + ?Sized>(&mut self, v: &T) -> R {
                    self.element(v)
                }
                fn end(self) -> R {
                    Ok(())
                }
            })*
            $(impl ser::$struct_trait for Compound<'_> {
                type Ok = ();
                type Error = NotFinite;
                fn serialize_field<T: Serialize + ?Sized>(&mut self, key: &'static str, v: &T) -> R {
                    self.visit(format!(".{key}"), v)
                }
                fn end(self) -> R {
                    Ok(())
                }
            })*
        };
    }
    compound!(
        SerializeSeq::serialize_element, SerializeTuple::serialize_element,
        SerializeTupleStruct::serialize_field, SerializeTupleVariant::serialize_field;
        SerializeStruct, SerializeStructVariant
    );

    impl ser::SerializeMap for Compound<'_> {
        type Ok = ();
        type Error = NotFinite;
        fn serialize_key<T: Serialize + ?Sized>(&mut self, k: &T) -> R {
            // The key names the value (a flattened struct serializes as a map).
            self.key = match serde_json::to_value(k) {
                Ok(serde_json::Value::String(s)) => Some(s),
                _ => None,
            };
            self.visit("[key]".into(), k)
        }
        fn serialize_value<T: Serialize + ?Sized>(&mut self, v: &T) -> R {
            match self.key.take() {
                Some(k) => self.visit(format!(".{k}"), v),
                None => self.element(v),
            }
        }
        fn end(self) -> R {
            Ok(())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeMap;

    #[derive(Serialize, Clone)]
    struct Flat {
        x: f64,
    }

    #[derive(Serialize, Clone)]
    enum Shape {
        Newtype(f64),
        Fields { y: f64 },
        Tuple(f64, f64),
        Unit,
    }

    #[derive(Serialize, Clone)]
    struct Inner {
        a: f64,
        b: Option<f64>,
        v: Vec<f32>,
        t: (f64, f64),
        m: BTreeMap<String, f64>,
    }

    #[derive(Serialize, Clone)]
    struct Report {
        #[serde(flatten)]
        flat: Flat,
        name: &'static str,
        n: u64,
        i: i32,
        yes: bool,
        inner: Inner,
        shapes: Vec<Shape>,
    }

    fn report() -> Report {
        Report {
            flat: Flat { x: 1.0 },
            name: "r",
            n: 3,
            i: -1,
            yes: true,
            inner: Inner {
                a: 2.0,
                b: None,
                v: vec![1.0, 2.0, 3.0],
                t: (4.0, 5.0),
                m: BTreeMap::from([("k".to_string(), 6.0)]),
            },
            shapes: vec![Shape::Newtype(7.0), Shape::Fields { y: 8.0 }, Shape::Tuple(9.0, 10.0), Shape::Unit],
        }
    }

    /// Every non-finite number is found with the path of its field; finite values, null
    /// (`None`), text, integers and booleans pass, and `None` is `null` in the JSON.
    #[test]
    fn non_finite_numbers_are_named_by_their_path() {
        assert_eq!(check_finite(&report(), "r"), Ok(()));
        assert_eq!(to_json(&report(), "r").unwrap()["inner"]["b"], serde_json::Value::Null);
        type Edit = fn(&mut Report);
        let cases: Vec<(Edit, &str)> = vec![
            (|r| r.flat.x = f64::NAN, "r.x is NaN"),
            (|r| r.inner.a = f64::INFINITY, "r.inner.a is inf"),
            (|r| r.inner.b = Some(f64::NEG_INFINITY), "r.inner.b is -inf"),
            (|r| r.inner.v[2] = f32::NAN, "r.inner.v[2] is NaN"),
            (|r| r.inner.t.1 = f64::NAN, "r.inner.t[1] is NaN"),
            (|r| r.inner.m.insert("k".into(), f64::NAN).map_or((), |_| ()), "r.inner.m.k is NaN"),
            (|r| r.shapes[0] = Shape::Newtype(f64::NAN), "r.shapes[0].Newtype is NaN"),
            (|r| r.shapes[1] = Shape::Fields { y: f64::NAN }, "r.shapes[1].y is NaN"),
            (|r| r.shapes[2] = Shape::Tuple(1.0, f64::NAN), "r.shapes[2][1] is NaN"),
        ];
        for (edit, want) in &cases {
            let mut r = report();
            edit(&mut r);
            assert_eq!(check_finite(&r, "r").map_err(|e| e.to_string()), Err(want.to_string()));
            assert!(to_json(&r, "r").is_err() && to_json_pretty(&r, "r").is_err() && to_json_text(&r, "r").is_err());
        }
        assert_eq!(cases.len(), 9);
    }
}
