//! The PCC quadratic (docs/model.md §5, rule R4): det(tI - S_{n-1} S_1) = (t - 1)(t² + p t + q),
//! from the 3×3 matrix by its trace, principal minors and determinant.

use super::model::Polygon;
use crate::arith::Num;

/// t² + p t + q and its discriminant.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Quadratic {
    /// p.
    pub p: Num,
    /// q.
    pub q: Num,
    /// p² - 4q.
    pub discriminant: Num,
}

impl Quadratic {
    /// Rule R4: complex roots (p² - 4q < 0) of modulus √q < 1.
    pub fn excludes_pcc(&self) -> bool {
        self.discriminant.is_negative() && (&self.q - &Num::int(&self.q.field, 1)).is_negative()
    }
}

/// The quadratic factor of det(tI - M) = (t - 1)(t² + p t + q) for a 3×3 M with eigenvalue 1;
/// panics when 1 is not an eigenvalue (the model would contradict itself).
pub fn quadratic_factor(m: &[[Num; 3]; 3]) -> Quadratic {
    let f = &m[0][0].field;
    let tr = &(&m[0][0] + &m[1][1]) + &m[2][2];
    let minor = |a: usize, b: usize| &(&m[a][a] * &m[b][b]) - &(&m[a][b] * &m[b][a]);
    let m2 = &(&minor(0, 1) + &minor(0, 2)) + &minor(1, 2);
    let det =
        &(&(&m[0][0] * &minor_of(m, 0)) - &(&m[0][1] * &minor_of(m, 1))) + &(&m[0][2] * &minor_of(m, 2));
    let one = Num::int(f, 1);
    // t³ - tr t² + m2 t - det at t = 1 must vanish.
    assert!((&(&(&one - &tr) + &m2) - &det).is_zero(), "1 is not an eigenvalue of S_(n-1) S_1");
    // (t - 1)(t² + p t + q) = t³ + (p - 1) t² + (q - p) t - q.
    let p = &one - &tr;
    let q = det;
    let discriminant = &(&p * &p) - &(&Num::int(f, 4) * &q);
    Quadratic { p, q, discriminant }
}

/// The minor of row 0 and column c (for the cofactor expansion along row 0).
fn minor_of(m: &[[Num; 3]; 3], c: usize) -> Num {
    let cols: Vec<usize> = (0..3).filter(|&k| k != c).collect();
    &(&m[1][cols[0]] * &m[2][cols[1]]) - &(&m[1][cols[1]] * &m[2][cols[0]])
}

/// The PCC quadratic of a regular polygon: the factor of S_{n-1} S_1.
pub fn pcc_quadratic(b: &Polygon) -> Quadratic {
    let n = b.n as i64;
    quadratic_factor(&b.matrix(|p| b.step(n - 1, &b.step(1, p))))
}
