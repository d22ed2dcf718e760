//! Spectral criteria of a cycle of step maps (issue 15 §3, docs/orbit-certificates.md §7): for a
//! word w = (w_1, ..., w_m) of steps, the product S_{w_1} S_{w_2} ... S_{w_m} (the matrix product
//! as written, so S_{w_m} is applied first) and the verdict "its dominant eigenvalue is real and
//! positive" (Elsner-Vandergraft with multiplicities, as for the paper's S_1 criterion).
//!
//! The candidate criterion for the triangle's band above the CC threshold is the word
//! (1, 1, 2, 2): S_1^2 S_2^2. An orbit with the impact pattern (2, 2, 1, 1) (steps in the order
//! they happen) has velocity map S_1 S_1 S_2 S_2 per period, which is this product; every phase of
//! the pattern gives a cyclic rotation of the product, with the same spectrum.
//!
//! Exactly as [`super::criteria`]: the step maps are affine in gamma, so the characteristic
//! coefficients of the product are polynomials in gamma of degree <= 3m (the determinant), found by
//! interpolation at 3m + 1 integer points; the criterion can only change where one of the
//! candidates of [`candidates_of`] vanishes, whose roots in (0, 1) are isolated exactly, and it is
//! evaluated exactly between neighbouring roots ([`profile`]).

use super::criteria::{Family, Profile, candidates_of, char_coefficients_at, profile};
use super::eigen::{Dominant, Spectrum};
use crate::exact::{OrderedField, Q};
use chatter_kernel::model::Polygon as Body;
use chatter_kernel::model::linalg::{Mat3, identity, mat_mul};

/// The candidate word of issue 15: S_1^2 S_2^2.
pub const CANDIDATE: [i64; 4] = [1, 1, 2, 2];

/// The product S_{w_1} ... S_{w_m} of one body (leftmost factor applied last).
pub fn word_product<F: OrderedField>(body: &Body<F>, word: &[i64]) -> Mat3<F> {
    word.iter().fold(identity(), |acc, &j| mat_mul(&acc, &body.step(j)))
}

/// S_j = A + gamma B at any rational gamma (also outside [0, 1], for interpolation).
fn step_at<F: OrderedField>(fam: &Family<F>, j: i64, gamma: &Q) -> Mat3<F> {
    let (a, b) = (fam.at(&Q::int(0)).step(j), fam.at(&Q::int(1)).step(j));
    let g = F::from_q(gamma);
    std::array::from_fn(|r| std::array::from_fn(|c| a[r][c].plus(&g.times(&b[r][c].minus(&a[r][c])))))
}

/// The product of a word at any rational gamma.
pub fn word_product_at<F: OrderedField>(fam: &Family<F>, word: &[i64], gamma: &Q) -> Mat3<F> {
    word.iter().fold(identity(), |acc, &j| mat_mul(&acc, &step_at(fam, j, gamma)))
}

/// The criterion of a word at one body: its spectrum, the dominant eigenvalue(s), and whether
/// the dominant eigenvalue is real and positive.
#[derive(Clone, Debug)]
pub struct CycleCriterion<F> {
    pub word: Vec<i64>,
    pub spectrum: Spectrum<F>,
    pub dominant: Dominant,
    pub holds: bool,
}

/// Decides the criterion of `word` at one body, exactly.
pub fn cycle_criterion<F: OrderedField>(body: &Body<F>, word: &[i64]) -> CycleCriterion<F> {
    let mut spectrum = Spectrum::of3(&word_product(body, word));
    let dominant = spectrum.dominant();
    CycleCriterion { word: word.to_vec(), spectrum, dominant, holds: dominant.real_positive() }
}

/// Where the criterion of `word` holds for gamma in (0, 1), n and kappa fixed: exact thresholds
/// (root enclosures with their defining polynomials) and the verdict between them.
pub fn cycle_profile<F: OrderedField>(fam: &Family<F>, word: &[i64]) -> Profile<F> {
    let xs: Vec<Q> = (0..=3 * word.len() as i64).map(Q::int).collect();
    let coefficients = char_coefficients_at(|g| word_product_at(fam, word, g), &xs);
    profile(&candidates_of(coefficients), |g| cycle_criterion(&fam.at(g), word).holds)
}

/// The verdict of a profile at a rational gamma strictly inside (0, 1) that is not a threshold:
/// the verdict of the sample between the neighbouring thresholds. `None` if gamma lies in one of
/// the thresholds' isolating intervals (then decide it directly with [`cycle_criterion`]).
pub fn verdict_from_profile<F: OrderedField>(p: &Profile<F>, gamma: &Q) -> Option<bool> {
    let mut verdict = p.near_zero;
    for t in &p.thresholds {
        if gamma >= &t.gamma.lo && gamma <= &t.gamma.hi {
            return None;
        }
        if gamma > &t.gamma.hi {
            verdict = t.above;
        }
    }
    Some(verdict)
}
