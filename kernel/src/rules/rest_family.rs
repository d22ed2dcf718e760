//! Time-to-rest certificates of a general convex body (feature `family-rest`;
//! docs/certificate-format.md §17, why: docs/kernel-soundness.md §10, "General bodies", and
//! docs/time-to-rest.md §5, Theorem 5.2): a virtual-time graph whose nodes carry the contact of
//! the last impact, in the paper's coordinates, with no relabelling. Rules, in the order they
//! are checked:
//!
//! - the file: the header, claim `CcOrPccFromAllDown` or `CompleteChatterFromAllDown`
//!   (`unknown-variant`), at most 64 contacts (`unsupported-body`), at most max-generators nodes
//!   and generators per node, the total digits (`too-large`);
//! - γ: a number, or in version 2 an interval [γ₀, γ₁] (`unsupported-version` in version 1)
//!   with canonical ends and γ₀ <= γ₁ (`parameter-out-of-range`), as for family certificates;
//! - the body at each end of γ in turn: the family certificates' body rules (A1), (A2), J
//!   positive definite, K0 with `inertia_tensor` (at the first end), and 0 < γ < 1;
//! - entries: one per contact (`wrong-arity`), `entries[i]` a node of contact i
//!   (`missing-successor`);
//! - each node r: its contact i(r) < n (`parameter-out-of-range`), then G1, G2 and F of
//!   [`super::rest`] with the rest points m_{i,i+1}, m_{i-1,i} of contact i (none of these
//!   depends on γ); then the number B;
//! - then at γ₀, then at γ₁ (a failure at an end of an interval names the end in its locus):
//!   - G3: for every j != i(r) with K_r ∩ C_{i(r)j} not {0}, a successor s with i(s) = j
//!     (`missing-successor`); on each vertex p of K_r ∩ C_{i(r)j}, I_j p is 0 or lies in K_s with
//!     v < 0 (`image-outside`, `image-not-below`), and for q in {m_{j-1,j}, m_{j,j+1}}:
//!     (a_s·q)(-b_r·p) <= (a_r·q)(-b_s·I_j p) (`virtual-time-increases`);
//!   - G4: I_i(-m_{k,k+1}) ∈ K_e, e = `entries[i]`, for every i and k (`initial-outside`);
//!   - G5: B (-b_e·I_i(-m_{k,k+1})) >= a_e·m for e = `entries[i]`, every k and m in {m_{i,i+1},
//!     m_{i-1,i}} (`bound-too-small`);
//!   - K4 (`CompleteChatterFromAllDown`): PCC excluded for every adjacent pair, as for family
//!     certificates.

use super::cone::{R2, Target, check_image, int_mat, int_vec};
use super::family::{all_down, body, cone, derived, gammas, pcc};
use super::rest::{Failure, Rationals, Read, Rested, bound_at, decreases, fail, node_forms, triple};
use crate::exact::{Field, ParseLimits, Ring};
use crate::geometry::{Scalar, clip};
use crate::model::convex::{ConvexBody, ConvexBodyError, MAX_CONTACTS};
use crate::model::linalg::{Vec3, mat_vec};
use crate::reject::{Code, Counted, KindDetail, KindInternal, KindLocus, Locus, Rejection};
use crate::syntax::cone::{Claim, Param};
use crate::syntax::family::ConvexBodyText;
use crate::syntax::numbers::{at_most, in_time, number, total};
use crate::syntax::rest_family::{FamilyNode, FamilyTimeToRest, INTERVAL_VERSION};
use crate::syntax::{Kind, expect};
use std::marker::PhantomData;

