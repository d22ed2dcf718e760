//! A general convex body (docs/model.md §11.1-§11.4) in the paper's coordinates
//! p = (ω_x, ω_y, v): contacts r_k, inertia J, restitution γ; covectors f_k = (y_k, -x_k, 1),
//! M = diag(J, 1), impacts I_k = I - (1 + γ) w_k f_kᵀ with w_k = M⁻¹ f_k / N_k, rest points by
//! solving h_k = h_l = 0, h = 1, and the cones C_ij from their generators (11.2).

use crate::arith::{Field, Num, Rat};
use crate::cone3::{dot, facets};
use crate::plane::{Pt, orient};
use std::sync::Arc;

/// A vector (ω_x, ω_y, v).
pub type V3 = [Num; 3];

/// The body.
#[derive(Clone, Debug)]
pub struct Body {
    /// Contacts r_k.
    pub contacts: Vec<Pt>,
    /// J⁻¹ (2×2).
    j_inv: [[Num; 2]; 2],
    /// γ.
    pub gamma: Num,
}

/// Why the data are not a body of §11.1.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BodyFault {
    /// Fewer than 3 or more than 64 contacts.
    Count,
    /// Not strictly convex and counter-clockwise (A1).
    NotConvex,
    /// The origin is not strictly inside (A2).
    OriginNotInside,
    /// J is not positive definite.
    Inertia,
    /// γ outside [0, 1].
    Gamma,
}

impl Body {
    /// Checks (A1), (A2), J positive definite and 0 ≤ γ ≤ 1, and builds the body. (A1) and (A2)
    /// are tested edge by edge: every other contact and the origin strictly left of each edge.
    pub fn new(contacts: Vec<Pt>, j: [Num; 3], gamma: Num) -> Result<Body, BodyFault> {
        let n = contacts.len();
        if !(3..=64).contains(&n) {
            return Err(BodyFault::Count);
        }
        let f = contacts[0].0.field.clone();
        let origin = (Num::int(&f, 0), Num::int(&f, 0));
        for k in 0..n {
            let (a, b) = (&contacts[k], &contacts[(k + 1) % n]);
            if (0..n).any(|i| i != k && i != (k + 1) % n && !orient(a, b, &contacts[i]).is_positive())
                || a == b
            {
                return Err(BodyFault::NotConvex);
            }
        }
        if (0..n).any(|k| !orient(&contacts[k], &contacts[(k + 1) % n], &origin).is_positive()) {
            return Err(BodyFault::OriginNotInside);
        }
        let det = &(&j[0] * &j[2]) - &(&j[1] * &j[1]);
        if !j[0].is_positive() || !det.is_positive() {
            return Err(BodyFault::Inertia);
        }
        if gamma.is_negative() || gamma > Num::int(&f, 1) {
            return Err(BodyFault::Gamma);
        }
        let j_inv = [[&j[2] / &det, &j[1].neg() / &det], [&j[1].neg() / &det, &j[0] / &det]];
        Ok(Body { contacts, j_inv, gamma })
    }

    fn field(&self) -> &Arc<Field> {
        &self.gamma.field
    }

    /// Number of contacts.
    pub fn n(&self) -> usize {
        self.contacts.len()
    }

    fn at(&self, k: i64) -> &Pt {
        &self.contacts[k.rem_euclid(self.n() as i64) as usize]
    }

    /// f_k = (y_k, -x_k, 1).
    pub fn covector(&self, k: i64) -> V3 {
        let r = self.at(k);
        [r.1.clone(), r.0.neg(), Num::int(self.field(), 1)]
    }

    /// M⁻¹ a for a covector a.
    fn inverse_mass(&self, a: &V3) -> V3 {
        let m = &self.j_inv;
        [&(&m[0][0] * &a[0]) + &(&m[0][1] * &a[1]), &(&m[1][0] * &a[0]) + &(&m[1][1] * &a[1]), a[2].clone()]
    }

    /// I_k p = p - (1 + γ) (f_k · p) w_k, w_k = M⁻¹ f_k / ⟨f_k, f_k⟩.
    pub fn impact(&self, k: i64, p: &V3) -> V3 {
        let f = self.covector(k);
        let mf = self.inverse_mass(&f);
        let norm = dot(&f, &mf);
        let scale = &(&(&Num::int(self.field(), 1) + &self.gamma) * &dot(&f, p)) / &norm;
        std::array::from_fn(|i| &p[i] - &(&scale * &mf[i]))
    }

