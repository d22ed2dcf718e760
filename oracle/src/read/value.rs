//! The parsed tree of a file, the same for both encodings once read.

/// A value of the strict syntax.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Value {
    /// A RON identifier with or without fields (`ContactVelocities`, `Seed(index: 0)`), or a
    /// RON struct without a name (`name` empty): an enum value or a struct.
    Named {
        /// The identifier (empty for an unnamed struct).
        name: String,
        /// The fields in textual order, `None` for a bare identifier.
        fields: Option<Vec<(String, Value)>>,
    },
    /// A JSON object: members in textual order.
    Object(Vec<(String, Value)>),
    /// A RON identifier followed by a parenthesised list of values (`Some("5/2")`): an optional
    /// field's value when the identifier is `Some`, otherwise an enum value of the wrong form.
    Wrapped {
        /// The identifier.
        name: String,
        /// The values inside the parentheses.
        items: Vec<Value>,
    },
    /// A RON tuple `( ... )`.
    Tuple(Vec<Value>),
    /// A RON list `[ ... ]`.
    List(Vec<Value>),
    /// A JSON array (a list or a tuple, as the schema expects).
    Array(Vec<Value>),
    /// A RON string (no escapes exist in the strict syntax).
    Str(String),
    /// A JSON string: also the form of a JSON enum value without fields (§11), where RON has an
    /// identifier.
    JsonStr(String),
    /// A plain decimal integer, as its digits.
    Int(String),
}

impl Value {
    /// A short name of the value's kind, for messages.
    pub fn kind(&self) -> &'static str {
        match self {
            Value::Named { fields: None, .. } => "identifier",
            Value::Named { .. } => "struct",
            Value::Wrapped { .. } => "wrapped value",
            Value::Object(_) => "object",
            Value::Tuple(_) => "tuple",
            Value::List(_) => "list",
            Value::Array(_) => "array",
            Value::Str(_) | Value::JsonStr(_) => "string",
            Value::Int(_) => "integer",
        }
    }
}
