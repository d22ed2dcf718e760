//! The rod's acceptance rules (docs/certificate-format.md §8).

use super::Accepted;
use crate::certificate::{Claim, Code, Rejection};
use crate::exact::{Field, Ring, scale_to_ints, to_canonical};
use crate::model::{Mat2, Rod, mat2_vec};
use std::cmp::Ordering;

/// The checks of docs/certificate-format.md for the rod (n = 2). A generator (u0, u1) with
/// w = -(u0 + u1) = -2v > 0 projects to s = u0 / w; K is the interval [s_lo, s_hi] of the
/// extreme generators, C_1 is s >= 0, and R4 holds trivially (with two contacts PCC is CC).
pub(super) fn check_rod<F: Field>(
    rod: &Rod<F>,
    gens: &[[F::Int; 2]],
    claim: Claim,
    bits: u64,
) -> Result<Accepted, Rejection> {
    let w = |g: &[F::Int; 2]| g[0].plus(&g[1]).negated();
    // s(a) < s(b) <=> a0 w(b) < b0 w(a) (both w > 0).
    let cmp = |a: &[F::Int; 2], b: &[F::Int; 2]| a[0].times(&w(b)).cmp(&b[0].times(&w(a)));
    let Some(lo) = (0..gens.len()).min_by(|&i, &j| cmp(&gens[i], &gens[j]).then(i.cmp(&j))) else {
        return Err(Rejection::new(Code::DegenerateCone, "field `cone` is empty: K must be a 2-D cone"));
    };
    let hi = (0..gens.len()).max_by(|&i, &j| cmp(&gens[i], &gens[j]).then(j.cmp(&i))).expect("non-empty");
    if cmp(&gens[lo], &gens[hi]) == Ordering::Equal {
        let msg = "the generators span a single ray: K must be a 2-D cone (two distinct rays)";
        return Err(Rejection::new(Code::DegenerateCone, msg));
    }
    let (a, b) = (&gens[lo], &gens[hi]);
    let inside = |q: &[F::Int; 2]| cmp(a, q) != Ordering::Greater && cmp(q, b) != Ordering::Greater;
    let point = |g: &[F::Int; 2]| {
        let two_over_w = F::from_int(&F::Int::from_i64(2)).over(&F::from_int(&w(g))).expect("w > 0");
        let c = |x: &F::Int| to_canonical(&F::from_int(x).times(&two_over_w));
        format!("({}, {})", c(&g[0]), c(&g[1]))
    };
    let check =
        |img: [F::Int; 2], what: &dyn Fn() -> String, outside: Code, above: Code| -> Result<(), Rejection> {
            if img.iter().all(Ring::is_zero) {
                return Ok(());
            }
            if !w(&img).is_positive() {
                return Err(Rejection::new(above, format!("{} to a velocity with v >= 0", what())));
            }
            if inside(&img) {
                return Ok(());
            }
            let (edge, end) = if cmp(&img, a) == Ordering::Less { (lo, a) } else { (hi, b) };
            let s = |g: &[F::Int; 2]| F::from_int(&g[0]).over(&F::from_int(&w(g))).expect("w > 0");
            let by = s(&img).minus(&s(end));
            let msg = format!(
                "{} to {} outside K, beyond generator {edge}, by {} in u0/(-2v)",
                what(),
                point(&img),
                to_canonical(&by)
            );
            Err(Rejection::new(outside, msg))
        };
    // K ∩ C_1: the part with s >= 0; its lower end is the ray u0 = 0, i.e. (0, -1), if s_lo < 0.
    let mut piece = Vec::new();
    if !b[0].is_negative() {
        piece.push(if a[0].is_negative() { [F::Int::zero(), F::Int::from_i64(-1)] } else { a.clone() });
        piece.push(b.clone());
    }
    let step = int_mat2(&rod.step());
    for (i, p) in piece.iter().enumerate() {
        let what = || format!("vertex {i} of K∩C_1, at {}, maps under S_1", point(p));
        check(mat2_vec(&step, p), &what, Code::ImageOutside, Code::ImageNotBelow)?;
    }
    let i0 = int_mat2(&rod.impact(0));
    if claim >= Claim::CcOrPccFromAllDown {
        for (k, g) in [[0, -1], [-1, 0]].iter().enumerate() {
            let g = g.map(F::Int::from_i64);
            let what = || format!("I_0 maps the all-down generator {k} = {}", point(&g));
            check(mat2_vec(&i0, &g), &what, Code::InitialOutside, Code::InitialOutside)?;
        }
    }
    let t = mat2_vec(&i0, &[F::Int::from_i64(-1), F::Int::from_i64(-1)]);
    let contains_translation = w(&t).is_positive() && inside(&t);
    let redundant = (0..gens.len()).filter(|i| *i != lo && *i != hi).collect();
    let pieces = vec![piece.len()];
    Ok(Accepted {
        claim,
        n: 2,
        generators: gens.len(),
        redundant,
        pieces,
        max_denominator_bits: bits,
        pcc: None,
        contains_translation,
    })
}

/// A positive integer multiple of a rational 2x2 matrix.
fn int_mat2<F: Field>(m: &Mat2<F>) -> [[F::Int; 2]; 2] {
    let z = scale_to_ints(&[m[0][0].clone(), m[0][1].clone(), m[1][0].clone(), m[1][1].clone()]);
    [[z[0].clone(), z[1].clone()], [z[2].clone(), z[3].clone()]]
}
