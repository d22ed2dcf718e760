//! Cone certificates of regular polygons, versions 1 to 3 (docs/certificate-format.md §2-§9,
//! §12): the schema, the file's rules (limits, version, numbers, body, range of γ, arity), then
//! the rod, a point, a field point or a box.

use super::limits::Limits;
use super::numbers::{denominator_bits, element};
use crate::arith::{Field, Num, Rat};
use crate::claim::Claim;
use crate::read::Value;
use crate::read::schema::{
    integer, list, optional, param, regular_polygon, string, strings, unit_variant, walk,
};
use crate::regular::boxes::{Gens, check_box};
use crate::regular::model::Polygon;
use crate::regular::rest::time_to_rest;
use crate::regular::rod::{Rod, check_rod};
use crate::regular::rules::check_point;
use crate::verdict::{Checked, Fail, Kind, Report};

/// A cone certificate as read.
pub struct ConeFile<'a> {
    version: u64,
    n: u64,
    kappa: Vec<&'a str>,
    gamma: Vec<&'a str>,
    claim: Claim,
    cone: Vec<Vec<&'a str>>,
    /// The optional `time_to_rest_bound` B as written (rule T1).
    bound: Option<&'a str>,
}

fn claim_of(v: &Value) -> Checked<Claim> {
    let known: Vec<(&str, bool)> = Claim::ALL.iter().map(|(_, n)| (*n, true)).collect();
    Ok(Claim::of_name(unit_variant(v, &known)?).expect("listed"))
}

/// The schema of §2.
pub fn read(v: &Value) -> Checked<ConeFile<'_>> {
    let mut f = ConeFile {
        version: 0,
        n: 0,
        kappa: vec![],
        gamma: vec![],
        claim: Claim::EffectivelyInvariant,
        cone: vec![],
        bound: None,
    };
    let fields = [
        ("format", true),
        ("version", true),
        ("body", true),
        ("coordinates", true),
        ("claim", true),
        ("cone", true),
        ("time_to_rest_bound", false),
        ("producer", false),
    ];
    walk(v, &fields, |name, value| {
        match name {
            "format" | "producer" => drop(string(value)?),
            "version" => f.version = integer(value)?,
            "body" => body(value, &mut f)?,
            "coordinates" => drop(unit_variant(value, &[("ContactVelocities", true)])?),
            "claim" => f.claim = claim_of(value)?,
            "time_to_rest_bound" => f.bound = optional(value)?.map(string).transpose()?,
            _ => f.cone = list(value)?.iter().map(strings).collect::<Checked<_>>()?,
        }
        Ok(())
    })?;
    Ok(f)
}

fn body<'a>(value: &'a Value, f: &mut ConeFile<'a>) -> Checked<()> {
    regular_polygon(value, |name, v| {
        match name {
            "n" => f.n = integer(v)?,
            "kappa" => f.kappa = param(v)?,
            _ => f.gamma = param(v)?,
        }
        Ok(())
    })
}

/// The limits on the whole file: generators, then the characters of all numbers.
fn size(f: &ConeFile, limits: &Limits) -> Checked<()> {
    if f.cone.len() > limits.max_generators {
        return Err(Fail::new("too-large", "more generators than max-generators"));
    }
    let chars: usize = f.kappa.iter().chain(&f.gamma).chain(f.cone.iter().flatten()).map(|s| s.len()).sum();
    if chars > limits.max_total_digits {
        return Err(Fail::new("too-large", "more characters of numbers than max-total-digits"));
    }
    Ok(())
}

/// The body's range: κ > 0, 0 ≤ γ ≤ 1 over the box; lo ≤ hi; the claims about drops need
/// 0 < γ < 1.
fn ranges(k: &[Num; 2], g: &[Num; 2], claim: Claim) -> Checked<()> {
    let out = |what: &str| Err(Fail::new("parameter-out-of-range", what.to_string()));
    if k[0] > k[1] || g[0] > g[1] {
        return out("an empty interval");
    }
    let one = Num::int(&k[0].field, 1);
    if !k[0].is_positive() {
        return out("kappa must be > 0");
    }
    if g[0].is_negative() || g[1] > one {
        return out("gamma must lie in [0, 1]");
    }
    if claim.about_drops() && (g[0].is_zero() || g[1] == one) {
        return out("the claims about drops need 0 < gamma < 1");
    }
    Ok(())
}

