//! `Tree` leaves of basin certificates (feature `basin`, version 2; docs/certificate-format.md
//! §15, why: docs/basin-certificates.md §4.2). Rules, in the order they are checked:
//!
//! - B1 (the tree, `basin-out-of-range` unless said), depth first, each list in order: a version-1
//!   file has no tree (`unsupported-version`); a list is not empty; at most
//!   [`MAX_TREE`] impacts in a tree and [`MAX_PREFIX`] on a path (`too-large`); each contact in
//!   0..n-1 at the root and 1..n-1 below it, not repeated in its list; a `Cc` end needs the orbit
//!   certificate, a `Rest` end the time-to-rest certificate and one of its nodes; the ends are all
//!   `Icc` or all `Cc` and `Rest`;
//! - B4 (`leaf-not-shown`), over the whole leaf as for prefixes: every contact up at the start;
//!   at a node with the list J, (i) every j in J approaches (-u_j > 0), (ii) every other contact m
//!   rises (u_m > 0) or lands after some j in J (h_m (-u_j) + h_j u_m > 0, J in list order); then
//!   each child from the state after the impact at j, and each end as a prefix's end.

use super::basin::{
    Context, End, Failure, LeafQuantity, MAX_PREFIX, dot_iv, fail, rest_node, shown, start, unshown,
};
use crate::basin::drop::{DIMS, Over};
use crate::exact::Field;
use crate::orbit::map::{Quantity, Stop, step};
use crate::reject::{Code, Detail, KindCounted, KindDetail, Rejection};
use crate::syntax::basin::{Impact, TREE_VERSION, Then};
use crate::syntax::numbers::at_most;

/// The most impacts in one tree (limit `max-basin-tree`).
pub const MAX_TREE: usize = 4096;

/// What B1 needs of the file besides the tree: n, the version, whether there is an orbit
/// certificate, the number of nodes of the time-to-rest certificate.
pub struct Frame {
    /// n.
    pub n: u64,
    /// The file's version.
    pub version: u64,
    /// Whether the file has an orbit certificate.
    pub orbit: bool,
    /// The time-to-rest certificate's number of nodes, if it has one.
    pub nodes: Option<usize>,
}

/// B1 on the tree of leaf `i`: `Ok(true)` when its ends are `Cc` or `Rest` (a CC leaf), `Ok(false)`
/// when they are `Icc`.
pub fn structure(i: usize, next: &[Impact], frame: &Frame) -> Result<bool, Rejection> {
    if frame.version < TREE_VERSION {
        let detail = Detail::Kind(KindDetail::Basin(Failure::TreeVersion));
        return Err(Rejection::at(Code::UnsupportedVersion, "version", detail));
    }
    let mut ends = [false; 2];
    walk_structure(i, next, frame, (0, &mut 0), &mut ends)?;
    if ends[0] && ends[1] {
        return Err(fail(Code::BasinOutOfRange, &format!("leaves[{i}].verdict"), Failure::MixedEnds));
    }
    Ok(ends[0])
}

/// One list of the tree at `depth` impacts; `count` the impacts seen so far; `ends` [CC, ICC] seen.
fn walk_structure(
    i: usize,
    next: &[Impact],
    frame: &Frame,
    (depth, count): (usize, &mut usize),
    ends: &mut [bool; 2],
) -> Result<(), Rejection> {
    let at = |what: &str| format!("leaves[{i}].{what}");
    if next.is_empty() {
        return Err(fail(Code::BasinOutOfRange, &at("verdict"), Failure::EmptyBranch));
    }
    *count += next.len();
    at_most("max-basin-tree", *count, MAX_TREE, KindCounted::Tree.into())?;
    at_most("max-basin-prefix", depth + 1, MAX_PREFIX, KindCounted::Prefix.into())?;
    for (k, imp) in next.iter().enumerate() {
        let c = imp.contact;
        if depth == 0 && c >= frame.n {
            return Err(fail(Code::BasinOutOfRange, &at("first"), Failure::First { first: c, n: frame.n }));
        }
        if depth > 0 && (c == 0 || c >= frame.n) {
            return Err(fail(Code::BasinOutOfRange, &at("steps"), Failure::Step { step: c, n: frame.n }));
        }
        if next[..k].iter().any(|o| o.contact == c) {
            let f = Failure::RepeatedContact { contact: c };
            return Err(fail(Code::BasinOutOfRange, &at("verdict"), f));
        }
    }
    for imp in next {
        match &imp.then {
            Then::Impacts { next } => walk_structure(i, next, frame, (depth + 1, count), ends)?,
            Then::Icc => ends[1] = true,
            Then::Cc if !frame.orbit => {
                return Err(fail(Code::BasinOutOfRange, &format!("leaves[{i}]"), Failure::NoOrbit));
            }
            Then::Cc => ends[0] = true,
            Then::Rest { node } => {
                rest_node(i, *node as usize, frame.nodes)?;
                ends[0] = true;
            }
        }
    }
    Ok(())
}

