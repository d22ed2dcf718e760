//! Time-to-rest certificates (feature `rest`; docs/certificate-format.md §16, why:
//! docs/kernel-soundness.md §9 and docs/time-to-rest.md Theorem 5.1): a virtual-time graph of a
//! regular polygon at a point. Rules, in the order they are checked:
//!
//! - the file: the header, claim `CcOrPccFromAllDown` or `CompleteChatterFromAllDown`
//!   (`unknown-variant`), at most max-generators nodes and generators per node, the total digits
//!   (`too-large`);
//! - a box (κ or γ an interval): the rules of [`super::rest_box`] (feature `boxes`, else
//!   `unsupported-version`), which run the rules below at the box's corners;
//! - the numbers: canonical rationals for n = 3, 4, 6; for irrational cos(2 pi/n) the rules of
//!   [`super::rest_field`] (feature `field`, else `unsupported-body`): canonical elements of
//!   Q(cos 2 pi/n) (docs/certificate-format.md §12) in a file of version 3 or more, and the
//!   rules below run over that field;
//! - a body at a point (`parameter-out-of-range`) with 0 < γ < 1;
//! - G1: every generator of K_r has v < 0 (`generator-not-below`), K_r has an interior
//!   (`degenerate-cone`), and -b_r·g > 0 (`virtual-time-not-positive`);
//! - the numerator a_r: version 1 gives c_r and a_r = c_r b_r, version 2 gives a_r (the other
//!   field absent: `unknown-field`, `missing-field`); b_r and a_r are read as written;
//! - G2: a_r·m_{0,1} >= 0, a_r·m_{n-1,0} >= 0 (version 1: b_r·m, and c_r >= 1)
//!   (`virtual-time-not-positive`);
//! - F (version 2; implied by c_r >= 1 in version 1): a_r·g <= b_r·g for every generator g of
//!   K_r, so the virtual time falls at least as fast as time in flight (`virtual-time-increases`);
//! - G3: for j = 1..n-1 with K_r ∩ C_j not {0}, a successor s in `next` (`missing-successor`);
//!   on each vertex p of K_r ∩ C_j, S_j p is 0 or lies in K_s with v < 0 (`image-outside`,
//!   `image-not-below`), and for q in {m_{j-1,j}, m_{j,j+1}}:
//!   (a_s·R_j q)(-b_r·p) <= (a_r·q)(-b_s·S_j p) (`virtual-time-increases`);
//! - G4: I_0(-m_{k,k+1}) ∈ K_0 for every k (`initial-outside`);
//! - G5: B (-b_0·I_0(-m_{k,k+1})) >= a_0·m for every k and m in {m_{0,1}, m_{n-1,0}}
//!   (`bound-too-small`);
//! - R4 (`CompleteChatterFromAllDown`): PCC excluded (`pcc-not-excluded`), as for cone certificates.

use super::body::{body_error, gamma_range};
use super::cone::{self as cone_rules, Cone, R2, Target, check_image, int_mat};
use super::generators::{self, Generators};
use crate::exact::{Field, ParseLimits, Ring};
use crate::geometry::Scalar;
use crate::model::linalg::{Mat3, Vec3, dot, mat_vec, neg};
use crate::model::polygon::{BodyError, Polygon, is_irrational};
use crate::reject::{Code, Counted, Detail, KindDetail, KindLocus, Locus, Rejection};
use crate::syntax::cone::{Body, Claim, Generator, Param};
use crate::syntax::numbers::{at_most, in_time, number, total};
use crate::syntax::rest::{Node, TimeToRest};
use crate::syntax::{Kind, expect};
use std::marker::PhantomData;

/// What an accepted time-to-rest certificate established.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Rested {
    /// The claim (with PCC excluded for `CompleteChatterFromAllDown`).
    pub claim: Claim,
    /// Number of contacts.
    pub n: u64,
    /// B, canonical text: T <= B h/|v| for every all-down drop.
    pub bound: String,
    /// Number of nodes.
    pub nodes: usize,
    /// On a box: [kappa, gamma] as [lo, hi] canonical text (docs/certificate-format.md §16).
    pub region: Option<[[String; 2]; 2]>,
    /// A general body over an interval of γ: [lo, hi] canonical text (§17, version 2).
    pub gamma_interval: Option<[String; 2]>,
}

