//! Time-to-rest certificates (docs/certificate-format.md §16): the schema, the file's rules (the
//! claim, the limits, a body at a point, 3 <= n <= 64 (in Q(cos 2π/n) where it is irrational),
//! 0 < γ < 1, the numbers and their arity), then the virtual-time graph's rules G1-G5 and R4
//! (`crate::regular::virtual_time`); or a box of (κ, γ) for n = 3, 4, 6, the rules at its corners
//! and at interior points, and R4 on the box.

use super::limits::Limits;
use super::numbers::{element, rational};
use crate::arith::rational::rational_text;
use crate::arith::{Field, Num, Rat};
use crate::claim::Claim;
use crate::read::Value;
use crate::read::schema::{
    integer, list, param, regular_polygon, string, strings, tuple, unit_variant, walk,
};
use crate::regular::boxes;
use crate::regular::model::{Polygon, V3};
use crate::regular::rules::Polygon2;
use crate::regular::virtual_time::{Node, bound_rules, graph_rules, node_rules};
use crate::verdict::{Checked, Fail, Report};
use std::sync::Arc;

/// A node as read: its cone's generators, its covector b_r, its scale c_r (version 1) or its
/// numerator a_r (version 2), and its successors.
struct NodeText<'a> {
    cone: Vec<Vec<&'a str>>,
    weight: Vec<&'a str>,
    scale: Option<&'a str>,
    numerator: Option<Vec<&'a str>>,
    next: Vec<(u64, u64)>,
}

/// A time-to-rest certificate as read.
pub struct RestFile<'a> {
    version: u64,
    n: u64,
    kappa: Vec<&'a str>,
    gamma: Vec<&'a str>,
    claim: Claim,
    bound: &'a str,
    nodes: Vec<NodeText<'a>>,
}

impl RestFile<'_> {
    /// The body as written: n, and κ and γ (one text each for a point, two for an interval).
    pub fn body(&self) -> (u64, &[&str], &[&str]) {
        (self.n, &self.kappa, &self.gamma)
    }

    /// The claim as written.
    pub fn claim(&self) -> Claim {
        self.claim
    }

    /// The number of nodes as written.
    pub fn node_count(&self) -> usize {
        self.nodes.len()
    }
}

/// A pair (j, s) of `next`: after step j, node s.
pub fn successor(v: &Value) -> Checked<(u64, u64)> {
    match tuple(v)? {
        [j, s] => Ok((integer(j)?, integer(s)?)),
        xs => Err(Fail::new("syntax", format!("a successor is a pair (j, s), found {} values", xs.len()))),
    }
}

fn node(v: &Value) -> Checked<NodeText<'_>> {
    let mut t = NodeText { cone: vec![], weight: vec![], scale: None, numerator: None, next: vec![] };
    let fields = [("cone", true), ("weight", true), ("scale", false), ("numerator", false), ("next", true)];
    walk(v, &fields, |name, value| {
        match name {
            "cone" => t.cone = list(value)?.iter().map(strings).collect::<Checked<_>>()?,
            "weight" => t.weight = strings(value)?,
            "scale" => t.scale = Some(string(value)?),
            "numerator" => t.numerator = Some(strings(value)?),
            _ => t.next = list(value)?.iter().map(successor).collect::<Checked<_>>()?,
        }
        Ok(())
    })?;
    Ok(t)
}

/// The schema of §16 ("Fields").
pub fn read(v: &Value) -> Checked<RestFile<'_>> {
    let mut f = RestFile {
        version: 0,
        n: 0,
        kappa: vec![],
        gamma: vec![],
        claim: Claim::EffectivelyInvariant,
        bound: "",
        nodes: vec![],
    };
    let fields = [
        ("format", true),
        ("version", true),
        ("body", true),
        ("coordinates", true),
        ("claim", true),
        ("bound", true),
        ("nodes", true),
        ("producer", false),
    ];
    let known: Vec<(&str, bool)> = Claim::ALL.iter().map(|(_, n)| (*n, true)).collect();
    walk(v, &fields, |name, value| {
        match name {
            "format" | "producer" => drop(string(value)?),
            "version" => f.version = integer(value)?,
            "body" => regular_polygon(value, |k, v| {
                match k {
                    "n" => f.n = integer(v)?,
                    "kappa" => f.kappa = param(v)?,
                    _ => f.gamma = param(v)?,
                }
                Ok(())
            })?,
            "coordinates" => drop(unit_variant(value, &[("ContactVelocities", true)])?),
            "claim" => f.claim = Claim::of_name(unit_variant(value, &known)?).expect("listed"),
            "bound" => f.bound = string(value)?,
            _ => f.nodes = list(value)?.iter().map(node).collect::<Checked<_>>()?,
        }
        Ok(())
    })?;
    Ok(f)
}

