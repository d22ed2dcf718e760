//! Orbit certificates, version 5 (docs/certificate-format.md §14): the schema, rule O1 (the
//! file's rules, decided exactly: two-sided), then conditions 1-3 at rational sample points of X
//! (one-sided: a failing point proves the certificate false, passing points prove nothing).
//! Every regular n from 3 to 64: where cos 2π/n is irrational the return map is evaluated
//! exactly in Q(cos 2π/n) (`crate::arith::field`), signs decided on the oracle's own rational
//! enclosures of cos 2π/n (`crate::arith::enclosure`).

use super::limits::Limits;
use super::numbers::element;
use crate::arith::text::element_text;
use crate::arith::{Field, Num};
use crate::claim::Claim;
use crate::orbit::map::Orbit;
use crate::orbit::sample::samples;
use crate::read::Value;
use crate::read::schema::{integer, list, regular_polygon, string, tuple, unit_variant, variant, walk};
use crate::regular::model::{Polygon, V3};
use crate::verdict::{Checked, Fail};

/// The set X as written.
enum SetText<'a> {
    Parallelepiped { centre: Vec<&'a str>, axes: Vec<Vec<&'a str>>, delta: &'a str },
    Box { lo: Vec<&'a str>, hi: Vec<&'a str> },
}

/// A version-5 certificate as read.
pub struct OrbitFile<'a> {
    n: u64,
    kappa: &'a str,
    gamma: &'a str,
    claim: Claim,
    pattern: Vec<u64>,
    set: Option<SetText<'a>>,
    subdivision: u64,
    rho: &'a str,
    lambda: &'a str,
    period: &'a str,
}

/// A tuple of exactly three strings.
fn triple(v: &Value) -> Checked<Vec<&str>> {
    let t = tuple(v)?;
    if t.len() != 3 {
        return Err(Fail::new("syntax", format!("expected 3 numbers, found {}", t.len())));
    }
    t.iter().map(string).collect()
}

fn set(v: &Value) -> Checked<SetText<'_>> {
    let (name, fields) = variant(v)?;
    let fields = match (name, fields) {
        ("Parallelepiped" | "Box", Some(f)) => f,
        ("Parallelepiped" | "Box", None) => return Err(Fail::new("syntax", "the set needs its fields")),
        _ => return Err(Fail::new("unknown-variant", format!("unknown set `{name}`"))),
    };
    if name == "Box" {
        let (mut lo, mut hi) = (vec![], vec![]);
        walk(fields, &[("lo", true), ("hi", true)], |f, v| {
            if f == "lo" {
                lo = triple(v)?
            } else {
                hi = triple(v)?
            }
            Ok(())
        })?;
        return Ok(SetText::Box { lo, hi });
    }
    let (mut centre, mut axes, mut delta) = (vec![], vec![], "");
    walk(fields, &[("centre", true), ("axes", true), ("delta", true)], |f, v| {
        match f {
            "centre" => centre = triple(v)?,
            "axes" => {
                let t = tuple(v)?;
                if t.len() != 3 {
                    return Err(Fail::new("syntax", "three axes"));
                }
                axes = t.iter().map(triple).collect::<Checked<_>>()?;
            }
            _ => delta = string(v)?,
        }
        Ok(())
    })?;
    Ok(SetText::Parallelepiped { centre, axes, delta })
}

