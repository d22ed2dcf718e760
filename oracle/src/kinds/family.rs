//! Family certificates of general convex bodies, version 4 (docs/certificate-format.md §13).

use super::limits::Limits;
use super::numbers::{denominator_bits, element};
use crate::arith::{Field, Num};
use crate::claim::Claim;
use crate::convex::model::{Body, BodyFault};
use crate::convex::rules::check_family;
use crate::read::Value;
use crate::read::schema::{integer, list, optional, string, strings, unit_variant, variant, walk};
use crate::verdict::{Checked, Fail, Report};

/// The generators of every cone of a family.
type Cones = Vec<Vec<[Num; 3]>>;

/// A version-4 certificate as read.
pub struct FamilyFile<'a> {
    contacts: Vec<Vec<&'a str>>,
    inertia: Vec<&'a str>,
    /// The optional full inertia tensor (Ixx, Ixy, Ixz, Iyy, Iyz, Izz) as written (rule K0).
    tensor: Option<Vec<&'a str>>,
    gamma: &'a str,
    claim: Claim,
    cones: Vec<Vec<Vec<&'a str>>>,
}

fn body<'a>(value: &'a Value, f: &mut FamilyFile<'a>) -> Checked<()> {
    let (name, fields) = variant(value)?;
    if name != "ConvexPolygon" {
        return Err(Fail::new("unknown-variant", format!("unknown body `{name}`")));
    }
    let fields = fields.ok_or_else(|| Fail::new("syntax", "ConvexPolygon needs its fields"))?;
    let known = [("contacts", true), ("inertia", true), ("gamma", true), ("inertia_tensor", false)];
    walk(fields, &known, |name, v| {
        match name {
            "contacts" => f.contacts = list(v)?.iter().map(strings).collect::<Checked<_>>()?,
            "inertia" => f.inertia = strings(v)?,
            "inertia_tensor" => f.tensor = optional(v)?.map(strings).transpose()?,
            _ => f.gamma = string(v)?,
        }
        Ok(())
    })
}

/// The schema of §13.
pub fn read(v: &Value) -> Checked<FamilyFile<'_>> {
    let mut f = FamilyFile {
        contacts: vec![],
        inertia: vec![],
        tensor: None,
        gamma: "",
        claim: Claim::EffectivelyInvariant,
        cones: vec![],
    };
    let fields = [
        ("format", true),
        ("version", true),
        ("body", true),
        ("coordinates", true),
        ("claim", true),
        ("cones", true),
        ("producer", false),
    ];
    walk(v, &fields, |name, value| {
        match name {
            "format" | "producer" => drop(string(value)?),
            "version" => drop(integer(value)?),
            "body" => body(value, &mut f)?,
            "coordinates" => drop(unit_variant(value, &[("PaperVelocities", true)])?),
            "claim" => {
                let known: Vec<(&str, bool)> = Claim::ALL.iter().map(|(_, n)| (*n, true)).collect();
                f.claim = Claim::of_name(unit_variant(value, &known)?).expect("listed");
            }
            _ => {
                f.cones = list(value)?
                    .iter()
                    .map(|c| list(c)?.iter().map(strings).collect::<Checked<Vec<_>>>())
                    .collect::<Checked<_>>()?
            }
        }
        Ok(())
    })?;
    Ok(f)
}

fn size(f: &FamilyFile, limits: &Limits) -> Checked<()> {
    if f.cones.iter().any(|c| c.len() > limits.max_generators) {
        return Err(Fail::new("too-large", "a cone with more generators than max-generators"));
    }
    let numbers =
        f.contacts.iter().flatten().chain(&f.inertia).chain([&f.gamma]).chain(f.tensor.iter().flatten());
    let chars: usize = numbers.chain(f.cones.iter().flatten().flatten()).map(|s| s.len()).sum();
    if chars > limits.max_total_digits {
        return Err(Fail::new("too-large", "more characters of numbers than max-total-digits"));
    }
    Ok(())
}

fn the_body(f: &FamilyFile, limits: &Limits) -> Checked<Body> {
    let q = Field::rationals();
    let mut contacts = vec![];
    for (k, c) in f.contacts.iter().enumerate() {
        if c.len() != 2 {
            return Err(Fail::new("wrong-arity", format!("contact {k} needs two coordinates")));
        }
        let path = format!("body.contacts[{k}]");
        contacts.push((element(&path, c[0], &q, limits)?, element(&path, c[1], &q, limits)?));
    }
    if f.inertia.len() != 3 {
        return Err(Fail::new("wrong-arity", "the inertia is (Jxx, Jxy, Jyy)"));
    }
    let j: Vec<Num> =
        f.inertia.iter().map(|s| element("body.inertia", s, &q, limits)).collect::<Checked<_>>()?;
    let gamma = element("body.gamma", f.gamma, &q, limits)?;
    let body =
        Body::new(contacts, [j[0].clone(), j[1].clone(), j[2].clone()], gamma).map_err(|e| match e {
            BodyFault::Gamma => Fail::new("parameter-out-of-range", "gamma must lie in [0, 1]"),
            BodyFault::Inertia => Fail {
                codes: vec!["unsupported-body", "parameter-out-of-range"],
                why: "J is not positive definite".into(),
            },
            other => Fail::new("unsupported-body", format!("{other:?}")),
        })?;
    if let Some(t) = &f.tensor {
        effective_inertia(t, &j, limits)?;
    }
    Ok(body)
}

