//! Basin certificates (feature `basin`; docs/basin-certificates.md, docs/certificate-format.md
//! §15, why: docs/kernel-soundness.md §9). Rules, in the order they are checked:
//!
//! - B1 (the file): the header, `max-total-digits`, the body as in rule O1, the box of drops
//!   (five coordinates, lo < hi, h's lower end > 0), at most [`MAX_LEAVES`] leaves, paths of at
//!   most [`MAX_PATH`] digits, prefixes of at most [`MAX_PREFIX`] impacts, the first contact in
//!   0..n-1 and every later step in 1..n-1 (`basin-out-of-range`);
//! - B2: the embedded orbit certificate (optional: without one, only `Icc`, `Rest` and
//!   `Undecided` leaves without cuts, else `basin-out-of-range`) names the same n, κ and γ
//!   (`basin-out-of-range`) and is accepted by rules O1-O2 (its own rejection otherwise; its
//!   rule O2, the slow one, is checked after B3); the embedded time-to-rest certificate
//!   (optional: without one, no `Rest` leaf, and each `Rest` leaf names one of its nodes, else
//!   `basin-out-of-range`) names the same n, κ and γ at a point and the claim
//!   `CompleteChatterFromAllDown` (`basin-out-of-range`), and is accepted by its own rules
//!   (G1-G5, F, R4; its own codes, after B3 and O2);
//! - B3: the leaves' paths are the leaves of one bisection tree of the box (`not-a-partition`);
//! - B4: on every leaf with a verdict, by exact interval arithmetic with outward rounding over
//!   the whole leaf (mean-value form, no subdivision): every contact strictly up at the start, the
//!   prefix forced at every impact (condition 1 of the orbit certificates, the same quantities),
//!   and at its end either the normalised state in X (`Cc`: hc > 0, -v > 0, |y_i| <= δ), or
//!   the velocity in the cone of a node r of the graph (`Rest`: hc > 0, -v > 0, -b_r·p > 0 and
//!   every facet of K_r >= 0), or v > 0 (`Icc`); a quantity not shown rejects the certificate
//!   (`leaf-not-shown`).
//!
//! The report: the shares of the box (exact, 2^-depth per leaf) proved CC, proved v > 0, and
//! undecided (`Cc` and `Rest` leaves are CC), and the largest bound on the time to rest over the
//! CC leaves.

use crate::basin::drop::{DIMS, Over, cos_sin, seeds, state};
use crate::basin::tree::{TreeError, partition};
use crate::exact::{Field, ParseLimits, to_canonical};
use crate::model::polygon::BodyError;
use crate::orbit::constants::enclosed_maps;
use crate::orbit::interval::{Centred, Iv, round_up};
use crate::orbit::map::Maps;
use crate::orbit::map::{Quantity, Stop, step};
use crate::reject::{Code, Detail, KindCounted, KindDetail, KindLocus, Locus, Rejection};
use crate::rules::branches::{self, Frame};
use crate::rules::orbit::{Orbit, cover, read_orbit_values};
use crate::rules::rest::{NodeForms, forms};
use crate::syntax::basin::{BasinCertificate, LeafVerdict};
use crate::syntax::cone::{Body, Claim, Param};
use crate::syntax::numbers::{at_most, in_time, number, total};
use crate::syntax::orbit::OrbitBody;
use crate::syntax::{Kind, expect};

/// The most leaves a certificate may have (limit `max-basin-leaves`).
pub const MAX_LEAVES: usize = 1 << 20;
/// The longest path (limit `max-basin-depth`).
pub const MAX_PATH: usize = 64;
/// The longest prefix of impacts (limit `max-basin-prefix`).
pub const MAX_PREFIX: usize = 4096;