/// Checks a time-to-rest certificate of a general body on the backend `F`. With γ an interval
/// [γ₀, γ₁] (version 2): the body at both ends, then the graph (which does not depend on γ),
/// then G3 to K4 at γ₀ and at γ₁ (why the two ends suffice: docs/kernel-soundness.md §10,
/// "General bodies").
pub fn check<F: Field>(cert: &FamilyTimeToRest, limits: ParseLimits) -> Result<Rested, Rejection> {
    file(cert, limits)?;
    let ConvexBodyText::ConvexPolygon { gamma, .. } = &cert.body;
    let ends = gammas::<F>(gamma, cert.version == INTERVAL_VERSION, cert.version, limits)?;
    let bodies = (ends.iter().enumerate())
        .map(|(k, (g, path))| convex_body::<F>(cert, (g, path), k == 0, limits))
        .collect::<Result<Vec<_>, _>>()?;
    let n = bodies[0].n();
    entries(cert, n)?;
    let nums = Rationals::<F>(limits, PhantomData);
    let graph: Vec<Read<F>> = (cert.nodes.iter().enumerate())
        .map(|(r, node)| read(&bodies[0], r, node, &nums))
        .collect::<Result<_, _>>()?;
    let bound: F = number("bound", &cert.bound, limits)?;
    let interval = matches!(gamma, Param::Interval(..));
    for ((g, _), body) in ends.iter().zip(&bodies) {
        let end = interval.then(|| g.text());
        at_gamma(body, cert, (&graph, &bound), limits).map_err(|e| at_end(e, end))?;
    }
    let gamma_interval = interval.then(|| [0, ends.len() - 1].map(|k| ends[k].0.text()));
    let (claim, bound) = (cert.claim, cert.bound.clone());
    Ok(Rested { claim, n: n as u64, bound, nodes: graph.len(), region: None, gamma_interval })
}

/// G3, G4, G5 and K4 at one γ.
fn at_gamma<F: Field>(
    body: &ConvexBody<F>,
    cert: &FamilyTimeToRest,
    (graph, bound): (&[Read<F>], &F),
    limits: ParseLimits,
) -> Result<(), Rejection> {
    for r in 0..graph.len() {
        transitions(body, cert, graph, r, limits)?;
    }
    for (i, &e) in cert.entries.iter().enumerate() {
        all_down(body, i, &graph[e].cone)?;
        let maps = (&body.impact(i as i64), &body.all_down_generators()[..]);
        bound_at(&graph[e], maps, heights(body, i), bound, e)?;
    }
    if cert.claim == Claim::CompleteChatterFromAllDown {
        (0..body.n()).try_for_each(|k| pcc(body, k))?;
    }
    Ok(())
}

/// A rejection at one end of an interval of γ: the end's value in the locus.
fn at_end(e: Rejection, end: Option<String>) -> Rejection {
    let mut e = super::family::at_end(e, end.clone());
    if let Locus::Kind(KindLocus::RestNode { gamma, .. }) = &mut e.locus {
        *gamma = end.map(String::into_boxed_str);
    }
    e
}

/// The file's rules: the header, a claim about drops, the limits.
fn file(cert: &FamilyTimeToRest, limits: ParseLimits) -> Result<(), Rejection> {
    expect(&cert.format, cert.version, Kind::RestFamily)?;
    if !matches!(cert.claim, Claim::CcOrPccFromAllDown | Claim::CompleteChatterFromAllDown) {
        return Err(fail(Code::UnknownVariant, None, Failure::Claim(cert.claim)));
    }
    let ConvexBodyText::ConvexPolygon { contacts, .. } = &cert.body;
    if contacts.len() > MAX_CONTACTS {
        let detail = KindDetail::Convex(ConvexBodyError::TooManyContacts(contacts.len()));
        return Err(Rejection::at(Code::UnsupportedBody, "body.contacts", detail));
    }
    at_most("max-generators", cert.nodes.len(), limits.max_generators, Counted::Generators)?;
    total(cert.numbers(), limits)
}

/// The body at one γ (at `path`): the family certificates' body rules, K0 (at the first end
/// only: it does not depend on γ), and 0 < γ < 1.
fn convex_body<F: Field>(
    cert: &FamilyTimeToRest,
    (gamma, path): (&F, &str),
    first: bool,
    limits: ParseLimits,
) -> Result<ConvexBody<F>, Rejection> {
    let ConvexBodyText::ConvexPolygon { inertia_tensor, .. } = &cert.body;
    let body = body::<F>(&cert.body, gamma.clone(), path, limits)?;
    if let (true, Some(t)) = (first, inertia_tensor) {
        derived(&body, t, limits)?;
    }
    super::body::gamma_range(body.gamma(), path, cert.claim)?;
    Ok(body)
}

/// One entry node per contact, `entries[i]` of contact i.
fn entries(cert: &FamilyTimeToRest, n: usize) -> Result<(), Rejection> {
    if cert.entries.len() != n {
        let detail = KindDetail::Rest(Failure::Entries(cert.entries.len(), n));
        return Err(Rejection::at(Code::WrongArity, "entries", detail));
    }
    for (i, &e) in cert.entries.iter().enumerate() {
        if cert.nodes.get(e).is_none_or(|node| node.contact != i) {
            let named = cert.nodes.get(e).map(|node| (e, node.contact));
            let detail = KindDetail::Rest(Failure::Entry(i, named));
            return Err(Rejection::at(Code::MissingSuccessor, format!("entries[{i}]"), detail));
        }
    }
    Ok(())
}