    /// w_k = M⁻¹ f_k / ⟨f_k, f_k⟩, the direction of I_k (not a function of γ; f_k · w_k = 1).
    fn direction(&self, k: i64) -> V3 {
        let mf = self.inverse_mass(&self.covector(k));
        let norm = dot(&self.covector(k), &mf);
        mf.map(|x| &x / &norm)
    }

    /// μ² = (f_k · w_{k+1}) (f_{k+1} · w_k) of the adjacent pair (k, k+1), not a function of γ.
    pub fn pair_coupling(&self, k: i64) -> Num {
        let (f0, f1) = (self.covector(k), self.covector(k + 1));
        &dot(&f0, &self.direction(k + 1)) * &dot(&f1, &self.direction(k))
    }

    /// (p, q) of the quadratic factor t² + p t + q of det(tI - I_k I_{k+1}) in closed form: with
    /// a = 1 + γ, I_k I_{k+1} = I - a w_k f_kᵀ - a w_{k+1} f_{k+1}ᵀ + a² (f_k · w_{k+1}) w_k f_{k+1}ᵀ
    /// has trace 3 - 2a + a² μ² and determinant (1 - a)² = γ² (each I_k fixes the plane f_k = 0
    /// and maps w_k to -γ w_k), and (t - 1)(t² + p t + q) = t³ + (p - 1) t² + (q - p) t - q gives
    /// p = 1 - trace = 2γ - a² μ², q = γ².
    pub fn pair_closed_form(&self, k: i64) -> (Num, Num) {
        let g = &self.gamma;
        let a = &Num::int(self.field(), 1) + g;
        let p = &(g + g) - &(&(&a * &a) * &self.pair_coupling(k));
        (p, g * g)
    }

    /// The same body at another γ in [0, 1] (the contacts and J, already checked, are kept).
    pub fn at_gamma(&self, gamma: Num) -> Body {
        Body { gamma, ..self.clone() }
    }

    /// m_{k,l} = (φ_x, φ_y, 1) with f_k · m = f_l · m = 0, by Cramer's rule.
    pub fn rest_point(&self, k: i64, l: i64) -> V3 {
        let (a, b) = (self.covector(k), self.covector(l));
        // a0 x + a1 y = -1, b0 x + b1 y = -1.
        let det = &(&a[0] * &b[1]) - &(&a[1] * &b[0]);
        let x = &(&b[1].neg() + &a[1]) / &det;
        let y = &(&b[0] - &a[0]) / &det;
        [x, y, Num::int(self.field(), 1)]
    }

    /// The facets of C_ij, from its generators B₋ - A₋, -A₋, -A₊, B₊ - A₊ (Lemma 11.3).
    pub fn next_contact_facets(&self, i: i64, j: i64) -> Vec<V3> {
        let (am, ap) = (self.rest_point(i - 1, i), self.rest_point(i, i + 1));
        let (bm, bp) = (self.rest_point(j - 1, j), self.rest_point(j, j + 1));
        let sub = |x: &V3, y: &V3| -> V3 { std::array::from_fn(|c| &x[c] - &y[c]) };
        let neg = |x: &V3| -> V3 { std::array::from_fn(|c| x[c].neg()) };
        facets(&[sub(&bm, &am), neg(&am), neg(&ap), sub(&bp, &ap)])
    }

    /// The generators -m_{k,k+1} of D (Lemma 11.2(4)).
    pub fn all_down(&self) -> Vec<V3> {
        (0..self.n() as i64).map(|k| self.rest_point(k, k + 1).map(|x| x.neg())).collect()
    }

    /// The matrix of I_k I_{k+1}.
    pub fn pair_matrix(&self, k: i64) -> [[Num; 3]; 3] {
        let f = self.field();
        let unit = |i: usize| -> V3 { std::array::from_fn(|r| Num::int(f, i64::from(r == i))) };
        let cols: Vec<V3> = (0..3).map(|i| self.impact(k, &self.impact(k + 1, &unit(i)))).collect();
        std::array::from_fn(|r| std::array::from_fn(|c| cols[c][r].clone()))
    }
}

/// A rational as an element of Q.
pub fn q(field: &Arc<Field>, x: Rat) -> Num {
    Num::rational(field, x)
}