/// Why a basin certificate is rejected (besides numbers, limits and the orbit certificate's own).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Failure {
    /// The orbit certificate's body differs from the basin's.
    OrbitBody,
    /// n is not modelled (3..=MAX_N with feature `field`, else 3, 4 or 6).
    Unsupported(u64),
    /// A `Cc` leaf, or cuts, without an orbit certificate.
    NoOrbit,
    /// `drops.lo` or `drops.hi` does not have five coordinates (the length found).
    Coordinates(usize),
    /// lo >= hi in this coordinate, or h's lower end <= 0 (coordinate 4).
    Flat(usize),
    /// The first contact is not in 0..n-1.
    First {
        /// The contact.
        first: u64,
        /// n.
        n: u64,
    },
    /// A step j not in 1..n-1.
    Step {
        /// The step.
        step: u64,
        /// n.
        n: u64,
    },
    /// The cuts are not strictly increasing impact counts in 1..=the prefix's length.
    Cuts,
    /// A `Rest` leaf without a time-to-rest certificate.
    NoRest,
    /// The time-to-rest certificate's body is not the basin's at a point.
    RestBody,
    /// The time-to-rest certificate's claim does not exclude PCC.
    RestClaim(Claim),
    /// A `Rest` leaf names a node the graph does not have.
    Node {
        /// The node named.
        node: u64,
        /// The graph's nodes.
        nodes: usize,
    },
    /// The paths are not a partition.
    Tree(TreeError),
    /// A `Tree` leaf in a version-1 file.
    TreeVersion,
    /// A `Tree` leaf's list of impacts is empty.
    EmptyBranch,
    /// A contact repeated in one list of a `Tree` leaf.
    RepeatedContact {
        /// The contact.
        contact: u64,
    },
    /// A `Tree` leaf ends in `Icc` on one path and in `Cc` or `Rest` on another.
    MixedEnds,
    /// A failure inside a `Tree` leaf, after these impacts from its root (the root: none).
    InTree {
        /// The contacts of the impacts from the root (the first absolute, the others steps).
        impacts: Vec<u64>,
        /// The failure there.
        failure: Box<Failure>,
    },
    /// A quantity of rule B4 not shown on the leaf (`wrong`: its sign is wrong at the centre).
    Leaf {
        /// The quantity.
        quantity: LeafQuantity,
        /// Whether its sign is wrong at the leaf's centre.
        wrong: bool,
    },
}

/// A quantity of rule B4 that must be positive (non-negative for [`Quantity::Inside`]) on a leaf.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LeafQuantity {
    /// h_k > 0 before the first impact.
    Start {
        /// The contact.
        contact: usize,
    },
    /// A quantity of an impact of the prefix (condition 1 of orbit certificates; step 0 is the
    /// first impact, at its absolute contact).
    Prefix(Quantity),
    /// Entry into X: hc > 0, -v > 0, δ ∓ y_i >= 0 ([`Quantity::PositionScale`],
    /// [`Quantity::VelocityScale`], [`Quantity::Inside`]).
    Entry(Quantity),
    /// At the cut after this many impacts: hc > 0 or -v > 0 ([`Quantity::PositionScale`],
    /// [`Quantity::VelocityScale`]).
    Cut {
        /// The impacts before the cut.
        impacts: usize,
        /// The quantity.
        quantity: Quantity,
    },
    /// v > 0 after the prefix.
    Separates,
    /// After the prefix, facet `facet` of node `node`'s cone K_r is >= 0 at the velocity.
    InCone {
        /// The node r.
        node: usize,
        /// The facet (the edge from its generator `facet` to the next, counter-clockwise).
        facet: usize,
    },
    /// After the prefix, -b_r·p > 0 (the virtual time's denominator).
    RestTime {
        /// The node r.
        node: usize,
    },
    /// In a `Tree` leaf, at step `step`: contact `contact`, not in the list, neither rises
    /// (u > 0) nor is shown to land after a contact of the list.
    Excluded {
        /// The step (from 0).
        step: usize,
        /// The contact (absolute at step 0, else relative to the one that landed last).
        contact: usize,
    },
}

impl LeafQuantity {
    fn strict(self) -> bool {
        !matches!(self, LeafQuantity::Entry(Quantity::Inside { .. }) | LeafQuantity::InCone { .. })
    }
}

pub(super) fn fail(code: Code, path: &str, f: Failure) -> Rejection {
    Rejection::at(code, path, Detail::Kind(KindDetail::Basin(f)))
}

/// What an accepted basin certificate established (shares of the box's volume, canonical text).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BasinReport {
    /// n.
    pub n: u64,
    /// The share of drops proved to enter X or a cone of the graph: complete chatter.
    pub cc_share: String,
    /// The share of drops proved to reach v > 0: they never come to rest (ICC).
    pub icc_share: String,
    /// The share with no verdict.
    pub undecided_share: String,
    /// Leaves: CC, ICC, undecided.
    pub leaves: [usize; 3],
    /// Of these, the `Tree` leaves (version 2; their drops that meet a simultaneous impact inside
    /// the tree are not claimed: volume zero).
    pub trees: usize,
    /// The largest bound, over the CC leaves, on the time to rest divided by the drop's h/|v|
    /// (prefix time + B hc/|v| at entry into X, B the orbit certificate's `time_to_rest_bound`;
    /// prefix time + Φ_r(q, p) at entry into K_r).
    pub time_to_rest_bound: Option<String>,
    /// The sub-boxes of X on which the orbit certificate's conditions were shown.
    pub orbit_boxes: usize,
}