/// m_{i,i+1} and m_{i-1,i}: the rest points of the configurations after an impact at contact i.
fn heights<F: Field>(body: &ConvexBody<F>, i: usize) -> [Vec3<F>; 2] {
    let i = i as i64;
    [body.edge_rest_point(i).clone(), body.edge_rest_point(i - 1).clone()]
}

/// Reads node r: its contact, K_r (K1's checks), b_r, a_r; then G1, G2 and F.
fn read<'a, F: Field>(
    body: &ConvexBody<F>,
    r: usize,
    node: &'a FamilyNode,
    nums: &Rationals<F>,
) -> Result<Read<'a, F>, Rejection> {
    let limits = nums.0;
    if node.contact >= body.n() {
        let detail = KindDetail::Rest(Failure::Contact(node.contact, body.n()));
        return Err(Rejection::at(Code::ParameterOutOfRange, format!("nodes[{r}].contact"), detail));
    }
    at_most("max-generators", node.cone.len(), limits.max_generators, Counted::Generators)?;
    let names = &["omega_x", "omega_y", "v"];
    let gens = super::generators::read::<F>(&node.cone, names, |i| format!("nodes[{r}].cone[{i}]"), limits)?;
    let cone =
        cone::<F>(r, &gens).map_err(|e| Rejection { locus: super::rest::locus(r, None, None), ..e })?;
    let path = |name: &str| format!("nodes[{r}].{name}");
    let weight = triple(&node.weight, &["b0", "b1", "b2"], &path("weight"), nums)?;
    let numerator = triple(&node.numerator, &["a0", "a1", "a2"], &path("numerator"), nums)?;
    let read = Read { cone, weight, numerator, next: &node.next };
    node_forms(&read, &gens, heights(body, node.contact), None, r)?;
    Ok(read)
}

/// G3 on node r: for each contact j != i(r) with K_r ∩ C_{i(r)j} not {0}, a successor of
/// contact j, containment of the images in its cone, and the virtual time.
fn transitions<F: Field>(
    body: &ConvexBody<F>,
    cert: &FamilyTimeToRest,
    graph: &[Read<F>],
    r: usize,
    limits: ParseLimits,
) -> Result<(), Rejection> {
    let i = cert.nodes[r].contact;
    for j in (0..body.n()).filter(|&j| j != i) {
        let Some(covectors) = body.next_contact_cone(i as i64, j as i64) else {
            return Err(Rejection::new(Code::Internal, Locus::Nowhere, KindInternal::NoCone(i, j)));
        };
        let piece =
            covectors.iter().fold(graph[r].cone.polygon.vertices.clone(), |p, l| clip(&p, &int_vec(l)));
        if piece.iter().all(|p| p.iter().all(Ring::is_zero)) {
            continue;
        }
        let to = graph[r].next.iter().find(|(step, _)| *step == j as u64).map(|&(_, s)| s);
        let s = to.filter(|&s| cert.nodes.get(s).is_some_and(|x| x.contact == j)).ok_or_else(|| {
            fail(Code::MissingSuccessor, Some((r, Some(j as u64), None)), Failure::Successor(j as u64, to))
        })?;
        let impact = body.impact(j as i64);
        let qs = [body.edge_rest_point(j as i64 - 1).clone(), body.edge_rest_point(j as i64).clone()];
        for (v, p) in piece.iter().enumerate() {
            in_time(limits, "checking the virtual time (rule G3)")?;
            let at = |outside| {
                Locus::Kind(KindLocus::RestNode {
                    node: r,
                    step: Some(j as u64),
                    vertex: Some(v),
                    outside,
                    corner: None,
                    gamma: None,
                })
            };
            let t = Target { point: p, locus: &at, codes: R2, n: body.n() };
            check_image::<F>(&graph[s].cone, &mat_vec(&int_mat(&impact), p), &t)?;
            let p: Vec3<F> = std::array::from_fn(|k| <F as Scalar>::lift(&p[k]));
            decreases((None, &impact), qs.clone(), (&graph[r], &graph[s]), &p, (r, j as u64, v))?;
        }
    }
    Ok(())
}
