//! Basin certificates (docs/certificate-format.md §15, docs/basin-certificates.md): the schema,
//! rules B1 and B2's comparisons of bodies (and of the time-to-rest certificate's claim) and rule
//! O1 of the embedded orbit certificate, decided exactly (two-sided); rule B3, the partition,
//! decided exactly (two-sided); every rule of the embedded time-to-rest certificate (§16, its own
//! codes, two-sided); the orbit certificate's conditions at its sample points and rule B4 at three
//! exact drops of every leaf with a verdict (one-sided: a failing drop proves the certificate
//! false, passing drops prove nothing), for a tree leaf (version 2, `tree.rs`) at every node of the
//! tree and along the drop's real motion. In the kernel's order of rules, so that the first
//! failing rule gives its code.

use super::limits::Limits;
use super::numbers::element;
use super::orbit::{self, OrbitFile};
use super::rest::{self, Graph, RestFile};
use crate::arith::rational::rational_text;
use crate::arith::{Field, Num, Rat};
use crate::basin::tree::{Impact, Then, follow_tree};
use crate::basin::{DIMS, End, drop_state, follow, leaf_box, leaf_points, partition, share};
use crate::claim::Claim;
use crate::orbit::map::Orbit;
use crate::read::Value;
use crate::read::header::{Reader, header};
use crate::read::schema::{integer, list, optional, regular_polygon, string, variant, walk};
use crate::regular::model::Polygon;
use crate::verdict::{Checked, Fail};
use num_traits::Zero;

mod tree;

/// The most leaves (`max-basin-leaves`), the longest path (`max-basin-depth`) and the longest
/// prefix (`max-basin-prefix`) of docs/certificate-format.md §15.
const MAX_LEAVES: usize = 1 << 20;
const MAX_PATH: usize = 64;
const MAX_PREFIX: usize = 4096;

/// Where a leaf's prefix ends: in the orbit certificate's X (`Cc`), at v > 0 (`Icc`), or in
/// node r of the time-to-rest certificate's graph (`Rest`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Ending {
    Cc,
    Icc,
    Rest(u64),
}

/// A leaf's verdict as read: `Cc` or `Icc` with (first, steps, cuts), `Rest` with (first, steps,
/// node) (no cuts), a `Tree` (its root list, version 2), or `Undecided`.
#[derive(Clone, Debug)]
enum LeafText {
    Prefix { ending: Ending, first: u64, steps: Vec<u64>, cuts: Vec<u64> },
    Tree(Vec<Impact>),
    Undecided,
}

/// A basin certificate as read.
pub struct BasinFile<'a> {
    version: u64,
    n: u64,
    kappa: &'a str,
    gamma: &'a str,
    lo: Vec<&'a str>,
    hi: Vec<&'a str>,
    orbit: Option<(&'a Value, OrbitFile<'a>)>,
    rest: Option<(&'a Value, RestFile<'a>)>,
    leaves: Vec<(&'a str, LeafText)>,
}

fn strings(v: &Value) -> Checked<Vec<&str>> {
    list(v)?.iter().map(string).collect()
}

fn integers(v: &Value) -> Checked<Vec<u64>> {
    list(v)?.iter().map(integer).collect()
}