/// The claim must be about all-down drops (§16: `unknown-variant` otherwise).
fn claim(f: &RestFile) -> Checked<()> {
    match f.claim {
        Claim::CcOrPccFromAllDown | Claim::CompleteChatterFromAllDown => Ok(()),
        c => Err(Fail::new("unknown-variant", format!("the claim {} is not about all-down drops", c.name()))),
    }
}

/// The limits: nodes and generators per node (`max-generators`), the characters of every number
/// (`max-total-digits`).
fn size(f: &RestFile, limits: &Limits) -> Checked<()> {
    let many =
        f.nodes.len() > limits.max_generators || f.nodes.iter().any(|n| n.cone.len() > limits.max_generators);
    if many {
        return Err(Fail::new("too-large", "more nodes or generators than max-generators"));
    }
    let numbers = f.nodes.iter().flat_map(|n| {
        let a = n.numerator.iter().flatten();
        n.cone.iter().flatten().chain(&n.weight).chain(a).chain(n.scale.as_ref())
    });
    let chars: usize = f.kappa.iter().chain(&f.gamma).chain([&f.bound]).chain(numbers).map(|s| s.len()).sum();
    if chars > limits.max_total_digits {
        return Err(Fail::new("too-large", "more characters of numbers than max-total-digits"));
    }
    Ok(())
}

/// The body: 3 <= n <= 64 (n beyond 64 refused first), a file of version 3 where cos 2π/n is
/// irrational, at a point, κ > 0 and 0 < γ < 1, read in Q(cos 2π/n).
fn body(f: &RestFile, limits: &Limits) -> Checked<Polygon> {
    let out = |what: &str| Err(Fail::new("parameter-out-of-range", what.to_string()));
    let unsupported =
        || Err(Fail::new("unsupported-body", format!("n = {} (time-to-rest: 3 <= n <= 64)", f.n)));
    if f.n > 64 {
        return unsupported();
    }
    let irrational = f.n >= 5 && f.n != 6;
    if irrational && f.version < 3 {
        return Err(Fail::new("unsupported-version", "a body with irrational cos 2π/n needs version 3"));
    }
    if f.kappa.len() != 1 || f.gamma.len() != 1 {
        return out("a time-to-rest certificate is about a body at a point");
    }
    if f.n < 3 {
        rational("body.kappa", f.kappa[0], limits)?;
        rational("body.gamma", f.gamma[0], limits)?;
        return unsupported();
    }
    let field = Field::cos(f.n as u32);
    let kappa = element("body.kappa", f.kappa[0], &field, limits)?;
    let gamma = element("body.gamma", f.gamma[0], &field, limits)?;
    if !kappa.is_positive() {
        return out("kappa must be > 0");
    }
    if !gamma.is_positive() || !(&gamma - &Num::int(&field, 1)).is_negative() {
        return out("the claims about drops need 0 < gamma < 1");
    }
    Ok(Polygon::new(f.n as usize, kappa, gamma))
}

/// A triple of numbers (a generator or a covector), `wrong-arity` unless it has three.
pub fn triple(path: &str, texts: &[&str], field: &Arc<Field>, limits: &Limits) -> Checked<V3> {
    if texts.len() != 3 {
        return Err(Fail::new("wrong-arity", format!("{path} has {} coordinates", texts.len())));
    }
    let x = |i: usize| -> Checked<Num> { element(path, texts[i], field, limits) };
    Ok([x(0)?, x(1)?, x(2)?])
}