/// Checks a basin certificate exactly over the field `F`: rules B1-B4.
pub fn check<F: Field>(cert: &BasinCertificate, limits: ParseLimits) -> Result<BasinReport, Rejection> {
    let (maps, orbit, lo, hi) = read::<F>(cert, limits)?;
    // B3 before B2's rule O2: a partition is checked in microseconds, O2 in seconds.
    partition(cert.leaves.iter().map(|l| l.path.as_str()), DIMS)
        .map_err(|e| fail(Code::NotAPartition, "leaves", Failure::Tree(e)))?;
    let orbit_boxes = match &orbit {
        Some(o) => cover(o, limits)?,
        None => 0,
    };
    let rest = match &cert.rest {
        Some(r) => Some(forms::<F>(r, limits)?.1),
        None => None,
    };
    let ctx = Context::new(maps, orbit).with_rest(rest);
    let (mut shares, mut counts, mut worst) = ([F::zero(), F::zero(), F::zero()], [0usize; 3], None::<F>);
    let mut trees = 0;
    for (i, leaf) in cert.leaves.iter().enumerate() {
        in_time(limits, "checking the leaves of a basin certificate")?;
        let kind = kind(&leaf.verdict);
        let (l, h) = leaf_box(&lo, &hi, &leaf.path);
        let shown = match &leaf.verdict {
            LeafVerdict::Tree { next } => Some(branches::examine(&ctx, &l, &h, next)),
            verdict => Prefix::of(verdict).map(|prefix| ctx.leaf(&l, &h, &prefix)),
        };
        if let Some(time) = shown {
            let detail = |f: Failure| Detail::Kind(KindDetail::Basin(f));
            let at = |f| Rejection::new(Code::LeafNotShown, leaf_locus(i, &leaf.path), detail(f));
            record(&mut worst, time.map_err(at)?);
        }
        trees += usize::from(matches!(leaf.verdict, LeafVerdict::Tree { .. }));
        counts[kind] += 1;
        let share = F::from_fraction(&crate::exact::Ring::one(), &pow2::<F>(leaf.path.len()));
        shares[kind] = shares[kind].plus(&share);
    }
    let [cc, icc, und] = shares.map(|s| to_canonical(&s));
    Ok(BasinReport {
        n: ctx.maps.n as u64,
        cc_share: cc,
        icc_share: icc,
        undecided_share: und,
        leaves: counts,
        trees,
        time_to_rest_bound: worst.map(|w| to_canonical(&w)),
        orbit_boxes,
    })
}

/// How a leaf's verdict counts: 0 CC (`Cc`, `Rest`, a tree ending in them), 1 ICC (`Icc`, a tree
/// ending in it), 2 undecided. A tree is read by its first end, which rule B1 made every end's kind.
pub fn kind(verdict: &LeafVerdict) -> usize {
    match verdict {
        LeafVerdict::Cc { .. } | LeafVerdict::Rest { .. } => 0,
        LeafVerdict::Icc { .. } => 1,
        LeafVerdict::Undecided => 2,
        LeafVerdict::Tree { next } => usize::from(!branches::ends_cc(next)),
    }
}

/// The enclosure of f·x for a covector f known by enclosures (a contact's height or velocity).
pub(super) fn dot_iv<F: Field>(f: &[Iv<F>; 3], x: &[Over<F>; 3]) -> Over<F> {
    x[0].scaled_by(&f[0]).plus(&x[1].scaled_by(&f[1])).plus(&x[2].scaled_by(&f[2]))
}

/// The largest time to rest over h of the CC leaves so far.
fn record<F: Field>(worst: &mut Option<F>, time: Option<F>) {
    if let Some(t) = time
        && worst.as_ref().is_none_or(|w| &t > w)
    {
        *worst = Some(t);
    }
}

fn pow2<F: Field>(k: usize) -> F::Int {
    use crate::exact::Ring;
    (0..k).fold(F::Int::one(), |acc, _| acc.times(&F::Int::from_i64(2)))
}

fn leaf_locus(leaf: usize, path: &str) -> Locus {
    Locus::Kind(KindLocus::BasinLeaf { leaf, path: path.to_string() })
}