/// Why a time-to-rest certificate is rejected (besides the shared codes), with the exact values.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Failure {
    /// The claim is not about all-down drops.
    Claim(Claim),
    /// κ or γ is an interval.
    NotAtPoint,
    /// A box of parameters in a file of this version (boxes need version 3).
    BoxVersion(u64),
    /// G1: -b_r·g <= 0 at generator `.0` of K_r; `.1` its value at the generator scaled to v = -1.
    Denominator(usize, String),
    /// G2: a_r·m < 0 (version 1: b_r·m) at m_{i,i+1} (`.0` true) or m_{i-1,i}, i the node's
    /// last contact (0 in a regular polygon's frame); `.1` its value.
    Height(bool, String),
    /// G2: c_r < 1.
    Scale(String),
    /// F: a_r·g > b_r·g at generator `.0` of K_r; both sides, at g scaled to v = -1.
    Flight(usize, String, String),
    /// A node has the field `.0` of the other version (`.1`: it is present).
    Version(&'static str, bool),
    /// G3: no successor for step `.0`, or one (`.1`) naming no node (a general body: no node of
    /// contact `.0`); step 0: no node at all.
    Successor(u64, Option<usize>),
    /// G3: the inequality fails at q = m_{j-1,j} (`.0` true) or m_{j,j+1}; both sides, at the
    /// vertex p scaled to v = -1.
    Increases(bool, String, String),
    /// G5 fails at generator `.0` of D: B (-b_0·I_0 g) and a_0·m.
    Bound(usize, String, String),
    /// A general body's entry of contact `.0` names no node of that contact (`.1`: the node it
    /// names and that node's contact).
    Entry(usize, Option<(usize, usize)>),
    /// A general body's file lists `.0` entries for `.1` contacts.
    Entries(usize, usize),
    /// A general body's node names contact `.0`, and the body has `.1` contacts.
    Contact(usize, usize),
}

/// Checks a time-to-rest certificate on the backend `F`: the file's rules, then the graph's over
/// the rationals (n = 3, 4, 6) or over Q(cos 2π/n) (feature `field`).
pub fn check<F: Field>(cert: &TimeToRest, limits: ParseLimits) -> Result<Rested, Rejection> {
    file(cert, limits)?;
    let Body::RegularPolygon { kappa, gamma, .. } = &cert.body;
    if matches!(kappa, Param::Interval(..)) || matches!(gamma, Param::Interval(..)) {
        return on_box::<F>(cert, limits);
    }
    if is_irrational(contacts(cert)) {
        return in_field::<F>(cert, limits);
    }
    let nums = Rationals::<F>(limits, PhantomData);
    at_point(&body(cert, &nums, Polygon::new)?, cert, &nums)
}

#[cfg(feature = "boxes")]
use super::rest_box::on_box;

/// Without the feature `boxes`, a box of parameters is not built (`unsupported-version`).
#[cfg(not(feature = "boxes"))]
#[allow(clippy::extra_unused_type_parameters)] // the signature of the box path's
fn on_box<F: Field>(cert: &TimeToRest, _: ParseLimits) -> Result<Rested, Rejection> {
    let detail = Detail::Needs(crate::reject::Needs::Feature("boxes"), cert.version);
    Err(Rejection::at(Code::UnsupportedVersion, "version", detail))
}

/// n.
pub(super) fn contacts(cert: &TimeToRest) -> u64 {
    let Body::RegularPolygon { n, .. } = cert.body;
    n
}

/// The file's rules: the header, a claim about drops, the limits.
pub(super) fn file(cert: &TimeToRest, limits: ParseLimits) -> Result<(), Rejection> {
    expect(&cert.format, cert.version, Kind::Rest)?;
    if !matches!(cert.claim, Claim::CcOrPccFromAllDown | Claim::CompleteChatterFromAllDown) {
        return Err(fail(Code::UnknownVariant, None, Failure::Claim(cert.claim)));
    }
    at_most("max-generators", cert.nodes.len(), limits.max_generators, Counted::Generators)?;
    total(cert.numbers(), limits)
}

#[cfg(feature = "field")]
use super::rest_field::in_field;