fn bounds(path: &str, texts: &[&str], field: &std::sync::Arc<Field>, limits: &Limits) -> Checked<[Num; 2]> {
    let lo = element(&format!("{path}[0]"), texts[0], field, limits)?;
    let hi = element(&format!("{path}[1]"), texts[texts.len() - 1], field, limits)?;
    Ok([lo, hi])
}

/// The generators: arity, then numbers, one generator after the other.
fn generators(
    f: &ConeFile,
    arity: usize,
    field: &std::sync::Arc<Field>,
    limits: &Limits,
) -> Checked<Vec<Vec<Num>>> {
    let mut out = vec![];
    for (i, g) in f.cone.iter().enumerate() {
        if g.len() != arity {
            return Err(Fail::new("wrong-arity", format!("cone[{i}] has {} coordinates", g.len())));
        }
        out.push(g.iter().map(|s| element(&format!("cone[{i}]"), s, field, limits)).collect::<Checked<_>>()?);
    }
    Ok(out)
}

/// A cone certificate after the file's rules: the model(s) and the generators.
pub enum Parts {
    /// A regular polygon at one point (rational or field).
    Point(Polygon, Vec<[Num; 3]>),
    /// The rod at one point.
    Rod(Rod, Vec<[Rat; 2]>),
    /// A box of a regular polygon (n ≥ 3) or of the rod (n = 2, generators (u0, u1, 0) unused).
    Box(usize, [Rat; 2], [Rat; 2], Vec<[Num; 3]>, Vec<[Rat; 2]>),
}

/// The file's rules (limits, version, numbers, body, range of γ, arity), in the kernel's order.
pub fn prepare(f: &ConeFile, limits: &Limits) -> Checked<(Parts, u64)> {
    claim_is_cone(f)?;
    size(f, limits)?;
    let interval = f.kappa.len() == 2 || f.gamma.len() == 2;
    if f.bound.is_some() && (f.n != 2 || interval) {
        return Err(Fail::new(
            "time-to-rest-not-shown",
            "time_to_rest_bound: rule T1 covers the rod at a point only (docs/time-to-rest.md §2)",
        ));
    }
    if f.n >= 5 && f.n != 6 {
        return prepare_field(f, interval, limits);
    }
    if interval && f.version < 2 {
        return Err(Fail::new("unsupported-version", "parameter intervals need version 2"));
    }
    let q = Field::rationals();
    let (k, g) = (bounds("body.kappa", &f.kappa, &q, limits)?, bounds("body.gamma", &f.gamma, &q, limits)?);
    if f.n < 2 {
        return Err(Fail::new("unsupported-body", format!("n = {}", f.n)));
    }
    ranges(&k, &g, f.claim)?;
    let gens = generators(f, if f.n == 2 { 2 } else { 3 }, &q, limits)?;
    let bits = denominator_bits(gens.iter().flatten());
    let rat = |x: &Num| x.as_rational().expect("rational").clone();
    let (kr, gr): ([Rat; 2], [Rat; 2]) = ([rat(&k[0]), rat(&k[1])], [rat(&g[0]), rat(&g[1])]);
    let rod_gens: Vec<[Rat; 2]> =
        if f.n == 2 { gens.iter().map(|g| [rat(&g[0]), rat(&g[1])]).collect() } else { vec![] };
    let field = Field::cos(f.n as u32);
    let lift = |g: &Vec<Num>| -> [Num; 3] { std::array::from_fn(|i| Num::rational(&field, rat(&g[i]))) };
    let poly_gens: Vec<[Num; 3]> = if f.n == 2 { vec![] } else { gens.iter().map(lift).collect() };
    let parts = match (interval, f.n) {
        (true, n) => Parts::Box(n as usize, kr, gr, poly_gens, rod_gens),
        (false, 2) => Parts::Rod(Rod { kappa: kr[0].clone(), gamma: gr[0].clone() }, rod_gens),
        (false, n) => {
            let b = Polygon::new(
                n as usize,
                Num::rational(&field, kr[0].clone()),
                Num::rational(&field, gr[0].clone()),
            );
            Parts::Point(b, poly_gens)
        }
    };
    Ok((parts, bits))
}