/// Rule B1, B2's comparison of bodies and rule O1 on the orbit certificate: the orbit's checked
/// content and the box of drops.
#[allow(clippy::type_complexity)]
pub fn read<F: Field>(
    cert: &BasinCertificate,
    limits: ParseLimits,
) -> Result<(Maps<Iv<F>>, Option<Orbit<F>>, [F; DIMS], [F; DIMS]), Rejection> {
    expect(&cert.format, cert.version, Kind::Basin)?;
    total(cert.numbers().into_iter().map(|(_, s)| s), limits)?;
    let OrbitBody::RegularPolygon { n, kappa, gamma } = &cert.body;
    let (k, g): (F, F) = (number("body.kappa", kappa, limits)?, number("body.gamma", gamma, limits)?);
    let maps = enclosed_maps(*n, k.clone(), g.clone()).map_err(|e| match e {
        BodyError::UnsupportedN(_) => fail(Code::UnsupportedBody, "body.n", Failure::Unsupported(*n)),
        _ => Rejection::at(Code::ParameterOutOfRange, "body", Detail::Body(e)),
    })?;
    let orbit = match &cert.orbit {
        Some(o) => {
            let OrbitBody::RegularPolygon { n: on, kappa: ok, gamma: og } = &o.body;
            let (ok, og): (F, F) =
                (number("orbit.body.kappa", ok, limits)?, number("orbit.body.gamma", og, limits)?);
            if *n != *on || k != ok || g != og {
                return Err(fail(Code::BasinOutOfRange, "orbit.body", Failure::OrbitBody));
            }
            Some(read_orbit_values::<F>(o, limits)?)
        }
        None => None,
    };
    if let Some(r) = &cert.rest {
        same_body::<F>(&r.body, (*n, &k, &g), limits)?;
        if r.claim != Claim::CompleteChatterFromAllDown {
            return Err(fail(Code::BasinOutOfRange, "rest.claim", Failure::RestClaim(r.claim)));
        }
    }
    let corner = |path: &str, v: &[String]| -> Result<[F; DIMS], Rejection> {
        if v.len() != DIMS {
            return Err(fail(Code::BasinOutOfRange, path, Failure::Coordinates(v.len())));
        }
        let xs: Vec<F> = v
            .iter()
            .enumerate()
            .map(|(i, s)| number(&format!("{path}[{i}]"), s, limits))
            .collect::<Result<_, _>>()?;
        Ok(std::array::from_fn(|i| xs[i].clone()))
    };
    let (lo, hi) = (corner("drops.lo", &cert.drops.lo)?, corner("drops.hi", &cert.drops.hi)?);
    if let Some(i) = (0..DIMS).find(|&i| lo[i] >= hi[i]) {
        return Err(fail(Code::BasinOutOfRange, "drops", Failure::Flat(i)));
    }
    if !lo[4].is_positive() {
        return Err(fail(Code::BasinOutOfRange, "drops.lo[4]", Failure::Flat(4)));
    }
    at_most("max-basin-leaves", cert.leaves.len(), MAX_LEAVES, KindCounted::Leaves.into())?;
    let frame = Frame {
        n: *n,
        version: cert.version,
        orbit: orbit.is_some(),
        nodes: cert.rest.as_ref().map(|r| r.nodes.len()),
    };
    for (i, leaf) in cert.leaves.iter().enumerate() {
        at_most("max-basin-depth", leaf.path.len(), MAX_PATH, KindCounted::Depth.into())?;
        if let LeafVerdict::Tree { next } = &leaf.verdict {
            branches::structure(i, next, &frame)?;
        }
        if let Some(Prefix { first, steps, cuts, end }) = Prefix::of(&leaf.verdict) {
            let (first, cuts) = (first as u64, cuts);
            at_most("max-basin-prefix", steps.len() + 1, MAX_PREFIX, KindCounted::Prefix.into())?;
            prefix(i, first, steps, *n)?;
            if let End::Rest(node) = end {
                rest_node(i, node, cert.rest.as_ref().map(|r| r.nodes.len()))?;
            }
            let cc = end == End::Cc;
            if orbit.is_none() && (cc || !cuts.is_empty()) {
                return Err(fail(Code::BasinOutOfRange, &format!("leaves[{i}]"), Failure::NoOrbit));
            }
            let increasing = cuts.windows(2).all(|w| w[0] < w[1]);
            if !increasing || cuts.iter().any(|&c| c == 0 || c > steps.len() as u64 + 1) {
                return Err(fail(Code::BasinOutOfRange, &format!("leaves[{i}].cuts"), Failure::Cuts));
            }
        }
    }
    Ok((maps, orbit, lo, hi))
}