/// A leaf's verdict: `Cc(first, steps, cuts)`, `Icc(...)`, `Rest(first, steps, node)`,
/// `Tree(next)` or `Undecided`.
fn verdict(v: &Value) -> Checked<LeafText> {
    match variant(v)? {
        ("Undecided", None) => Ok(LeafText::Undecided),
        ("Tree", Some(fields)) => tree::read_tree(fields).map(LeafText::Tree),
        (name @ ("Cc" | "Icc" | "Rest"), Some(fields)) => {
            let (mut first, mut steps, mut cuts, mut node) = (0, vec![], vec![], 0);
            let last = if name == "Rest" { "node" } else { "cuts" };
            walk(fields, &[("first", true), ("steps", true), (last, true)], |f, v| {
                match f {
                    "first" => first = integer(v)?,
                    "steps" => steps = integers(v)?,
                    "node" => node = integer(v)?,
                    _ => cuts = integers(v)?,
                }
                Ok(())
            })?;
            let ending = match name {
                "Cc" => Ending::Cc,
                "Icc" => Ending::Icc,
                _ => Ending::Rest(node),
            };
            Ok(LeafText::Prefix { ending, first, steps, cuts })
        }
        ("Undecided" | "Cc" | "Icc" | "Rest" | "Tree", _) => {
            Err(Fail::new("syntax", "a leaf's verdict has the wrong form"))
        }
        (name, _) => Err(Fail::new("unknown-variant", format!("unknown verdict `{name}`"))),
    }
}

fn leaf(v: &Value) -> Checked<(&str, LeafText)> {
    let (mut path, mut text) = ("", LeafText::Undecided);
    walk(v, &[("path", true), ("verdict", true)], |f, v| {
        if f == "path" {
            path = string(v)?;
        } else {
            text = verdict(v)?;
        }
        Ok(())
    })?;
    Ok((path, text))
}

/// The schema of §15.
pub fn read(v: &Value) -> Checked<BasinFile<'_>> {
    let mut f = BasinFile {
        version: 0,
        n: 0,
        kappa: "",
        gamma: "",
        lo: vec![],
        hi: vec![],
        orbit: None,
        rest: None,
        leaves: vec![],
    };
    let fields = [
        ("format", true),
        ("version", true),
        ("body", true),
        ("drops", true),
        ("orbit", false),
        ("rest", false),
        ("leaves", true),
        ("producer", false),
    ];
    walk(v, &fields, |name, value| {
        match name {
            "format" | "producer" => drop(string(value)?),
            "version" => f.version = integer(value)?,
            "body" => regular_polygon(value, |k, v| {
                match k {
                    "n" => f.n = integer(v)?,
                    "kappa" => f.kappa = string(v)?,
                    _ => f.gamma = string(v)?,
                }
                Ok(())
            })?,
            "drops" => walk(value, &[("lo", true), ("hi", true)], |k, v| {
                if k == "lo" {
                    f.lo = strings(v)?;
                } else {
                    f.hi = strings(v)?;
                }
                Ok(())
            })?,
            "orbit" => {
                if let Some(o) = optional(value)? {
                    f.orbit = Some((o, orbit::read(o)?));
                }
            }
            "rest" => {
                if let Some(r) = optional(value)? {
                    // A RON struct name is part of the embedded certificate's schema (§16's
                    // `TimeToRest`); its format and version are its own rules, after B3.
                    if let Value::Named { name, .. } = r
                        && !name.is_empty()
                        && name != "TimeToRest"
                    {
                        return Err(Fail::new(
                            "syntax",
                            format!("expected struct `TimeToRest`, found `{name}`"),
                        ));
                    }
                    f.rest = Some((r, rest::read(r)?));
                }
            }
            _ => f.leaves = list(value)?.iter().map(leaf).collect::<Checked<_>>()?,
        }
        Ok(())
    })?;
    Ok(f)
}

fn out_of_range(why: impl Into<String>) -> Fail {
    Fail::new("basin-out-of-range", why)
}

fn too_large(why: &str) -> Fail {
    Fail::new("too-large", why)
}

/// The exact content of a basin certificate that passed rules B1 and O1 (and the limits it was
/// read with, for the embedded time-to-rest certificate's rules).
pub struct Basin {
    body: Polygon,
    orbit: Option<Orbit>,
    lo: [Rat; DIMS],
    hi: [Rat; DIMS],
    limits: Limits,
}