/// Without the feature `field`, irrational cos(2π/n) is not built (`unsupported-body`).
#[cfg(not(feature = "field"))]
#[allow(clippy::extra_unused_type_parameters)] // the signature of the field path's
fn in_field<F: Field>(cert: &TimeToRest, _: ParseLimits) -> Result<Rested, Rejection> {
    let detail = Detail::Needs(crate::reject::Needs::Feature("field"), cert.version);
    Err(Rejection::at(Code::UnsupportedBody, "body.n", detail))
}

/// The oldest version of the file that may be about a body with irrational cos(2π/n).
pub const FIELD_VERSION: u64 = 3;

/// Rules G1 to G5 on the body.
pub(super) fn graph<N: Numbers>(
    body: &Polygon<N::E>,
    cert: &TimeToRest,
    nums: &N,
) -> Result<Rested, Rejection> {
    let graph: Vec<Read<N::E>> = (cert.nodes.iter().enumerate())
        .map(|(r, n)| read(body, (r, cert.version), n, nums))
        .collect::<Result<_, _>>()?;
    for r in 0..graph.len() {
        transitions(body, &graph, r, nums.limits())?;
    }
    cone_rules::all_down(body, &graph.first().ok_or_else(no_nodes)?.cone)?;
    bound_holds(body, &graph[0], &nums.rational("bound", &cert.bound)?)?;
    Ok(Rested {
        claim: cert.claim,
        n: contacts(cert),
        bound: cert.bound.clone(),
        nodes: graph.len(),
        region: None,
        gamma_interval: None,
    })
}

/// Rules G1 to G5, then R4 at the point.
pub(super) fn at_point<N: Numbers>(
    body: &Polygon<N::E>,
    cert: &TimeToRest,
    nums: &N,
) -> Result<Rested, Rejection> {
    let rested = graph(body, cert, nums)?;
    if cert.claim == Claim::CompleteChatterFromAllDown {
        cone_rules::pcc(body)?;
    }
    Ok(rested)
}

/// How a file's numbers are read: canonical rationals (n = 3, 4, 6), or canonical elements of
/// Q(cos 2π/n) (feature `field`).
pub(super) trait Numbers {
    /// The body's scalar.
    type E: Scalar;
    /// The limits of the reading.
    fn limits(&self) -> ParseLimits;
    /// The number at `path`.
    fn number(&self, path: &str, text: &str) -> Result<Self::E, Rejection>;
    /// The rational at `path` (B, in every version).
    fn rational(&self, path: &str, text: &str) -> Result<Self::E, Rejection>;
    /// Vectors (coordinates `names`, vector i at `path(i)`), each as a positive multiple over
    /// the scalar's ring.
    fn vectors<'a>(
        &self,
        written: &'a [Generator],
        names: &'static [&'static str],
        path: &dyn Fn(usize) -> String,
    ) -> Result<Generators<'a, <Self::E as Scalar>::R>, Rejection>;
}

/// Canonical rationals on the backend `F`.
pub(super) struct Rationals<F>(pub(super) ParseLimits, pub(super) PhantomData<F>);

impl<F: Field> Numbers for Rationals<F> {
    type E = F;
    fn limits(&self) -> ParseLimits {
        self.0
    }
    fn number(&self, path: &str, text: &str) -> Result<F, Rejection> {
        number(path, text, self.0)
    }
    fn rational(&self, path: &str, text: &str) -> Result<F, Rejection> {
        number(path, text, self.0)
    }
    fn vectors<'a>(
        &self,
        written: &'a [Generator],
        names: &'static [&'static str],
        path: &dyn Fn(usize) -> String,
    ) -> Result<Generators<'a, F::Int>, Rejection> {
        generators::read::<F>(written, names, path, self.0)
    }
}

/// What a basin certificate's `Rest` leaves need of node r of an accepted graph: the inner
/// normals of K_r's facets (p ∈ K_r iff v < 0 and every `facets[i]·p >= 0`), b_r and a_r.
#[derive(Clone, Debug)]
pub struct NodeForms<F> {
    /// The facets' inner normals, in (u0, u1, v).
    pub facets: Vec<Vec3<F>>,
    /// b_r, applied to velocities.
    pub weight: Vec3<F>,
    /// a_r, applied to configurations (h0, h1, hc).
    pub numerator: Vec3<F>,
}

