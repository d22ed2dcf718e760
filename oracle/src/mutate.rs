//! Structure-aware mutations of certificate and refutation files, decoded from bytes (for the
//! differential tests and the fuzz target): every byte string decodes to a base file and a list
//! of edits of its [`Value`] tree (a number perturbed, scaled, negated or made non-canonical, a
//! list element dropped, duplicated, swapped or interpolated, an identifier or integer changed
//! (claim, n, version, pattern steps, indices), two fields' values swapped, a parameter widened
//! to an interval, a number or integer inside a field named in [`FIELDS`] edited, such as a
//! time-to-rest certificate's weight, scale, numerator, bound, generator or successor), then written back as
//! RON. Missing bytes read as 0. Sizes stay bounded.

use crate::arith::Rat;
use crate::arith::rational::{parse_rational, rational_text};
use crate::read::Value;
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

/// Most edits decoded from one input.
pub const MAX_EDITS: usize = 8;
/// No list grows beyond this many elements.
pub const MAX_LIST: usize = 96;
/// Numbers longer than this are not scaled or shifted further.
pub const MAX_NUMBER: usize = 400;

/// One edit; indices count nodes of a kind in depth-first order, modulo their number.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Edit {
    /// Numerator (or denominator) ± 1 of the `at`-th rational.
    Nudge {
        /// Which node of its kind (modulo their number).
        at: u8,
        /// The denominator instead of the numerator.
        denominator: bool,
        /// Up (+) or down (-).
        up: bool,
    },
    /// The `at`-th rational times a factor of [`FACTORS`].
    Scale {
        /// Which node of its kind (modulo their number).
        at: u8,
        /// Index into [`FACTORS`].
        factor: u8,
    },
    /// The `at`-th rational ± 10^-exponent.
    Shift {
        /// Which node of its kind (modulo their number).
        at: u8,
        /// Up (+) or down (-).
        up: bool,
        /// The exponent e.
        exponent: u8,
    },
    /// The `at`-th rational negated.
    Negate {
        /// Which node of its kind (modulo their number).
        at: u8,
    },
    /// The `at`-th rational written in a non-canonical way.
    Spoil {
        /// Which node of its kind (modulo their number).
        at: u8,
        /// Which non-canonical spelling.
        how: u8,
    },
    /// Element `index` of the `at`-th list removed.
    Drop {
        /// Which node of its kind (modulo their number).
        at: u8,
        /// Which element (modulo the length).
        index: u8,
    },
    /// Element `index` of the `at`-th list repeated (numbers doubled) at the end.
    Duplicate {
        /// Which node of its kind (modulo their number).
        at: u8,
        /// Which element (modulo the length).
        index: u8,
    },
    /// Elements `a` and `b` of the `at`-th list swapped.
    Swap {
        /// Which node of its kind (modulo their number).
        at: u8,
        /// The first element or field (modulo the length).
        a: u8,
        /// The second element or field (modulo the length).
        b: u8,
    },
    /// A new element ((16 - t) x_a + t x_b) / 16 appended to the `at`-th list of number tuples.
    Between {
        /// Which node of its kind (modulo their number).
        at: u8,
        /// The first element or field (modulo the length).
        a: u8,
        /// The second element or field (modulo the length).
        b: u8,
        /// The weight t, 0 to 16.
        t: u8,
    },
    /// The `at`-th bare identifier replaced by another of [`IDENTS`].
    Ident {
        /// Which node of its kind (modulo their number).
        at: u8,
        /// Which new value.
        to: u8,
    },
    /// The `at`-th integer replaced by a value of [`INTEGERS`] or moved by ±1.
    Integer {
        /// Which node of its kind (modulo their number).
        at: u8,
        /// Which new value.
        to: u8,
    },
    /// The values of fields `a` and `b` of the `at`-th struct swapped.
    SwapFields {
        /// Which node of its kind (modulo their number).
        at: u8,
        /// The first element or field (modulo the length).
        a: u8,
        /// The second element or field (modulo the length).
        b: u8,
    },
    /// The `at`-th point parameter `kappa` or `gamma` widened to an interval [x, x + 10^-e].
    Widen {
        /// Which node of its kind (modulo their number).
        at: u8,
        /// The exponent e.
        exponent: u8,
    },
    /// Inside the `at`-th value of a field named `FIELDS[name]`: a number scaled, shifted or
    /// negated (`how % 3`, with the parameter `how / 3`), or in `next` an integer changed.
    Field {
        /// Which field name of [`FIELDS`] (modulo their number).
        name: u8,
        /// Which value of a field of that name, then which number inside it (modulo their number).
        at: u8,
        /// Which edit and its parameter.
        how: u8,
    },
}