/// B2: the time-to-rest certificate's body is the basin's, at a point.
fn same_body<F: Field>(body: &Body, (n, k, g): (u64, &F, &F), limits: ParseLimits) -> Result<(), Rejection> {
    let Body::RegularPolygon { n: rn, kappa: Param::Point(rk), gamma: Param::Point(rg) } = body else {
        return Err(fail(Code::BasinOutOfRange, "rest.body", Failure::RestBody));
    };
    let (rk, rg): (F, F) = (number("rest.body.kappa", rk, limits)?, number("rest.body.gamma", rg, limits)?);
    if *rn != n || rk != *k || rg != *g {
        return Err(fail(Code::BasinOutOfRange, "rest.body", Failure::RestBody));
    }
    Ok(())
}

/// B1: a `Rest` leaf needs a time-to-rest certificate with the node it names.
pub(super) fn rest_node(i: usize, node: usize, nodes: Option<usize>) -> Result<(), Rejection> {
    let nodes = nodes.ok_or_else(|| fail(Code::BasinOutOfRange, &format!("leaves[{i}]"), Failure::NoRest))?;
    if node >= nodes {
        let f = Failure::Node { node: node as u64, nodes };
        return Err(fail(Code::BasinOutOfRange, &format!("leaves[{i}].node"), f));
    }
    Ok(())
}

/// The first contact in 0..n-1 and every later step in 1..n-1.
fn prefix(i: usize, first: u64, steps: &[u64], n: u64) -> Result<(), Rejection> {
    if first >= n {
        return Err(fail(Code::BasinOutOfRange, &format!("leaves[{i}].first"), Failure::First { first, n }));
    }
    if let Some(&step) = steps.iter().find(|&&j| j == 0 || j >= n) {
        return Err(fail(Code::BasinOutOfRange, &format!("leaves[{i}].steps"), Failure::Step { step, n }));
    }
    Ok(())
}

/// The leaf's box: the box halved along the path (digit 2k: lower half of coordinate k).
pub fn leaf_box<F: Field>(lo: &[F; DIMS], hi: &[F; DIMS], path: &str) -> ([F; DIMS], [F; DIMS]) {
    let (mut lo, mut hi) = (lo.clone(), hi.clone());
    let two = F::from_i64(2);
    for ch in path.bytes() {
        let d = (ch - b'0') as usize;
        let k = d / 2;
        let mid = lo[k].plus(&hi[k]).over(&two).unwrap_or_else(F::zero);
        if d % 2 == 1 {
            lo[k] = mid;
        } else {
            hi[k] = mid;
        }
    }
    (lo, hi)
}

/// What rule B4 needs of an accepted orbit certificate: its content, (cos, sin) 2π/n enclosed
/// and B = T̄/(1 − ρ).
#[derive(Clone, Debug)]
pub struct Context<F> {
    /// The body's constants.
    pub maps: Maps<Iv<F>>,
    /// The orbit certificate's checked content, if the file has one.
    pub orbit: Option<Orbit<F>>,
    /// The forms of the time-to-rest certificate's nodes, if the file has one (checked by its rules).
    pub rest: Option<Vec<NodeForms<F>>>,
    cs: (Iv<F>, Iv<F>),
    b: F,
}

impl<F: Field> Context<F> {
    /// The context of an orbit certificate's content (rules O1-O2 are the caller's).
    pub fn new(maps: Maps<Iv<F>>, orbit: Option<Orbit<F>>) -> Self {
        let b = orbit.as_ref().and_then(|o| o.period.over(&F::one().minus(&o.rho))).unwrap_or_else(F::zero);
        let cs = cos_sin(&maps);
        Context { maps, orbit, rest: None, cs, b }
    }

    /// The same context with the nodes of an accepted time-to-rest certificate (for `Rest` leaves).
    pub fn with_rest(self, rest: Option<Vec<NodeForms<F>>>) -> Self {
        Context { rest, ..self }
    }

    /// Rule B4 on the leaf [lo, hi]: `Ok(Some(bound))` for a CC leaf (`Cc` or `Rest`; the time
    /// to rest over h/|v|, upper end), `Ok(None)` for an ICC leaf.
    pub fn leaf(&self, lo: &[F; DIMS], hi: &[F; DIMS], prefix: &Prefix<'_>) -> Result<Option<F>, Failure> {
        examine(self, lo, hi, prefix)
    }
}