/// Checks the certificate ([`check`]) and returns every node's forms (docs/basin-certificates.md §4).
pub fn forms<F: Field>(
    cert: &TimeToRest,
    limits: ParseLimits,
) -> Result<(Rested, Vec<NodeForms<F>>), Rejection> {
    let rested = check::<F>(cert, limits)?;
    let nums = Rationals::<F>(limits, PhantomData);
    let body = body(cert, &nums, Polygon::new)?;
    let lift = |v: &Vec3<F::Int>| -> Vec3<F> { std::array::from_fn(|i| F::from_int(&v[i])) };
    let nodes = (cert.nodes.iter().enumerate())
        .map(|(r, n)| {
            let node = read(&body, (r, cert.version), n, &nums)?;
            let facets = node.cone.polygon.facets.iter().map(lift).collect();
            Ok(NodeForms { facets, weight: node.weight, numerator: node.numerator })
        })
        .collect::<Result<_, Rejection>>()?;
    Ok((rested, nodes))
}

/// The body at a point, with 0 < γ < 1, built by `make` from n, κ and γ.
pub(super) fn body<N: Numbers>(
    cert: &TimeToRest,
    nums: &N,
    make: impl FnOnce(u64, N::E, N::E) -> Result<Polygon<N::E>, BodyError>,
) -> Result<Polygon<N::E>, Rejection> {
    let Body::RegularPolygon { n, kappa: Param::Point(k), gamma: Param::Point(g) } = &cert.body else {
        return Err(Rejection::at(Code::ParameterOutOfRange, "body", KindDetail::Rest(Failure::NotAtPoint)));
    };
    let (kappa, gamma) = (nums.number("body.kappa", k)?, nums.number("body.gamma", g)?);
    let body = make(*n, kappa, gamma).map_err(|e| body_error(e, "body.kappa", "body.gamma"))?;
    gamma_range(body.gamma(), "body.gamma", cert.claim)?;
    Ok(body)
}

/// A node read: K_r (R1's checks), b_r, a_r and the successors, over the body's scalar `E`.
pub(super) struct Read<'a, E: Scalar> {
    pub(super) cone: Cone<E::R>,
    pub(super) weight: Vec3<E>,
    pub(super) numerator: Vec3<E>,
    pub(super) next: &'a [(u64, usize)],
}

/// Reads node r of a file of the given version and checks G1, G2 and F on it.
fn read<'a, N: Numbers>(
    body: &Polygon<N::E>,
    (r, version): (usize, u64),
    node: &'a Node,
    nums: &N,
) -> Result<Read<'a, N::E>, Rejection> {
    let (own, other) = if version == 1 { ("scale", "numerator") } else { ("numerator", "scale") };
    let path = |name: &str| format!("nodes[{r}].{name}");
    let (own_absent, other_present) = if version == 1 {
        (node.scale.is_empty(), !node.numerator.0.is_empty())
    } else {
        (node.numerator.0.is_empty(), !node.scale.is_empty())
    };
    let limits = nums.limits();
    at_most("max-generators", node.cone.len(), limits.max_generators, Counted::Generators)?;
    let gens = nums.vectors(&node.cone, &["u0", "u1", "v"], &|i| format!("nodes[{r}].cone[{i}]"))?;
    let cone = cone_rules::cone::<N::E>(&gens).map_err(|e| Rejection { locus: locus(r, None, None), ..e })?;
    if other_present {
        let detail = KindDetail::Rest(Failure::Version(other, true));
        return Err(Rejection::at(Code::UnknownField, path(other), detail));
    }
    if own_absent {
        let detail = KindDetail::Rest(Failure::Version(own, false));
        return Err(Rejection::at(Code::MissingField, path(own), detail));
    }
    let weight = triple(&node.weight, &["b0", "b1", "b2"], &path("weight"), nums)?;
    let scale = if version == 1 { Some(nums.number(&path("scale"), &node.scale)?) } else { None };
    let numerator = match &scale {
        Some(c) => weight.clone().map(|b| b.times(c)),
        None => triple(&node.numerator, &["a0", "a1", "a2"], &path("numerator"), nums)?,
    };
    let read = Read { cone, weight, numerator, next: &node.next };
    node_forms(&read, &gens, [rest(body, 0), rest(body, -1)], scale.as_ref(), r)?;
    Ok(read)
}

