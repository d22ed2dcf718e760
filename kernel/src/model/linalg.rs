//! 3-vectors and 3x3 matrices over any exact ring.

use crate::exact::Ring;

/// A 3-vector, e.g. (u0, u1, v).
pub type Vec3<R> = [R; 3];
/// A 3x3 matrix, row-major.
pub type Mat3<R> = [[R; 3]; 3];

/// `a . b`.
pub fn dot<R: Ring>(a: &Vec3<R>, b: &Vec3<R>) -> R {
    a[0].times(&b[0]).plus(&a[1].times(&b[1])).plus(&a[2].times(&b[2]))
}

/// `a x b`.
pub fn cross<R: Ring>(a: &Vec3<R>, b: &Vec3<R>) -> Vec3<R> {
    [
        a[1].times(&b[2]).minus(&a[2].times(&b[1])),
        a[2].times(&b[0]).minus(&a[0].times(&b[2])),
        a[0].times(&b[1]).minus(&a[1].times(&b[0])),
    ]
}

/// det[a, b, c] with a, b, c as the rows (= (a x b) . c).
pub fn det3<R: Ring>(a: &Vec3<R>, b: &Vec3<R>, c: &Vec3<R>) -> R {
    dot(&cross(a, b), c)
}

/// `m x`.
pub fn mat_vec<R: Ring>(m: &Mat3<R>, x: &Vec3<R>) -> Vec3<R> {
    [dot(&m[0], x), dot(&m[1], x), dot(&m[2], x)]
}

/// `a b`.
pub fn mat_mul<R: Ring>(a: &Mat3<R>, b: &Mat3<R>) -> Mat3<R> {
    let col = |j: usize| [b[0][j].clone(), b[1][j].clone(), b[2][j].clone()];
    let cols = [col(0), col(1), col(2)];
    let row = |i: usize| [dot(&a[i], &cols[0]), dot(&a[i], &cols[1]), dot(&a[i], &cols[2])];
    [row(0), row(1), row(2)]
}

/// The identity matrix.
pub fn identity<R: Ring>() -> Mat3<R> {
    let (o, z) = (R::one(), R::zero());
    [[o.clone(), z.clone(), z.clone()], [z.clone(), o.clone(), z.clone()], [z.clone(), z, o]]
}

/// `s x`.
pub fn scale<R: Ring>(s: &R, x: &Vec3<R>) -> Vec3<R> {
    [s.times(&x[0]), s.times(&x[1]), s.times(&x[2])]
}

/// `-x`.
pub fn neg<R: Ring>(x: &Vec3<R>) -> Vec3<R> {
    [x[0].negated(), x[1].negated(), x[2].negated()]
}

/// `a - b`.
pub fn sub<R: Ring>(a: &Vec3<R>, b: &Vec3<R>) -> Vec3<R> {
    [a[0].minus(&b[0]), a[1].minus(&b[1]), a[2].minus(&b[2])]
}

/// Whether every entry is zero.
pub fn is_zero<R: Ring>(x: &Vec3<R>) -> bool {
    x.iter().all(Ring::is_zero)
}

/// Characteristic polynomial det(t I - M) = t^3 - c2 t^2 + c1 t - c0, returned as (c2, c1, c0)
/// = (trace, sum of principal 2x2 minors, determinant).
pub fn char_poly<R: Ring>(m: &Mat3<R>) -> (R, R, R) {
    let tr = m[0][0].plus(&m[1][1]).plus(&m[2][2]);
    let minor = |i: usize, j: usize| m[i][i].times(&m[j][j]).minus(&m[i][j].times(&m[j][i]));
    let s = minor(0, 1).plus(&minor(0, 2)).plus(&minor(1, 2));
    (tr, s, det3(&m[0], &m[1], &m[2]))
}
