//! A certified cover of the CC region (issue 11 §3): a box of parameters is subdivided
//! adaptively into boxes, each certified (one box certificate proves an all-down claim on the
//! whole box), refuted at its corners (exact refutations at points), or left undecided (outside
//! the CC region at every corner with a corner not refuted, or at the finest size along the axis
//! it would be split). Boxes are processed generation by generation, in parallel, and every
//! result is a pure function of the box, so the output does not depend on the number of threads.

pub mod area;
pub mod summary;
pub use summary::CoverSummary;

use crate::certify::{ClaimChoice, Request, certify};
use crate::exact::{Q, QExt};
use crate::refute::{RefuteConfig, refute};
use crate::spectral::criteria::{cc_criterion, rod_cc_criterion};
use chatter_kernel::certificate::{Certificate, Claim};
use chatter_kernel::model::Shape;
use chatter_kernel::refute::Refutation;
use chatter_kernel::verify::{MALACHITE, Verdict, verify_refutation};
use rayon::prelude::*;
use std::collections::BTreeMap;
use std::sync::Mutex;

/// A box of kappa x gamma with its depth of subdivision in each direction.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct Cell {
    pub kappa: [Q; 2],
    pub gamma: [Q; 2],
    pub depth: [u32; 2],
}

impl Cell {
    pub fn area(&self) -> Q {
        (&self.kappa[1] - &self.kappa[0]) * (&self.gamma[1] - &self.gamma[0])
    }

    /// The corners in the kernel's order (kappa, gamma): (lo, lo), (hi, lo), (lo, hi), (hi, hi).
    pub fn corners(&self) -> [(Q, Q); 4] {
        let (k, g) = (&self.kappa, &self.gamma);
        [
            (k[0].clone(), g[0].clone()),
            (k[1].clone(), g[0].clone()),
            (k[0].clone(), g[1].clone()),
            (k[1].clone(), g[1].clone()),
        ]
    }

    /// The centre (kappa, gamma).
    pub fn centre(&self) -> (Q, Q) {
        let mid = |r: &[Q; 2]| (&r[0] + &r[1]) / Q::int(2);
        (mid(&self.kappa), mid(&self.gamma))
    }

    /// The halves along kappa (axis 0) or gamma (axis 1).
    fn halves(&self, axis: usize) -> [Cell; 2] {
        let r = if axis == 0 { &self.kappa } else { &self.gamma };
        let mid = (&r[0] + &r[1]) / Q::int(2);
        let mut depth = self.depth;
        depth[axis] += 1;
        let (lo, hi) = ([r[0].clone(), mid.clone()], [mid, r[1].clone()]);
        let make = |range: [Q; 2]| {
            let mut c = Cell { depth, ..self.clone() };
            if axis == 0 {
                c.kappa = range
            } else {
                c.gamma = range
            }
            c
        };
        [make(lo), make(hi)]
    }
}

/// How a leaf box ended.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Status {
    /// A box certificate of an all-down claim.
    Certified { claim: Claim, certificate: Certificate },
    /// The CC criterion fails at every corner and every corner has an exact refutation.
    Refuted { refutations: Vec<Refutation> },
    /// Neither: outside the CC region at every corner with a corner not refuted (not split), or
    /// at the finest size along the axis it would be split.
    Undecided,
}

impl Status {
    pub fn name(&self) -> &'static str {
        match self {
            Status::Certified { .. } => "certified",
            Status::Refuted { .. } => "refuted",
            Status::Undecided => "undecided",
        }
    }
}

/// A leaf of the subdivision.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Leaf {
    pub cell: Cell,
    pub status: Status,
    /// The exact CC criterion at the four corners.
    pub criterion: [bool; 4],
    /// The exact CC criterion at the centre (a certified box where it fails is a finding).
    pub centre: bool,
}

/// A cover request.
#[derive(Clone, Debug)]
pub struct CoverRequest {
    pub n: u64,
    pub kappa: [Q; 2],
    pub gamma: [Q; 2],
    /// The finest subdivision in kappa and in gamma, as numbers of halvings.
    pub max_depth: [u32; 2],
}

/// The exact CC criterion at a point.
pub fn criterion(n: u64, kappa: &Q, gamma: &Q) -> bool {
    match Shape::new(n, kappa.clone(), gamma.clone()) {
        Ok(Shape::Rod(r)) => rod_cc_criterion(&r).0,
        Ok(Shape::Polygon(b)) => cc_criterion(&b).0,
        Err(_) => false,
    }
}

