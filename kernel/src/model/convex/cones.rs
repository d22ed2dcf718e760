//! The rest points m_{k,l}, the cones C_{ij} of velocities after an impact at contact i from
//! which contact j can be the next to hit, and the all-down cone D of a general convex body
//! (docs/model.md §11.3-11.5; generalises the paper's Lemma on C_j, docs/model.md §4).

use super::ConvexBody;
use crate::exact::OrderedField;
use crate::model::linalg::{Vec3, cross, neg, scale, sub};

/// m = (f_k x f_l) / D with D = (f_k x f_l)_3 = x_k y_l - x_l y_k: the configuration with
/// h_k = h_l = 0 and h = 1. `None` when D = 0 (the two contacts are collinear with the origin).
pub(super) fn rest_point_of<F: OrderedField>(fk: &Vec3<F>, fl: &Vec3<F>) -> Option<Vec3<F>> {
    let c = cross(fk, fl);
    let inv = F::one().over(&c[2])?;
    Some(scale(&inv, &c))
}

impl<F: OrderedField> ConvexBody<F> {
    /// m_{k,l}: the configuration q = (phi_x, phi_y, h) with contacts k and l on the floor and the
    /// centre of mass at height h = 1 (the paper's m_{k,l}); `None` if r_k, r_l and the origin are
    /// collinear (e.g. opposite contacts of a centrally symmetric body).
    pub fn rest_point(&self, k: i64, l: i64) -> Option<Vec3<F>> {
        rest_point_of(self.covector(k), self.covector(l))
    }

    /// m_{k,k+1}, which always exists: (x_{k+1} - x_k, y_{k+1} - y_k, D) / D with
    /// D = x_k y_{k+1} - x_{k+1} y_k > 0 (docs/model.md §11.3).
    pub fn edge_rest_point(&self, k: i64) -> &Vec3<F> {
        &self.rest[k.rem_euclid(self.n() as i64) as usize]
    }

    /// The four generators of C_{ij} (docs/model.md §11.4), with A- = m_{i-1,i}, A+ = m_{i,i+1},
    /// B- = m_{j-1,j}, B+ = m_{j,j+1}: [B- - A-, -A-, -A+, B+ - A+], in this cyclic order
    /// (the paper's Lemma on C_j for i = 0). `None` when i = j (mod n).
    pub fn next_contact_generators(&self, i: i64, j: i64) -> Option<[Vec3<F>; 4]> {
        self.distinct(i, j)?;
        let (am, ap) = (self.edge_rest_point(i - 1), self.edge_rest_point(i));
        let (bm, bp) = (self.edge_rest_point(j - 1), self.edge_rest_point(j));
        Some([sub(bm, am), neg(am), neg(ap), sub(bp, ap)])
    }

    /// Covectors l with C_{ij} = { p : l . p >= 0 for all four } (docs/model.md §11.4):
    /// [f_i, (0, 0, -1), B+ x A+, A- x B-] (u_i >= 0 after the impact, v <= 0, and the two
    /// conditions for j to land before any other contact). For j = i + 1 the third is a positive
    /// multiple of -f_{i+1} and the fourth of f_i; for j = i - 1 the third is a positive multiple
    /// of f_i and the fourth of -f_{i-1}. `None` when i = j (mod n).
    pub fn next_contact_cone(&self, i: i64, j: i64) -> Option<[Vec3<F>; 4]> {
        self.distinct(i, j)?;
        let (am, ap) = (self.edge_rest_point(i - 1), self.edge_rest_point(i));
        let (bm, bp) = (self.edge_rest_point(j - 1), self.edge_rest_point(j));
        let (z, o) = (F::zero(), F::one());
        Some([self.covector(i).clone(), [z.clone(), z, o.negated()], cross(bp, ap), cross(am, bm)])
    }

    /// Generators -m_{k,k+1}, k = 0..n-1, of D = { p : u_k <= 0 for all k } = -F, the velocities
    /// with every contact moving down or at rest (docs/model.md §11.5).
    pub fn all_down_generators(&self) -> Vec<Vec3<F>> {
        (0..self.n() as i64).map(|k| neg(self.edge_rest_point(k))).collect()
    }

    fn distinct(&self, i: i64, j: i64) -> Option<()> {
        let n = self.n() as i64;
        (i.rem_euclid(n) != j.rem_euclid(n)).then_some(())
    }
}
