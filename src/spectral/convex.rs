//! Conjectural spectral criteria of a general convex body (docs/model.md §11.11), exact over
//! the body's field: the products of the impact maps once around the contact polygon,
//! P_ccw = I_0 I_{n-1} ... I_1 (impacts at 1, 2, ..., n-1, 0; the map applied first is
//! rightmost) and P_cw = I_0 I_1 ... I_{n-1}, their spectra and the verdict "the dominant
//! eigenvalue is real and positive" (the analogue of the paper's S_1 criterion: for a regular
//! n-gon S_1^n = W P_ccw W^-1). Beside them the PCC exclusion of each adjacent pair (k, k+1),
//! which is a proved lemma (docs/model.md §11.6), not a conjecture.

use super::criteria::{Profile, candidates_of, char_coefficients_at, profile};
use super::eigen::{Dominant, Spectrum};
use crate::exact::{OrderedField, Q};
use chatter_kernel::model::linalg::{Mat3, identity, mat_mul};
use chatter_kernel::model::{ConvexBody, PccExclusion, PccQuadratic};

/// Which way the impacts go around the contact polygon (docs/model.md §11.11).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Direction {
    /// Impacts at 1, 2, ..., n-1, 0: P_ccw = I_0 I_{n-1} ... I_1 (S_1^n for regular polygons).
    CounterClockwise,
    /// Impacts at n-1, n-2, ..., 1, 0: P_cw = I_0 I_1 ... I_{n-1} (S_{n-1}^n for regular polygons).
    Clockwise,
}

impl Direction {
    /// Both directions, counter-clockwise first.
    pub const BOTH: [Direction; 2] = [Direction::CounterClockwise, Direction::Clockwise];

    /// `counter-clockwise` or `clockwise`.
    pub fn name(self) -> &'static str {
        match self {
            Direction::CounterClockwise => "counter-clockwise",
            Direction::Clockwise => "clockwise",
        }
    }

    /// The contacts in the order the factors are written, leftmost first (docs/model.md §11.11).
    pub fn factors(self, n: usize) -> Vec<usize> {
        match self {
            Direction::CounterClockwise => std::iter::once(0).chain((1..n).rev()).collect(),
            Direction::Clockwise => (0..n).collect(),
        }
    }

    /// The product as text, e.g. `I_0 I_3 I_2 I_1` (docs/model.md §11.11).
    pub fn matrix_text(self, n: usize) -> String {
        self.factors(n).iter().map(|k| format!("I_{k}")).collect::<Vec<_>>().join(" ")
    }
}

/// The product of the impact maps once around the polygon in `dir` (docs/model.md §11.11).
pub fn product_around<F: OrderedField>(body: &ConvexBody<F>, dir: Direction) -> Mat3<F> {
    product_of(dir.factors(body.n()).iter().map(|&k| body.impact(k as i64)))
}

/// I_k at any rational gamma, I - (1 + gamma) w_k f_k^T (docs/model.md §11.2).
fn impact_at<F: OrderedField>(body: &ConvexBody<F>, k: usize, gamma: &Q) -> Mat3<F> {
    let c = F::one().plus(&F::from_q(gamma));
    let (w, f) = (body.impact_direction(k as i64), body.covector(k as i64));
    std::array::from_fn(|r| {
        std::array::from_fn(|s| {
            let delta = if r == s { F::one() } else { F::zero() };
            delta.minus(&c.times(&w[r]).times(&f[s]))
        })
    })
}

/// The product around the polygon at another restitution (also outside [0, 1], for
/// interpolation in gamma; docs/model.md §11.11).
pub fn product_at<F: OrderedField>(body: &ConvexBody<F>, dir: Direction, gamma: &Q) -> Mat3<F> {
    product_of(dir.factors(body.n()).iter().map(|&k| impact_at(body, k, gamma)))
}

fn product_of<F: OrderedField>(maps: impl Iterator<Item = Mat3<F>>) -> Mat3<F> {
    maps.fold(identity(), |acc, m| mat_mul(&acc, &m))
}

/// A conjectural product criterion at one body (docs/model.md §11.11).
#[derive(Clone, Debug)]
pub struct ProductCriterion<F> {
    pub direction: Direction,
    pub spectrum: Spectrum<F>,
    pub dominant: Dominant,
    /// The dominant eigenvalue is real and positive (Elsner-Vandergraft, with multiplicities).
    pub holds: bool,
}

/// The criterion of the product around the polygon in `dir` (docs/model.md §11.11).
pub fn product_criterion<F: OrderedField>(body: &ConvexBody<F>, dir: Direction) -> ProductCriterion<F> {
    let mut spectrum = Spectrum::of3(&product_around(body, dir));
    let dominant = spectrum.dominant();
    ProductCriterion { direction: dir, spectrum, dominant, holds: dominant.real_positive() }
}

/// Where the criterion of `dir` holds for gamma in (0, 1), the contacts and J fixed: the
/// product's characteristic coefficients have degree <= 2n in gamma (docs/model.md §11.11).
pub fn product_profile<F: OrderedField>(body: &ConvexBody<F>, dir: Direction) -> Profile<F> {
    let xs: Vec<Q> = (0..=2 * body.n() as i64).map(Q::int).collect();
    let coefficients = char_coefficients_at(|g| product_at(body, dir, g), &xs);
    profile(&candidates_of(coefficients), |g| {
        let mut s = Spectrum::of3(&product_at(body, dir, g));
        s.dominant().real_positive()
    })
}

/// The PCC lemma at the adjacent pair (k, k+1) (docs/model.md §11.6: proved, not conjectural).
#[derive(Clone, Debug)]
pub struct PairExclusion<F> {
    /// The first contact of the pair; the second is k + 1 mod n.
    pub k: usize,
    /// t^2 + p t + q of det(tI - I_k I_{k+1}) = (t - 1)(t^2 + p t + q), or `Err` with the value at
    /// t = 1 when 1 is not a root (impossible for a correct model).
    pub quadratic: Result<PccQuadratic<F>, F>,
}

impl<F: OrderedField> PairExclusion<F> {
    /// The lemma's verdict (`None` when the quadratic could not be formed).
    pub fn exclusion(&self) -> Option<PccExclusion> {
        self.quadratic.as_ref().ok().map(PccQuadratic::exclusion)
    }
}

/// The PCC exclusion of every adjacent pair (k, k+1), k = 0..n-1 (docs/model.md §11.6).
pub fn pair_exclusions<F: OrderedField>(body: &ConvexBody<F>) -> Vec<PairExclusion<F>> {
    (0..body.n()).map(|k| PairExclusion { k, quadratic: body.pair_pcc_quadratic(k as i64) }).collect()
}