/// Field names an [`Edit::Field`] aims at: the parts of a time-to-rest certificate's nodes
/// (docs/certificate-format.md §16), the bound, and a cone.
pub const FIELDS: [&str; 6] = ["weight", "scale", "bound", "cone", "next", "numerator"];

/// Positive factors of [`Edit::Scale`].
pub const FACTORS: [(i64, i64); 8] =
    [(2, 1), (1, 2), (7, 5), (10, 1), (1, 10), (1_000_003, 1), (1, 999_983), (3, 2)];
/// Identifiers an [`Edit::Ident`] may write.
pub const IDENTS: [&str; 8] = [
    "EffectivelyInvariant",
    "CcOrPccFromAllDown",
    "CompleteChatterFromAllDown",
    "CompleteChatterFromSet",
    "ContactVelocities",
    "PaperVelocities",
    "Seed",
    "Unknown",
];
/// Integers an [`Edit::Integer`] may write (besides ±1).
pub const INTEGERS: [u64; 10] = [0, 1, 2, 3, 4, 5, 6, 8, 12, 65];

/// A decoded input: which base file, and the edits.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Plan {
    /// Index of the base file (modulo their number).
    pub base: u8,
    /// The edits, in order.
    pub edits: Vec<Edit>,
}

/// Decodes bytes into a plan: byte 0 picks the base, then 4 bytes per edit.
pub fn decode(data: &[u8]) -> Plan {
    let byte = |i: usize| data.get(i).copied().unwrap_or(0);
    let mut edits = vec![];
    for k in 0..MAX_EDITS.min(data.len().saturating_sub(1).div_ceil(4)) {
        let (op, a, b, c) = (byte(1 + 4 * k), byte(2 + 4 * k), byte(3 + 4 * k), byte(4 + 4 * k));
        edits.push(match op % 14 {
            0 => Edit::Nudge { at: a, denominator: b % 2 == 1, up: c % 2 == 1 },
            1 => Edit::Scale { at: a, factor: b },
            2 => Edit::Shift { at: a, up: b % 2 == 1, exponent: 1 + c % 40 },
            3 => Edit::Negate { at: a },
            4 => Edit::Spoil { at: a, how: b },
            5 => Edit::Drop { at: a, index: b },
            6 => Edit::Duplicate { at: a, index: b },
            7 => Edit::Swap { at: a, a: b, b: c },
            8 => Edit::Between { at: a, a: b, b: c, t: byte(5 + 4 * k) % 17 },
            9 => Edit::Ident { at: a, to: b },
            10 => Edit::Integer { at: a, to: b },
            11 => Edit::SwapFields { at: a, a: b, b: c },
            12 => Edit::Field { name: a, at: b, how: c },
            _ => Edit::Widen { at: a, exponent: 1 + b % 12 },
        });
    }
    Plan { base: byte(0), edits }
}

/// The nodes of a tree in depth-first order that satisfy `pick`, as mutable references.
fn nodes<'a>(v: &'a mut Value, pick: &dyn Fn(&Value) -> bool, out: &mut Vec<&'a mut Value>) {
    let hit = pick(v);
    if hit {
        out.push(v);
        return;
    }
    match v {
        Value::Named { fields: Some(fs), .. } | Value::Object(fs) => {
            for (_, x) in fs {
                nodes(x, pick, out);
            }
        }
        Value::Tuple(xs) | Value::List(xs) | Value::Array(xs) | Value::Wrapped { items: xs, .. } => {
            for x in xs {
                nodes(x, pick, out);
            }
        }
        _ => {}
    }
}

/// The `at`-th node satisfying `pick`.
fn nth<'a>(v: &'a mut Value, at: u8, pick: &dyn Fn(&Value) -> bool) -> Option<&'a mut Value> {
    let mut all = vec![];
    nodes(v, pick, &mut all);
    let len = all.len();
    (len > 0).then(|| all.swap_remove(usize::from(at) % len))
}