/// Every rule of a cone certificate after its schema.
pub fn check(f: &ConeFile, limits: &Limits) -> Checked<(Kind, Report)> {
    checked(f, limits).map(|(kind, report, _)| (kind, report))
}

/// Every rule of a cone certificate after its schema, with B of rule T1 (canonical text) when the
/// file carries one and it is shown.
pub fn checked(f: &ConeFile, limits: &Limits) -> Checked<(Kind, Report, Option<String>)> {
    let (parts, bits) = prepare(f, limits)?;
    match parts {
        Parts::Point(b, gens) => Ok((Kind::Cone, check_point(&b, f.claim, &gens, bits)?, None)),
        Parts::Rod(rod, gens) => {
            let report = check_rod(&rod, f.claim, &gens, bits)?;
            let bound = f.bound.map(|b| time_to_rest(&rod, f.claim, b, limits)).transpose()?;
            Ok((Kind::Rod, report, bound))
        }
        Parts::Box(2, k, g, _, gens) => {
            Ok((Kind::Box, check_box(2, &k, &g, f.claim, &Gens::Rod(&gens), bits)?, None))
        }
        Parts::Box(n, k, g, gens, _) => {
            Ok((Kind::Box, check_box(n, &k, &g, f.claim, &Gens::Polygon(&gens), bits)?, None))
        }
    }
}

/// The claim of a file.
pub fn claim(f: &ConeFile) -> Claim {
    f.claim
}

/// The text of the file's `time_to_rest_bound`, when it carries one.
pub fn bound<'a>(f: &ConeFile<'a>) -> Option<&'a str> {
    f.bound
}

/// n = 5 and 7..64: Q(cos 2π/n) (§12).
fn prepare_field(f: &ConeFile, interval: bool, limits: &Limits) -> Checked<(Parts, u64)> {
    if f.n > 64 {
        return Err(Fail::new("unsupported-body", format!("n = {}", f.n)));
    }
    if interval {
        return Err(Fail::new("unsupported-body", "boxes need a rational cos 2π/n"));
    }
    let texts = f.kappa.iter().chain(&f.gamma).chain(f.cone.iter().flatten());
    if f.version < 3 && texts.clone().any(|t| t.contains('c')) {
        return Err(Fail::new("unsupported-version", "field elements need version 3"));
    }
    let field = Field::cos(f.n as u32);
    let kappa = element("body.kappa", f.kappa[0], &field, limits)?;
    let gamma = element("body.gamma", f.gamma[0], &field, limits)?;
    ranges(&[kappa.clone(), kappa.clone()], &[gamma.clone(), gamma.clone()], f.claim)?;
    let gens = generators(f, 3, &field, limits)?;
    let bits = denominator_bits(gens.iter().flatten());
    let gens: Vec<[Num; 3]> = gens.into_iter().map(|g| [g[0].clone(), g[1].clone(), g[2].clone()]).collect();
    Ok((Parts::Point(Polygon::new(f.n as usize, kappa, gamma), gens), bits))
}

/// Whether the claim is a cone claim (an orbit claim in a cone certificate is refused).
pub fn claim_is_cone(f: &ConeFile) -> Checked<()> {
    if f.claim == Claim::CompleteChatterFromSet {
        return Err(Fail::new("unknown-variant", "CompleteChatterFromSet is an orbit claim"));
    }
    Ok(())
}
