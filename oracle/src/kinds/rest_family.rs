//! Time-to-rest certificates of a general convex body (docs/certificate-format.md §17, format
//! `chatter-family-time-to-rest`, versions 1 and 2; docs/time-to-rest.md §5): the body of a
//! family certificate at one γ (version 2: also over an interval [γ_lo, γ_hi], written as family
//! certificates of version 2 write it), one entry node per contact, and a virtual-time graph
//! whose nodes carry the contact of the last impact. The rules, in the kernel's order (the
//! documents leave the order open): the claim, at most 64 contacts, the limits; γ (an interval
//! needs version 2, canonical ends, lo ≤ hi: the family certificates' code,
//! [`super::family::gamma_ends`]); the body at each value of γ in turn (the family certificates'
//! body rules, K0 at the first, 0 < γ < 1); the entries; node after node its contact, its cone's
//! numbers and R1, b_r, a_r, then G1, G2 and F (none depends on γ); B; then at each value of γ in
//! turn G3 on every node, G4 and G5 contact after contact, K4 for `CompleteChatterFromAllDown`
//! ([`crate::convex::virtual_time`], which also says why the ends of an interval suffice; a
//! failure at an end names it); over an interval, the same rules at interior values of γ.

use super::family::{BodyText, End, body_text, contact_count, convex_body, gamma_ends};
use super::limits::Limits;
use super::numbers::rational;
use super::rest::{successor, triple};
use crate::arith::rational::rational_text;
use crate::arith::{Field, Num, Rat};
use crate::claim::Claim;
use crate::convex::model::Body;
use crate::convex::virtual_time::{ContactGraph, at_gamma, heights, interior};
use crate::read::Value;
use crate::read::schema::{integer, list, string, strings, unit_variant, walk};
use crate::regular::rules::{Polygon2, cone_polygon};
use crate::regular::virtual_time::{Node, node_forms};
use crate::verdict::{Checked, Fail, Report};
use std::sync::Arc;

/// A node as read: the contact of its last impact, its cone's generators, b_r, a_r and its
/// successors (j, s).
struct NodeText<'a> {
    contact: u64,
    cone: Vec<Vec<&'a str>>,
    weight: Vec<&'a str>,
    numerator: Vec<&'a str>,
    next: Vec<(u64, u64)>,
}

/// A general body's time-to-rest certificate as read.
pub struct RestFamilyFile<'a> {
    /// 1, or 2 (γ may be an interval).
    version: u64,
    body: BodyText<'a>,
    claim: Claim,
    bound: &'a str,
    entries: Vec<u64>,
    nodes: Vec<NodeText<'a>>,
}

/// One node of §17 ("Fields"): every field required.
fn node(v: &Value) -> Checked<NodeText<'_>> {
    let mut t = NodeText { contact: 0, cone: vec![], weight: vec![], numerator: vec![], next: vec![] };
    let fields = [("contact", true), ("cone", true), ("weight", true), ("numerator", true), ("next", true)];
    walk(v, &fields, |name, value| {
        match name {
            "contact" => t.contact = integer(value)?,
            "cone" => t.cone = list(value)?.iter().map(strings).collect::<Checked<_>>()?,
            "weight" => t.weight = strings(value)?,
            "numerator" => t.numerator = strings(value)?,
            _ => t.next = list(value)?.iter().map(successor).collect::<Checked<_>>()?,
        }
        Ok(())
    })?;
    Ok(t)
}

/// The schema of §17 ("Fields"); the header was read first.
pub fn read(v: &Value) -> Checked<RestFamilyFile<'_>> {
    let mut f = RestFamilyFile {
        version: 0,
        body: BodyText::default(),
        claim: Claim::EffectivelyInvariant,
        bound: "",
        entries: vec![],
        nodes: vec![],
    };
    let fields = [
        ("format", true),
        ("version", true),
        ("body", true),
        ("coordinates", true),
        ("claim", true),
        ("bound", true),
        ("entries", true),
        ("nodes", true),
        ("producer", false),
    ];
    let known: Vec<(&str, bool)> = Claim::ALL.iter().map(|(_, n)| (*n, true)).collect();
    walk(v, &fields, |name, value| {
        match name {
            "format" | "producer" => drop(string(value)?),
            "version" => f.version = integer(value)?,
            "body" => f.body = body_text(value)?,
            "coordinates" => drop(unit_variant(value, &[("PaperVelocities", true)])?),
            "claim" => f.claim = Claim::of_name(unit_variant(value, &known)?).expect("listed"),
            "bound" => f.bound = string(value)?,
            "entries" => f.entries = list(value)?.iter().map(integer).collect::<Checked<_>>()?,
            _ => f.nodes = list(value)?.iter().map(node).collect::<Checked<_>>()?,
        }
        Ok(())
    })?;
    Ok(f)
}