/// Whether a tree that passed B1 is a CC leaf (its first end, in list order, is `Cc` or `Rest`).
pub fn ends_cc(next: &[Impact]) -> bool {
    match next.first().map(|imp| &imp.then) {
        Some(Then::Impacts { next }) => ends_cc(next),
        Some(then) => !matches!(then, Then::Icc),
        None => false,
    }
}

/// B4 on a tree leaf [lo, hi]: `Ok(Some(bound))` for a CC leaf (the largest time to rest over
/// h/|v| of its ends, upper end), `Ok(None)` for an ICC leaf.
pub fn examine<F: Field>(
    ctx: &Context<F>,
    lo: &[F; DIMS],
    hi: &[F; DIMS],
    next: &[Impact],
) -> Result<Option<F>, Failure> {
    let (q, p, h) = start(ctx, lo, hi)?;
    let mut walk = Walk { ctx, h: &h, path: Vec::new(), worst: None };
    walk.node(&q, &p, &Over::constant(&F::zero()), next)?;
    Ok(walk.worst)
}

/// The walk of B4 through a tree: the impacts from the root to the current node, the largest
/// time to rest over h seen at a CC end.
struct Walk<'a, F: Field> {
    ctx: &'a Context<F>,
    h: &'a Over<F>,
    path: Vec<u64>,
    worst: Option<F>,
}

impl<F: Field> Walk<'_, F> {
    /// A failure at the current node (or, after `push`, at an end).
    fn here(&self, failure: Failure) -> Failure {
        Failure::InTree { impacts: self.path.clone(), failure: Box::new(failure) }
    }

    /// (i) and (ii) at the state (q, p), then each child; `time` the flights so far.
    fn node(
        &mut self,
        q: &[Over<F>; 3],
        p: &[Over<F>; 3],
        time: &Over<F>,
        next: &[Impact],
    ) -> Result<(), Failure> {
        let step_no = self.path.len();
        let contacts = &self.ctx.maps.contacts;
        let (h, u): (Vec<Over<F>>, Vec<Over<F>>) =
            contacts.iter().map(|f| (dot_iv(f, q), dot_iv(f, p))).unzip();
        let zero = Over::constant(&F::zero());
        let landing: Vec<usize> = next.iter().map(|imp| imp.contact as usize).collect();
        for &j in &landing {
            let quantity = LeafQuantity::Prefix(Quantity::Approach { step: step_no, contact: j });
            shown(quantity, &zero.minus(&u[j])).map_err(|f| self.here(f))?;
        }
        for m in (0..contacts.len()).filter(|m| !landing.contains(m)) {
            let later = |&j: &usize| h[m].times(&zero.minus(&u[j])).plus(&h[j].times(&u[m]));
            let rises = u[m].b.v.lo.is_positive();
            if !(rises || landing.iter().any(|j| later(j).b.v.lo.is_positive())) {
                let wrong = !u[m].c.hi.is_positive() && landing.iter().all(|j| !later(j).c.hi.is_positive());
                let quantity = LeafQuantity::Excluded { step: step_no, contact: m };
                return Err(self.here(Failure::Leaf { quantity, wrong }));
            }
        }
        for imp in next {
            let mut approached = |_: Quantity, _: &Over<F>| Ok::<(), Stop>(());
            let j = imp.contact as usize;
            let (t, q1, p1) = step(&self.ctx.maps, step_no, j, q, p, &mut approached).map_err(|_| {
                self.here(unshown(LeafQuantity::Prefix(Quantity::Approach { step: step_no, contact: j })))
            })?;
            self.path.push(imp.contact);
            self.then(&q1, &p1, &time.plus(&t), &imp.then)?;
            self.path.pop();
        }
        Ok(())
    }

    /// What follows an impact: the next node, or an end as a prefix's end.
    fn then(
        &mut self,
        q: &[Over<F>; 3],
        p: &[Over<F>; 3],
        time: &Over<F>,
        then: &Then,
    ) -> Result<(), Failure> {
        let end = match then {
            Then::Impacts { next } => return self.node(q, p, time, next),
            Then::Icc => End::Icc,
            Then::Cc => End::Cc,
            Then::Rest { node } => End::Rest(*node as usize),
        };
        let total = super::basin::finish(self.ctx, q, p, time, end).map_err(|f| self.here(f))?;
        if let Some(total) = total {
            let t = total
                .over(self.h)
                .map(|v| v.b.v.hi)
                .ok_or_else(|| self.here(unshown(LeafQuantity::Separates)))?;
            if self.worst.as_ref().is_none_or(|w| &t > w) {
                self.worst = Some(t);
            }
        }
        Ok(())
    }
}
