//! The model for all parameters at once: the maps of a regular polygon with rational cosines as
//! matrices of polynomials in gamma and kappa, from the same geometry as the certificate kernel
//! (docs/model.md §2-5), in the proof's coordinates p_proof = M^-1 p_model.
//!
//! Maps are scaled by 1 + kappa > 0 so that their entries are polynomials: (1 + kappa) I_0 =
//! (1 + kappa) I - (1 + gamma) d_0 f_0^T with d_0 = (kappa + c_0, kappa + c_{-1}, kappa). A positive
//! scale changes no cone, no sign and no eigenvector.

use super::failure::Failure;
use super::poly::Poly;
use crate::exact::Field;
use crate::model::linalg::{Mat3, Vec3, det3};
use crate::model::polygon::Polygon;

/// A 3x3 matrix of polynomials.
pub type PMat<F> = [[Poly<F>; 3]; 3];
/// A 3-vector of polynomials.
pub type PVec<F> = [Poly<F>; 3];

/// The maps and cones of the model in the proof's coordinates.
pub struct SymbolicModel<F> {
    /// Number of contacts.
    pub n: usize,
    /// (1 + kappa) S_j for j = 1..n-1 (index j - 1).
    pub steps: Vec<PMat<F>>,
    /// (1 + kappa) I_0.
    pub impact: PMat<F>,
    /// Covectors of C_j for j = 1..n-1 (index j - 1), four each.
    pub cones: Vec<[PVec<F>; 4]>,
    /// Generators -m_{k,k+1} of D.
    pub all_down: Vec<PVec<F>>,
}

/// `a b`.
pub fn mat_mul<F: Field>(a: &PMat<F>, b: &PMat<F>) -> PMat<F> {
    std::array::from_fn(|r| {
        std::array::from_fn(|c| {
            (0..3).fold(Poly::zero(a[0][0].nvars()), |acc, i| acc.add(&a[r][i].mul(&b[i][c])))
        })
    })
}

/// `m x`.
pub fn mat_vec<F: Field>(m: &PMat<F>, x: &PVec<F>) -> PVec<F> {
    std::array::from_fn(|r| (0..3).fold(Poly::zero(x[0].nvars()), |acc, i| acc.add(&m[r][i].mul(&x[i]))))
}

/// `det m`.
pub fn det<F: Field>(m: &PMat<F>) -> Poly<F> {
    let t = |a: usize, b: usize, c: usize| m[0][a].mul(&m[1][b]).mul(&m[2][c]);
    t(0, 1, 2).add(&t(1, 2, 0)).add(&t(2, 0, 1)).sub(&t(2, 1, 0)).sub(&t(0, 2, 1)).sub(&t(1, 0, 2))
}

fn lift_mat<F: Field>(nvars: usize, m: &Mat3<F>) -> PMat<F> {
    std::array::from_fn(|r| std::array::from_fn(|c| Poly::constant(nvars, m[r][c].clone())))
}

fn lift_vec<F: Field>(nvars: usize, v: &Vec3<F>) -> PVec<F> {
    std::array::from_fn(|i| Poly::constant(nvars, v[i].clone()))
}

/// The inverse of an invertible constant matrix (adjugate over determinant).
fn inverse<F: Field>(m: &Mat3<F>) -> Mat3<F> {
    let minor = |r: usize, c: usize| {
        let (r0, r1) = ([1, 0, 0][r], [2, 2, 1][r]);
        let (c0, c1) = ([1, 0, 0][c], [2, 2, 1][c]);
        m[r0][c0].times(&m[r1][c1]).minus(&m[r0][c1].times(&m[r1][c0]))
    };
    let det = det3(&m[0], &m[1], &m[2]);
    std::array::from_fn(|r| {
        std::array::from_fn(|c| {
            let cof = minor(c, r);
            let cof = if (r + c) % 2 == 1 { cof.negated() } else { cof };
            cof.over(&det).expect("the caller checks det != 0")
        })
    })
}

impl<F: Field> SymbolicModel<F> {
    /// The model of the regular n-gon in variables where `gamma` and `kappa` have the given
    /// indices, in the coordinates given by the invertible matrix `m` (p_model = m p_proof; the
    /// caller checks that `m` is invertible).
    pub fn new(n: u64, nvars: usize, gamma: usize, kappa: usize, m: &Mat3<F>) -> Result<Self, Failure> {
        // Only the geometry (cosines, contact covectors, C_j, D) is used: it does not depend on
        // kappa and gamma, so any valid values build it.
        if !matches!(n, 3 | 4 | 6) {
            return Err(Failure::UnsupportedN(n));
        }
        let geo = Polygon::<F>::new(n, F::one(), F::zero()).map_err(Failure::Body)?;
        let (g, k) = (Poly::var(nvars, gamma), Poly::var(nvars, kappa));
        let one = Poly::constant(nvars, F::one());
        let (one_k, one_g) = (one.add(&k), one.add(&g));
        let d0 = [k.add(&one.scale(geo.cos(0))), k.add(&one.scale(geo.cos(-1))), k.clone()];
        let f0 = geo.contact(0);
        let impact: PMat<F> = std::array::from_fn(|r| {
            std::array::from_fn(|c| {
                let diag = if r == c { one_k.clone() } else { Poly::zero(nvars) };
                diag.sub(&one_g.mul(&d0[r]).scale(&f0[c]))
            })
        });
        let inv = lift_mat(nvars, &inverse(m));
        let mm = lift_mat(nvars, m);
        let conj = |x: &PMat<F>| mat_mul(&inv, &mat_mul(x, &mm));
        let steps =
            (1..n as i64).map(|j| conj(&mat_mul(&impact, &lift_mat(nvars, &geo.relabel(j))))).collect();
        // A covector l of the model is l^T M in the proof's coordinates.
        let covector = |l: &Vec3<F>| -> PVec<F> {
            std::array::from_fn(|c| {
                Poly::constant(nvars, (0..3).fold(F::zero(), |a, r| a.plus(&l[r].times(&m[r][c]))))
            })
        };
        let cones = (1..n as i64).map(|j| geo.next_contact_cone(j).map(|l| covector(&l))).collect();
        let all_down = geo.all_down_generators().iter().map(|g| mat_vec(&inv, &lift_vec(nvars, g))).collect();
        Ok(SymbolicModel { n: geo.n(), steps, impact: conj(&impact), cones, all_down })
    }
}
