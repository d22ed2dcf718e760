//! Writing a [`Value`] tree back as strict RON text (docs/certificate-format.md §2), one field
//! per line: the mutations' output.

use super::Value;

fn write_into(v: &Value, indent: usize, out: &mut String) {
    let pad = "    ".repeat(indent + 1);
    let close = "    ".repeat(indent);
    match v {
        Value::Named { name, fields: None } => out.push_str(name),
        Value::Named { name, fields: Some(fs) } => {
            out.push_str(name);
            fields_into(fs, &pad, &close, indent, out);
        }
        Value::Object(fs) => fields_into(fs, &pad, &close, indent, out),
        Value::Wrapped { name, items } => {
            out.push_str(name);
            seq(items, "(", ")", indent, out);
        }
        Value::Tuple(xs) => seq(xs, "(", ")", indent, out),
        Value::List(xs) | Value::Array(xs) => seq(xs, "[", "]", indent, out),
        Value::Str(s) | Value::JsonStr(s) => out.push_str(&format!("\"{s}\"")),
        Value::Int(d) => out.push_str(d),
    }
}

fn seq(xs: &[Value], open: &str, close: &str, indent: usize, out: &mut String) {
    let flat = xs.iter().all(|x| {
        matches!(x, Value::Str(_) | Value::JsonStr(_) | Value::Int(_) | Value::Named { fields: None, .. })
    });
    out.push_str(open);
    if flat {
        let parts: Vec<String> = xs.iter().map(|x| to_ron_at(x, indent)).collect();
        out.push_str(&parts.join(", "));
    } else {
        let pad = "    ".repeat(indent + 1);
        out.push('\n');
        for x in xs {
            out.push_str(&pad);
            write_into(x, indent + 1, out);
            out.push_str(",\n");
        }
        out.push_str(&"    ".repeat(indent));
    }
    out.push_str(close);
}

fn to_ron_at(v: &Value, indent: usize) -> String {
    let mut s = String::new();
    write_into(v, indent, &mut s);
    s
}

/// The RON text of a value tree.
pub fn to_ron(v: &Value) -> String {
    let mut s = to_ron_at(v, 0);
    s.push('\n');
    s
}

/// `(\n    k: v,\n ... )`: the fields of a struct, one per line at the next indent.
fn fields_into(fs: &[(String, Value)], pad: &str, close: &str, indent: usize, out: &mut String) {
    out.push_str("(\n");
    for (k, x) in fs {
        out.push_str(&format!("{pad}{k}: "));
        write_into(x, indent + 1, out);
        out.push_str(",\n");
    }
    out.push_str(close);
    out.push(')');
}