/// The schema of §14.
pub fn read(v: &Value) -> Checked<OrbitFile<'_>> {
    let mut f = OrbitFile {
        n: 0,
        kappa: "",
        gamma: "",
        claim: Claim::CompleteChatterFromSet,
        pattern: vec![],
        set: None,
        subdivision: 0,
        rho: "",
        lambda: "",
        period: "",
    };
    let fields = [
        ("format", true),
        ("version", true),
        ("body", true),
        ("claim", true),
        ("pattern", true),
        ("set", true),
        ("subdivision", true),
        ("rho", true),
        ("lambda", true),
        ("period", true),
        ("producer", false),
    ];
    walk(v, &fields, |name, value| {
        match name {
            "format" | "producer" => drop(string(value)?),
            "version" => drop(integer(value)?),
            "body" => {
                regular_polygon(value, |k, v| {
                    match k {
                        "n" => f.n = integer(v)?,
                        "kappa" => f.kappa = string(v)?,
                        _ => f.gamma = string(v)?,
                    }
                    Ok(())
                })?;
            }
            "claim" => {
                let known: Vec<(&str, bool)> = Claim::ALL.iter().map(|(_, n)| (*n, true)).collect();
                f.claim = Claim::of_name(unit_variant(value, &known)?).expect("listed");
            }
            "pattern" => f.pattern = list(value)?.iter().map(integer).collect::<Checked<_>>()?,
            "set" => f.set = Some(set(value)?),
            "subdivision" => f.subdivision = integer(value)?,
            "rho" => f.rho = string(value)?,
            "lambda" => f.lambda = string(value)?,
            _ => f.period = string(value)?,
        }
        Ok(())
    })?;
    Ok(f)
}

impl OrbitFile<'_> {
    /// The body as written: (n, κ, γ).
    pub fn body(&self) -> (u64, &str, &str) {
        (self.n, self.kappa, self.gamma)
    }
}

fn all_numbers<'a>(f: &'a OrbitFile) -> Vec<&'a str> {
    let mut out = vec![f.kappa, f.gamma, f.rho, f.lambda, f.period];
    match f.set.as_ref().expect("read") {
        SetText::Parallelepiped { centre, axes, delta } => {
            out.extend(centre.iter().chain(axes.iter().flatten()).copied());
            out.push(delta);
        }
        SetText::Box { lo, hi } => out.extend(lo.iter().chain(hi).copied()),
    }
    out
}

fn out_of_range(why: String) -> Fail {
    Fail::new("orbit-out-of-range", why)
}

/// (x*, A, δ) of the set.
fn the_set(f: &OrbitFile, q: &std::sync::Arc<Field>, limits: &Limits) -> Checked<(V3, [V3; 3], Num)> {
    let three = |path: &str, t: &[&str]| -> Checked<V3> {
        let v: Vec<Num> = t.iter().map(|s| element(path, s, q, limits)).collect::<Checked<_>>()?;
        Ok([v[0].clone(), v[1].clone(), v[2].clone()])
    };
    match f.set.as_ref().expect("read") {
        SetText::Parallelepiped { centre, axes, delta } => {
            let centre = three("set.centre", centre)?;
            let cols: Vec<V3> = axes.iter().map(|a| three("set.axes", a)).collect::<Checked<_>>()?;
            let a: [V3; 3] = std::array::from_fn(|i| std::array::from_fn(|k| cols[k][i].clone()));
            let delta = element("set.delta", delta, q, limits)?;
            if !delta.is_positive() {
                return Err(Fail::new("degenerate-set", "delta must be > 0"));
            }
            Ok((centre, a, delta))
        }
        SetText::Box { lo, hi } => {
            let (lo, hi) = (three("set.lo", lo)?, three("set.hi", hi)?);
            if (0..3).any(|i| lo[i] >= hi[i]) {
                return Err(Fail::new("degenerate-set", "lo >= hi"));
            }
            let two = Num::int(q, 2);
            let centre: V3 = std::array::from_fn(|i| &(&lo[i] + &hi[i]) / &two);
            let a: [V3; 3] = std::array::from_fn(|i| {
                std::array::from_fn(|k| if i == k { &(&hi[i] - &lo[i]) / &two } else { Num::int(q, 0) })
            });
            Ok((centre, a, Num::int(q, 1)))
        }
    }
}

/// A⁻¹ by cofactors, `None` when singular.
fn inverse(a: &[V3; 3]) -> Option<[V3; 3]> {
    let c = |r: usize, k: usize| {
        let (r1, r2) = ((r + 1) % 3, (r + 2) % 3);
        let (k1, k2) = ((k + 1) % 3, (k + 2) % 3);
        &(&a[r1][k1] * &a[r2][k2]) - &(&a[r1][k2] * &a[r2][k1])
    };
    let det = &(&(&a[0][0] * &c(0, 0)) + &(&a[0][1] * &c(0, 1))) + &(&a[0][2] * &c(0, 2));
    if det.is_zero() {
        return None;
    }
    Some(std::array::from_fn(|i| std::array::from_fn(|k| &c(k, i) / &det)))
}