fn rational_of(v: &Value) -> Option<Rat> {
    match v {
        Value::Str(s) if s.len() <= MAX_NUMBER => parse_rational(s, usize::MAX).ok(),
        _ => None,
    }
}

fn is_rational(v: &Value) -> bool {
    rational_of(v).is_some()
}

/// Applies `f` to the `at`-th rational.
fn on_rational(v: &mut Value, at: u8, f: impl Fn(Rat) -> Option<String>) {
    if let Some(node) = nth(v, at, &is_rational)
        && let Some(x) = rational_of(node)
        && let Some(s) = f(x)
    {
        *node = Value::Str(s);
    }
}

fn ratio(p: i64, q: i64) -> Rat {
    Rat::new(BigInt::from(p), BigInt::from(q))
}

/// Performs one edit (a no-op where it does not apply).
pub fn apply(v: &mut Value, e: Edit) {
    let text = |x: Rat| Some(rational_text(&x));
    match e {
        Edit::Nudge { at, denominator, up } => on_rational(v, at, |x| {
            let d = BigInt::from(if up { 1 } else { -1 });
            let (n, q) = (x.numer().clone(), x.denom().clone());
            let (n, q) = if denominator { (n, q + d) } else { (n + d, q) };
            (!q.is_zero()).then(|| rational_text(&Rat::new(n, q)))
        }),
        Edit::Scale { at, factor } => {
            let (p, q) = FACTORS[usize::from(factor) % FACTORS.len()];
            on_rational(v, at, |x| text(x * ratio(p, q)));
        }
        Edit::Shift { at, up, exponent } => on_rational(v, at, |x| {
            let d = Rat::new(BigInt::one(), BigInt::from(10).pow(u32::from(exponent)));
            text(if up { x + d } else { x - d })
        }),
        Edit::Negate { at } => on_rational(v, at, |x| text(-x)),
        Edit::Spoil { at, how } => on_rational(v, at, |x| {
            let t = rational_text(&x);
            Some(match how % 5 {
                0 => format!("{}/{}", x.numer() * 2, x.denom() * 2),
                1 => format!("{t}/1"),
                2 if !x.is_negative() => format!("+{t}"),
                3 => format!("0{t}"),
                _ => format!(" {t}"),
            })
        }),
        Edit::Drop { at, index } => {
            if let Some(Value::List(xs) | Value::Array(xs)) =
                nth(v, at, &|x| matches!(x, Value::List(l) | Value::Array(l) if !l.is_empty()))
            {
                xs.remove(usize::from(index) % xs.len());
            }
        }
        Edit::Duplicate { at, index } => {
            if let Some(Value::List(xs) | Value::Array(xs)) = nth(
                v,
                at,
                &|x| matches!(x, Value::List(l) | Value::Array(l) if !l.is_empty() && l.len() < MAX_LIST),
            ) {
                let mut copy = xs[usize::from(index) % xs.len()].clone();
                let mut inner = vec![];
                nodes(&mut copy, &is_rational, &mut inner);
                for n in inner {
                    if let Some(x) = rational_of(n) {
                        *n = Value::Str(rational_text(&(x * ratio(2, 1))));
                    }
                }
                xs.push(copy);
            }
        }
        Edit::Swap { at, a, b } => {
            if let Some(Value::List(xs) | Value::Array(xs) | Value::Tuple(xs)) = nth(
                v,
                at,
                &|x| matches!(x, Value::List(l) | Value::Array(l) | Value::Tuple(l) if l.len() >= 2),
            ) {
                let n = xs.len();
                xs.swap(usize::from(a) % n, usize::from(b) % n);
            }
        }
        Edit::Between { at, a, b, t } => between(v, at, a, b, t),
        Edit::Ident { at, to } => {
            if let Some(node) = nth(v, at, &|x| matches!(x, Value::Named { fields: None, .. })) {
                *node = Value::Named { name: IDENTS[usize::from(to) % IDENTS.len()].into(), fields: None };
            }
        }
        Edit::Integer { at, to } => {
            if let Some(Value::Int(d)) = nth(v, at, &|x| matches!(x, Value::Int(_))) {
                let old: u64 = d.parse().unwrap_or(0);
                let new = match to % 12 {
                    10 => old + 1,
                    11 => old.saturating_sub(1),
                    k => INTEGERS[usize::from(k) % INTEGERS.len()],
                };
                *d = new.to_string();
            }
        }
        Edit::SwapFields { at, a, b } => {
            if let Some(Value::Named { fields: Some(fs), .. }) =
                nth(v, at, &|x| matches!(x, Value::Named { fields: Some(f), .. } if f.len() >= 2))
            {
                let n = fs.len();
                let (i, j) = (usize::from(a) % n, usize::from(b) % n);
                let (x, y) = (fs[i].1.clone(), fs[j].1.clone());
                fs[i].1 = y;
                fs[j].1 = x;
            }
        }
        Edit::Widen { at, exponent } => widen(v, at, exponent),
        Edit::Field { name, at, how } => field(v, name, at, how),
    }
}