/// The file's rules: a claim about all-down drops (`unknown-variant`), at most 64 contacts, at
/// most max-generators nodes, max-total-digits.
fn file_rules(f: &RestFamilyFile, limits: &Limits) -> Checked<()> {
    if !matches!(f.claim, Claim::CcOrPccFromAllDown | Claim::CompleteChatterFromAllDown) {
        let why = format!("the claim {} is not about all-down drops", f.claim.name());
        return Err(Fail::new("unknown-variant", why));
    }
    contact_count(&f.body)?;
    if f.nodes.len() > limits.max_generators {
        return Err(Fail::new("too-large", "more nodes than max-generators"));
    }
    let nodes = f.nodes.iter().flat_map(|n| n.cone.iter().flatten().chain(&n.weight).chain(&n.numerator));
    let chars: usize = f.body.numbers().chain([&f.bound]).chain(nodes).map(|s| s.len()).sum();
    if chars > limits.max_total_digits {
        return Err(Fail::new("too-large", "more characters of numbers than max-total-digits"));
    }
    Ok(())
}

/// The body at each value of γ in turn (the one γ, or γ_lo then γ_hi of an interval, version 2):
/// the family certificates' body rules, K0 (at the first value only), then 0 < γ < 1, each
/// failure at the value's path.
fn bodies(f: &RestFamilyFile, ends: &[End], limits: &Limits) -> Checked<Vec<Body>> {
    let mut out = vec![];
    for (k, end) in ends.iter().enumerate() {
        let b = convex_body(&f.body, (&end.gamma, end.path), k == 0, limits)?;
        if b.gamma.is_zero() || b.gamma == Num::int(&b.gamma.field, 1) {
            return Err(end.field("parameter-out-of-range", "the claims about drops need 0 < gamma < 1"));
        }
        out.push(b);
    }
    Ok(out)
}

/// One entry per contact (`wrong-arity`), `entries[i]` a node of contact i (`missing-successor`).
fn entries(f: &RestFamilyFile, n: usize) -> Checked<Vec<usize>> {
    if f.entries.len() != n {
        let why = format!("field `entries`: {} entries for {n} contacts", f.entries.len());
        return Err(Fail::new("wrong-arity", why));
    }
    let mut out = vec![];
    for (i, &e) in f.entries.iter().enumerate() {
        let node = usize::try_from(e).ok().filter(|&e| f.nodes.get(e).is_some_and(|t| t.contact == i as u64));
        let why = || format!("field `entries[{i}]`: node {e} is not a node of contact {i}");
        out.push(node.ok_or_else(|| Fail::new("missing-successor", why()))?);
    }
    Ok(out)
}

/// Node r's cone: at most max-generators generators, each three canonical numbers, then R1.
fn cone(r: usize, t: &NodeText, field: &Arc<Field>, limits: &Limits) -> Checked<(Vec<[Num; 3]>, Polygon2)> {
    if t.cone.len() > limits.max_generators {
        return Err(Fail::new("too-large", format!("node {r}: more generators than max-generators")));
    }
    let gens: Vec<[Num; 3]> = (t.cone.iter().enumerate())
        .map(|(i, g)| triple(&format!("nodes[{r}].cone[{i}]"), g, field, limits))
        .collect::<Checked<_>>()?;
    let k = cone_polygon(&gens).map_err(|e| Fail { why: format!("node {r}: {}", e.why), ..e })?;
    Ok((gens, k))
}

