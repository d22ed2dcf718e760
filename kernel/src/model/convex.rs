//! General convex bodies (docs/model.md §11): contacts (x_k, y_k), k = 0..n-1, counter-clockwise
//! around the projection of the centre of mass (the origin), a horizontal inertia tensor J per
//! unit mass about the centre of mass, and a restitution gamma. Unlike [`super::Polygon`] this
//! model has no symmetry: it works in the paper's coordinates p = (omega_x, omega_y, v),
//! q = (phi_x, phi_y, h), where contact k has the covector f_k = (y_k, -x_k, 1) (u_k = f_k . p,
//! h_k = f_k . q), and every map is rational when the contacts and J are.
//!
//! - this file: the body, its covectors f_k and the impact maps I_k (§11.2);
//! - `shape`: validation of the data (§11.1);
//! - `cones`: the rest points m_{k,l}, the cones C_{ij} and the all-down cone D (§11.3-11.5);
//! - `pcc`: the PCC quadratic of an adjacent pair (§11.6).
//!
//! (The transport of a body by a linear map of the plane, §11.7, is in the untrusted tool.)

mod cones;
mod pcc;
pub mod shape;

pub use shape::{ConvexBodyError, MAX_CONTACTS, check_convex_polygon};

use super::linalg::{Mat3, Vec3, dot, identity};
use super::rod::{Mat2, Vec2};
use crate::exact::OrderedField;

/// A rigid body resting on n >= 3 contacts in strictly convex position around its centre of
/// mass (docs/model.md §11.1). Built only by [`ConvexBody::new`], so every instance is valid.
#[derive(Clone, Debug)]
pub struct ConvexBody<F> {
    contacts: Vec<Vec2<F>>,
    inertia: Mat2<F>,
    gamma: F,
    /// f_k = (y_k, -x_k, 1).
    covectors: Vec<Vec3<F>>,
    /// N_k = f_k^T M^{-1} f_k, M = diag(J, 1).
    norms: Vec<F>,
    /// w_k = M^{-1} f_k / N_k: I_k = I - (1 + gamma) w_k f_k^T.
    pushes: Vec<Vec3<F>>,
    /// m_{k,k+1}, k = 0..n-1 (docs/model.md §11.3).
    rest: Vec<Vec3<F>>,
}

impl<F: OrderedField> ConvexBody<F> {
    /// The body with contacts `contacts` (counter-clockwise, strictly convex, the origin strictly
    /// inside; 3 to [`MAX_CONTACTS`] of them), inertia `inertia` (J, symmetric positive definite,
    /// per unit mass, about the centre of mass; J_xy = -sum m x y as in an inertia tensor) and
    /// restitution 0 <= gamma <= 1. Every violation is a typed [`ConvexBodyError`].
    pub fn new(contacts: Vec<Vec2<F>>, inertia: Mat2<F>, gamma: F) -> Result<Self, ConvexBodyError> {
        shape::check_body(&contacts, &inertia, &gamma)?;
        let covectors: Vec<Vec3<F>> = contacts.iter().map(covector).collect();
        let (norms, pushes) = impact_data(&covectors, &shape::inverse_inertia(&inertia)?)?;
        let rest = edge_rest_points(&covectors)?;
        Ok(ConvexBody { contacts, inertia, gamma, covectors, norms, pushes, rest })
    }

    /// Number of contacts n.
    pub fn n(&self) -> usize {
        self.contacts.len()
    }

    fn index(&self, k: i64) -> usize {
        k.rem_euclid(self.n() as i64) as usize
    }

    /// The contact points (x_k, y_k), counter-clockwise.
    pub fn contacts(&self) -> &[Vec2<F>] {
        &self.contacts
    }

    /// Contact point k (indices are taken modulo n).
    pub fn contact_point(&self, k: i64) -> &Vec2<F> {
        &self.contacts[self.index(k)]
    }

    /// The horizontal inertia tensor J per unit mass, about the centre of mass.
    pub fn inertia(&self) -> &Mat2<F> {
        &self.inertia
    }

    /// The coefficient of restitution.
    pub fn gamma(&self) -> &F {
        &self.gamma
    }

    /// Covector f_k = (y_k, -x_k, 1) of contact k: u_k = f_k . p, h_k = f_k . q (the paper's f_i).
    pub fn covector(&self, k: i64) -> &Vec3<F> {
        &self.covectors[self.index(k)]
    }