/// G1, G2 and F on node r: -b_r·g > 0 on every generator g, a_r·m >= 0 at the two rest points
/// `heights` of the configurations after the node's impact (m_{i,i+1}, m_{i-1,i}; version 1:
/// b_r·m and c_r >= 1), and a_r·g <= b_r·g on every generator.
pub(super) fn node_forms<E: Scalar>(
    node: &Read<'_, E>,
    gens: &Generators<'_, E::R>,
    heights: [Vec3<E>; 2],
    scale: Option<&E>,
    r: usize,
) -> Result<(), Rejection> {
    let (weight, numerator) = (&node.weight, &node.numerator);
    let at = Some((r, None, None));
    let lifted = |g: &[E::R]| -> Vec3<E> { std::array::from_fn(|i| E::lift(&g[i])) };
    for (index, g) in gens.vectors.iter().enumerate() {
        let g = lifted(g);
        let value = dot(weight, &g).negated();
        if !value.is_positive() {
            let failure = Failure::Denominator(index, unit(&value, &g));
            return Err(fail(Code::VirtualTimeNotPositive, at, failure));
        }
    }
    let height = if scale.is_some() { weight } else { numerator };
    for (first, m) in [true, false].into_iter().zip(heights) {
        let value = dot(height, &m);
        if value.is_negative() {
            return Err(fail(Code::VirtualTimeNotPositive, at, Failure::Height(first, value.text())));
        }
    }
    if let Some(c) = scale.filter(|c| *c < &E::one()) {
        return Err(fail(Code::VirtualTimeNotPositive, at, Failure::Scale(c.text())));
    }
    for (index, g) in gens.vectors.iter().enumerate() {
        let g = lifted(g);
        let (a, b) = (dot(numerator, &g), dot(weight, &g));
        if a > b {
            let failure = Failure::Flight(index, unit(&a, &g), unit(&b, &g));
            return Err(fail(Code::VirtualTimeIncreases, at, failure));
        }
    }
    Ok(())
}

/// Three canonical numbers (`wrong-arity` unless there are three).
pub(super) fn triple<N: Numbers>(
    g: &Generator,
    names: &'static [&'static str],
    path: &str,
    nums: &N,
) -> Result<Vec3<N::E>, Rejection> {
    if g.0.len() != 3 {
        return Err(Rejection::at(Code::WrongArity, path, Detail::Arity(names, g.0.len())));
    }
    let x = |i: usize| nums.number(&format!("{path}.{}", names[i]), &g.0[i]);
    Ok([x(0)?, x(1)?, x(2)?])
}

/// G3 on node r: for each step j with K_r ∩ C_j not {0}, containment in K_s and the virtual time.
fn transitions<E: Scalar>(
    body: &Polygon<E>,
    graph: &[Read<E>],
    r: usize,
    limits: ParseLimits,
) -> Result<(), Rejection> {
    let pieces = cone_rules::pieces(body, &graph[r].cone);
    for (j, piece) in (1..).zip(&pieces) {
        if piece.iter().all(|p| p.iter().all(Ring::is_zero)) {
            continue;
        }
        let to = graph[r].next.iter().find(|(step, _)| *step == j).map(|&(_, s)| s);
        let s = to.filter(|&s| s < graph.len()).ok_or_else(|| {
            fail(Code::MissingSuccessor, Some((r, Some(j), None)), Failure::Successor(j, to))
        })?;
        let step = body.step(j as i64);
        for (i, p) in piece.iter().enumerate() {
            in_time(limits, "checking the virtual time (rule G3)")?;
            let at = |outside| {
                Locus::Kind(KindLocus::RestNode {
                    node: r,
                    step: Some(j),
                    vertex: Some(i),
                    outside,
                    corner: None,
                    gamma: None,
                })
            };
            let t = Target { point: p, locus: &at, codes: R2, n: body.n() };
            check_image::<E>(&graph[s].cone, &mat_vec(&int_mat(&step), p), &t)?;
            let p: Vec3<E> = std::array::from_fn(|k| E::lift(&p[k]));
            let maps = (Some(&body.relabel(j as i64)), &body.step(j as i64));
            let qs = [rest(body, j as i64 - 1), rest(body, j as i64)];
            decreases(maps, qs, (&graph[r], &graph[s]), &p, (r, j, i))?;
        }
    }
    Ok(())
}