/// Rule K0 read from docs/model.md Proposition 11.0: the tensor [[A, b], [bᵀ, c]] (A the
/// horizontal block, b = (Ixz, Iyz), c = Izz) has c > 0 and A - b bᵀ / c equal to J, entry by
/// entry (J = (Jxx, Jxy, Jyy)).
fn effective_inertia(t: &[&str], j: &[Num], limits: &Limits) -> Checked<()> {
    if t.len() != 6 {
        return Err(Fail::new("syntax", "the inertia tensor has six numbers"));
    }
    let q = Field::rationals();
    let i: Vec<Num> =
        t.iter().map(|s| element("body.inertia_tensor", s, &q, limits)).collect::<Checked<_>>()?;
    let (a, b, c) = ([[&i[0], &i[1]], [&i[1], &i[3]]], [&i[2], &i[4]], &i[5]);
    if !c.is_positive() {
        return Err(Fail::new("inertia-not-derived", "Izz <= 0"));
    }
    for (k, (r, s)) in [(0, 0), (0, 1), (1, 1)].into_iter().enumerate() {
        let schur = a[r][s] - &(&(b[r] * b[s]) / c);
        if schur != j[k] {
            return Err(Fail::new("inertia-not-derived", format!("J entry {k} is not J_eff's")));
        }
    }
    Ok(())
}

/// Every content rule evaluated on its own (K1 alone if it fails; then K2, K3, K4), for
/// [`crate::isolate`].
pub fn every_failure(v: &Value) -> Checked<Vec<&'static str>> {
    let f = read(v)?;
    let (b, cones, _) = prepare(&f, &Limits::default())?;
    let ks = crate::convex::rules::polygons(&cones)?;
    let mut out = vec![];
    if let Err(e) = crate::convex::rules::transitions(&b, &ks) {
        out.extend(e.codes);
    }
    if f.claim >= Claim::CcOrPccFromAllDown && crate::convex::rules::all_down(&b, &ks).is_err() {
        out.push("initial-outside");
    }
    let pcc = |k: i64| crate::regular::pcc::quadratic_factor(&b.pair_matrix(k)).excludes_pcc();
    if f.claim >= Claim::CompleteChatterFromAllDown && !(0..b.n() as i64).all(pcc) {
        out.push("pcc-not-excluded");
    }
    Ok(out)
}

/// Every rule of a version-4 certificate after its schema.
pub fn check(f: &FamilyFile, limits: &Limits) -> Checked<Report> {
    let (b, cones, bits) = prepare(f, limits)?;
    check_family(&b, f.claim, &cones, bits)
}

/// The file's rules of a version-4 certificate: the body, the range of γ, the cones' numbers.
fn prepare(f: &FamilyFile, limits: &Limits) -> Checked<(Body, Cones, u64)> {
    if f.claim == Claim::CompleteChatterFromSet {
        return Err(Fail::new("unknown-variant", "CompleteChatterFromSet is an orbit claim"));
    }
    size(f, limits)?;
    let b = the_body(f, limits)?;
    let one = Num::int(&b.gamma.field, 1);
    if f.claim.about_drops() && (b.gamma.is_zero() || b.gamma == one) {
        return Err(Fail::new("parameter-out-of-range", "the claims about drops need 0 < gamma < 1"));
    }
    if f.cones.len() != b.n() {
        return Err(Fail::new("wrong-arity", "one cone per contact"));
    }
    let q = Field::rationals();
    let mut cones = vec![];
    for (i, c) in f.cones.iter().enumerate() {
        let mut gens = vec![];
        for (g, x) in c.iter().enumerate() {
            if x.len() != 3 {
                return Err(Fail::new("wrong-arity", format!("cones[{i}][{g}] needs three coordinates")));
            }
            let path = format!("cones[{i}][{g}]");
            let v: Vec<Num> = x.iter().map(|s| element(&path, s, &q, limits)).collect::<Checked<_>>()?;
            gens.push([v[0].clone(), v[1].clone(), v[2].clone()]);
        }
        // K1 of each cone right after its numbers, before the next cone's (the kernel's order;
        // §13 does not order the numbers of later cones against K1 of earlier ones).
        crate::regular::rules::cone_polygon(&gens)?;
        cones.push(gens);
    }
    let bits = denominator_bits(cones.iter().flatten().flatten());
    Ok((b, cones, bits))
}