/// Node r read and checked: its contact < n (`parameter-out-of-range`), its cone (R1), b_r, a_r,
/// then G1, G2 and F with the rest points of its contact.
fn node_checked(b: &Body, r: usize, t: &NodeText, limits: &Limits) -> Checked<(usize, Node, Polygon2)> {
    let contact = usize::try_from(t.contact).ok().filter(|&i| i < b.n()).ok_or_else(|| {
        Fail::new("parameter-out-of-range", format!("field `nodes[{r}].contact`: {} >= n", t.contact))
    })?;
    let field = Field::rationals();
    let (gens, k) = cone(r, t, &field, limits)?;
    let weight = triple(&format!("nodes[{r}].weight"), &t.weight, &field, limits)?;
    let numerator = triple(&format!("nodes[{r}].numerator"), &t.numerator, &field, limits)?;
    let node = Node { cone: gens, weight, numerator, scale: None, next: t.next.clone() };
    node_forms(r, &node, &heights(b, contact))?;
    Ok((contact, node, k))
}

/// A general body's graph after the rules that do not depend on γ, with the values of γ to check
/// and the body at each.
pub struct Prepared {
    /// The graph, its body at the first value of γ.
    pub graph: ContactGraph,
    /// The values of γ (the one γ, or the distinct ends of the interval) with the body at each.
    pub ends: Vec<(End, Body)>,
}

/// The file's rules, γ (a number, or in version 2 an interval), the body at each value of γ, the
/// entries, then every node's own rules in order (none of these after γ depends on it).
pub fn prepare(f: &RestFamilyFile, limits: &Limits) -> Checked<Prepared> {
    file_rules(f, limits)?;
    let ends = gamma_ends(&f.body.gamma, f.version, limits)?;
    let bodies = bodies(f, &ends, limits)?;
    let entries = entries(f, bodies[0].n())?;
    let body = bodies[0].clone();
    let mut g = ContactGraph { body, entries, contacts: vec![], nodes: vec![], polygons: vec![] };
    for (r, t) in f.nodes.iter().enumerate() {
        let (contact, node, k) = node_checked(&g.body, r, t, limits)?;
        g.contacts.push(contact);
        g.nodes.push(node);
        g.polygons.push(k);
    }
    Ok(Prepared { graph: g, ends: ends.into_iter().zip(bodies).collect() })
}

/// Every rule after the schema: [`prepare`], the number B, then G3, G4, G5 and K4 at each value of
/// γ in turn (a failure at an end of an interval names the end); over an interval, the same rules
/// at interior values of γ, a brute-force test of the reduction to the ends
/// (`corner-argument-violated` if one fails). Returns the checked graph and B.
pub fn verified(f: &RestFamilyFile, limits: &Limits) -> Checked<(ContactGraph, Rat)> {
    let p = prepare(f, limits)?;
    let bound = rational("bound", f.bound, limits)?;
    let complete = f.claim == Claim::CompleteChatterFromAllDown;
    let b = Num::rational(&p.graph.body.gamma.field, bound.clone());
    for (end, body) in &p.ends {
        at_gamma(&p.graph, body, &b, complete).map_err(|e| end.content(e))?;
    }
    if let [(lo, _), (hi, _)] = &p.ends[..] {
        interior(&p.graph, (&lo.gamma, &hi.gamma), &b, complete)?;
    }
    Ok((p.graph, bound))
}

/// Every rule after the schema; the report (claim, n, the number of nodes) and B as canonical
/// text.
pub fn check(f: &RestFamilyFile, limits: &Limits) -> Checked<(Report, String)> {
    let (g, bound) = verified(f, limits)?;
    let report = Report {
        claim: f.claim.name().into(),
        n: g.body.n() as u64,
        rest_nodes: Some(g.nodes.len()),
        ..Report::default()
    };
    Ok((report, rational_text(&bound)))
}

impl RestFamilyFile<'_> {
    /// [γ_lo, γ_hi] as written when γ is an interval (an accepted file's numbers are canonical):
    /// what the report gives as `gamma_interval`.
    pub fn gamma_interval(&self) -> Option<[String; 2]> {
        match self.body.gamma[..] {
            [lo, hi] => Some([lo.to_string(), hi.to_string()]),
            _ => None,
        }
    }
}