/// Whether `v` is shown > 0 (>= 0 for the entry into X) over the leaf.
pub(super) fn shown<F: Field, const D: usize>(q: LeafQuantity, v: &Centred<F, D>) -> Result<(), Failure> {
    let ok = if q.strict() { v.b.v.lo.is_positive() } else { !v.b.v.lo.is_negative() };
    let wrong = v.c.hi.is_negative() || (q.strict() && !v.c.hi.is_positive());
    if ok { Ok(()) } else { Err(Failure::Leaf { quantity: q, wrong }) }
}

pub(super) fn unshown(quantity: LeafQuantity) -> Failure {
    Failure::Leaf { quantity, wrong: false }
}

/// Rule B4 on one leaf ([`Context::leaf`]): the first segment over the five coordinates of the
/// drops, the later ones (after each cut) over the three parameters y of X.
fn examine<F: Field>(
    ctx: &Context<F>,
    lo: &[F; DIMS],
    hi: &[F; DIMS],
    plan: &Prefix<'_>,
) -> Result<Option<F>, Failure> {
    let maps = &ctx.maps;
    let list: Vec<usize> =
        std::iter::once(plan.first).chain(plan.steps.iter().map(|&j| j as usize)).collect();
    let (q, p, h) = start(ctx, lo, hi)?;
    let h = &h;
    let per_h = |x: &Over<F>| x.over(h).map(|v| v.b.v.hi).ok_or(unshown(LeafQuantity::Separates));
    let ends: Vec<usize> = plan.cuts.iter().map(|&c| c as usize).chain(std::iter::once(list.len())).collect();
    let (q, p, t) = follow(maps, &list, 0, ends[0], q, p)?;
    if plan.cuts.is_empty() {
        return finish(ctx, &q, &p, &t, plan.end)?.map(|total| per_h(&total)).transpose();
    }
    let orbit = ctx.orbit.as_ref().ok_or(Failure::NoOrbit)?;
    let (mut ybox, ratio) = normalise(orbit, &q, &p, Cut::At(ends[0]))?;
    let (mut acc, mut scale) = (per_h(&t)?, per_h(&ratio)?);
    for w in 0..plan.cuts.len() {
        let (q0, p0) = section_seeds(orbit, &ybox);
        let (q, p, t) = follow(maps, &list, ends[w], ends[w + 1], q0, p0)?;
        if w + 1 == plan.cuts.len() {
            return Ok(finish(ctx, &q, &p, &t, plan.end)?
                .map(|total| round_up(&acc.plus(&scale.times(&total.b.v.hi)))));
        }
        let (next, ratio) = normalise(orbit, &q, &p, Cut::At(ends[w + 1]))?;
        // Rounded up (upper bounds stay upper bounds), so that the numbers stay short.
        acc = round_up(&acc.plus(&scale.times(&t.b.v.hi)));
        scale = round_up(&scale.times(&ratio.b.v.hi));
        ybox = next;
    }
    Ok(None)
}

/// A leaf's drops before the first impact: q, p and h over the leaf.
pub(super) type Start<F> = ([Over<F>; 3], [Over<F>; 3], Over<F>);

/// The drops of the leaf [lo, hi] (over its five coordinates): the state before the first
/// impact, every contact shown strictly up, and h.
pub(super) fn start<F: Field>(ctx: &Context<F>, lo: &[F; DIMS], hi: &[F; DIMS]) -> Result<Start<F>, Failure> {
    let y = seeds(lo, hi);
    let (q, p) = state(&y, &ctx.cs);
    for (k, f) in ctx.maps.contacts.iter().enumerate() {
        shown(LeafQuantity::Start { contact: k }, &dot_iv(f, &q))?;
    }
    let [.., h] = y;
    Ok((q, p, h))
}

/// A leaf's prefix as given: the impacts, the cuts (impact counts after which the state is
/// re-enclosed in X's parameters), and where it ends.
#[derive(Clone, Copy, Debug)]
pub struct Prefix<'a> {
    /// The contact that lands first.
    pub first: usize,
    /// The later steps.
    pub steps: &'a [u64],
    /// The cuts, strictly increasing, in 1..=1 + steps.len() (none for `Rest`).
    pub cuts: &'a [u64],
    /// Where the prefix ends.
    pub end: End,
}

/// Where a leaf's prefix ends.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum End {
    /// In the orbit certificate's X (`Cc`).
    Cc,
    /// With v > 0 (`Icc`).
    Icc,
    /// In the cone K_r of node r of the time-to-rest certificate (`Rest`).
    Rest(usize),
}

