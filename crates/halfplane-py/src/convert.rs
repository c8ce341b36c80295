//! Report structs to Python objects with no text in between. The CLI's reports are `Serialize`
//! (their JSON is that serialization); here the same `Serialize` implementations fill a [`Node`]
//! tree instead of JSON text, so every number keeps its exact `f64` (non-finite ones included,
//! which JSON would write as null) and every key and nesting is the JSON's. A [`Node`] becomes
//! nested dicts, lists, floats, ints and strings ([`Node::into_py`]), and a list of row records
//! becomes one numpy array per column ([`columns`]) for a DataFrame.

use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use serde::ser::{self, Serialize};
use std::fmt;

/// A serialized value: serde's data model reduced to what Python needs.
#[derive(Debug, Clone, PartialEq)]
pub enum Node {
    /// `None` and unit values (JSON null).
    Null,
    /// A boolean.
    Bool(bool),
    /// A signed integer.
    Int(i64),
    /// An unsigned integer.
    UInt(u64),
    /// A number, exactly as the struct holds it.
    Float(f64),
    /// A string (and a unit enum variant's name).
    Str(String),
    /// A sequence, tuple or array.
    List(Vec<Node>),
    /// A struct or map, its keys in serialization (declaration) order.
    Map(Vec<(String, Node)>),
}

/// Why a value could not be converted (only a map key that is not a string, which no report has).
#[derive(Debug)]
pub struct Unsupported(String);

impl fmt::Display for Unsupported {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for Unsupported {}

impl ser::Error for Unsupported {
    fn custom<T: fmt::Display>(msg: T) -> Self {
        Self(msg.to_string())
    }
}

impl From<Unsupported> for PyErr {
    fn from(e: Unsupported) -> Self {
        pyo3::exceptions::PyRuntimeError::new_err(format!("cannot convert a report: {}", e.0))
    }
}

/// The tree of `value`, as its `Serialize` implementation describes it.
pub fn to_node<T: Serialize + ?Sized>(value: &T) -> Result<Node, Unsupported> {
    value.serialize(NodeSerializer)
}

impl Node {
    /// The member `key` of a map (None for another key or another kind of node).
    pub fn get(&self, key: &str) -> Option<&Node> {
        match self {
            Node::Map(entries) => entries.iter().find(|(k, _)| k == key).map(|(_, v)| v),
            _ => None,
        }
    }

    /// The map without its member `key`, and that member (Null when absent).
    pub fn take(self, key: &str) -> (Node, Node) {
        match self {
            Node::Map(entries) => {
                let (taken, kept): (Vec<_>, Vec<_>) =
                    entries.into_iter().partition(|(k, _)| k == key);
                let value = taken.into_iter().next().map_or(Node::Null, |(_, v)| v);
                (Node::Map(kept), value)
            }
            other => (other, Node::Null),
        }
    }

    /// Python objects: dicts (in key order), lists, floats, ints, bools, strings and None.
    pub fn into_py(self, py: Python<'_>) -> PyResult<Bound<'_, PyAny>> {
        Ok(match self {
            Node::Null => py.None().into_bound(py),
            Node::Bool(b) => b.into_pyobject(py)?.to_owned().into_any(),
            Node::Int(i) => i.into_pyobject(py)?.into_any(),
            Node::UInt(u) => u.into_pyobject(py)?.into_any(),
            Node::Float(x) => x.into_pyobject(py)?.into_any(),
            Node::Str(s) => s.into_pyobject(py)?.into_any(),
            Node::List(items) => {
                let list = PyList::empty(py);
                for item in items {
                    list.append(item.into_py(py)?)?;
                }
                list.into_any()
            }
            Node::Map(entries) => {
                let dict = PyDict::new(py);
                for (k, v) in entries {
                    dict.set_item(k, v.into_py(py)?)?;
                }
                dict.into_any()
            }
        })
    }
}

/// The rows `rows` (a list of records) as one column per key of `keys`, in that order: a float64
/// array where every value is a number or null (null as NaN, as a CSV reader reads an empty
/// cell), an int64 array where every value is an integer, otherwise a list of the values (strings,
/// with "" and null as NaN, as a CSV reader reads an empty text cell). A key missing from a row
/// is an error naming it: the columns are the report's public CSV columns.
pub fn columns<'py>(py: Python<'py>, rows: &Node, keys: &[&str]) -> PyResult<Bound<'py, PyDict>> {
    let rows: &[Node] = match rows {
        Node::List(rows) => rows,
        Node::Null => &[],
        _ => return Err(Unsupported("the rows are not a list".into()).into()),
    };
    let out = PyDict::new(py);
    for key in keys {
        let cells = rows
            .iter()
            .map(|r| {
                r.get(key)
                    .ok_or_else(|| Unsupported(format!("a row has no column {key:?}")))
            })
            .collect::<Result<Vec<&Node>, _>>()?;
        out.set_item(key, column(py, &cells)?)?;
    }
    Ok(out)
}