/// Node r's numbers (cone, weight, and the scale in version 1 or the numerator in version 2; the
/// field of the other version is `unknown-field`, its own absent `missing-field`).
fn node_numbers(r: usize, t: &NodeText, version: u64, field: &Arc<Field>, limits: &Limits) -> Checked<Node> {
    let cone = (t.cone.iter().enumerate())
        .map(|(i, g)| triple(&format!("nodes[{r}].cone[{i}]"), g, field, limits))
        .collect::<Checked<_>>()?;
    match (version, t.scale.is_some(), t.numerator.is_some()) {
        (1, _, true) | (2 | 3, true, _) => {
            return Err(Fail::new("unknown-field", format!("node {r} has the field of the other version")));
        }
        (1, false, _) | (2 | 3, _, false) => {
            return Err(Fail::new("missing-field", format!("node {r} lacks its version's field")));
        }
        _ => {}
    }
    let weight = triple(&format!("nodes[{r}].weight"), &t.weight, field, limits)?;
    let scale = t.scale.map(|c| rational(&format!("nodes[{r}].scale"), c, limits)).transpose()?;
    let scale = scale.map(|c| Num::rational(field, c));
    let numerator = match &scale {
        Some(c) => weight.clone().map(|b| &b * c),
        None => triple(
            &format!("nodes[{r}].numerator"),
            t.numerator.as_deref().unwrap_or_default(),
            field,
            limits,
        )?,
    };
    Ok(Node { cone, weight, numerator, scale, next: t.next.clone() })
}

/// A time-to-rest certificate after the file's rules and G1-G2: the body, the graph's nodes and
/// their polygons.
pub struct Graph {
    /// The regular polygon at (κ, γ).
    pub body: Polygon,
    /// The nodes, node 0 entered at the first impact.
    pub nodes: Vec<Node>,
    /// Each node's cone K_r on the plane v = -1.
    pub polygons: Vec<Polygon2>,
}

/// The file's rules of §16 ("Acceptance rules", first item), then node after node its numbers
/// and rules G1 and G2 (the kernel reads a node's numbers just before its rules, and B only for
/// G5: the mutation tests show it, the documents leave it open).
pub fn prepare(f: &RestFile, limits: &Limits) -> Checked<Graph> {
    claim(f)?;
    size(f, limits)?;
    let body = body(f, limits)?;
    let (mut nodes, mut polygons) = (vec![], vec![]);
    for (r, t) in f.nodes.iter().enumerate() {
        let node = node_numbers(r, t, f.version, &body.kappa.field, limits)?;
        polygons.push(node_rules(&body, r, &node)?);
        nodes.push(node);
    }
    Ok(Graph { body, nodes, polygons })
}

/// B, a canonical rational.
pub fn bound(f: &RestFile, limits: &Limits) -> Checked<Rat> {
    rational("bound", f.bound, limits)
}

/// Every rule of a time-to-rest certificate after its schema, in §16's order; returns the checked
/// graph and B.
pub fn verified(f: &RestFile, limits: &Limits) -> Checked<(Graph, Rat)> {
    let g = prepare(f, limits)?;
    graph_rules(&g.body, &g.nodes, &g.polygons)?;
    let b = bound(f, limits)?;
    bound_rules(&g.body, f.claim, &Num::rational(&g.body.kappa.field, b.clone()), &g.nodes[0])?;
    Ok((g, b))
}

/// A parameter as an interval [lo, hi] (a point gives lo = hi), lo <= hi.
fn interval(path: &str, texts: &[&str], limits: &Limits) -> Checked<[Rat; 2]> {
    let lo = rational(path, texts[0], limits)?;
    let hi = match texts.get(1) {
        Some(t) => rational(path, t, limits)?,
        None => lo.clone(),
    };
    if lo > hi {
        return Err(Fail::new("parameter-out-of-range", format!("{path}: lo > hi")));
    }
    Ok([lo, hi])
}

