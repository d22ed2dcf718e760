//! The exactifier (untrusted): turns a floating-point polygon into a rational cone that the
//! exact check accepts.
//!
//! K is kept as an outer approximation { x : n_i . x <= h_i } with a fixed set of small-integer
//! normals n_i (the float polygon's rounded edge normals plus eight compass directions) and
//! dyadic offsets h_i. Each round computes the exact images of the vertices of every K ∩ C_j
//! (and the exact seed points), and raises every offset that an image exceeds to the image's
//! support value plus a small slack, rounded up. It stops when no image leaves K. Offsets are
//! raised only as far as exact images demand, so points that the maps send onto each other with
//! no contraction (two contacts at rest) stay exactly on K with no slack.

pub mod family;
mod points;

pub use points::{Exact, Nf, nf_f64};
pub(crate) use points::{int_mat, int_vec, primitive};

use crate::exact::{Field, Q, QExt};
use crate::finder::geometry::P2;
use chatter_kernel::geometry::clip;
use chatter_kernel::model::Polygon as Body;
use chatter_kernel::model::linalg::Vec3;
use malachite::Integer;
use std::fmt;

/// Tuning of the exactifier.
#[derive(Clone, Copy, Debug)]
pub struct ExactifyConfig {
    /// Normals are rounded to integers of magnitude up to 2^normal_bits.
    pub normal_bits: u32,
    /// Offsets are rounded up to multiples of scale * 2^-grid_bits.
    pub grid_bits: u32,
    /// Slack added to a raised offset: scale * 2^-slack_bits.
    pub slack_bits: u32,
    pub max_rounds: usize,
    /// Whether a raised offset overshoots by the excess itself (faster under a clear contraction);
    /// without it, by the slack only. Close to a threshold the overshoot can make the offsets
    /// grow geometrically until a cone reaches v = 0 (the lander at gamma 0.059: from 1.5e-4 to
    /// 2.5 in 21 rounds), where creeping up by the slack converges (63 rounds): the retries of
    /// `certify` end with it off.
    pub overshoot: bool,
    /// When the offsets do not converge, retry with a finer and then a coarser grid, and
    /// without overshoot (see `certify`); a cover, which splits a box instead, turns this off.
    pub retry: bool,
}

impl Default for ExactifyConfig {
    fn default() -> Self {
        ExactifyConfig {
            normal_bits: 12,
            grid_bits: 40,
            slack_bits: 24,
            max_rounds: 600,
            overshoot: true,
            retry: true,
        }
    }
}

/// Why exactification failed.
#[derive(Clone, Debug, PartialEq)]
pub enum ExactifyError {
    /// The float polygon is degenerate or not finite.
    BadInput(String),
    /// An exact image of a vertex of K ∩ C_j has v >= 0.
    ImageAbove { round: usize, step: usize },
    /// An exact image of a vertex of K_from ∩ C_(from,to) under I_to has v >= 0 (a family of
    /// cones of a general body).
    TransitionAbove { round: usize, from: usize, to: usize },
    /// Offsets kept growing.
    NoConvergence { rounds: usize, worst_excess: f64 },
}

impl fmt::Display for ExactifyError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ExactifyError::BadInput(s) => write!(f, "bad float polygon: {s}"),
            ExactifyError::ImageAbove { round, step } => {
                write!(
                    f,
                    "round {round}: an exact image under S_{step} has v >= 0 (the rational cone grew too large)"
                )
            }
            ExactifyError::TransitionAbove { round, from, to } => write!(
                f,
                "round {round}: an exact image of K_{from} ∩ C_({from},{to}) under I_{to} has v >= 0 (the rational cones grew too large)"
            ),
            ExactifyError::NoConvergence { rounds, worst_excess } => write!(
                f,
                "offsets still growing after {rounds} rounds (largest excess {worst_excess:.3e}): the maps barely contract here"
            ),
        }
    }
}

/// An exact polygon on the plane v = -1 as primitive integer homogeneous vectors.
pub type HPoly = Vec<Vec3<Integer>>;