/// One column of [`columns`].
fn column<'py>(py: Python<'py>, cells: &[&Node]) -> PyResult<Bound<'py, PyAny>> {
    let as_int = |n: &Node| match *n {
        Node::Int(i) => Some(i),
        Node::UInt(u) => i64::try_from(u).ok(),
        _ => None,
    };
    let ints: Option<Vec<i64>> = cells.iter().map(|n| as_int(n)).collect();
    match ints {
        Some(ints) if !cells.is_empty() => return Ok(PyArray1::from_vec(py, ints).into_any()),
        _ => {}
    }
    let as_float = |n: &Node| match *n {
        Node::Float(x) => Some(x),
        Node::Null => Some(f64::NAN),
        Node::Int(i) => Some(i as f64),
        Node::UInt(u) => Some(u as f64),
        _ => None,
    };
    if let Some(floats) = cells
        .iter()
        .map(|n| as_float(n))
        .collect::<Option<Vec<f64>>>()
    {
        return Ok(PyArray1::from_vec(py, floats).into_any());
    }
    let list = PyList::empty(py);
    for cell in cells {
        match cell {
            Node::Null => list.append(f64::NAN)?,
            Node::Str(s) if s.is_empty() => list.append(f64::NAN)?,
            other => list.append((*other).clone().into_py(py)?)?,
        }
    }
    Ok(list.into_any())
}

/// Serializes into a [`Node`].
struct NodeSerializer;

/// A sequence, tuple or (tuple) variant being filled.
struct SeqBuilder {
    items: Vec<Node>,
    /// The enum variant wrapping it, as serde_json's externally tagged form.
    variant: Option<&'static str>,
}

/// A struct, map or struct variant being filled.
struct MapBuilder {
    entries: Vec<(String, Node)>,
    /// A map key waiting for its value.
    key: Option<String>,
    variant: Option<&'static str>,
}

/// `node`, wrapped as `{variant: node}` for an enum variant.
fn tagged(variant: Option<&'static str>, node: Node) -> Node {
    match variant {
        Some(v) => Node::Map(vec![(v.to_string(), node)]),
        None => node,
    }
}

impl ser::Serializer for NodeSerializer {
    type Ok = Node;
    type Error = Unsupported;
    type SerializeSeq = SeqBuilder;
    type SerializeTuple = SeqBuilder;
    type SerializeTupleStruct = SeqBuilder;
    type SerializeTupleVariant = SeqBuilder;
    type SerializeMap = MapBuilder;
    type SerializeStruct = MapBuilder;
    type SerializeStructVariant = MapBuilder;

    fn serialize_bool(self, v: bool) -> Result<Node, Unsupported> {
        Ok(Node::Bool(v))
    }
    fn serialize_i8(self, v: i8) -> Result<Node, Unsupported> {
        Ok(Node::Int(v.into()))
    }
    fn serialize_i16(self, v: i16) -> Result<Node, Unsupported> {
        Ok(Node::Int(v.into()))
    }
    fn serialize_i32(self, v: i32) -> Result<Node, Unsupported> {
        Ok(Node::Int(v.into()))
    }
    fn serialize_i64(self, v: i64) -> Result<Node, Unsupported> {
        Ok(Node::Int(v))
    }
    fn serialize_u8(self, v: u8) -> Result<Node, Unsupported> {
        Ok(Node::UInt(v.into()))
    }
    fn serialize_u16(self, v: u16) -> Result<Node, Unsupported> {
        Ok(Node::UInt(v.into()))
    }
    fn serialize_u32(self, v: u32) -> Result<Node, Unsupported> {
        Ok(Node::UInt(v.into()))
    }
    fn serialize_u64(self, v: u64) -> Result<Node, Unsupported> {
        Ok(Node::UInt(v))
    }
    fn serialize_f32(self, v: f32) -> Result<Node, Unsupported> {
        Ok(Node::Float(v.into()))
    }
    fn serialize_f64(self, v: f64) -> Result<Node, Unsupported> {
        Ok(Node::Float(v))
    }
    fn serialize_char(self, v: char) -> Result<Node, Unsupported> {
        Ok(Node::Str(v.to_string()))
    }
    fn serialize_str(self, v: &str) -> Result<Node, Unsupported> {
        Ok(Node::Str(v.to_string()))
    }
    fn serialize_bytes(self, v: &[u8]) -> Result<Node, Unsupported> {
        Ok(Node::List(
            v.iter().map(|&b| Node::UInt(b.into())).collect(),
        ))
    }
    fn serialize_none(self) -> Result<Node, Unsupported> {
        Ok(Node::Null)
    }
    fn serialize_some<T: Serialize + ?Sized>(self, value: &T) -> Result<Node, Unsupported> {
        value.serialize(self)
    }
    fn serialize_unit(self) -> Result<Node, Unsupported> {
        Ok(Node::Null)
    }
    fn serialize_unit_struct(self, _: &'static str) -> Result<Node, Unsupported> {
        Ok(Node::Null)
    }
    fn serialize_unit_variant(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
    ) -> Result<Node, Unsupported> {
        Ok(Node::Str(variant.to_string()))
    }
    fn serialize_newtype_struct<T: Serialize + ?Sized>(
        self,
        _: &'static str,
        value: &T,
    ) -> Result<Node, Unsupported> {
        value.serialize(self)
    }
    fn serialize_newtype_variant<T: Serialize + ?Sized>(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
        value: &T,
    ) -> Result<Node, Unsupported> {
        Ok(tagged(Some(variant), value.serialize(self)?))
    }
    fn serialize_seq(self, len: Option<usize>) -> Result<SeqBuilder, Unsupported> {
        Ok(SeqBuilder {
            items: Vec::with_capacity(len.unwrap_or(0)),
            variant: None,
        })
    }
    fn serialize_tuple(self, len: usize) -> Result<SeqBuilder, Unsupported> {
        self.serialize_seq(Some(len))
    }
    fn serialize_tuple_struct(
        self,
        _: &'static str,
        len: usize,
    ) -> Result<SeqBuilder, Unsupported> {
        self.serialize_seq(Some(len))
    }
    fn serialize_tuple_variant(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
        len: usize,
    ) -> Result<SeqBuilder, Unsupported> {
        Ok(SeqBuilder {
            items: Vec::with_capacity(len),
            variant: Some(variant),
        })
    }
    fn serialize_map(self, len: Option<usize>) -> Result<MapBuilder, Unsupported> {
        Ok(MapBuilder {
            entries: Vec::with_capacity(len.unwrap_or(0)),
            key: None,
            variant: None,
        })
    }
    fn serialize_struct(self, _: &'static str, len: usize) -> Result<MapBuilder, Unsupported> {
        self.serialize_map(Some(len))
    }
    fn serialize_struct_variant(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
        len: usize,
    ) -> Result<MapBuilder, Unsupported> {
        Ok(MapBuilder {
            entries: Vec::with_capacity(len),
            key: None,
            variant: Some(variant),
        })
    }
}