/// The body's numbers (B1, as rule O1 reads a body): κ > 0, 0 ≤ γ ≤ 1, 3 ≤ n ≤ 64.
fn body(f: &BasinFile, limits: &Limits) -> Checked<(Num, Num)> {
    let q = Field::rationals();
    let kappa = element("body.kappa", f.kappa, &q, limits)?;
    let gamma = element("body.gamma", f.gamma, &q, limits)?;
    if !(3..=orbit::MAX_N).contains(&f.n) {
        return Err(Fail::new(
            "unsupported-body",
            format!("n = {}: basin certificates need 3 <= n <= 64", f.n),
        ));
    }
    if !kappa.is_positive() || gamma.is_negative() || gamma > Num::int(&q, 1) {
        return Err(Fail::new("parameter-out-of-range", "kappa > 0 and 0 <= gamma <= 1"));
    }
    Ok((kappa, gamma))
}

/// Rule B2's first half: the embedded certificate names the same body, has the orbit header,
/// and passes rule O1.
fn embedded(f: &BasinFile, kappa: &Num, gamma: &Num, limits: &Limits) -> Checked<Option<Orbit>> {
    let Some((value, o)) = &f.orbit else { return Ok(None) };
    let q = Field::rationals();
    let (on, ok, og) = o.body();
    let ok = element("orbit.body.kappa", ok, &q, limits)?;
    let og = element("orbit.body.gamma", og, &q, limits)?;
    if on != f.n || ok != *kappa || og != *gamma {
        return Err(out_of_range("the orbit certificate names another body"));
    }
    if header(value)? != Reader::Orbit {
        return Err(Fail::new("wrong-format", "the embedded certificate is not an orbit certificate"));
    }
    orbit::rules(o, limits).map(Some)
}

/// Rule B2's comparisons for the time-to-rest certificate (right after the orbit certificate's):
/// a body at a point with the same n, κ, γ (exact rationals), and the claim
/// `CompleteChatterFromAllDown` (`basin-out-of-range` otherwise). Its own rules come after B3.
fn same_rest(f: &BasinFile, kappa: &Num, gamma: &Num, limits: &Limits) -> Checked<()> {
    let Some((_, r)) = &f.rest else { return Ok(()) };
    let (rn, rk, rg) = r.body();
    let ([rk], [rg]) = (rk, rg) else {
        return Err(out_of_range("the time-to-rest certificate's body is not at a point"));
    };
    let q = Field::rationals();
    let rk = element("rest.body.kappa", rk, &q, limits)?;
    let rg = element("rest.body.gamma", rg, &q, limits)?;
    if rn != f.n || rk != *kappa || rg != *gamma {
        return Err(out_of_range("the time-to-rest certificate names another body"));
    }
    if r.claim() != Claim::CompleteChatterFromAllDown {
        return Err(out_of_range("the time-to-rest certificate's claim is not CompleteChatterFromAllDown"));
    }
    Ok(())
}

/// A corner of the box: five canonical numbers.
fn corner(path: &str, v: &[&str], limits: &Limits) -> Checked<[Rat; DIMS]> {
    if v.len() != DIMS {
        return Err(out_of_range(format!("{path} has {} coordinates, not 5", v.len())));
    }
    let q = Field::rationals();
    let mut out: [Rat; DIMS] = std::array::from_fn(|_| Rat::zero());
    for (i, s) in v.iter().enumerate() {
        out[i] = element(&format!("{path}[{i}]"), s, &q, limits)?.as_rational().expect("rational").clone();
    }
    Ok(out)
}