/// An exact refutation at a point, checked by the kernel (EffectivelyInvariant first: refuting
/// it refutes every claim, since every claimed cone contains the seed; then CcOrPccFromAllDown).
fn refute_point(n: u64, k: &Q, g: &Q) -> Option<Refutation> {
    // Points whose float iteration needs many steps lie close to the threshold: their exact
    // derivations are long and slow, and refuting them adds nothing to the certified area.
    let cfg = RefuteConfig { max_iterations: 120, ..RefuteConfig::default() };
    [Claim::EffectivelyInvariant, Claim::CcOrPccFromAllDown]
        .iter()
        .find_map(|c| refute(n, k, g, *c, &cfg).ok())
        .filter(|r| {
            let v = verify_refutation(r, Default::default(), &[MALACHITE]);
            matches!(v, Verdict::Accepted(_))
        })
}

/// Refutes the corners of the boxes where the criterion fails at every corner, in four rounds
/// (one corner of every pending box per round, each distinct point once, in parallel); a box
/// whose corner has no refutation drops out, so its other corners are not tried.
fn refute_corners(req: &CoverRequest, pending: &mut [Leaf], t: &Timings) {
    let mut memo: BTreeMap<(Q, Q), Option<Refutation>> = BTreeMap::new();
    let mut alive: Vec<usize> = (0..pending.len()).collect();
    for corner in 0..4 {
        let points: Vec<(Q, Q)> = alive
            .iter()
            .map(|&i| pending[i].cell.corners()[corner].clone())
            .filter(|p| !memo.contains_key(p))
            .collect::<std::collections::BTreeSet<_>>()
            .into_iter()
            .collect();
        let found: Vec<Option<Refutation>> = Timings::add(&t.refute, || {
            points.par_iter().with_max_len(1).map(|(k, g)| refute_point(req.n, k, g)).collect()
        });
        memo.extend(points.into_iter().zip(found));
        alive.retain(|&i| memo[&pending[i].cell.corners()[corner]].is_some());
    }
    for i in alive {
        let refutations = pending[i].cell.corners().iter().filter_map(|p| memo[p].clone()).collect();
        pending[i].status = Status::Refuted { refutations };
    }
}

/// Where the time went (summed over threads), for the report.
#[derive(Debug, Default)]
pub struct Timings {
    pub criterion: Mutex<std::time::Duration>,
    pub certify: Mutex<std::time::Duration>,
    pub refute: Mutex<std::time::Duration>,
}

impl Timings {
    fn add<T>(slot: &Mutex<std::time::Duration>, f: impl FnOnce() -> T) -> T {
        let start = std::time::Instant::now();
        let out = f();
        *slot.lock().expect("not poisoned") += start.elapsed();
        out
    }

    /// Seconds in the criterion, box certification and refutation.
    pub fn seconds(&self) -> [f64; 3] {
        [&self.criterion, &self.certify, &self.refute].map(|m| m.lock().expect("not poisoned").as_secs_f64())
    }
}

/// What became of one box: a leaf, or its children.
enum Outcome {
    Leaf(Box<Leaf>),
    Split(Vec<Cell>),
}

/// The axes to split along, from the corners' criteria: the direction in which the criterion
/// changes; both when it changes in both or neither.
fn split_axes(c: &Cell, crit: &[bool; 4]) -> Vec<usize> {
    let gamma_changes = crit[0] != crit[2] || crit[1] != crit[3];
    let kappa_changes = crit[0] != crit[1] || crit[2] != crit[3];
    let axes = match (kappa_changes, gamma_changes) {
        (true, false) => vec![0],
        (false, true) => vec![1],
        _ => vec![0, 1],
    };
    axes.into_iter().filter(|&a| c.depth[a] < u32::MAX).collect()
}

fn children(c: &Cell, axes: &[usize]) -> Vec<Cell> {
    let mut out = vec![c.clone()];
    for &a in axes {
        out = out.iter().flat_map(|x| x.halves(a)).collect();
    }
    out
}

