//! Family certificates of general convex bodies (docs/certificate-format.md §13): version 1 (the
//! legacy header's version 4) at one γ; version 2 also over a closed interval of γ, written
//! `gamma: ["1/100", "1/50"]` (RON) or `"gamma": ["1/100", "1/50"]` (JSON). The file's rules, in
//! the kernel's order: the claim, at most 64 contacts and cones, the limits; then γ (an interval
//! needs version 2, its ends are canonical numbers, lo ≤ hi); then, at each distinct end in turn
//! (γ_lo, then γ_hi), the body with that γ, K0 (at the first end only) and the range of γ for the
//! claims about drops; then, at each end in turn, the count, the cones' numbers and K1, and K2-K4
//! (why the ends suffice: [`crate::convex::rules`]); a failure of K2-K4 at an end of an interval
//! names the end.

use super::limits::Limits;
use super::numbers::{denominator_bits, element};
use crate::arith::{Field, Num};
use crate::claim::Claim;
use crate::convex::model::{Body, BodyFault};
use crate::convex::rules::{Family, all_down, at_end, check_family, interior, pcc_excluded, transitions};
use crate::read::Value;
use crate::read::schema::{integer, list, optional, param, string, strings, unit_variant, variant, walk};
use crate::regular::rules::cone_polygon;
use crate::verdict::{Checked, Fail, Report};

/// The version whose γ may be an interval.
pub const INTERVALS: u64 = 2;

/// The most contacts of a body, and cones of a family (§13).
const MAX_CONTACTS: usize = 64;

/// The body `ConvexPolygon(...)` as written (§13; also the body of a general body's time-to-rest
/// certificate, §17).
#[derive(Default)]
pub struct BodyText<'a> {
    /// The contacts r_k, two numbers each.
    pub contacts: Vec<Vec<&'a str>>,
    /// J as (Jxx, Jxy, Jyy).
    pub inertia: Vec<&'a str>,
    /// The optional full inertia tensor (Ixx, Ixy, Ixz, Iyy, Iyz, Izz) as written (rule K0).
    pub tensor: Option<Vec<&'a str>>,
    /// γ as written: one number, or the two ends of an interval.
    pub gamma: Vec<&'a str>,
}

impl<'a> BodyText<'a> {
    /// Every number of the body as text, for `max-total-digits`.
    pub fn numbers(&self) -> impl Iterator<Item = &&'a str> {
        let contacts = self.contacts.iter().flatten();
        contacts.chain(&self.inertia).chain(&self.gamma).chain(self.tensor.iter().flatten())
    }
}

/// A family certificate as read.
pub struct FamilyFile<'a> {
    /// 1 or 2 (4 with the legacy header).
    version: u64,
    body: BodyText<'a>,
    claim: Claim,
    cones: Vec<Vec<Vec<&'a str>>>,
}

impl FamilyFile<'_> {
    /// [γ_lo, γ_hi] as written when γ is an interval (an accepted file's numbers are canonical):
    /// what the report gives as `gamma_interval`.
    pub fn gamma_interval(&self) -> Option<[String; 2]> {
        match self.body.gamma[..] {
            [lo, hi] => Some([lo.to_string(), hi.to_string()]),
            _ => None,
        }
    }
}

/// A value of γ at which the rules are checked: the file's one γ, or an end of its interval
/// (also of a general body's time-to-rest certificate, §17 version 2).
pub struct End {
    /// The value.
    pub gamma: Num,
    /// The path of its number: `body.gamma`, `body.gamma[0]` or `body.gamma[1]`.
    pub path: &'static str,
    /// Whether it is an end of an interval (failures of K2-K4 there name it).
    pub of_interval: bool,
}

impl End {
    /// A failure at this value of γ of a rule about the field `path`.
    pub fn field(&self, code: &'static str, why: &str) -> Fail {
        Fail::new(code, format!("field `{}`: {why}", self.path))
    }

    /// A failure of K2-K4 at this value: at an end of an interval, its reason names the end.
    pub fn content(&self, f: Fail) -> Fail {
        if self.of_interval { at_end(&self.gamma, f) } else { f }
    }
}