/// Rule B1's fields of a leaf with a prefix: the limits, the contacts, the orbit it needs, the
/// time-to-rest certificate and node it needs (`rest_nodes`: the embedded certificate's number of
/// nodes), the cuts.
fn prefix_fields(t: &LeafText, n: u64, has_orbit: bool, rest_nodes: Option<usize>) -> Checked<()> {
    let LeafText::Prefix { ending, first, steps, cuts } = t else { return Ok(()) };
    if steps.len() + 1 > MAX_PREFIX {
        return Err(too_large("a prefix longer than max-basin-prefix"));
    }
    if *first >= n || steps.iter().any(|&j| j == 0 || j >= n) {
        return Err(out_of_range("a contact or step out of range"));
    }
    if !has_orbit && (*ending == Ending::Cc || !cuts.is_empty()) {
        return Err(out_of_range("a Cc leaf or cuts without an orbit certificate"));
    }
    if let Ending::Rest(r) = ending {
        let Some(count) = rest_nodes else {
            return Err(out_of_range("a Rest leaf without a time-to-rest certificate"));
        };
        if usize::try_from(*r).map_or(true, |r| r >= count) {
            return Err(out_of_range(format!("a Rest leaf names node {r} of {count}")));
        }
    }
    let len = steps.len() as u64 + 1;
    if cuts.windows(2).any(|w| w[0] >= w[1]) || cuts.iter().any(|&c| c == 0 || c > len) {
        return Err(out_of_range("the cuts are not strictly increasing impact counts in the prefix"));
    }
    Ok(())
}

/// Rules B1, B2's comparison of bodies and O1, in the kernel's order.
pub fn rules(f: &BasinFile, limits: &Limits) -> Checked<Basin> {
    let numbers = [f.kappa, f.gamma].into_iter().chain(f.lo.iter().copied()).chain(f.hi.iter().copied());
    if numbers.map(str::len).sum::<usize>() > limits.max_total_digits {
        return Err(too_large("more characters of numbers than max-total-digits"));
    }
    let (kappa, gamma) = body(f, limits)?;
    let orbit = embedded(f, &kappa, &gamma, limits)?;
    same_rest(f, &kappa, &gamma, limits)?;
    let (lo, hi) = (corner("drops.lo", &f.lo, limits)?, corner("drops.hi", &f.hi, limits)?);
    if (0..DIMS).any(|i| lo[i] >= hi[i]) || lo[4] <= Rat::zero() {
        return Err(out_of_range("the box is flat, or h <= 0 in it"));
    }
    if f.leaves.len() > MAX_LEAVES {
        return Err(too_large("more leaves than max-basin-leaves"));
    }
    let rest_nodes = f.rest.as_ref().map(|(_, r)| r.node_count());
    let context = tree::Context { version: f.version, n: f.n, orbit: orbit.is_some(), rest_nodes };
    for (i, (path, t)) in f.leaves.iter().enumerate() {
        if path.len() > MAX_PATH {
            return Err(too_large("a path longer than max-basin-depth"));
        }
        match t {
            LeafText::Tree(next) => tree::tree_rules(i, next, &context)?,
            _ => prefix_fields(t, f.n, orbit.is_some(), rest_nodes)?,
        }
    }
    let body = match &orbit {
        Some(o) => o.body.clone(),
        None => {
            let field = Field::cos(f.n as u32);
            let to = |x: &Num| Num::rational(&field, x.as_rational().expect("rational").clone());
            Polygon::new(f.n as usize, to(&kappa), to(&gamma))
        }
    };
    Ok(Basin { body, orbit, lo, hi, limits: *limits })
}

/// What the oracle found for an accepted basin certificate: the shares (CC, ICC, undecided) as
/// canonical text, the leaves of each kind, and the largest exact (time to rest)/h over the drops
/// it followed into X (a lower bound of the kernel's `time_to_rest_bound`, which bounds every drop
/// of every CC leaf).
pub struct Found {
    /// The three shares.
    pub shares: [String; 3],
    /// The leaves of each kind.
    pub leaves: [usize; 3],
    /// The largest time to rest over h of the drops followed, if any leaf is CC.
    pub time: Option<Num>,
}