/// max_q n . x(q), exact: the float supports pick the candidates within a margin far above
/// rounding error, and only those are compared exactly.
fn max_support<E: Exact>(n: &(i64, i64), pts: &[E::P], approx: &[(f64, f64)]) -> Option<E> {
    let f = |p: &(f64, f64)| n.0 as f64 * p.0 + n.1 as f64 * p.1;
    let top = approx.iter().map(f).fold(f64::NEG_INFINITY, f64::max);
    let size = approx.iter().map(|p| p.0.abs().max(p.1.abs())).fold(1.0, f64::max);
    let margin = 1e-9 * (n.0.unsigned_abs() + n.1.unsigned_abs()) as f64 * size;
    pts.iter()
        .zip(approx)
        .filter(|(_, p)| !top.is_finite() || f(p) >= top - margin)
        .map(|(q, _)| E::support(n, q))
        .max()
}

/// The exact polygon { x : n_i . x <= h_i } (non-empty, bounded by the compass normals).
fn polygon_of(normals: &[(i64, i64)], h: &[Q]) -> HPoly {
    let big = h.iter().map(Q::abs).max().expect("normals").ceil_dyadic(0) + Q::int(1);
    let b = big.numer();
    let one = -Integer::from(1u32);
    let mut poly: HPoly = vec![
        [-b.clone(), -b.clone(), one.clone()],
        [b.clone(), -b.clone(), one.clone()],
        [b.clone(), b.clone(), one.clone()],
        [-b.clone(), b, one],
    ];
    for (n, hi) in normals.iter().zip(h) {
        // n . (p0, p1)/(-p2) <= h  <=>  -n0 p0 - n1 p1 - h p2 >= 0 (scaled by den(h) > 0).
        let l = [-Integer::from(n.0) * hi.denom(), -Integer::from(n.1) * hi.denom(), -hi.numer()];
        poly = clip(&poly, &l).into_iter().map(primitive).collect();
    }
    poly
}

/// The exact images of the vertices of every K ∩ C_j under S_j of every body (the corners of a
/// box of parameters share C_j), or the step j of an image with v >= 0.
pub fn exact_images(bodies: &[Body<Q>], poly: &HPoly) -> Result<Vec<Vec3<Integer>>, usize> {
    Q::images(bodies, poly)
}

/// Rounded outward normals of the float polygon's edges plus the compass directions, as
/// primitive integer vectors, deduplicated.
fn normals_of(poly: &[P2], bits: u32) -> Vec<(i64, i64)> {
    let mut out: Vec<(i64, i64)> = vec![(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1)];
    let m = poly.len();
    let scale = f64::from(2u32.pow(bits));
    for i in 0..m {
        let d = poly[(i + 1) % m] - poly[i];
        let (nx, ny) = (d.y, -d.x);
        let big = nx.abs().max(ny.abs());
        if big.is_finite() && big > 0.0 {
            let (a, b) = ((nx / big * scale).round() as i64, (ny / big * scale).round() as i64);
            let g = gcd_i64(a, b);
            if g != 0 {
                out.push((a / g, b / g));
            }
        }
    }
    out.sort_by(|p, q| f64::atan2(p.1 as f64, p.0 as f64).total_cmp(&f64::atan2(q.1 as f64, q.0 as f64)));
    out.dedup();
    out
}

fn norm(n: &(i64, i64)) -> f64 {
    (n.0 as f64).hypot(n.1 as f64)
}

