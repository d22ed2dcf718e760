//! The exact points of the exactifier in each number system: over Q, primitive integer
//! homogeneous vectors (fast gcd reduction); over Q(cos 2 pi/n), vectors of field elements. K
//! itself always has rational vertices; only the pieces K ∩ C_j and their images live in the field.

use super::HPoly;
use crate::exact::{Algebraic, Field, Int, OrderedField, Q, QExt, QField, Ring};
use chatter_kernel::exact::OrderedField as _;
use chatter_kernel::geometry::clip;
use chatter_kernel::model::Polygon as Body;
use chatter_kernel::model::linalg::{Vec3, mat_vec};
use malachite::Integer;
use malachite::base::num::arithmetic::traits::Gcd;

/// An exact field the exactifier can work in.
pub trait Exact: OrderedField {
    /// An exact homogeneous point (v < 0).
    type P: Clone;
    /// The images of the vertices of every K ∩ C_j under S_j of every body, or the step j of an
    /// image with v >= 0.
    fn images(bodies: &[Body<Self>], poly: &HPoly) -> Result<Vec<Self::P>, usize>;
    /// An exact seed point.
    fn point(v: &Vec3<Self>) -> Self::P;
    /// n . x for the plane point x of q, exact.
    fn support(n: &(i64, i64), q: &Self::P) -> Self;
    /// A rational >= x, within 2^-100 of it (x itself for a rational).
    fn upper(x: &Self) -> Q;
    /// The plane point of q in floats (for choosing candidates only).
    fn plane_f64(q: &Self::P) -> (f64, f64);
    /// The nearest float (for the untrusted search).
    fn approx(x: &Self) -> f64;
}

/// Divides a homogeneous vector by the gcd of its entries.
pub fn primitive(p: Vec3<Integer>) -> Vec3<Integer> {
    let g = Integer::from(p[0].unsigned_abs_ref().gcd(p[1].unsigned_abs_ref()).gcd(p[2].unsigned_abs_ref()));
    if g <= 1u32 { p } else { p.map(|c| c.div_exact(&g)) }
}

pub fn int_vec(v: &Vec3<Q>) -> Vec3<Integer> {
    let z = crate::exact::scale_to_ints(v);
    std::array::from_fn(|i| z[i].clone())
}

pub fn int_mat(m: &[[Q; 3]; 3]) -> [[Integer; 3]; 3] {
    let flat: Vec<Q> = m.iter().flatten().cloned().collect();
    let z = crate::exact::scale_to_ints(&flat);
    std::array::from_fn(|r| std::array::from_fn(|c| z[3 * r + c].clone()))
}

impl Exact for Q {
    type P = Vec3<Integer>;
    fn images(bodies: &[Body<Q>], poly: &HPoly) -> Result<Vec<Self::P>, usize> {
        let mut out = Vec::new();
        for j in 1..bodies[0].n() as i64 {
            let mut piece = poly.clone();
            for l in bodies[0].next_contact_cone(j) {
                piece = clip(&piece, &int_vec(&l)).into_iter().map(primitive).collect();
            }
            for body in bodies {
                let s = int_mat(&body.step(j));
                for p in &piece {
                    let q = primitive(mat_vec(&s, p));
                    if q.iter().all(|c| *c == 0u32) {
                        continue;
                    }
                    if q[2] >= 0u32 {
                        return Err(j as usize);
                    }
                    out.push(q);
                }
            }
        }
        Ok(out)
    }
    fn point(v: &Vec3<Q>) -> Self::P {
        primitive(int_vec(v))
    }
    fn support(n: &(i64, i64), q: &Self::P) -> Q {
        let num = Integer::from(n.0) * &q[0] + Integer::from(n.1) * &q[1];
        Q::from_fraction(&num, &(-&q[2]))
    }
    fn upper(x: &Q) -> Q {
        x.clone()
    }
    fn approx(x: &Q) -> f64 {
        x.to_f64()
    }
    fn plane_f64(q: &Self::P) -> (f64, f64) {
        let w = -&q[2];
        (Q::from_fraction(&q[0], &w).to_f64(), Q::from_fraction(&q[1], &w).to_f64())
    }
}

/// An element of Q(cos 2 pi/n) over malachite.
pub type Nf = Algebraic<Q>;

/// The nearest float of a field element (within 2^-60 before rounding).
pub fn nf_f64(x: &Nf) -> f64 {
    x.nearest_f64()
}

impl Exact for Nf {
    type P = Vec3<Nf>;
    fn images(bodies: &[Body<Nf>], poly: &HPoly) -> Result<Vec<Self::P>, usize> {
        let lift = |p: &Vec3<Integer>| p.clone().map(|c| Nf::rational(Q::from_int(&c)));
        let k: Vec<Vec3<Nf>> = poly.iter().map(lift).collect();
        let mut out = Vec::new();
        for j in 1..bodies[0].n() as i64 {
            let mut piece = k.clone();
            for l in bodies[0].next_contact_cone(j) {
                piece = clip(&piece, &l);
            }
            for body in bodies {
                let s = body.step(j);
                for p in &piece {
                    let q = mat_vec(&s, p);
                    if q.iter().all(Ring::is_zero) {
                        continue;
                    }
                    if !q[2].is_negative() {
                        return Err(j as usize);
                    }
                    out.push(q);
                }
            }
        }
        Ok(out)
    }
    fn point(v: &Vec3<Nf>) -> Self::P {
        v.clone()
    }
    fn support(n: &(i64, i64), q: &Self::P) -> Nf {
        let num = Nf::from_i64(n.0).times(&q[0]).plus(&Nf::from_i64(n.1).times(&q[1]));
        num.over(&q[2].negated()).expect("v < 0")
    }
    fn upper(x: &Nf) -> Q {
        x.enclose(&Q::new(1, 1 << 50).times(&Q::new(1, 1 << 50))).1
    }
    fn approx(x: &Nf) -> f64 {
        nf_f64(x)
    }
    fn plane_f64(q: &Self::P) -> (f64, f64) {
        let w = q[2].negated();
        (nf_f64(&q[0].over(&w).expect("v < 0")), nf_f64(&q[1].over(&w).expect("v < 0")))
    }
}
