//! Time-to-rest certificates of a general convex body (docs/certificate-format.md §17, format
//! `chatter-family-time-to-rest`, version 1; docs/time-to-rest.md §5): the body of a family
//! certificate at one γ, one entry node per contact, and a virtual-time graph whose nodes carry
//! the contact of the last impact. The rules, in the kernel's order (the documents leave the
//! order open): the claim, at most 64 contacts, the limits; the body at a point (the family
//! certificates' body rules, K0, 0 < γ < 1); the entries; node after node its contact, its cone's
//! numbers and R1, b_r, a_r, then G1, G2 and F; G3 on every node; B; G4 and G5 contact after
//! contact; K4 for `CompleteChatterFromAllDown` ([`crate::convex::virtual_time`]).

use super::family::{BodyText, body_text, contact_count, convex_body};
use super::limits::Limits;
use super::numbers::{element, rational};
use super::rest::{successor, triple};
use crate::arith::rational::rational_text;
use crate::arith::{Field, Num, Rat};
use crate::claim::Claim;
use crate::convex::model::Body;
use crate::convex::virtual_time::{ContactGraph, entry_rules, g3, heights, pcc};
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
            "version" => drop(integer(value)?),
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

/// The body at a point γ (`parameter-out-of-range` for an interval, before its numbers): γ
/// first, then the family certificates' body rules and K0, then 0 < γ < 1.
fn body(f: &RestFamilyFile, limits: &Limits) -> Checked<Body> {
    let [gamma] = f.body.gamma[..] else {
        return Err(Fail::new(
            "parameter-out-of-range",
            "field `body.gamma`: a time-to-rest certificate is about a body at a point",
        ));
    };
    let gamma = element("body.gamma", gamma, &Field::rationals(), limits)?;
    let b = convex_body(&f.body, (&gamma, "body.gamma"), true, limits)?;
    if b.gamma.is_zero() || b.gamma == Num::int(&b.gamma.field, 1) {
        return Err(Fail::new(
            "parameter-out-of-range",
            "field `body.gamma`: the claims about drops need 0 < gamma < 1",
        ));
    }
    Ok(b)
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

/// The file's rules, the body and the entries, then every node's own rules in order.
pub fn prepare(f: &RestFamilyFile, limits: &Limits) -> Checked<ContactGraph> {
    file_rules(f, limits)?;
    let body = body(f, limits)?;
    let entries = entries(f, body.n())?;
    let mut g = ContactGraph { body, entries, contacts: vec![], nodes: vec![], polygons: vec![] };
    for (r, t) in f.nodes.iter().enumerate() {
        let (contact, node, k) = node_checked(&g.body, r, t, limits)?;
        g.contacts.push(contact);
        g.nodes.push(node);
        g.polygons.push(k);
    }
    Ok(g)
}

/// Every rule after the schema; returns the checked graph and B.
pub fn verified(f: &RestFamilyFile, limits: &Limits) -> Checked<(ContactGraph, Rat)> {
    let g = prepare(f, limits)?;
    g3(&g)?;
    let bound = rational("bound", f.bound, limits)?;
    entry_rules(&g, &Num::rational(&g.body.gamma.field, bound.clone()))?;
    if f.claim == Claim::CompleteChatterFromAllDown {
        pcc(&g.body)?;
    }
    Ok((g, bound))
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
