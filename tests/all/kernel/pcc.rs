//! Tests of `chatter_kernel::model::pcc_quadratic`: the factor (t - 1)(t^2 + p t + q) of S_{n-1} S_1.

use crate::common::{GAMMAS, KAPPAS, NS, body};
use chatter::exact::{Q, QExt, Ring};
use chatter::model::mat_f64;
use chatter_kernel::model::linalg::{mat_mul, mat_vec};
use chatter_kernel::model::pcc_quadratic;
use num_rational::BigRational;

#[test]
fn one_is_always_an_eigenvalue_with_eigenvector_m01() {
    for n in NS {
        for k in KAPPAS {
            for g in GAMMAS {
                let b = body(n, k, g);
                let quad = pcc_quadratic(&b).expect("t = 1 is a root");
                // The constant term is det(S_{n-1} S_1) = det(S_1)^2 = gamma^2.
                assert_eq!(quad.q, b.gamma() * b.gamma(), "n={n} kappa={k} gamma={g}");
                let m01 = b.rest_point(0, 1).unwrap();
                let last = n as i64 - 1;
                assert_eq!(mat_vec(&mat_mul(&b.step(last), &b.step(1)), &m01), m01);
            }
        }
    }
}

#[test]
fn the_discriminant_sign_matches_float_eigenvalues() {
    for n in NS {
        for k in KAPPAS {
            for g in ["1/100", "1/20", "3/10", "9/10"] {
                let b = body(n, k, g);
                let quad = pcc_quadratic(&b).unwrap();
                let m = mat_f64(&mat_mul(&b.step(n as i64 - 1), &b.step(1)));
                let ev = m.complex_eigenvalues();
                let max_im = ev.iter().map(|z| z.im.abs()).fold(0.0, f64::max);
                let d = quad.discriminant.to_f64();
                if d.abs() > 1e-9 {
                    assert_eq!(
                        max_im > 1e-9,
                        d < 0.0,
                        "n={n} kappa={k} gamma={g}: disc {d:e}, eigenvalues {ev:?}"
                    );
                }
            }
        }
    }
}

#[test]
fn both_backends_factor_identically() {
    for n in NS {
        let a = pcc_quadratic(&body(n, "3/20", "1/20")).unwrap();
        let nb = chatter_kernel::model::Polygon::<BigRational>::new(
            n,
            "3/20".parse().unwrap(),
            "1/20".parse().unwrap(),
        )
        .unwrap();
        let b = pcc_quadratic(&nb).unwrap();
        assert_eq!(a.discriminant.to_string(), b.discriminant.to_string());
        assert_eq!(a.p.to_string(), b.p.to_string());
    }
}

#[test]
fn square_pcc_is_excluded_at_moderate_gamma() {
    // Where the paper's claim holds for the square plate: kappa = 1/6, 1/100 <= gamma < 1.
    for g in 1..=99 {
        let b = chatter_kernel::model::Polygon::<Q>::new(4, Q::new(1, 6), Q::new(g, 100)).unwrap();
        assert!(pcc_quadratic(&b).unwrap().excludes_pcc(), "gamma={g}/100");
    }
}

/// Regression record of a disagreement with the paper: it states that the PCC Lemma's condition
/// (all eigenvalues real) is never met for n >= 4, which its theorem for the square relies on.
/// For the square plate (kappa = 1/6) at gamma = 1/1000 (where S_1 has a real positive dominant
/// eigenvalue), all eigenvalues are real, so PCC is not excluded there.
#[test]
fn square_plate_at_tiny_gamma_has_all_eigenvalues_real_contrary_to_the_paper() {
    let quad = pcc_quadratic(&body(4, "1/6", "1/1000")).unwrap();
    assert!(quad.discriminant.is_positive(), "discriminant {}", quad.discriminant);
    let quad = pcc_quadratic(&body(4, "1/4", "1/100")).unwrap();
    assert!(quad.discriminant.is_positive(), "discriminant {}", quad.discriminant);
}

#[test]
fn triangles_admit_pcc_in_a_small_region_only() {
    assert!(!pcc_quadratic(&body(3, "1/8", "1/100")).unwrap().excludes_pcc());
    assert!(pcc_quadratic(&body(3, "3/20", "1/20")).unwrap().excludes_pcc());
}

/// Regression record of a disagreement with the paper: it states the PCC Lemma's condition (all
/// eigenvalues of U_0 P_{2pi/n} U_0 P_{-2pi/n} real) is never met for n >= 4. For the hexagon it
/// is met, e.g. at kappa = 1/6, gamma = 1/100: the quadratic factor has real roots.
#[test]
fn hexagons_can_have_all_eigenvalues_real_contrary_to_the_paper() {
    let quad = pcc_quadratic(&body(6, "1/6", "1/100")).unwrap();
    assert!(quad.discriminant.is_positive());
    assert!(!quad.excludes_pcc());
}
