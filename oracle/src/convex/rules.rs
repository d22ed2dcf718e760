//! Rules K1 to K4 of docs/certificate-format.md §13 for a family K_0, ..., K_{n-1}, at one γ or
//! over an interval [γ_lo, γ_hi] of γ (version 2).
//!
//! Over an interval the rules are checked at its ends ([`crate::kinds::family`] runs them at γ_lo,
//! then at γ_hi), for reasons derived here from the oracle's model ([`super::model`]): K_i, C_ij
//! and D are not functions of γ, and I_j(γ) p = p - (1 + γ)(f_j · p) w_j is affine in γ with w_j
//! not a function of γ, so for a fixed vertex p the set of γ with I_j(γ) p in the convex cone K_j
//! (and v < 0) is an interval: K2 and K3 hold on [γ_lo, γ_hi] iff they hold at both ends. K4 is
//! decided from the closed form p = 2γ - (1 + γ)² μ², q = γ² of the quadratic factor
//! ([`Body::pair_closed_form`], μ² not a function of γ; checked equal to the matrix's factor at
//! every γ visited): p² - 4q = (p - 2γ)(p + 2γ) = -(1 + γ)² μ² h(γ) with h(γ) = 4γ - (1 + γ)² μ²
//! concave, so the discriminant is negative on the interval iff μ² ≠ 0 and h > 0 at both ends;
//! q < 1 iff γ_hi < 1, a rule of the claims about drops. The argument is then tested by brute force
//! at two interior rational values of γ, where K2-K4 must hold too (a failure there is
//! `corner-argument-violated`, as for boxes).

use super::model::{Body, V3};
use crate::arith::Num;
use crate::arith::rational::ratio;
use crate::arith::text::element_text;
use crate::claim::Claim;
use crate::plane::{HalfPlane, Pt, clip_vertices, lift};
use crate::regular::pcc::quadratic_factor;
use crate::regular::rules::{Polygon2, cone_polygon, leaving, misses};
use crate::verdict::{Checked, Fail, Report};

/// How the reason for a failure of K2, K3 or K4 at an end of an interval of γ begins (the end's
/// canonical text follows, then [`OF_THE_INTERVAL`]); the kernel's message begins alike and its
/// locus carries the end.
pub const AT_END: &str = "at the end gamma = ";
/// What follows the end's text in [`AT_END`]'s prefix.
pub const OF_THE_INTERVAL: &str = " of the interval: ";

/// A failure of K2, K3 or K4 at the end γ of an interval, its reason prefixed with the end.
pub fn at_end(gamma: &Num, f: Fail) -> Fail {
    Fail { codes: f.codes, why: format!("{AT_END}{}{OF_THE_INTERVAL}{}", element_text(gamma), f.why) }
}

/// The end of the interval a reason names ([`at_end`]), as text.
pub fn end_named(why: &str) -> Option<&str> {
    why.strip_prefix(AT_END)?.split_once(OF_THE_INTERVAL).map(|(end, _)| end)
}

/// Interior values of γ, as fractions t of [γ_lo, γ_hi] (γ = γ_lo + t (γ_hi - γ_lo)), at which the
/// reduction to the ends is tested.
const SAMPLES: [(i64, i64); 2] = [(1, 3), (5, 7)];

/// The interior values of γ of [lo, hi] at which a reduction to the ends is tested (`SAMPLES`).
pub fn interior_gammas(lo: &Num, hi: &Num) -> Vec<Num> {
    SAMPLES.iter().map(|&(a, c)| lo + &(&(hi - lo) * &Num::rational(&lo.field, ratio(a, c)))).collect()
}

/// `corner-argument-violated`: the ends of an interval pass but `gamma` inside it fails with `f`.
pub fn violated(gamma: &Num, f: Fail) -> Fail {
    let why = format!(
        "the ends pass but gamma = {} fails ({}): {}",
        element_text(gamma),
        f.codes.join(", "),
        f.why
    );
    Fail::new("corner-argument-violated", why)
}

/// The brute-force test of the reduction to the ends (the module's documentation): K2-K4 of the
/// claim at the interior samples (`SAMPLES`) of [lo, hi], `b` being the body at either end.
pub fn interior(b: &Body, claim: Claim, family: &Family, lo: &Num, hi: &Num) -> Checked<()> {
    for gamma in interior_gammas(lo, hi) {
        if let Err(f) = check_family(&b.at_gamma(gamma.clone()), claim, family, 0) {
            return Err(violated(&gamma, f));
        }
    }
    Ok(())
}