impl SeqBuilder {
    fn push<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Unsupported> {
        self.items.push(to_node(value)?);
        Ok(())
    }

    fn finish(self) -> Node {
        tagged(self.variant, Node::List(self.items))
    }
}

impl ser::SerializeSeq for SeqBuilder {
    type Ok = Node;
    type Error = Unsupported;
    fn serialize_element<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Unsupported> {
        self.push(value)
    }
    fn end(self) -> Result<Node, Unsupported> {
        Ok(self.finish())
    }
}

impl ser::SerializeTuple for SeqBuilder {
    type Ok = Node;
    type Error = Unsupported;
    fn serialize_element<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Unsupported> {
        self.push(value)
    }
    fn end(self) -> Result<Node, Unsupported> {
        Ok(self.finish())
    }
}

impl ser::SerializeTupleStruct for SeqBuilder {
    type Ok = Node;
    type Error = Unsupported;
    fn serialize_field<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Unsupported> {
        self.push(value)
    }
    fn end(self) -> Result<Node, Unsupported> {
        Ok(self.finish())
    }
}

impl ser::SerializeTupleVariant for SeqBuilder {
    type Ok = Node;
    type Error = Unsupported;
    fn serialize_field<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Unsupported> {
        self.push(value)
    }
    fn end(self) -> Result<Node, Unsupported> {
        Ok(self.finish())
    }
}

impl MapBuilder {
    fn field<T: Serialize + ?Sized>(&mut self, key: &str, value: &T) -> Result<(), Unsupported> {
        self.entries.push((key.to_string(), to_node(value)?));
        Ok(())
    }

    fn finish(self) -> Node {
        tagged(self.variant, Node::Map(self.entries))
    }
}

impl ser::SerializeMap for MapBuilder {
    type Ok = Node;
    type Error = Unsupported;
    fn serialize_key<T: Serialize + ?Sized>(&mut self, key: &T) -> Result<(), Unsupported> {
        self.key = Some(match to_node(key)? {
            Node::Str(s) => s,
            Node::Int(i) => i.to_string(),
            Node::UInt(u) => u.to_string(),
            other => {
                return Err(Unsupported(format!(
                    "a map key that is not a string: {other:?}"
                )))
            }
        });
        Ok(())
    }
    fn serialize_value<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Unsupported> {
        let key = self
            .key
            .take()
            .ok_or_else(|| Unsupported("a map value without a key".into()))?;
        self.field(&key, value)
    }
    fn end(self) -> Result<Node, Unsupported> {
        Ok(self.finish())
    }
}

impl ser::SerializeStruct for MapBuilder {
    type Ok = Node;
    type Error = Unsupported;
    fn serialize_field<T: Serialize + ?Sized>(
        &mut self,
        key: &'static str,
        value: &T,
    ) -> Result<(), Unsupported> {
        self.field(key, value)
    }
    fn end(self) -> Result<Node, Unsupported> {
        Ok(self.finish())
    }
}

impl ser::SerializeStructVariant for MapBuilder {
    type Ok = Node;
    type Error = Unsupported;
    fn serialize_field<T: Serialize + ?Sized>(
        &mut self,
        key: &'static str,
        value: &T,
    ) -> Result<(), Unsupported> {
        self.field(key, value)
    }
    fn end(self) -> Result<Node, Unsupported> {
        Ok(self.finish())
    }
}