/// The values of the fields named `name`, in depth-first order.
fn field_values<'a>(v: &'a mut Value, name: &str, out: &mut Vec<&'a mut Value>) {
    match v {
        Value::Named { fields: Some(fs), .. } | Value::Object(fs) => {
            for (k, x) in fs {
                if k == name {
                    out.push(x);
                } else {
                    field_values(x, name, out);
                }
            }
        }
        Value::Tuple(xs) | Value::List(xs) | Value::Array(xs) | Value::Wrapped { items: xs, .. } => {
            for x in xs {
                field_values(x, name, out);
            }
        }
        _ => {}
    }
}

/// [`Edit::Field`]: one edit inside the `at`-th value of a field named `FIELDS[name]`.
fn field(v: &mut Value, name: u8, at: u8, how: u8) {
    let (name, mut values) = (FIELDS[usize::from(name) % FIELDS.len()], vec![]);
    field_values(v, name, &mut values);
    let len = values.len();
    if len == 0 {
        return;
    }
    let value = values.swap_remove(usize::from(at) % len);
    let (inner, p) = (at / 7, how / 3);
    let edit = match how % 3 {
        _ if name == "next" => Edit::Integer { at: inner, to: how },
        0 => Edit::Scale { at: inner, factor: p },
        1 => Edit::Shift { at: inner, up: p % 2 == 1, exponent: 1 + p % 24 },
        _ => Edit::Negate { at: inner },
    };
    apply(value, edit);
}

/// A new tuple ((16 - t) x_a + t x_b)/16 appended to a list of equal-length number tuples.
fn between(v: &mut Value, at: u8, a: u8, b: u8, t: u8) {
    let numeric = |x: &Value| matches!(x, Value::Tuple(xs) if !xs.is_empty() && xs.iter().all(is_rational));
    let pick = move |x: &Value| matches!(x, Value::List(l) if !l.is_empty() && l.len() < MAX_LIST && l.iter().all(numeric));
    if let Some(Value::List(xs)) = nth(v, at, &pick) {
        let n = xs.len();
        let (Value::Tuple(p), Value::Tuple(q)) = (&xs[usize::from(a) % n], &xs[usize::from(b) % n]) else {
            return;
        };
        if p.len() != q.len() {
            return;
        }
        let (wa, wb) = (ratio(16 - i64::from(t), 16), ratio(i64::from(t), 16));
        let mix: Vec<Value> = p
            .iter()
            .zip(q)
            .map(|(x, y)| {
                let (x, y) = (rational_of(x).expect("numeric"), rational_of(y).expect("numeric"));
                Value::Str(rational_text(&(&wa * x + &wb * y)))
            })
            .collect();
        xs.push(Value::Tuple(mix));
    }
}

/// A point `kappa` or `gamma` becomes [x, x + 10^-e] (a box, §9).
fn widen(v: &mut Value, at: u8, exponent: u8) {
    let pick =
        |x: &Value| matches!(x, Value::Named { fields: Some(f), .. } if f.iter().any(|(k, _)| k == "kappa"));
    if let Some(Value::Named { fields: Some(fs), .. }) = nth(v, 0, &pick) {
        let n = fs.len();
        let (_, value) = &mut fs[usize::from(at) % n];
        if let Some(x) = rational_of(value) {
            let hi = &x + Rat::new(BigInt::one(), BigInt::from(10).pow(u32::from(exponent)));
            *value = Value::List(vec![Value::Str(rational_text(&x)), Value::Str(rational_text(&hi))]);
        }
    }
}

/// The mutated RON text of a base file's tree.
pub fn mutated(base: &Value, edits: &[Edit]) -> String {
    let mut v = base.clone();
    for e in edits {
        apply(&mut v, *e);
    }
    crate::read::write::to_ron(&v)
}