/// K4 at the adjacent pair (k, k+1): the quadratic factor of the matrix I_k I_{k+1} has complex
/// roots of modulus < 1. The factor must equal the closed form [`Body::pair_closed_form`] (the
/// model would contradict itself otherwise).
pub fn pcc_excluded(b: &Body, k: i64) -> bool {
    let quad = quadratic_factor(&b.pair_matrix(k));
    let (p, q) = b.pair_closed_form(k);
    assert!(quad.p == p && quad.q == q, "the closed form of K4 differs from the matrix at the pair {k}");
    quad.excludes_pcc()
}

/// K1 for every cone, in order.
pub fn polygons(cones: &[Vec<V3>]) -> Checked<Vec<Polygon2>> {
    cones
        .iter()
        .enumerate()
        .map(|(i, c)| cone_polygon(c).map_err(|f| Fail { codes: f.codes, why: format!("K_{i}: {}", f.why) }))
        .collect()
}

/// What a family's rules use that does not depend on γ, computed once for every γ visited: the
/// cones K_i as polygons on v = -1 (rule K1 holds) and the pieces K_i ∩ C_ij (C_ij is spanned by
/// rest points, which the contacts alone fix).
pub struct Family {
    /// K_0, ..., K_{n-1}.
    pub ks: Vec<Polygon2>,
    /// (i, j, the vertices of K_i ∩ C_ij) for i = 0..n-1, j ≠ i, in order.
    pieces: Vec<(usize, usize, Vec<Pt>)>,
    /// The number of generators of each cone as written.
    written: Vec<usize>,
}

impl Family {
    /// The family of the polygons `ks` of `cones` (K1 checked) for the body's contacts.
    pub fn new(b: &Body, cones: &[Vec<V3>], ks: Vec<Polygon2>) -> Family {
        let mut pieces = vec![];
        for i in 0..ks.len() {
            for j in (0..ks.len()).filter(|&j| j != i) {
                let c: Vec<HalfPlane> =
                    b.next_contact_facets(i as i64, j as i64).iter().map(HalfPlane::of_covector).collect();
                pieces.push((i, j, clip_vertices(&ks[i].vertices, &c)));
            }
        }
        Family { ks, pieces, written: cones.iter().map(Vec::len).collect() }
    }
}

/// K2 at the body's γ: I_j(K_i ∩ C_ij) ⊆ K_j for all i ≠ j; the piece sizes in the order (i, j).
pub fn transitions(b: &Body, family: &Family) -> Checked<Vec<usize>> {
    let mut sizes = vec![];
    for (i, j, piece) in &family.pieces {
        let codes = leaving(&family.ks[*j], piece.iter().map(|p| b.impact(*j as i64, &lift(p))));
        if !codes.is_empty() {
            return Err(Fail { codes, why: format!("I_{j}(K_{i} ∩ C_({i},{j})) is not in K_{j}") });
        }
        sizes.push(piece.len());
    }
    Ok(sizes)
}

/// K3: I_i(-m_{k,k+1}) ∈ K_i for all i, k.
pub fn all_down(b: &Body, ks: &[Polygon2]) -> Checked<()> {
    for (i, k) in ks.iter().enumerate() {
        for g in b.all_down() {
            if misses(k, &b.impact(i as i64, &g)).is_some() {
                return Err(Fail::new("initial-outside", format!("I_{i}(D) is not in K_{i}")));
            }
        }
    }
    Ok(())
}

/// K2-K4 at the body's γ (the body, the file's rules and K1 already checked).
pub fn check_family(b: &Body, claim: Claim, family: &Family, bits: u64) -> Checked<Report> {
    let ks = &family.ks;
    let pieces = transitions(b, family)?;
    if claim >= Claim::CcOrPccFromAllDown {
        all_down(b, ks)?;
    }
    if claim >= Claim::CompleteChatterFromAllDown {
        for k in 0..b.n() as i64 {
            if !pcc_excluded(b, k) {
                return Err(Fail::new(
                    "pcc-not-excluded",
                    format!("PCC of contacts {k} and {} is possible", k + 1),
                ));
            }
        }
    }
    let mut redundant = vec![];
    let mut offset = 0;
    for (written, k) in family.written.iter().zip(ks) {
        redundant.extend(k.redundant.iter().map(|r| r + offset));
        offset += written;
    }
    let f = b.gamma.field.clone();
    let down = [Num::int(&f, 0), Num::int(&f, 0), Num::int(&f, -1)];
    let translation = ks.iter().enumerate().all(|(i, k)| misses(k, &b.impact(i as i64, &down)).is_none());
    Ok(Report {
        claim: claim.name().into(),
        n: b.n() as u64,
        generators: Some(offset),
        redundant: Some(redundant),
        pieces: Some(pieces),
        max_denominator_bits: Some(bits),
        pcc: None,
        contains_translation: Some(translation),
        region: None,
        refutation: None,
        basin: None,
        rest_nodes: None,
    })
}
