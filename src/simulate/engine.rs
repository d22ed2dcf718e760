//! The interface shared by the two arithmetics: one event at a time, plus read-outs of the
//! state for classification and recording (the types of [`super::snapshot`], re-exported here
//! under their former paths).

use super::pcc::PairSummary;
use super::scalar::Nf;
pub use super::snapshot::{LOG2_ZERO, Scaled, Snapshot, pow2};
use crate::exact::Q;
use chatter_kernel::model::linalg::Vec3;

/// What happened at one event.
#[derive(Clone, Debug, PartialEq)]
pub enum Step {
    /// Contact `contact` hit the floor after the interval `dt`; the impact map has been applied.
    Impact { contact: usize, dt: Scaled },
    /// Several contacts reach the floor at the same instant: `exact` when the times are equal as
    /// rationals, otherwise they agree to within rounding in `f64`. Nothing has been applied.
    Tie { contacts: Vec<usize>, dt: Scaled, exact: bool },
    /// No contact moves towards the floor: no further impact.
    NoApproach,
    /// The `f64` state stopped being finite.
    Breakdown,
}

/// An event-driven simulation in one arithmetic (docs/model.md §10: the state is q and p only).
pub trait Engine {
    /// Finds the next impact (the approaching contact that reaches height 0 first) and applies it.
    fn step(&mut self) -> Step;
    /// Whether the centre of mass moves up (v > 0).
    fn v_positive(&self) -> bool;
    /// Whether the velocity is exactly zero.
    fn at_rest(&self) -> bool;
    /// Time since the start at the last impact (`f64`).
    fn time(&self) -> f64;
    /// Exact engines: a rational upper bound of the time since the start at the last impact (the
    /// sum of the exact intervals, each rounded up). `None` for `f64` engines.
    fn time_above(&self) -> Option<Q> {
        None
    }
    /// Exact engines, while the centre moves down (v < 0): a rational upper bound of h/|v|, the
    /// centre's height over its speed. `None` otherwise.
    fn centre_ratio_above(&self) -> Option<Q> {
        None
    }
    /// Exact engines, once the first impact happened: if every contact moved down or rested just
    /// before it (an all-down drop), rational upper bounds of the time of that impact and of h/|v|
    /// there. `None` otherwise.
    fn first_drop(&self) -> Option<(Q, Q)> {
        None
    }
    /// The current state, normalised.
    fn snapshot(&self) -> Snapshot;
    /// The exact pair-chatter test of [`super::pcc::prove_pair_chatter`] (exact engines only).
    fn prove_pair(&self, _hit: usize, _other: usize) -> Option<Result<PairSummary, String>> {
        None
    }
    /// Whether this engine computes exactly.
    fn is_exact(&self) -> bool;
    /// Exact engines on regular polygons: the state right after the last impact, relabelled so
    /// that the contact that landed is contact 0 (docs/model.md §3, R_j), as q = (h0, h1, hc) and
    /// p = (u0, u1, v) in the kernel's exact scalars; what the membership tests of issue 22 §1
    /// read (the rod: (h0, h1, 0), (u0, u1, 0) relabelled). `None` before the first impact, for
    /// `f64` engines and for general bodies.
    fn relabelled(&self) -> Option<(Vec3<Nf>, Vec3<Nf>)> {
        None
    }
}