/// G3's inequality at the vertex p for both generators q of the configurations with h_j = 0
/// (`qs`: m_{j-1,j}, m_{j,j+1}), with the step's maps: R_j on configurations (`None`: the
/// identity, a general body) and S_j on velocities.
pub(super) fn decreases<E: Scalar>(
    (relabel, step): (Option<&Mat3<E>>, &Mat3<E>),
    qs: [Vec3<E>; 2],
    (from, to): (&Read<E>, &Read<E>),
    p: &Vec3<E>,
    (r, j, i): (usize, u64, usize),
) -> Result<(), Rejection> {
    let sp = mat_vec(step, p);
    for (left, q) in [true, false].into_iter().zip(qs) {
        let rq = relabel.map_or_else(|| q.clone(), |m| mat_vec(m, &q));
        let lhs = dot(&to.numerator, &rq).times(&dot(&from.weight, p).negated());
        let rhs = dot(&from.numerator, &q).times(&dot(&to.weight, &sp).negated());
        if lhs > rhs {
            let failure = Failure::Increases(left, unit(&lhs, p), unit(&rhs, p));
            return Err(fail(Code::VirtualTimeIncreases, Some((r, Some(j), Some(i))), failure));
        }
    }
    Ok(())
}

/// G5: B (-b_0·I_0 g) >= a_0·m for every generator g of D and both m.
fn bound_holds<E: Scalar>(body: &Polygon<E>, entry: &Read<E>, bound: &E) -> Result<(), Rejection> {
    let heights = [rest(body, 0), rest(body, -1)];
    bound_at(entry, (&body.impact(0), &body.all_down_generators()), heights, bound, 0)
}

/// G5 at the entry node `r` of an impact with the map I (`impact`): B (-b_r·I g) >= a_r·m for
/// every generator g of D (`down`) and both rest points m of `heights`.
pub(super) fn bound_at<E: Scalar>(
    entry: &Read<E>,
    (impact, down): (&Mat3<E>, &[Vec3<E>]),
    heights: [Vec3<E>; 2],
    bound: &E,
    r: usize,
) -> Result<(), Rejection> {
    let heights = heights.map(|m| dot(&entry.numerator, &m));
    for (generator, g) in down.iter().enumerate() {
        let lhs = bound.times(&dot(&entry.weight, &mat_vec(impact, g)).negated());
        if let Some(rhs) = heights.iter().find(|h| lhs < **h) {
            let failure = Failure::Bound(generator, lhs.text(), rhs.text());
            return Err(fail(Code::BoundTooSmall, Some((r, None, None)), failure));
        }
    }
    Ok(())
}

/// m_{k,k+1} (k mod n): minus generator k of D.
fn rest<E: Scalar>(body: &Polygon<E>, k: i64) -> Vec3<E> {
    neg(&body.all_down_generators()[k.rem_euclid(body.n() as i64) as usize])
}

/// A value linear in the vector x (v < 0), as at x scaled to v = -1: the same for every positive
/// multiple of x, so for the vector as written.
pub(super) fn unit<E: Scalar>(value: &E, x: &Vec3<E>) -> String {
    value.over(&x[2].negated()).unwrap_or_else(|| value.clone()).text()
}

pub(super) fn locus(node: usize, step: Option<u64>, vertex: Option<usize>) -> Locus {
    Locus::Kind(KindLocus::RestNode { node, step, vertex, outside: None, corner: None, gamma: None })
}

pub(super) fn fail(code: Code, at: Option<(usize, Option<u64>, Option<usize>)>, f: Failure) -> Rejection {
    let locus = at.map_or(Locus::Nowhere, |(r, j, i)| locus(r, j, i));
    Rejection::new(code, locus, Detail::Kind(KindDetail::Rest(f)))
}

pub(super) fn no_nodes() -> Rejection {
    fail(Code::MissingSuccessor, None, Failure::Successor(0, None))
}