/// Rule B3, then O2 at the orbit certificate's sample points, then every rule of the embedded
/// time-to-rest certificate, then B4 at three drops of every leaf (the kernel's order: B3 before
/// the slow rule O2).
pub fn check(f: &BasinFile, b: &Basin) -> Checked<Found> {
    partition(&paths(f))?;
    if let Some(o) = &b.orbit {
        orbit::check(o)?;
    }
    let graph = rest_rules(f, &b.limits)?;
    leaves(f, b, graph.as_ref())
}

/// The embedded time-to-rest certificate's own rules (§16: its header, then its file's rules,
/// G1-G5, F and R4, with its own codes): its checked graph.
fn rest_rules(f: &BasinFile, limits: &Limits) -> Checked<Option<Graph>> {
    let Some((value, r)) = &f.rest else { return Ok(None) };
    // The struct's name was read with the schema (B1); the header's format and version here.
    let owned;
    let unnamed = match value {
        Value::Named { fields: Some(fields), .. } => {
            owned = Value::Object(fields.clone());
            &owned
        }
        other => *other,
    };
    if header(unnamed)? != Reader::Rest {
        return Err(Fail::new("wrong-format", "the embedded certificate is not a time-to-rest certificate"));
    }
    rest::verified(r, limits).map(|(g, _)| Some(g))
}

fn paths<'a>(f: &'a BasinFile) -> Vec<&'a [u8]> {
    f.leaves.iter().map(|(p, _)| p.as_bytes()).collect()
}

/// Rule B4 at the sample drops of every leaf with a verdict, and the shares (a `Rest` leaf is a
/// CC leaf; a tree is a CC leaf with `Cc`/`Rest` ends, an ICC leaf with `Icc` ends). `graph`: the
/// embedded time-to-rest certificate's (`None` only where its rules failed, in
/// [`every_failure`]: leaves with `Rest` ends are then not followed).
fn leaves(f: &BasinFile, b: &Basin, graph: Option<&Graph>) -> Checked<Found> {
    let (mut shares, mut leaves, mut time) = ([Rat::zero(), Rat::zero(), Rat::zero()], [0; 3], None::<Num>);
    for (i, (path, t)) in f.leaves.iter().enumerate() {
        let kind = match t {
            LeafText::Prefix { ending: Ending::Icc, .. } => 1,
            LeafText::Tree(next) if tree::icc(next) => 1,
            LeafText::Prefix { .. } | LeafText::Tree(_) => 0,
            LeafText::Undecided => 2,
        };
        let worst = sample_leaf(b, graph, path.as_bytes(), t)
            .map_err(|e| Fail { codes: e.codes, why: format!("leaf {i} (path {path:?}): {}", e.why) })?;
        time = match (time, worst) {
            (Some(t), Some(w)) if w > t => Some(w),
            (None, w) => w,
            (t, _) => t,
        };
        shares[kind] = &shares[kind] + &share(path.len());
        leaves[kind] += 1;
    }
    Ok(Found { shares: shares.map(|s| rational_text(&s)), leaves, time })
}

/// Where a prefix or a tree's path ends, as the dynamics check it (`None`: a node of a graph that
/// failed its own rules).
fn end_of<'a>(ending: Ending, b: &'a Basin, graph: Option<&'a Graph>) -> Option<End<'a>> {
    Some(match (ending, &b.orbit, graph) {
        (Ending::Cc, Some(o), _) => End::Cc(o),
        (Ending::Rest(r), _, Some(g)) => End::Rest(&g.nodes[r as usize], &g.polygons[r as usize]),
        (Ending::Rest(_), _, None) => return None,
        _ => End::Icc,
    })
}

/// A tree's end as an [`Ending`] (`Impacts` is no end; not called with it).
fn ending(then: &Then) -> Ending {
    match then {
        Then::Cc => Ending::Cc,
        Then::Rest(r) => Ending::Rest(*r),
        _ => Ending::Icc,
    }
}