impl<'a> Prefix<'a> {
    /// The prefix of a leaf with one (`None` for `Undecided` and `Tree`).
    pub fn of(v: &'a LeafVerdict) -> Option<Self> {
        let (first, steps, cuts, end): (u64, &[u64], &[u64], End) = match v {
            LeafVerdict::Cc { first, steps, cuts } => (*first, steps, cuts, End::Cc),
            LeafVerdict::Icc { first, steps, cuts } => (*first, steps, cuts, End::Icc),
            LeafVerdict::Rest { first, steps, node } => (*first, steps, &[], End::Rest(*node as usize)),
            LeafVerdict::Undecided | LeafVerdict::Tree { .. } => return None,
        };
        Some(Prefix { first: first as usize, steps, cuts, end })
    }
}

/// Where a state is normalised: at a cut (after this many impacts) or at the end of the prefix.
#[derive(Clone, Copy)]
enum Cut {
    At(usize),
    End,
}

/// The impacts list[from..to] from (q, p): the state after them and the flights' time.
#[allow(clippy::type_complexity)]
fn follow<F: Field, const D: usize>(
    maps: &crate::orbit::map::Maps<Iv<F>>,
    list: &[usize],
    from: usize,
    to: usize,
    mut q: [Centred<F, D>; 3],
    mut p: [Centred<F, D>; 3],
) -> Result<([Centred<F, D>; 3], [Centred<F, D>; 3], Centred<F, D>), Failure> {
    let mut failed = None;
    let mut check = |qt: Quantity, v: &Centred<F, D>| {
        shown(LeafQuantity::Prefix(qt), v).map_err(|f| {
            failed = Some(f);
            Stop::Failed(qt)
        })
    };
    let mut time = Centred::constant(&F::zero());
    for (s, &j) in list.iter().enumerate().take(to).skip(from) {
        match step(maps, s, j, &q, &p, &mut check) {
            Ok((t, q1, p1)) => (time, q, p) = (time.plus(&t), q1, p1),
            Err(Stop::Failed(qt) | Stop::Division(qt)) => {
                return Err(failed.take().unwrap_or(unshown(LeafQuantity::Prefix(qt))));
            }
        }
    }
    Ok((q, p, time))
}

/// α = hc > 0, β = -v > 0 (shown), x = (h_1/α, u_0/β, u_1/β), and y = A^-1 (x - x*) with α/β.
#[allow(clippy::type_complexity)]
fn normalise<F: Field, const D: usize>(
    orbit: &Orbit<F>,
    q: &[Centred<F, D>; 3],
    p: &[Centred<F, D>; 3],
    at: Cut,
) -> Result<([Iv<F>; 3], Centred<F, D>), Failure> {
    let (y, ratio) = normalised(orbit, q, p, at)?;
    Ok((y.map(|v| v.b.v), ratio))
}

#[allow(clippy::type_complexity)]
fn normalised<F: Field, const D: usize>(
    orbit: &Orbit<F>,
    q: &[Centred<F, D>; 3],
    p: &[Centred<F, D>; 3],
    at: Cut,
) -> Result<([Centred<F, D>; 3], Centred<F, D>), Failure> {
    let named = |quantity: Quantity| match at {
        Cut::At(impacts) => LeafQuantity::Cut { impacts, quantity },
        Cut::End => LeafQuantity::Entry(quantity),
    };
    let alpha = q[2].clone();
    let beta = Centred::constant(&F::zero()).minus(&p[2]);
    shown(named(Quantity::PositionScale), &alpha)?;
    shown(named(Quantity::VelocityScale), &beta)?;
    let div = |a: &Centred<F, D>, b: &Centred<F, D>, qt: Quantity| a.over(b).ok_or(unshown(named(qt)));
    let x = [
        div(&q[1], &alpha, Quantity::PositionScale)?,
        div(&p[0], &beta, Quantity::VelocityScale)?,
        div(&p[1], &beta, Quantity::VelocityScale)?,
    ];
    let y = std::array::from_fn(|i| {
        let mut g = Centred::constant(&F::zero());
        for (k, xk) in x.iter().enumerate() {
            g = g.plus(&xk.minus(&Centred::constant(&orbit.centre[k])).scaled(&orbit.a_inv[i][k]));
        }
        g
    });
    Ok((y, div(&alpha, &beta, Quantity::VelocityScale)?))
}

