//! The exact sign of u_0 u_1 on the eigenvectors of S_{n-1} S_1 (src/spectral/pcc_sign.rs,
//! docs/orbit-certificates.md §7.4) against a naive `f64` computation, and at the points of §7.4.

use chatter::exact::{Q, QExt};
use chatter::spectral::criteria::pcc_criterion;
use chatter::spectral::pcc_sign::pair_signs;
use chatter_kernel::model::Polygon;
use chatter_kernel::model::linalg::mat_mul;
use std::cmp::Ordering;

fn body(n: u64, kappa: Q, gamma: Q) -> Polygon<Q> {
    Polygon::new(n, kappa, gamma).unwrap()
}

/// Naive reference: M in f64, its eigenvalues other than 1 from the quadratic factor, eigenvectors
/// as the null vectors of M − λI by the largest cross product of two rows.
fn float_signs(b: &Polygon<Q>) -> Option<[f64; 2]> {
    let m = mat_mul(&b.step(b.n() as i64 - 1), &b.step(1));
    let m: [[f64; 3]; 3] = std::array::from_fn(|r| std::array::from_fn(|c| m[r][c].to_f64()));
    let tr = m[0][0] + m[1][1] + m[2][2];
    // t^3 - tr t^2 + e2 t - det = (t - 1)(t^2 - bt + c): b = tr - 1.
    let bq = tr - 1.0;
    let det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
        - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
        + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    let c = det;
    let d = bq * bq - 4.0 * c;
    if d <= 0.0 {
        return None;
    }
    let mut out = [0.0; 2];
    for (k, l) in [(bq + d.sqrt()) / 2.0, (bq - d.sqrt()) / 2.0].into_iter().enumerate() {
        let a: [[f64; 3]; 3] =
            std::array::from_fn(|r| std::array::from_fn(|c| m[r][c] - if r == c { l } else { 0.0 }));
        let cross = |x: &[f64; 3], y: &[f64; 3]| {
            [x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]]
        };
        let v = [cross(&a[0], &a[1]), cross(&a[0], &a[2]), cross(&a[1], &a[2])]
            .into_iter()
            .max_by(|x, y| {
                x.iter().map(|t| t * t).sum::<f64>().total_cmp(&y.iter().map(|t| t * t).sum::<f64>())
            })
            .unwrap();
        let norm2: f64 = v.iter().map(|t| t * t).sum();
        out[k] = v[0] * v[1] / norm2;
    }
    Some(out)
}

#[test]
fn the_exact_signs_agree_with_f64_where_f64_is_clear() {
    let mut compared = 0;
    for (n, kappa) in [(3, Q::new(1, 8)), (4, Q::new(1, 6)), (6, Q::new(1, 6)), (4, Q::new(1, 20))] {
        for k in 1..40 {
            let gamma = Q::new(k, 400);
            let b = body(n, kappa.clone(), gamma.clone());
            let exact = pair_signs(&b).unwrap();
            let float = float_signs(&b);
            assert_eq!(exact.signs.is_some(), float.is_some(), "n = {n}, kappa = {kappa}, gamma = {gamma}");
            if let (Some(e), Some(f)) = (exact.signs, float) {
                for (s, x) in e.into_iter().zip(f) {
                    if x.abs() > 1e-9 {
                        assert_eq!(
                            s,
                            x.partial_cmp(&0.0).unwrap(),
                            "n = {n}, kappa = {kappa}, gamma = {gamma}"
                        );
                        compared += 1;
                    }
                }
            }
        }
    }
    assert!(compared > 100, "{compared}");
}

#[test]
fn the_square_blocks_the_alternation_where_the_pcc_criterion_holds_and_the_triangle_does_not() {
    // docs/orbit-certificates.md §7.4: the square kappa = 1/6 below gamma = 0.0051548 (the PCC
    // criterion holds, every drop ends in CC) and the hexagon; the triangle kappa = 1/8 (drops PCC).
    for g in [Q::new(1, 1000), Q::new(1, 500), Q::new(1, 250), Q::new(1, 200)] {
        let b = body(4, Q::new(1, 6), g.clone());
        assert!(pcc_criterion(&b).0, "gamma = {g}");
        let s = pair_signs(&b).unwrap();
        assert!(s.blocks_alternation(), "square, gamma = {g}: {s:?}");
    }
    assert!(pair_signs(&body(6, Q::new(1, 6), Q::new(1, 100))).unwrap().blocks_alternation());
    for g in [Q::new(1, 200), Q::new(1, 100)] {
        let s = pair_signs(&body(3, Q::new(1, 8), g.clone())).unwrap();
        assert_eq!(s.signs, Some([Ordering::Less, Ordering::Less]), "triangle, gamma = {g}");
    }
    // The README's example: det(tI − S_3 S_1) = (t − 1)(t² − (18449/1000000) t + 1/1000000).
    let s = pair_signs(&body(4, Q::new(1, 6), Q::new(1, 1000))).unwrap();
    assert_eq!(s.quadratic, (Q::new(18449, 1_000_000), Q::new(1, 1_000_000)));
    assert_eq!(s.discriminant, Q::new(336365601, 1_000_000_000_000));
}