/// A tuple of exactly `n` strings (a contact, the inertia, the tensor): another length is a
/// `syntax` error of the reading, before any rule (unlike a generator's arity, `wrong-arity`).
fn exactly<'a>(v: &'a Value, n: usize, what: &str) -> Checked<Vec<&'a str>> {
    let xs = strings(v)?;
    if xs.len() != n {
        return Err(Fail::new("syntax", format!("{what} has {n} numbers, not {}", xs.len())));
    }
    Ok(xs)
}

/// The body `ConvexPolygon(contacts, inertia, gamma, inertia_tensor)` of §13 as written.
pub fn body_text(value: &Value) -> Checked<BodyText<'_>> {
    let mut f = BodyText::default();
    let (name, fields) = variant(value)?;
    if name != "ConvexPolygon" {
        return Err(Fail::new("unknown-variant", format!("unknown body `{name}`")));
    }
    let fields = fields.ok_or_else(|| Fail::new("syntax", "ConvexPolygon needs its fields"))?;
    let known = [("contacts", true), ("inertia", true), ("gamma", true), ("inertia_tensor", false)];
    walk(fields, &known, |name, v| {
        match name {
            "contacts" => {
                f.contacts = list(v)?.iter().map(|c| exactly(c, 2, "a contact")).collect::<Checked<_>>()?
            }
            "inertia" => f.inertia = exactly(v, 3, "the inertia")?,
            "inertia_tensor" => {
                f.tensor = optional(v)?.map(|t| exactly(t, 6, "the inertia tensor")).transpose()?
            }
            _ => f.gamma = param(v)?,
        }
        Ok(())
    })?;
    Ok(f)
}