fn gcd_i64(a: i64, b: i64) -> i64 {
    let (mut a, mut b) = (a.abs(), b.abs());
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// The result of exactification: the generators on the plane v = -1, and the rounds used.
#[derive(Clone, Debug)]
pub struct Exactified {
    pub generators: Vec<[Q; 3]>,
    pub rounds: usize,
}

/// The outer approximation { x : n_l . x <= h_l } of one float polygon: rounded normals, dyadic
/// offsets, and each normal's slack and grid.
pub(crate) struct Offsets {
    normals: Vec<(i64, i64)>,
    h: Vec<Q>,
    slacks: Vec<Q>,
    grids: Vec<u64>,
    overshoot: bool,
}

impl Offsets {
    /// The offsets of `float_poly`'s support, rounded up, plus slack.
    pub(crate) fn new(float_poly: &[P2], cfg: &ExactifyConfig) -> Result<Offsets, ExactifyError> {
        if float_poly.is_empty() || float_poly.iter().any(|p| !p.x.is_finite() || !p.y.is_finite()) {
            return Err(ExactifyError::BadInput(format!("{} vertices", float_poly.len())));
        }
        let normals = normals_of(float_poly, cfg.normal_bits);
        let size = float_poly.iter().map(|p| p.x.abs().max(p.y.abs())).fold(1.0, f64::max);
        let e = size.log2().ceil() as i64;
        let unit =
            Q::from_rational(malachite::rational::Rational::from(1u32) >> (i64::from(cfg.slack_bits) - e));
        // Slack and grid in units of |n|, so that every edge moves by about the same distance.
        let nbits: Vec<u32> = normals
            .iter()
            .map(|n| 63 - (n.0.unsigned_abs().max(n.1.unsigned_abs())).leading_zeros())
            .collect();
        let slacks: Vec<Q> =
            nbits.iter().map(|b| Q::from_rational(unit.as_rational().clone() << i64::from(*b))).collect();
        let grids: Vec<u64> =
            nbits.iter().map(|b| (i64::from(cfg.grid_bits) - e - i64::from(*b)).max(0) as u64).collect();
        let h = normals
            .iter()
            .zip(slacks.iter().zip(&grids))
            .map(|(n, (sl, gb))| {
                let m = float_poly
                    .iter()
                    .map(|p| n.0 as f64 * p.x + n.1 as f64 * p.y)
                    .fold(f64::NEG_INFINITY, f64::max);
                (Q::from_f64_exact(m).expect("finite") + sl).ceil_dyadic(*gb)
            })
            .collect();
        Ok(Offsets { normals, h, slacks, grids, overshoot: cfg.overshoot })
    }

    /// The exact polygon of the current offsets.
    pub(crate) fn polygon(&self) -> HPoly {
        polygon_of(&self.normals, &self.h)
    }

    /// Raises every offset that an exact point exceeds; whether one changed, and the largest
    /// excess (in distance).
    pub(crate) fn raise<E: Exact>(&mut self, pts: &[E::P]) -> (bool, f64) {
        let approx: Vec<(f64, f64)> = pts.iter().map(E::plane_f64).collect();
        let (mut changed, mut worst) = (false, 0.0);
        let rows = self.normals.iter().zip(self.h.iter_mut()).zip(&self.slacks).zip(&self.grids);
        for (((n, hi), sl), gb) in rows {
            let Some(m) = max_support::<E>(n, pts, &approx) else { continue };
            if m > E::from_q(hi) {
                // Overshoot by the excess itself: under a contraction the offsets then reach
                // their fixed point in a few rounds instead of creeping towards it.
                let excess = &E::upper(&m) - &*hi;
                worst = f64::max(worst, excess.to_f64() / norm(n));
                let bump = if self.overshoot && excess > *sl { excess } else { sl.clone() };
                *hi = (E::upper(&m) + bump).ceil_dyadic(*gb);
                changed = true;
            }
        }
        (changed, worst)
    }
}

/// The plane points (omega_x, omega_y, -1) of an exact polygon's vertices.
pub(crate) fn generators_of(poly: &HPoly) -> Vec<[Q; 3]> {
    poly.iter()
        .map(|p| {
            let w = Q::from_int(&-&p[2]);
            [Q::from_int(&p[0]) / &w, Q::from_int(&p[1]) / &w, Q::int(-1)]
        })
        .collect()
}

/// Exactifies a float polygon for the maps of `bodies` (one body, or the corners of a box).
/// `seeds` are exact points that K must contain (e.g. I_0 of the generators of D); every exact
/// image is added as the rounds go.
pub fn exactify<E: Exact>(
    bodies: &[Body<E>],
    float_poly: &[P2],
    seeds: &[Vec3<E>],
    cfg: &ExactifyConfig,
) -> Result<Exactified, ExactifyError> {
    if float_poly.len() < 2 {
        return Err(ExactifyError::BadInput(format!("{} vertices", float_poly.len())));
    }
    let mut offsets = Offsets::new(float_poly, cfg)?;
    let seeds: Vec<E::P> = seeds.iter().map(E::point).collect();
    let mut worst_excess = 0.0;
    for round in 0..cfg.max_rounds {
        let poly = offsets.polygon();
        let mut pts = E::images(bodies, &poly).map_err(|step| ExactifyError::ImageAbove { round, step })?;
        pts.extend(seeds.iter().cloned());
        let (changed, worst) = offsets.raise::<E>(&pts);
        worst_excess = worst;
        if !changed {
            return Ok(Exactified { generators: generators_of(&poly), rounds: round + 1 });
        }
    }
    Err(ExactifyError::NoConvergence { rounds: cfg.max_rounds, worst_excess })
}