/// A time-to-rest certificate over a box of (κ, γ) (version 3, n = 3, 4, 6): the box's rules, then
/// G1-G5 at every corner, the corner argument tested at interior points (brute force), R4 on the
/// box.
fn check_box(f: &RestFile, limits: &Limits) -> Checked<(Report, String)> {
    claim(f)?;
    size(f, limits)?;
    if f.version < 3 {
        return Err(Fail::new("unsupported-version", "a box of parameters needs version 3"));
    }
    if f.n >= 5 && f.n != 6 {
        return Err(Fail::new("unsupported-body", "boxes need a rational cos 2π/n"));
    }
    let (k, g) = (interval("body.kappa", &f.kappa, limits)?, interval("body.gamma", &f.gamma, limits)?);
    if f.n < 3 {
        return Err(Fail::new("unsupported-body", format!("n = {}", f.n)));
    }
    let out = |what: &str| Err(Fail::new("parameter-out-of-range", what.to_string()));
    let cs = boxes::corners(&k, &g);
    let zero = Rat::from_integer(0.into());
    if cs.iter().any(|(kappa, gamma)| *kappa <= zero || *gamma < zero || *gamma > Rat::from_integer(1.into()))
    {
        return out("a corner outside kappa > 0, 0 <= gamma <= 1");
    }
    if g[0] <= zero || g[1] >= Rat::from_integer(1.into()) {
        return out("the claims about drops need 0 < gamma < 1 on the box");
    }
    for (kappa, gamma) in &cs {
        at_point(f, kappa, gamma, limits)?;
    }
    for (a, b, c, d) in [(1, 3, 5, 7), (6, 7, 2, 9)] {
        let kappa = &k[0] + (&k[1] - &k[0]) * Rat::new(a.into(), b.into());
        let gamma = &g[0] + (&g[1] - &g[0]) * Rat::new(c.into(), d.into());
        if let Err(e) = at_point(f, &kappa, &gamma, limits) {
            let why =
                format!("the corners pass but ({kappa}, {gamma}) fails ({}): {}", e.codes.join(", "), e.why);
            return Err(Fail::new("corner-argument-violated", why));
        }
    }
    if f.claim == Claim::CompleteChatterFromAllDown {
        boxes::pcc_on_box(f.n as usize, &k, &g)?;
    }
    let report = Report {
        claim: f.claim.name().into(),
        n: f.n,
        rest_nodes: Some(f.nodes.len()),
        region: Some([
            [rational_text(&k[0]), rational_text(&k[1])],
            [rational_text(&g[0]), rational_text(&g[1])],
        ]),
        ..Report::default()
    };
    Ok((report, rational_text(&bound(f, limits)?)))
}

/// G1-G5 (not R4) at one point of a box.
fn at_point(f: &RestFile, kappa: &Rat, gamma: &Rat, limits: &Limits) -> Checked<()> {
    let field = Field::cos(f.n as u32);
    let body = Polygon::new(
        f.n as usize,
        Num::rational(&field, kappa.clone()),
        Num::rational(&field, gamma.clone()),
    );
    let (mut nodes, mut polygons) = (vec![], vec![]);
    for (r, t) in f.nodes.iter().enumerate() {
        let node = node_numbers(r, t, f.version, &field, limits)?;
        polygons.push(node_rules(&body, r, &node)?);
        nodes.push(node);
    }
    graph_rules(&body, &nodes, &polygons)?;
    let b = Num::rational(&field, bound(f, limits)?);
    let Some(node0) = nodes.first() else {
        return Err(Fail::new("missing-successor", "no node 0 for the first impact"));
    };
    bound_rules(&body, Claim::CcOrPccFromAllDown, &b, node0)
}

/// Every rule of a time-to-rest certificate after its schema, in §16's order; returns the report
/// and B (canonical text).
pub fn check(f: &RestFile, limits: &Limits) -> Checked<(Report, String)> {
    if f.kappa.len() == 2 || f.gamma.len() == 2 {
        return check_box(f, limits);
    }
    let (g, b) = verified(f, limits)?;
    let report =
        Report { claim: f.claim.name().into(), n: f.n, rest_nodes: Some(g.nodes.len()), ..Report::default() };
    Ok((report, rational_text(&b)))
}