    /// w_k = M^{-1} f_k / (f_k^T M^{-1} f_k): the velocity change of an impact at k per unit of
    /// -(1 + gamma) u_k (docs/model.md §11.2). Its v-component 1/N_k is positive.
    pub fn impact_direction(&self, k: i64) -> &Vec3<F> {
        &self.pushes[self.index(k)]
    }

    /// N_k = f_k^T M^{-1} f_k = 1 + g_k^T J^{-1} g_k with g_k = (y_k, -x_k) (>= 1).
    pub fn effective_inverse_mass(&self, k: i64) -> &F {
        &self.norms[self.index(k)]
    }

    /// <f_a, f_b> = f_a^T M^{-1} f_b, the inverse-inertia product of two contact covectors
    /// (for the regular polygon with J = kappa I: (c_{a-b} + kappa) / kappa, docs/model.md §2).
    pub fn inverse_inertia_product(&self, a: i64, b: i64) -> F {
        dot(self.covector(a), self.impact_direction(b)).times(self.effective_inverse_mass(b))
    }

    /// Impact map I_k = I - (1 + gamma) w_k f_k^T (docs/model.md §11.2; the paper's U_i):
    /// p+ = p - (1 + gamma) u_k M^{-1} f_k / (f_k^T M^{-1} f_k), so u_k+ = -gamma u_k-.
    pub fn impact(&self, k: i64) -> Mat3<F> {
        let c = F::one().plus(&self.gamma);
        let (w, f) = (self.impact_direction(k), self.covector(k));
        let mut m = identity::<F>();
        for (r, row) in m.iter_mut().enumerate() {
            for (s, e) in row.iter_mut().enumerate() {
                *e = e.minus(&c.times(&w[r]).times(&f[s]));
            }
        }
        m
    }

    /// Kinetic energy per unit mass T = omega^T J omega / 2 + v^2 / 2 of p = (omega_x, omega_y, v).
    pub fn kinetic_energy(&self, p: &Vec3<F>) -> F {
        let j = &self.inertia;
        let (wx, wy) = (&p[0], &p[1]);
        let off = j[0][1].times(wx).times(wy);
        let rot = j[0][0].times(wx).times(wx).plus(&off).plus(&off).plus(&j[1][1].times(wy).times(wy));
        rot.plus(&p[2].times(&p[2])).times(&F::from_ratio(1, 2))
    }
}

/// f = (y, -x, 1) of the contact (x, y).
fn covector<F: OrderedField>(r: &Vec2<F>) -> Vec3<F> {
    [r[1].clone(), r[0].negated(), F::one()]
}

/// N_k and w_k of every contact (the error is unreachable for a positive definite J).
fn impact_data<F: OrderedField>(
    covectors: &[Vec3<F>],
    j_inv: &Mat2<F>,
) -> Result<(Vec<F>, Vec<Vec3<F>>), ConvexBodyError> {
    let data = covectors.iter().map(|f| push(j_inv, f).ok_or(ConvexBodyError::InertiaNotPositiveDefinite));
    Ok(data.collect::<Result<Vec<_>, _>>()?.into_iter().unzip())
}

/// m_{k,k+1} for every edge (the error is unreachable once the origin is strictly inside).
fn edge_rest_points<F: OrderedField>(covectors: &[Vec3<F>]) -> Result<Vec<Vec3<F>>, ConvexBodyError> {
    let n = covectors.len();
    let m = |k: usize| cones::rest_point_of(&covectors[k], &covectors[(k + 1) % n]);
    (0..n).map(|k| m(k).ok_or(ConvexBodyError::OriginOnEdge { edge: k })).collect()
}

/// (N, w) with N = f^T M^{-1} f and w = M^{-1} f / N, M^{-1} = diag(J^{-1}, 1); `None` only if
/// N = 0 (impossible for a positive definite J, where N >= 1).
fn push<F: OrderedField>(j_inv: &Mat2<F>, f: &Vec3<F>) -> Option<(F, Vec3<F>)> {
    let a = j_inv[0][0].times(&f[0]).plus(&j_inv[0][1].times(&f[1]));
    let b = j_inv[1][0].times(&f[0]).plus(&j_inv[1][1].times(&f[1]));
    let norm = a.times(&f[0]).plus(&b.times(&f[1])).plus(&F::one());
    let w = [a.over(&norm)?, b.over(&norm)?, F::one().over(&norm)?];
    Some((norm, w))
}
