//! The points m_{k,l}, the cones C_j of velocities from which contact j hits next
//! (the paper's Lemma on C_j, docs/model.md §4), and the all-down cone D (docs/model.md §5).

use super::linalg::{Vec3, cross, neg};
use super::polygon::Polygon;
use crate::exact::OrderedField;

impl<F: OrderedField> Polygon<F> {
    /// m_{k,l}: the configuration with h_k = h_l = 0 and h_c = 1 (`None` if k, l are opposite).
    pub fn rest_point(&self, k: i64, l: i64) -> Option<Vec3<F>> {
        let [ak, bk, ek] = self.contact(k);
        let [al, bl, el] = self.contact(l);
        // a h0 + b h1 = -e for both contacts (Cramer's rule).
        let det = ak.times(bl).minus(&al.times(bk));
        let h0 = el.times(bk).minus(&ek.times(bl)).over(&det)?;
        let h1 = ek.times(al).minus(&el.times(ak)).over(&det)?;
        Some([h0, h1, F::one()])
    }

    fn adjacent_rest_point(&self, k: i64) -> Vec3<F> {
        self.rest_point(k, k + 1).expect("adjacent contacts of a polygon are never opposite")
    }

    /// Covectors l with C_j = { p : l . p >= 0 for all four } (docs/model.md §4), j = 1..n-1.
    pub fn next_contact_cone(&self, j: i64) -> [Vec3<F>; 4] {
        let (z, o) = (F::zero(), F::one());
        let m01 = self.adjacent_rest_point(0);
        let m_last = self.adjacent_rest_point(-1);
        [
            [o.clone(), z.clone(), z.clone()],
            [z.clone(), z, o.negated()],
            cross(&self.adjacent_rest_point(j), &m01),
            cross(&m_last, &self.adjacent_rest_point(j - 1)),
        ]
    }

    /// Generators -m_{k,k+1} (k = 0..n-1) of D = { p : u_k <= 0 for all k } (docs/model.md §5).
    pub fn all_down_generators(&self) -> Vec<Vec3<F>> {
        (0..self.n() as i64).map(|k| neg(&self.adjacent_rest_point(k))).collect()
    }
}
