//! PCC exclusion for an adjacent pair of contacts of a general convex body (docs/model.md §11.6,
//! generalising the paper's Lemma on PCC, docs/model.md §5): I_k I_{k+1} fixes m_{k,k+1}, so its
//! characteristic polynomial is (t - 1)(t^2 + p t + q), with q = gamma^2 and
//! p = 2 gamma - (1 + gamma)^2 mu^2, mu^2 = <f_k, f_{k+1}>^2 / (N_k N_{k+1}).

use super::ConvexBody;
use crate::exact::OrderedField;
use crate::model::PccQuadratic;
use crate::model::linalg::{Mat3, char_poly, mat_mul};

impl<F: OrderedField> ConvexBody<F> {
    /// I_k I_{k+1}: the velocity after an impact at k mapped to the velocity after the next
    /// impact at k when the impact in between is at k + 1 (the paper's U_0 P_{2 pi/n} U_0
    /// P_{-2 pi/n}; for the regular polygon, S_{n-1} S_1 in contact coordinates).
    pub fn pair_map(&self, k: i64) -> Mat3<F> {
        mat_mul(&self.impact(k), &self.impact(k + 1))
    }

    /// The quadratic factor t^2 + p t + q of det(t I - I_k I_{k+1}) for the adjacent pair
    /// (k, k+1); PCC of that pair is excluded when its roots are not real (docs/model.md §11.6),
    /// see [`PccQuadratic::exclusion`]. `Err` with the characteristic polynomial's value at
    /// t = 1 if 1 is not a root (impossible for a correct model).
    pub fn pair_pcc_quadratic(&self, k: i64) -> Result<PccQuadratic<F>, F> {
        let (tr, s, det) = char_poly(&self.pair_map(k));
        // t^3 - tr t^2 + s t - det = (t - 1)(t^2 + p t + q) = t^3 + (p - 1) t^2 + (q - p) t - q.
        let at_one = F::one().minus(&tr).plus(&s).minus(&det);
        if !at_one.is_zero() {
            return Err(at_one);
        }
        let p = F::one().minus(&tr);
        let discriminant = p.times(&p).minus(&F::from_i64(4).times(&det));
        Ok(PccQuadratic { p, q: det, discriminant })
    }

    /// mu^2 = <f_a, f_b>^2 / (N_a N_b), the squared cosine of the angle between f_a and f_b in
    /// the inverse-inertia metric (docs/model.md §11.6); 0 <= mu^2 < 1 for distinct contacts.
    pub fn coupling_squared(&self, a: i64, b: i64) -> F {
        let g = self.inverse_inertia_product(a, b);
        let nn = self.effective_inverse_mass(a).times(self.effective_inverse_mass(b));
        g.times(&g).over(&nn).unwrap_or_else(F::zero)
    }
}
