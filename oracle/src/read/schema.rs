//! Hand-written schema checks on a [`Value`] tree (docs/certificate-format.md §2 and §11): fields
//! in textual order, an unknown or repeated field is an error where it appears, a wrong type is
//! `syntax`, an unknown enum value `unknown-variant`, and absent required fields are
//! `missing-field` at the end.

use super::Value;
use crate::verdict::{Checked, Fail};

/// The fields of a struct: a RON struct (named or not) or a JSON object.
pub fn record(v: &Value) -> Checked<&[(String, Value)]> {
    match v {
        Value::Named { fields: Some(f), .. } | Value::Object(f) => Ok(f),
        other => Err(Fail::new("syntax", format!("expected a struct, found a {}", other.kind()))),
    }
}

/// Walks the fields of a struct: `fields` lists the known names and whether each is required;
/// `each` reads one field's value.
pub fn walk<'a>(
    v: &'a Value,
    fields: &[(&str, bool)],
    mut each: impl FnMut(&str, &'a Value) -> Checked<()>,
) -> Checked<()> {
    let rec = record(v)?;
    let mut seen: Vec<&str> = vec![];
    for (name, value) in rec {
        if !fields.iter().any(|(f, _)| f == name) {
            return Err(Fail::new("unknown-field", format!("unknown field `{name}`")));
        }
        if seen.contains(&name.as_str()) {
            return Err(Fail::new("duplicate-field", format!("duplicate field `{name}`")));
        }
        seen.push(name);
        each(name, value)?;
    }
    for (f, required) in fields {
        if *required && !seen.contains(f) {
            return Err(Fail::new("missing-field", format!("missing field `{f}`")));
        }
    }
    Ok(())
}

/// An enum value: its variant's name and, for a variant with fields, the struct of its fields.
/// RON: `Name` or `Name(...)`; JSON: `"Name"` or `{"Name": {...}}`.
pub fn variant(v: &Value) -> Checked<(&str, Option<&Value>)> {
    match v {
        Value::Named { name, fields: None } => Ok((name, None)),
        Value::Named { name, fields: Some(_) } if !name.is_empty() => Ok((name, Some(v))),
        Value::Wrapped { name, .. } => Ok((name, Some(v))),
        Value::JsonStr(name) => Ok((name, None)),
        Value::Object(m) if m.len() == 1 => Ok((&m[0].0, Some(&m[0].1))),
        other => Err(Fail::new("syntax", format!("expected an enum value, found a {}", other.kind()))),
    }
}

/// A unit variant among `known` (all of the enum's variants, with whether each is a unit).
pub fn unit_variant<'a>(v: &'a Value, known: &[(&str, bool)]) -> Checked<&'a str> {
    let (name, fields) = variant(v)?;
    match known.iter().find(|(k, _)| *k == name) {
        None => Err(Fail::new("unknown-variant", format!("unknown variant `{name}`"))),
        Some((_, true)) if fields.is_none() => Ok(name),
        Some(_) => Err(Fail::new("syntax", format!("`{name}` has the wrong form"))),
    }
}

/// A string.
pub fn string(v: &Value) -> Checked<&str> {
    match v {
        Value::Str(s) | Value::JsonStr(s) => Ok(s),
        other => Err(Fail::new("syntax", format!("expected a string, found a {}", other.kind()))),
    }
}

/// A non-negative integer that fits 64 bits.
pub fn integer(v: &Value) -> Checked<u64> {
    match v {
        Value::Int(d) => d.parse().map_err(|_| Fail::new("syntax", format!("integer {d} is too large"))),
        other => Err(Fail::new("syntax", format!("expected an integer, found a {}", other.kind()))),
    }
}

/// A list (RON `[...]`, JSON array).
pub fn list(v: &Value) -> Checked<&[Value]> {
    match v {
        Value::List(xs) | Value::Array(xs) => Ok(xs),
        other => Err(Fail::new("syntax", format!("expected a list, found a {}", other.kind()))),
    }
}

/// A tuple (RON `(...)`, JSON array).
pub fn tuple(v: &Value) -> Checked<&[Value]> {
    match v {
        Value::Tuple(xs) | Value::Array(xs) => Ok(xs),
        other => Err(Fail::new("syntax", format!("expected a tuple, found a {}", other.kind()))),
    }
}

/// A tuple of strings (a generator, a contact, an inertia triple).
pub fn strings(v: &Value) -> Checked<Vec<&str>> {
    tuple(v)?.iter().map(string).collect()
}

/// A parameter: a number, or an interval `[lo, hi]` (§9, §13: a two-element RON list or JSON
/// array; a RON tuple is `syntax`, as the kernel's strict reader has it).
pub fn param(v: &Value) -> Checked<Vec<&str>> {
    match v {
        Value::Str(s) | Value::JsonStr(s) => Ok(vec![s]),
        Value::List(xs) | Value::Array(xs) if xs.len() == 2 => xs.iter().map(string).collect(),
        Value::Tuple(_) => Err(Fail::new("syntax", "a parameter interval is a list [lo, hi], not a tuple")),
        other => {
            Err(Fail::new("syntax", format!("expected a number or an interval, found a {}", other.kind())))
        }
    }
}

/// An optional field's value (docs/certificate-format.md §2 and §11): RON `None` or `Some(x)`;
/// in JSON the value itself (the strict JSON syntax has no `null`). Anything else is `syntax`.
pub fn optional(v: &Value) -> Checked<Option<&Value>> {
    match v {
        Value::Named { name, fields: None } if name == "None" => Ok(None),
        Value::Wrapped { name, items } if name == "Some" && items.len() == 1 => Ok(Some(&items[0])),
        Value::JsonStr(_) | Value::Array(_) | Value::Object(_) => Ok(Some(v)),
        other => Err(Fail::new("syntax", format!("expected an optional value, found a {}", other.kind()))),
    }
}

/// The body `RegularPolygon(n: .., kappa: .., gamma: ..)` of cone, orbit and refutation files:
/// `each` receives each of its three fields.
pub fn regular_polygon<'a>(
    value: &'a Value,
    each: impl FnMut(&str, &'a Value) -> Checked<()>,
) -> Checked<()> {
    let (name, fields) = variant(value)?;
    if name != "RegularPolygon" {
        return Err(Fail::new("unknown-variant", format!("unknown body `{name}`")));
    }
    let fields = fields.ok_or_else(|| Fail::new("syntax", "RegularPolygon needs its fields"))?;
    walk(fields, &[("n", true), ("kappa", true), ("gamma", true)], each)
}