/// Decides one box.
fn decide(req: &CoverRequest, c: &Cell, t: &Timings) -> Outcome {
    let corners = c.corners();
    let crit = Timings::add(&t.criterion, || corners.clone().map(|(k, g)| criterion(req.n, &k, &g)));
    let finest = |axes: &[usize]| axes.iter().all(|&a| c.depth[a] >= req.max_depth[a]);
    let centre = || criterion(req.n, &c.centre().0, &c.centre().1);
    let leaf =
        |status| Outcome::Leaf(Box::new(Leaf { cell: c.clone(), status, criterion: crit, centre: centre() }));
    if crit.iter().all(|x| !x) {
        // Outside the CC region by the exact criterion at every corner: left for the refutation
        // of the corners (undecided until then), and not subdivided (finer boxes would not add
        // certified area).
        return leaf(Status::Undecided);
    } else if c.gamma[0] > Q::int(0) && crit.iter().all(|x| *x) {
        // A box certificate needs a cone at every corner; where the exact CC criterion fails at
        // a corner, the paper's Conjecture 1 says there is none, and trying costs the finder's
        // whole budget. Such boxes are split (or left undecided at the finest size).
        // A survey's budget: near the threshold the search would run long and fail anyway, and
        // the box is split instead.
        let mut r = Request::boxed(req.n, c.kappa.clone(), c.gamma.clone()).survey();
        r.claim = ClaimChoice::StrongestAboutDrops;
        let r = Timings::add(&t.certify, || certify(&r));
        if let Ok(cert) = r.result
            && cert.claim > Claim::EffectivelyInvariant
        {
            return leaf(Status::Certified { claim: cert.claim, certificate: cert });
        }
    }
    // Split: gamma first when the bottom touches gamma = 0 (no claim about drops holds there).
    let mut axes =
        if c.gamma[0] == Q::int(0) && crit.iter().any(|x| *x) { vec![1] } else { split_axes(c, &crit) };
    axes.retain(|&a| c.depth[a] < req.max_depth[a]);
    if axes.is_empty() || finest(&[0, 1]) {
        return leaf(Status::Undecided);
    }
    Outcome::Split(children(c, &axes))
}

/// Runs the subdivision; `tick` is called with the number of boxes examined so far.
pub fn cover(req: &CoverRequest, t: &Timings, tick: &(dyn Fn(usize) + Sync)) -> Vec<Leaf> {
    let mut generation = vec![Cell { kappa: req.kappa.clone(), gamma: req.gamma.clone(), depth: [0, 0] }];
    let mut leaves = Vec::new();
    let mut examined = 0;
    while !generation.is_empty() {
        let outcomes: Vec<Outcome> =
            generation.par_iter().with_max_len(1).map(|c| decide(req, c, t)).collect();
        examined += generation.len();
        tick(examined);
        let mut next = Vec::new();
        for o in outcomes {
            match o {
                Outcome::Leaf(l) => leaves.push(*l),
                Outcome::Split(cs) => next.extend(cs),
            }
        }
        generation = next;
    }
    leaves.sort_by(|a, b| a.cell.cmp(&b.cell));
    let (mut outside, mut rest): (Vec<Leaf>, Vec<Leaf>) =
        leaves.into_iter().partition(|l| l.criterion.iter().all(|x| !x));
    refute_corners(req, &mut outside, t);
    rest.extend(outside);
    rest.sort_by(|a, b| a.cell.cmp(&b.cell));
    rest
}

/// Areas and findings of a cover.
#[derive(Clone, Debug)]
pub struct Tally {
    pub certified_area: Q,
    pub refuted_area: Q,
    pub undecided_area: Q,
    /// The largest gamma-height of an undecided box (the width of the undecided band).
    pub undecided_height: Q,
    /// Certified boxes with a corner or the centre where the CC criterion fails (against
    /// Conjecture 1).
    pub certified_criterion_fails: Vec<usize>,
    /// Refuted boxes with a corner where the criterion holds (impossible: refuted boxes are
    /// tried only where it fails at every corner; kept as a check).
    pub refuted_criterion_holds: Vec<usize>,
}

pub fn tally(leaves: &[Leaf]) -> Tally {
    let mut t = Tally {
        certified_area: Q::int(0),
        refuted_area: Q::int(0),
        undecided_area: Q::int(0),
        undecided_height: Q::int(0),
        certified_criterion_fails: vec![],
        refuted_criterion_holds: vec![],
    };
    for (i, l) in leaves.iter().enumerate() {
        let a = l.cell.area();
        match &l.status {
            Status::Certified { .. } => {
                t.certified_area = &t.certified_area + &a;
                if l.criterion.iter().any(|x| !x) || !l.centre {
                    t.certified_criterion_fails.push(i);
                }
            }
            Status::Refuted { .. } => {
                t.refuted_area = &t.refuted_area + &a;
                if l.criterion.iter().any(|x| *x) {
                    t.refuted_criterion_holds.push(i);
                }
            }
            Status::Undecided => {
                t.undecided_area = &t.undecided_area + &a;
                let h = &l.cell.gamma[1] - &l.cell.gamma[0];
                if h > t.undecided_height {
                    t.undecided_height = h;
                }
            }
        }
    }
    t
}

/// A float for reports.
pub fn f(x: &Q) -> f64 {
    x.to_f64()
}
