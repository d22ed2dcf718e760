//! The heaviest files the default limits allow, built from the corpus (shared by
//! `kernel/tests/all/worst/mod.rs`, which asserts their verdicts, and `benches/worst.rs`, which times
//! them): every number of a valid file moved by a tiny amount, ±1/(10^k + 7), so that it has as
//! many digits as `max-digits` (10,000) and the file's numbers together about as many characters
//! as `max-total-digits` (2,000,000) allow. The verdict is unchanged where the file has slack.

use malachite::Integer;
use malachite::base::num::arithmetic::traits::Pow;
use malachite::rational::Rational;
use std::path::Path;
use std::str::FromStr;

/// The default `max-digits` and `max-total-digits`, with a margin.
const MAX_DIGITS: usize = 9_990;
const MAX_TOTAL: usize = 1_990_000;

/// One heavy file: a name, the kind, the text, and whether it is valid.
pub struct Worst {
    /// e.g. `cone-n3-64-generators`.
    pub name: &'static str,
    /// RON text.
    pub text: String,
}

fn canonical(x: &Rational) -> String {
    let (n, d) = (x.to_numerator(), x.to_denominator());
    let sign = if *x < 0u32 { "-" } else { "" };
    if d == 1u32 { format!("{sign}{n}") } else { format!("{sign}{n}/{d}") }
}

/// `x` moved towards zero's other side by 1/(10^k + 7) (away from zero, so signs stay), with k
/// chosen for about `digits` digits in all.
fn moved(x: &str, digits: usize) -> String {
    let r = Rational::from_str(x).expect("a canonical rational");
    let own = x.len();
    let k = (digits.saturating_sub(own) / 2).max(1) as u64;
    let q = Integer::from(10u32).pow(k) + Integer::from(7u32);
    let eps = Rational::from_integers(Integer::from(1u32), q);
    canonical(&if r < 0u32 { r - eps } else { r + eps })
}

/// Every quoted canonical rational of `text` accepted by `pick` (given its index among them)
/// moved to about `digits` digits.
fn heavier(text: &str, digits: usize, pick: impl Fn(usize, &str) -> bool) -> String {
    let mut out = String::with_capacity(text.len() * 4);
    let mut index = 0;
    for (i, part) in text.split('"').enumerate() {
        if i > 0 {
            out.push('"');
        }
        let number = i % 2 == 1
            && !part.is_empty()
            && part.bytes().all(|b| b.is_ascii_digit() || b == b'-' || b == b'/');
        if number && pick(index, part) {
            out.push_str(&moved(part, digits));
        } else {
            out.push_str(part);
        }
        index += usize::from(number);
    }
    out
}

/// The count of quoted canonical rationals of `text`.
fn count(text: &str) -> usize {
    text.split('"')
        .enumerate()
        .filter(|(i, p)| {
            i % 2 == 1 && !p.is_empty() && p.bytes().all(|b| b.is_ascii_digit() || b == b'-' || b == b'/')
        })
        .count()
}

fn read(root: &Path, file: &str) -> String {
    std::fs::read_to_string(root.join(file)).unwrap_or_else(|e| panic!("{file}: {e}"))
}

/// Every number moved, digits shared out within the total limit.
fn all(root: &Path, file: &str) -> String {
    let text = read(root, file);
    let digits = MAX_DIGITS.min(MAX_TOTAL / count(&text).max(1));
    heavier(&text, digits, |_, _| true)
}

/// The body's numbers (the first `k` of the file) moved to the digit limit.
fn body(root: &Path, file: &str, k: usize) -> String {
    heavier(&read(root, file), MAX_DIGITS, |i, _| i < k)
}

/// A field element for kappa: `base` plus tiny parts on each power of c below `degree`, all
/// coefficients together at the digit limit of one element.
fn element_kappa(root: &Path, file: &str, base: &str, degree: usize) -> String {
    let per = MAX_DIGITS / degree;
    let mut terms = vec![moved(base, per)];
    for k in 1..degree {
        let power = if k == 1 { "c".to_string() } else { format!("c^{k}") };
        terms.push(format!("{}*{power}", moved("0", per)));
    }
    let text = read(root, file).replacen("version: 1,", "version: 3,", 1);
    text.replacen(&format!("kappa: \"{base}\""), &format!("kappa: \"{}\"", terms.join(" + ")), 1)
}

/// The heavy files of every kind, from the repository at `root`.
pub fn files(root: &Path) -> Vec<Worst> {
    let v = |f: &str| format!("certificates/valid/{f}");
    vec![
        Worst {
            name: "cone-n3-64-generators",
            text: all(root, &v("n3-kappa3_20-gamma1_20-64-generators.ron")),
        },
        Worst {
            name: "cone-n4",
            text: all(root, &v("n4-kappa1_6-gamma1_100-complete-chatter-from-all-down.ron")),
        },
        Worst { name: "cone-n6", text: all(root, &v("n6-kappa1_40-gamma1_100-cc-or-pcc-from-all-down.ron")) },
        Worst {
            name: "rod-body",
            text: body(root, &v("n2-kappa1_3-gamma1_20-complete-chatter-from-all-down.ron"), 2),
        },
        Worst { name: "box-n4-body", text: body(root, &v("n4-kappa1_10_3_25-gamma1_100_1_50-box.ron"), 4) },
        Worst {
            name: "field-n5-kappa",
            text: body(root, &v("n5-kappa1_200-gamma1_5-complete-chatter-from-all-down.ron"), 1),
        },
        Worst {
            name: "field-n5-all",
            text: all(root, &v("n5-kappa1_200-gamma1_5-complete-chatter-from-all-down.ron")),
        },
        Worst {
            name: "field-n5-element",
            text: element_kappa(
                root,
                &v("n5-kappa1_200-gamma1_5-complete-chatter-from-all-down.ron"),
                "1/200",
                2,
            ),
        },
        Worst {
            name: "field-n7-all",
            text: all(root, &v("n7-kappa1_200-gamma1_5-complete-chatter-from-all-down.ron")),
        },
        Worst {
            name: "field-n12-element",
            text: element_kappa(root, &v("n12-kappa1_200-gamma1_5-effectively-invariant.ron"), "1/200", 2),
        },
        Worst {
            name: "refutation-n6-body",
            text: body(root, &v("refutation-n6-kappa1_20-gamma1_10.ron"), 2),
        },
        Worst { name: "refutation-n4-all", text: all(root, &v("refutation-n4-kappa1_6-gamma1_20.ron")) },
        Worst {
            name: "family-rectangle-gamma",
            text: heavier(&read(root, &v("convex-rectangle-2x1-gamma1_50.ron")), MAX_DIGITS, |i, _| i == 11),
        },
    ]
}