/// Rule O1, in the kernel's order: the exact data of the certificate.
pub fn rules(f: &OrbitFile, limits: &Limits) -> Checked<Orbit> {
    if all_numbers(f).iter().map(|s| s.len()).sum::<usize>() > limits.max_total_digits {
        return Err(Fail::new("too-large", "more characters of numbers than max-total-digits"));
    }
    let q = Field::rationals();
    let kappa = element("body.kappa", f.kappa, &q, limits)?;
    let gamma = element("body.gamma", f.gamma, &q, limits)?;
    if !(3..=MAX_N).contains(&f.n) {
        return Err(Fail::new(
            "unsupported-body",
            format!("n = {}: orbit certificates need 3 <= n <= {MAX_N}", f.n),
        ));
    }
    if !kappa.is_positive() || gamma.is_negative() || gamma > Num::int(&q, 1) {
        return Err(Fail::new("parameter-out-of-range", "kappa > 0 and 0 <= gamma <= 1"));
    }
    if f.claim != Claim::CompleteChatterFromSet {
        return Err(out_of_range(format!("{} is a cone claim", f.claim.name())));
    }
    if f.pattern.is_empty() || f.pattern.len() > 64 {
        return Err(out_of_range("a pattern has 1 to 64 steps".into()));
    }
    if let Some(j) = f.pattern.iter().find(|&&j| j == 0 || j >= f.n) {
        return Err(out_of_range(format!("step {j} is not in 1..n-1")));
    }
    let bound = |path: &str, s: &str, below_one: bool| -> Checked<Num> {
        let x = element(path, s, &q, limits)?;
        if !x.is_positive() || (below_one && x >= Num::int(&q, 1)) {
            return Err(out_of_range(format!("{path} = {s} is out of range")));
        }
        Ok(x)
    };
    let (rho, lambda, period) =
        (bound("rho", f.rho, true)?, bound("lambda", f.lambda, true)?, bound("period", f.period, false)?);
    if f.subdivision > 10 {
        return Err(Fail::new("too-large", "subdivision deeper than max-orbit-depth"));
    }
    let (centre, a, delta) = the_set(f, &q, limits)?;
    let a_inv = inverse(&a).ok_or_else(|| Fail::new("degenerate-set", "the axes are linearly dependent"))?;
    // Every number of the file is rational; the body's constants live in Q(cos 2π/n), so the
    // return map is evaluated there, exactly, with every datum lifted into that field.
    let field = Field::cos(f.n as u32);
    let to = |x: &Num| Num::rational(&field, x.as_rational().expect("rational").clone());
    let v3 = |x: &V3| -> V3 { std::array::from_fn(|i| to(&x[i])) };
    let body = Polygon::new(f.n as usize, to(&kappa), to(&gamma));
    let pattern = f.pattern.iter().map(|&j| j as i64).collect();
    Ok(Orbit {
        body,
        pattern,
        centre: v3(&centre),
        a: std::array::from_fn(|r| v3(&a[r])),
        a_inv: std::array::from_fn(|r| v3(&a_inv[r])),
        delta: to(&delta),
        rho: to(&rho),
        lambda: to(&lambda),
        period: to(&period),
    })
}

/// The largest n of a regular polygon (docs/certificate-format.md §12 and §14).
pub const MAX_N: u64 = 64;

/// Number of pseudo-random sample points, besides the 54 grid points.
pub const RANDOM_SAMPLES: usize = 40;

/// Conditions 1-3 at the sample points: the first failure found.
pub fn check(o: &Orbit) -> Checked<()> {
    for y in samples(&o.delta, RANDOM_SAMPLES) {
        o.conditions(&y).map_err(|f| {
            let at: Vec<String> = y.iter().map(element_text).collect();
            Fail { codes: f.codes, why: format!("{} at y = ({})", f.why, at.join(", ")) }
        })?;
    }
    Ok(())
}
