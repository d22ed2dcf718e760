//! The family finder against the simulator on a grid of gamma for one general body (issue 13
//! §4): at each gamma the whole pipeline ([`certify_convex`]) and a batch of the paper's random
//! drops (f64). A drop is an all-down start (|omega| r_k / R is at most about 0.15 < |v| = 1), so
//! a certified claim about drops must agree with every decided drop: a drop ending ICC where
//! CC-or-PCC is certified, or PCC where CC is, would be a contradiction (a bug).

use crate::certify::convex::{ConvexRequest, certify_convex};
use crate::exact::Q;
use crate::simulate::{Arithmetic, Model, Options, Outcome, counts, simulate_many};
use chatter_kernel::certificate::Claim;
use chatter_kernel::model::ConvexBody;
use rayon::prelude::*;
use std::time::{Duration, Instant};

/// One grid point.
#[derive(Clone, Debug)]
pub struct GridPoint {
    pub gamma: Q,
    /// The claim certified, if any.
    pub certified: Option<Claim>,
    /// The pipeline's wall-clock time.
    pub time: Duration,
    /// Drop outcomes (f64: evidence) in the order of [`Outcome::ALL`] (CC, PCC, ICC, undecided,
    /// simultaneous, and no-ICC-no-PCC, which f64 never gives).
    pub drops: [usize; Outcome::COUNT],
}

impl GridPoint {
    /// Every drop ended in CC.
    pub fn all_cc(&self) -> bool {
        self.drops[0] == self.drops.iter().sum::<usize>()
    }

    /// A decided drop that the certified claim excludes.
    pub fn contradicts(&self) -> bool {
        match self.certified {
            Some(Claim::CompleteChatterFromAllDown) => self.drops[1] + self.drops[2] > 0,
            Some(Claim::CcOrPccFromAllDown) => self.drops[2] > 0,
            _ => false,
        }
    }
}

/// The body with restitution `g`.
fn at(body: &ConvexBody<Q>, g: &Q) -> ConvexBody<Q> {
    ConvexBody::new(body.contacts().to_vec(), body.inertia().clone(), g.clone()).expect("the same valid body")
}

/// The pipeline (claims about drops) and `runs` drops with budget `budget` at every gamma, in
/// parallel; the result is in the order of `gammas`.
pub fn finder_vs_simulation(body: &ConvexBody<Q>, gammas: &[Q], runs: u64, budget: usize) -> Vec<GridPoint> {
    gammas
        .par_iter()
        .map(|g| {
            let b = at(body, g);
            let mut req = ConvexRequest::new(b.clone());
            req.claim = crate::certify::ClaimChoice::StrongestAboutDrops;
            let start = Instant::now();
            let certified = certify_convex(&req).result.ok().map(|c| c.claim);
            let time = start.elapsed();
            let briefs =
                simulate_many(&Model::convex(&b), 0, runs, Arithmetic::Float, &Options::new(budget), &|| {});
            GridPoint { gamma: g.clone(), certified, time, drops: counts(&briefs) }
        })
        .collect()
}

/// The summary of a grid: points, points with every drop CC, certified points, certified points
/// with every drop CC, and contradictions.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Agreement {
    pub points: usize,
    pub all_cc: usize,
    pub certified: usize,
    pub certified_and_all_cc: usize,
    pub contradictions: usize,
}

impl Agreement {
    /// Tallies a grid.
    pub fn of(points: &[GridPoint]) -> Agreement {
        let count = |f: &dyn Fn(&GridPoint) -> bool| points.iter().filter(|p| f(p)).count();
        Agreement {
            points: points.len(),
            all_cc: count(&GridPoint::all_cc),
            certified: count(&|p| p.certified.is_some()),
            certified_and_all_cc: count(&|p| p.certified.is_some() && p.all_cc()),
            contradictions: count(&GridPoint::contradicts),
        }
    }

    /// The finder's success rate: certified among the points where every drop ended CC.
    pub fn success_rate(&self) -> f64 {
        if self.all_cc == 0 { 0.0 } else { self.certified_and_all_cc as f64 / self.all_cc as f64 }
    }
}

/// The outcome names of [`GridPoint::drops`].
pub fn outcome_names() -> [&'static str; Outcome::COUNT] {
    Outcome::ALL.map(|o| o.name())
}