/// The section's state q = (0, a, 1), p = (b, c, -1) for x = x* + A y, y in the box `y`
/// (seeded as in the orbit certificates' sub-boxes, gradient A).
fn section_seeds<F: Field>(orbit: &Orbit<F>, y: &[Iv<F>; 3]) -> ([Centred<F, 3>; 3], [Centred<F, 3>; 3]) {
    let two = F::from_i64(2);
    let centre: [F; 3] = std::array::from_fn(|k| y[k].lo.plus(&y[k].hi).over(&two).unwrap_or_else(F::zero));
    let r = std::sync::Arc::new(std::array::from_fn(|k| {
        let w = y[k].hi.minus(&y[k].lo).over(&two).unwrap_or_else(F::zero);
        Iv { lo: w.negated(), hi: w }
    }));
    let x: [Centred<F, 3>; 3] = std::array::from_fn(|i| {
        let mut at_c = Iv::point(&orbit.centre[i]);
        let mut over = at_c.clone();
        for (k, ck) in centre.iter().enumerate() {
            at_c = at_c.plus(&Iv::point(ck).scaled(&orbit.a[i][k]));
            over = over.plus(&y[k].scaled(&orbit.a[i][k]));
        }
        Centred::seed(at_c, over, std::array::from_fn(|k| Iv::point(&orbit.a[i][k])), r.clone())
    });
    let (zero, one) = (Centred::constant(&F::zero()), Centred::constant(&F::one()));
    let [a, b, c] = x;
    ([zero.clone(), a, one.clone()], [b, c, zero.minus(&one)])
}

/// The end of the prefix: `Icc`: v > 0 (`None`); `Cc`: the state in X, and the time of the
/// segment plus B α/β (the orbit's bound on the rest, in the segment's units); `Rest`: [`enters`].
pub(super) fn finish<F: Field, const D: usize>(
    ctx: &Context<F>,
    q: &[Centred<F, D>; 3],
    p: &[Centred<F, D>; 3],
    time: &Centred<F, D>,
    end: End,
) -> Result<Option<Centred<F, D>>, Failure> {
    match end {
        End::Icc => {
            shown(LeafQuantity::Separates, &p[2])?;
            return Ok(None);
        }
        End::Rest(node) => return enters(ctx, node, q, p).map(|phi| Some(time.plus(&phi))),
        End::Cc => {}
    }
    let orbit = ctx.orbit.as_ref().ok_or(Failure::NoOrbit)?;
    let (y, ratio) = normalised(orbit, q, p, Cut::End)?;
    let delta = Centred::constant(&orbit.delta);
    for (i, yi) in y.iter().enumerate() {
        shown(LeafQuantity::Entry(Quantity::Inside { coordinate: i, upper: true }), &delta.minus(yi))?;
        shown(LeafQuantity::Entry(Quantity::Inside { coordinate: i, upper: false }), &yi.plus(&delta))?;
    }
    Ok(Some(time.plus(&ratio.scaled(&ctx.b))))
}

/// `Rest` (docs/basin-certificates.md §4; docs/time-to-rest.md Theorem 5.1 from node r): hc > 0,
/// -v > 0, every facet of K_r >= 0 and -b_r·p > 0 at the velocity p; returns the virtual time
/// Φ_r(q, p) = (a_r·q)/(-b_r·p), which bounds the time left to rest.
fn enters<F: Field, const D: usize>(
    ctx: &Context<F>,
    node: usize,
    q: &[Centred<F, D>; 3],
    p: &[Centred<F, D>; 3],
) -> Result<Centred<F, D>, Failure> {
    let forms = ctx.rest.as_ref().and_then(|r| r.get(node)).ok_or(Failure::NoRest)?;
    let dot = |f: &[F; 3], x: &[Centred<F, D>; 3]| {
        x[0].scaled(&f[0]).plus(&x[1].scaled(&f[1])).plus(&x[2].scaled(&f[2]))
    };
    shown(LeafQuantity::Entry(Quantity::PositionScale), &q[2])?;
    shown(LeafQuantity::Entry(Quantity::VelocityScale), &Centred::constant(&F::zero()).minus(&p[2]))?;
    for (facet, f) in forms.facets.iter().enumerate() {
        shown(LeafQuantity::InCone { node, facet }, &dot(f, p))?;
    }
    let denominator = Centred::constant(&F::zero()).minus(&dot(&forms.weight, p));
    shown(LeafQuantity::RestTime { node }, &denominator)?;
    dot(&forms.numerator, q).over(&denominator).ok_or(unshown(LeafQuantity::RestTime { node }))
}
