//! Untrusted: the transport of a general convex body by a linear map of the plane, used by the
//! family search (`crate::certify::convex`). The paper's Theorem on affine images in general form (docs/model.md §11.7): a linear map L of
//! the plane with det L > 0 carries a body (contacts r_k, inertia J) to the body with contacts
//! L r_k and inertia B J B^T, B = P L P^T = det(L) L^{-T}, P = [[0, 1], [-1, 0]]; velocities and
//! configurations map by T = diag(L / det L, 1), so I'_k = T I_k T^{-1}, m'_{k,l} = T m_{k,l},
//! C'_{ij} = T C_{ij} and covectors map by T^{-T} = diag(B, 1).

use chatter_kernel::exact::OrderedField;
use chatter_kernel::model::ConvexBody;
use chatter_kernel::model::linalg::{Mat3, Vec3, mat_vec};
use chatter_kernel::model::rod::{Mat2, mat2_mul, mat2_vec};

/// A body's image under a linear map L of the plane, with the maps that carry its velocities,
/// configurations and covectors along.
#[derive(Clone, Debug)]
pub struct AffineImage<F> {
    /// The image body: contacts L r_k (same labels), inertia B J B^T, the same gamma.
    pub body: ConvexBody<F>,
    /// T = diag(L / det L, 1): p' = T p and q' = T q (contact heights and speeds are unchanged).
    pub velocity_map: Mat3<F>,
    /// T^{-T} = diag(B, 1), B = det(L) L^{-T}: covectors l' = T^{-T} l, so l' . T p = l . p.
    pub covector_map: Mat3<F>,
}

impl<F: OrderedField> AffineImage<F> {
    /// T p: a velocity, configuration or cone generator of the original body, carried over.
    pub fn velocity(&self, p: &Vec3<F>) -> Vec3<F> {
        mat_vec(&self.velocity_map, p)
    }

    /// T^{-T} l: a covector (e.g. of a cone l . p >= 0) of the original body, carried over.
    pub fn covector(&self, l: &Vec3<F>) -> Vec3<F> {
        mat_vec(&self.covector_map, l)
    }
}

/// B = P L P^T = [[d, -c], [-b, a]] for L = [[a, b], [c, d]] (= det(L) L^{-T}).
fn cofactor<F: OrderedField>(l: &Mat2<F>) -> Mat2<F> {
    [[l[1][1].clone(), l[1][0].negated()], [l[0][1].negated(), l[0][0].clone()]]
}

fn transpose<F: OrderedField>(m: &Mat2<F>) -> Mat2<F> {
    [[m[0][0].clone(), m[1][0].clone()], [m[0][1].clone(), m[1][1].clone()]]
}

/// diag(m, 1).
fn block<F: OrderedField>(m: &Mat2<F>) -> Mat3<F> {
    let (z, o) = (F::zero(), F::one());
    [
        [m[0][0].clone(), m[0][1].clone(), z.clone()],
        [m[1][0].clone(), m[1][1].clone(), z.clone()],
        [z.clone(), z, o],
    ]
}

/// The image of the body under the linear map `l` (row-major; docs/model.md §11.7). `None` when
/// det L <= 0: a reflection reverses the order of the contacts (relabel k -> -k and use
/// docs/model.md §11.7's remark); for det L > 0 the image of a valid body is valid.
pub fn affine_image<F: OrderedField>(body: &ConvexBody<F>, l: &Mat2<F>) -> Option<AffineImage<F>> {
    let det = l[0][0].times(&l[1][1]).minus(&l[0][1].times(&l[1][0]));
    if !det.is_positive() {
        return None;
    }
    let contacts = body.contacts().iter().map(|r| mat2_vec(l, r)).collect();
    let b = cofactor(l);
    let inertia = mat2_mul(&mat2_mul(&b, body.inertia()), &transpose(&b));
    let body = ConvexBody::new(contacts, inertia, body.gamma().clone()).ok()?;
    let inv_det = F::one().over(&det)?;
    let t = l.clone().map(|row| row.map(|x| x.times(&inv_det)));
    Some(AffineImage { body, velocity_map: block(&t), covector_map: block(&b) })
}
