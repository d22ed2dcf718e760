//! PCC exclusion on a box of parameters (feature `boxes`, docs/kernel-soundness.md §2 "Boxes"):
//! the discriminant and q - 1 of the PCC quadratic as polynomials in (kappa, gamma).

use super::linalg::Mat3;
use super::polygon::Polygon;
use crate::bivariate::Bi;
use crate::exact::OrderedField;

/// PCC exclusion as polynomials in (kappa, gamma), for boxes of parameters: with s = (1 + kappa)^2,
/// `discriminant` = s^3 (p^2 - 4 q) and `modulus` = s^3 (q - 1), where t^2 + p t + q is the
/// quadratic factor of det(t I - S_{n-1} S_1). (1 + kappa) S_j has entries affine in kappa and in
/// gamma (docs/kernel-soundness.md §2, "Boxes"), so both are polynomials.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PccPolynomials<F> {
    /// s^3 (p^2 - 4 q).
    pub discriminant: Bi<F>,
    /// s^3 (q - 1).
    pub modulus: Bi<F>,
}

/// (1 + kappa) I_0 = (1 + kappa) I - (1 + gamma) d_0 f_0^T with d_0 = (kappa + 1, kappa + c_1,
/// kappa) (docs/model.md §3), as polynomials: only the cosines and the covector f_0 of `body` are
/// used, never its kappa and gamma.
fn scaled_impact<F: OrderedField>(body: &Polygon<F>) -> Mat3<Bi<F>> {
    let (z, o) = (F::zero(), F::one());
    let bi = |a: &F, b: &F, c: &F, d: &F| Bi::bilinear(a.clone(), b.clone(), c.clone(), d.clone());
    // d_r = kappa + offset_r, so (1 + gamma) d_r = offset_r + kappa + offset_r gamma + kappa gamma.
    let offsets = [body.cos(0).clone(), body.cos(-1).clone(), z.clone()];
    let f0 = body.contact(0);
    std::array::from_fn(|r| {
        std::array::from_fn(|c| {
            let diag = if r == c { bi(&o, &o, &z, &z) } else { Bi::constant(z.clone()) };
            let off = &offsets[r];
            let push = bi(off, &o, off, &o).times(&Bi::constant(f0[c].clone()));
            diag.minus(&push)
        })
    })
}

fn mat_mul_bi<F: OrderedField>(a: &Mat3<Bi<F>>, b: &Mat3<Bi<F>>) -> Mat3<Bi<F>> {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            (0..3).fold(Bi::constant(F::zero()), |acc, k| acc.plus(&a[i][k].times(&b[k][j])))
        })
    })
}

/// The PCC polynomials of the regular polygon with `body`'s number of contacts. `Err` with the
/// residue if t = 1 is not a root of the characteristic polynomial identically (impossible for a
/// correct model).
pub fn pcc_polynomials<F: OrderedField>(body: &Polygon<F>) -> Result<PccPolynomials<F>, Bi<F>> {
    let i0 = scaled_impact(body);
    let relabel = |j: i64| body.relabel(j).map(|row| row.map(Bi::constant));
    let step = |j: i64| mat_mul_bi(&i0, &relabel(j));
    let a = mat_mul_bi(&step(body.n() as i64 - 1), &step(1));
    let minor = |i: usize, j: usize| a[i][i].times(&a[j][j]).minus(&a[i][j].times(&a[j][i]));
    let tr = a[0][0].plus(&a[1][1]).plus(&a[2][2]);
    let m2 = minor(0, 1).plus(&minor(0, 2)).plus(&minor(1, 2));
    let cof =
        |i: usize, j: usize, k: usize, l: usize| a[i][k].times(&a[j][l]).minus(&a[i][l].times(&a[j][k]));
    let det = a[0][0]
        .times(&cof(1, 2, 1, 2))
        .minus(&a[0][1].times(&cof(1, 2, 0, 2)))
        .plus(&a[0][2].times(&cof(1, 2, 0, 1)));
    let one_plus_k = Bi::bilinear(F::one(), F::one(), F::zero(), F::zero());
    let s = one_plus_k.times(&one_plus_k);
    let s3 = s.times(&s).times(&s);
    // det(t I - A/s) s^3 at t = 1: s^3 - s^2 tr + s m2 - det.
    let at_one = s3.minus(&s.times(&s).times(&tr)).plus(&s.times(&m2)).minus(&det);
    if !at_one.is_zero() {
        return Err(at_one);
    }
    // p = 1 - tr/s, q = det/s^3: s^3 (p^2 - 4q) = s (s - tr)^2 - 4 det.
    let gap = s.minus(&tr);
    let discriminant = s.times(&gap).times(&gap).minus(&Bi::constant(F::from_i64(4)).times(&det));
    Ok(PccPolynomials { discriminant, modulus: det.minus(&s3) })
}