/// The schema of §13.
pub fn read(v: &Value) -> Checked<FamilyFile<'_>> {
    let mut f = FamilyFile {
        version: 0,
        body: BodyText::default(),
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
            "version" => f.version = integer(value)?,
            "body" => f.body = body_text(value)?,
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

/// The file's rules before γ: the claim, at most 64 contacts, max-generators per cone, at most
/// 64 cones, max-total-digits (the kernel's order).
fn file_rules(f: &FamilyFile, limits: &Limits) -> Checked<()> {
    if f.claim == Claim::CompleteChatterFromSet {
        return Err(Fail::new("unknown-variant", "CompleteChatterFromSet is an orbit claim"));
    }
    contact_count(&f.body)?;
    if f.cones.iter().any(|c| c.len() > limits.max_generators) {
        return Err(Fail::new("too-large", "a cone with more generators than max-generators"));
    }
    if f.cones.len() > MAX_CONTACTS {
        let why = format!("field `cones`: {} cones, at most {MAX_CONTACTS}", f.cones.len());
        return Err(Fail::new("wrong-arity", why));
    }
    let chars: usize = f.body.numbers().chain(f.cones.iter().flatten().flatten()).map(|s| s.len()).sum();
    if chars > limits.max_total_digits {
        return Err(Fail::new("too-large", "more characters of numbers than max-total-digits"));
    }
    Ok(())
}

/// The values of γ to check: the one γ; or, for an interval (version 2 only), its ends as
/// canonical numbers with lo ≤ hi, each distinct end once.
fn ends(f: &FamilyFile, limits: &Limits) -> Checked<Vec<End>> {
    gamma_ends(&f.body.gamma, f.version, limits)
}

/// The values of γ written `gamma` in a file of version `version`: the one γ; or, for an
/// interval (version 2 only, else `unsupported-version`), its ends as canonical numbers with
/// lo ≤ hi (`parameter-out-of-range`), each distinct end once. Family certificates (§13) and
/// general bodies' time-to-rest certificates (§17) alike.
pub fn gamma_ends(gamma: &[&str], version: u64, limits: &Limits) -> Checked<Vec<End>> {
    let q = Field::rationals();
    let [lo, hi] = match gamma[..] {
        [g] => {
            let gamma = element("body.gamma", g, &q, limits)?;
            return Ok(vec![End { gamma, path: "body.gamma", of_interval: false }]);
        }
        [lo, hi] => [lo, hi],
        _ => return Err(Fail::new("syntax", "gamma is a number or an interval [lo, hi]")),
    };
    if version != INTERVALS {
        let why = format!("field `version`: an interval of gamma needs version {INTERVALS}, not {version}");
        return Err(Fail::new("unsupported-version", why));
    }
    let lo =
        End { gamma: element("body.gamma[0]", lo, &q, limits)?, path: "body.gamma[0]", of_interval: true };
    let hi =
        End { gamma: element("body.gamma[1]", hi, &q, limits)?, path: "body.gamma[1]", of_interval: true };
    if lo.gamma > hi.gamma {
        let why = format!("field `body.gamma`: the interval [{}, {}] is empty", gamma[0], gamma[1]);
        return Err(Fail::new("parameter-out-of-range", why));
    }
    Ok(if lo.gamma == hi.gamma { vec![lo] } else { vec![lo, hi] })
}

/// At most 64 contacts (`unsupported-body`), a rule of the file before any number.
pub fn contact_count(t: &BodyText) -> Checked<()> {
    if t.contacts.len() > MAX_CONTACTS {
        let why = format!("field `body.contacts`: {} contacts, at most {MAX_CONTACTS}", t.contacts.len());
        return Err(Fail::new("unsupported-body", why));
    }
    Ok(())
}

/// The body at the value `end` of γ; rule K0 with it when `first`.
fn the_body(f: &FamilyFile, end: &End, first: bool, limits: &Limits) -> Checked<Body> {
    convex_body(&f.body, (&end.gamma, end.path), first, limits)
}

/// The body of `t` at γ (read from the field `path`): its numbers, (A1), (A2), J positive
/// definite, 0 ≤ γ ≤ 1, and rule K0 when `tensor` (and the file has one).
pub fn convex_body(
    t: &BodyText,
    (gamma, path): (&Num, &str),
    tensor: bool,
    limits: &Limits,
) -> Checked<Body> {
    let q = Field::rationals();
    let mut contacts = vec![];
    // The arities of the contacts, the inertia and the tensor were read ([`exactly`]).
    for (k, c) in t.contacts.iter().enumerate() {
        let path = format!("body.contacts[{k}]");
        contacts.push((element(&path, c[0], &q, limits)?, element(&path, c[1], &q, limits)?));
    }
    let j: Vec<Num> =
        t.inertia.iter().map(|s| element("body.inertia", s, &q, limits)).collect::<Checked<_>>()?;
    let body = Body::new(contacts, [j[0].clone(), j[1].clone(), j[2].clone()], gamma.clone()).map_err(
        |e| match e {
            BodyFault::Gamma => {
                Fail::new("parameter-out-of-range", format!("field `{path}`: gamma must lie in [0, 1]"))
            }
            BodyFault::Inertia => Fail {
                codes: vec!["unsupported-body", "parameter-out-of-range"],
                why: "J is not positive definite".into(),
            },
            other => Fail::new("unsupported-body", format!("{other:?}")),
        },
    )?;
    if let Some(t) = &t.tensor
        && tensor
    {
        effective_inertia(t, &j, limits)?;
    }
    Ok(body)
}

/// Rule K0 read from docs/model.md Proposition 11.0: the tensor [[A, b], [bᵀ, c]] (A the
/// horizontal block, b = (Ixz, Iyz), c = Izz) has c > 0 and A - b bᵀ / c equal to J, entry by
/// entry (J = (Jxx, Jxy, Jyy)).
fn effective_inertia(t: &[&str], j: &[Num], limits: &Limits) -> Checked<()> {
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

/// Every content rule evaluated on its own (K1 alone if it fails; then K2, K3, K4 at each end of
/// an interval of γ), each code once, for [`crate::isolate`]. A file failing before the content
/// rules at the first end gives that rule's codes; at the second end, they join those of the
/// first.
pub fn every_failure(v: &Value) -> Checked<Vec<&'static str>> {
    let f = read(v)?;
    let limits = Limits::default();
    file_rules(&f, &limits)?;
    let mut out = vec![];
    let mut bodies = vec![];
    for (i, end) in ends(&f, &limits)?.iter().enumerate() {
        match at(&f, end, i == 0, &limits) {
            Ok(b) => bodies.push(b),
            Err(e) if i == 0 => return Err(e),
            Err(e) => out.extend(e.codes),
        }
    }
    let mut family = None;
    for b in bodies {
        if family.is_none() {
            family = Some(cones(&f, &b, &limits)?.0);
        }
        let family = family.as_ref().expect("read at the first end");
        if let Err(e) = transitions(&b, family) {
            out.extend(e.codes);
        }
        if f.claim >= Claim::CcOrPccFromAllDown && all_down(&b, &family.ks).is_err() {
            out.push("initial-outside");
        }
        if f.claim >= Claim::CompleteChatterFromAllDown && !(0..b.n() as i64).all(|k| pcc_excluded(&b, k)) {
            out.push("pcc-not-excluded");
        }
    }
    let mut once = vec![];
    for c in out {
        if !once.contains(&c) {
            once.push(c);
        }
    }
    Ok(once)
}

/// Every rule of a family certificate after its schema: at one γ, or at the ends of an interval
/// of γ (then tested at interior values); the report is the first end's, with
/// `contains_translation` at every end (I_i(0, 0, -1) is affine in γ, K_i convex: then on the
/// whole interval).
pub fn check(f: &FamilyFile, limits: &Limits) -> Checked<Report> {
    file_rules(f, limits)?;
    let ends = ends(f, limits)?;
    // The bodies and the range of γ at every end first, then the rules of the cones at each.
    let bodies =
        ends.iter().enumerate().map(|(i, end)| at(f, end, i == 0, limits)).collect::<Checked<Vec<_>>>()?;
    let mut reports: Vec<Report> = vec![];
    let mut family = None;
    for (i, (end, b)) in ends.iter().zip(bodies).enumerate() {
        if family.is_none() {
            family = Some(cones(f, &b, limits)?);
        }
        let (family, bits) = family.as_ref().expect("read at the first end");
        reports.push(check_family(&b, f.claim, family, *bits).map_err(|e| end.content(e))?);
        if let [lo, hi] = &ends[..]
            && i == 1
        {
            interior(&b, f.claim, family, &lo.gamma, &hi.gamma)?;
        }
    }
    let translation = reports.iter().all(|r| r.contains_translation == Some(true));
    let mut report = reports.swap_remove(0);
    report.contains_translation = Some(translation);
    Ok(report)
}

/// The rules at one value of γ before the cones: the body, K0 (at the `first` value), the range
/// of γ for the claims about drops.
fn at(f: &FamilyFile, end: &End, first: bool, limits: &Limits) -> Checked<Body> {
    let b = the_body(f, end, first, limits)?;
    let one = Num::int(&b.gamma.field, 1);
    if f.claim.about_drops() && (b.gamma.is_zero() || b.gamma == one) {
        return Err(end.field("parameter-out-of-range", "the claims about drops need 0 < gamma < 1"));
    }
    Ok(b)
}

/// The rules of the cones, which do not depend on γ (read once, at the first value of γ): the
/// count, the cones' numbers with K1 of each; the family's geometry for the body's contacts and
/// the largest denominator.
fn cones(f: &FamilyFile, b: &Body, limits: &Limits) -> Checked<(Family, u64)> {
    if f.cones.len() != b.n() {
        return Err(Fail::new("wrong-arity", "one cone per contact"));
    }
    let q = Field::rationals();
    let (mut cones, mut ks) = (vec![], vec![]);
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
        ks.push(cone_polygon(&gens).map_err(|e| Fail { codes: e.codes, why: format!("K_{i}: {}", e.why) })?);
        cones.push(gens);
    }
    let bits = denominator_bits(cones.iter().flatten().flatten());
    Ok((Family::new(b, &cones, ks), bits))
}