/// How one drop of a leaf is followed: through a prefix, or through a tree.
enum Followed<'a> {
    Prefix(Vec<i64>, End<'a>),
    Tree(&'a [Impact], Box<dyn Fn(&Then) -> End<'a> + 'a>),
}

/// How the drops of a leaf are followed (`None`: no verdict, or an end in a graph that failed its
/// own rules).
fn followed<'a>(b: &'a Basin, graph: Option<&'a Graph>, t: &'a LeafText) -> Option<Followed<'a>> {
    match t {
        LeafText::Prefix { ending, first, steps, .. } => {
            let list = std::iter::once(*first as i64).chain(steps.iter().map(|&j| j as i64)).collect();
            Some(Followed::Prefix(list, end_of(*ending, b, graph)?))
        }
        LeafText::Tree(next) => {
            if graph.is_none() && tree::has_rest(next) {
                return None;
            }
            let end = move |then: &Then| end_of(ending(then), b, graph).expect("the graph is present");
            Some(Followed::Tree(next, Box::new(end)))
        }
        LeafText::Undecided => None,
    }
}

/// Rule B4 at the leaf's sample drops: the largest time to rest over h (CC leaves).
fn sample_leaf(b: &Basin, graph: Option<&Graph>, path: &[u8], t: &LeafText) -> Checked<Option<Num>> {
    if !path.iter().all(u8::is_ascii_digit) {
        return Ok(None); // not a leaf of the box (rule B3)
    }
    let Some(how) = followed(b, graph, t) else { return Ok(None) };
    let (lo, hi) = leaf_box(&b.lo, &b.hi, path);
    let mut worst: Option<Num> = None;
    for m in leaf_points(&lo, &hi) {
        let Some((q, p)) = drop_state(&b.body, &m, &lo, &hi) else { continue };
        let time = match &how {
            Followed::Prefix(list, end) => follow(&b.body, q, p, list, *end)?,
            Followed::Tree(next, end) => follow_tree(&b.body, &q, &p, next, end.as_ref())?,
        };
        if let Some(t) = time {
            worst = Some(match worst {
                Some(w) if w >= t => w,
                _ => t,
            });
        }
    }
    Ok(worst)
}

/// The codes of every failing rule, each evaluated on its own where it can be (for the test that a
/// corpus file breaks one rule only): B1 with O1 and B2's comparisons (the first failure), B3 (it
/// needs only the paths), and where B1 holds, O2 at the orbit's sample points, the embedded
/// time-to-rest certificate's rules, and B4 at the leaves' drops (`Rest` leaves whenever that
/// certificate's nodes pass their numbers, G1 and G2, which give the cones and Φ).
pub fn every_failure(v: &Value) -> Checked<Vec<&'static str>> {
    let f = read(v)?;
    let mut out = vec![];
    let mut collect = |r: Checked<()>| {
        if let Err(e) = r {
            out.extend(e.codes.into_iter().filter(|c| !out.contains(c)).collect::<Vec<_>>());
        }
    };
    let rules = rules(&f, &Limits::default());
    collect(rules.as_ref().map(|_| ()).map_err(Clone::clone));
    collect(partition(&paths(&f)));
    if let Ok(b) = &rules {
        collect(b.orbit.as_ref().map_or(Ok(()), orbit::check));
        let graph = rest_rules(&f, &b.limits);
        collect(graph.as_ref().map(|_| ()).map_err(Clone::clone));
        let graph = match graph {
            Ok(g) => g,
            Err(_) => f.rest.as_ref().and_then(|(_, r)| rest::prepare(r, &b.limits).ok()),
        };
        collect(leaves(&f, b, graph.as_ref()).map(|_| ()));
    }
    Ok(out)
}

/// A rational lower bound of an exact time (within 2^-64), as canonical text: the kernel's
/// `time_to_rest_bound` must be at least this.
pub fn time_text(x: &Num) -> String {
    rational_text(&x.enclosure(64).0)
}

/// n as written.
pub fn n(f: &BasinFile) -> u64 {
    f.n
}
