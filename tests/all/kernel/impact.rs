//! Tests of `chatter_kernel::model::Polygon`: contact covectors, impact maps, relabelling and step maps.

use crate::common::{GAMMAS, KAPPAS, NS, body, q};
use chatter::exact::{Q, QExt};
use chatter::model::{kinetic_energy, square_paper_to_contact};
use chatter_kernel::model::linalg::{Mat3, Vec3, char_poly, dot, identity, mat_mul, mat_vec};
use chatter_kernel::model::{BodyError, Polygon as Body, rational_cos as cos_step};
use proptest::prelude::*;

fn v3(a: i64, b: i64, c: i64) -> Vec3<Q> {
    [Q::int(a), Q::int(b), Q::int(c)]
}

/// Every supported body over the test grids.
fn bodies() -> Vec<Body<Q>> {
    let mut out = Vec::new();
    for n in NS {
        for k in KAPPAS {
            for g in GAMMAS {
                out.push(body(n, k, g));
            }
        }
    }
    out
}

/// Chebyshev T_m(x) by the recursion, independent of the body.
fn chebyshev_t(m: usize, x: &Q) -> Q {
    let (mut a, mut b) = (Q::int(1), x.clone());
    for _ in 0..m {
        let next = Q::int(2) * x * &b - &a;
        a = b;
        b = next;
    }
    a
}

fn inverse(m: &Mat3<Q>) -> Mat3<Q> {
    // Adjugate over determinant (3x3).
    let d = chatter_kernel::model::linalg::det3(&m[0], &m[1], &m[2]);
    let c = |r: usize, s: usize| {
        let (r1, r2) = ((r + 1) % 3, (r + 2) % 3);
        let (s1, s2) = ((s + 1) % 3, (s + 2) % 3);
        &m[r1][s1] * &m[r2][s2] - &m[r1][s2] * &m[r2][s1]
    };
    std::array::from_fn(|i| std::array::from_fn(|j| c(j, i) / &d))
}

#[test]
fn cos_step_is_the_cosine_of_a_primitive_nth_root() {
    for n in NS {
        let c: Q = cos_step(n).unwrap();
        assert!((c.to_f64() - (2.0 * std::f64::consts::PI / n as f64).cos()).abs() < 1e-15);
        assert_eq!(chebyshev_t(n as usize, &c), Q::int(1), "T_n(c1) = cos(2 pi) = 1");
        for m in 1..n as usize {
            assert_ne!(chebyshev_t(m, &c), Q::int(1), "2 pi m/n is not a full turn for 0 < m < n");
        }
    }
    for n in [0, 1, 2, 5, 7, 8, 12] {
        assert!(cos_step::<Q>(n).is_none(), "n = {n}");
    }
}

#[test]
fn invalid_bodies_are_rejected_with_the_reason() {
    for n in [0, 1, 2, 5, 7, 8] {
        assert_eq!(Body::new(n, q("1/6"), q("1/100")).unwrap_err(), BodyError::UnsupportedN(n));
    }
    for k in ["0", "-1/6"] {
        assert_eq!(Body::new(4, q(k), q("1/100")).unwrap_err(), BodyError::KappaNotPositive);
    }
    for g in ["-1/100", "101/100", "2"] {
        assert_eq!(Body::new(4, q("1/6"), q(g)).unwrap_err(), BodyError::GammaOutOfRange);
    }
    assert!(Body::new(4, q("1/6"), q("0")).is_ok());
    assert!(Body::new(4, q("1/6"), q("1")).is_ok());
}

#[test]
fn cosines_follow_the_chebyshev_recursion() {
    for n in NS {
        let b = body(n, "1/6", "1/100");
        for m in -(n as i64)..2 * n as i64 {
            let expect = (2.0 * std::f64::consts::PI * m as f64 / n as f64).cos();
            assert!((b.cos(m).to_f64() - expect).abs() < 1e-12, "n={n} m={m}");
        }
    }
}

#[test]
fn contact_covectors_match_the_examples_of_the_model() {
    let sq = body(4, "1/6", "1/100");
    assert_eq!(sq.contact(0), &v3(1, 0, 0));
    assert_eq!(sq.contact(1), &v3(0, 1, 0));
    assert_eq!(sq.contact(2), &v3(-1, 0, 2), "u2 = -u0 + 2v");
    assert_eq!(sq.contact(3), &v3(0, -1, 2), "u3 = -u1 + 2v");
    assert_eq!(sq.contact(4), sq.contact(0), "indices are taken mod n");
    let tri = body(3, "1/6", "1/100");
    assert_eq!(tri.contact(2), &v3(-1, -1, 3), "u2 = -u0 - u1 + 3v");
}

#[test]
fn contact_covectors_agree_with_the_sine_formula() {
    // a_k = -sin(theta_{k-1}) / sin(theta_1), b_k = sin(theta_k) / sin(theta_1).
    for n in NS {
        let b = body(n, "1/6", "1/100");
        let th = |k: i64| 2.0 * std::f64::consts::PI * k as f64 / n as f64;
        for k in 0..n as i64 {
            let f = b.contact(k);
            let a = -th(k - 1).sin() / th(1).sin();
            let bb = th(k).sin() / th(1).sin();
            assert!((f[0].to_f64() - a).abs() < 1e-12 && (f[1].to_f64() - bb).abs() < 1e-12, "n={n} k={k}");
            assert_eq!(&f[0] + &f[1] + &f[2], Q::int(1), "a pure translation moves every contact alike");
        }
    }
}

#[test]
fn contact_velocities_match_rigid_body_kinematics() {
    // In the paper's coordinates (omega_x, omega_y, v), u_k = y_k omega_x - x_k omega_y + v with
    // (x_k, y_k) = (cos theta_k, sin theta_k); our p = (u0, u1, v) must predict the same u_k.
    for n in NS {
        let b = body(n, "1/6", "1/100");
        let th = |k: i64| 2.0 * std::f64::consts::PI * k as f64 / n as f64;
        for (wx, wy, v) in [(0.3, -0.7, -1.0), (-1.1, 0.4, 0.25), (2.0, 2.0, -3.0)] {
            let u = |k: i64| th(k).sin() * wx - th(k).cos() * wy + v;
            let p = [u(0), u(1), v];
            for k in 0..n as i64 {
                let f = b.contact(k);
                let pred = f[0].to_f64() * p[0] + f[1].to_f64() * p[1] + f[2].to_f64() * p[2];
                assert!((pred - u(k)).abs() < 1e-12, "n={n} k={k}");
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn an_impact_reverses_the_contact_velocity_by_gamma(a in -50i64..50, b in -50i64..50, c in -50i64..50, k in 0i64..6) {
        for body in bodies() {
            let p = [Q::new(a, 7), Q::new(b, 3), Q::new(c, 5)];
            let k = k % body.n() as i64;
            let f = body.contact(k).clone();
            let before = dot(&f, &p);
            let after = mat_vec(&body.impact(k), &p);
            prop_assert_eq!(dot(&f, &after), -(body.gamma() * &before));
            // Every other contact j changes by -(1 + gamma) u_k (kappa + c_{j-k}) / (1 + kappa).
            for j in 0..body.n() as i64 {
                let fj = body.contact(j);
                let change = dot(fj, &after) - dot(fj, &p);
                let expect = -(Q::int(1) + body.gamma()) * &before * (body.kappa() + body.cos(j - k)) / (Q::int(1) + body.kappa());
                prop_assert_eq!(change, expect);
            }
        }
    }

    #[test]
    fn impacts_dissipate_exactly_the_effective_mass_energy(a in -50i64..50, b in -50i64..50, c in -50i64..50, k in 0i64..6) {
        for body in bodies() {
            let p = [Q::new(a, 3), Q::new(b, 11), Q::new(c, 2)];
            let k = k % body.n() as i64;
            let uk = dot(body.contact(k), &p);
            let after = mat_vec(&body.impact(k), &p);
            let loss = kinetic_energy(&body, &p) - kinetic_energy(&body, &after);
            // Loss = (1 - gamma^2)/2 * m_eff * u_k^2 with m_eff = kappa / (1 + kappa).
            let one = Q::int(1);
            let expect = (&one - (body.gamma() * body.gamma())) / Q::int(2) * body.kappa() / (&one + body.kappa()) * &uk * &uk;
            prop_assert_eq!(&loss, &expect);
            prop_assert!(loss >= Q::int(0), "an impact never increases kinetic energy");
            if *body.gamma() == one {
                prop_assert_eq!(loss, Q::int(0), "gamma = 1 conserves energy");
            }
            if uk < Q::int(0) {
                prop_assert!(after[2] >= p[2], "v never decreases in an impact");
            }
        }
    }
}

#[test]
fn relabelling_is_a_rotation_of_the_labels() {
    for n in NS {
        let b = body(n, "3/20", "1/20");
        let r1 = b.relabel(1);
        let mut acc = identity::<Q>();
        for j in 1..=n as i64 {
            acc = mat_mul(&r1, &acc);
            if j < n as i64 {
                assert_eq!(acc, b.relabel(j), "R_j = R_1^j");
            }
        }
        assert_eq!(acc, identity::<Q>(), "R_1^n = I");
        // Impacts commute with relabelling: R_k I_k = I_0 R_k.
        for k in 0..n as i64 {
            assert_eq!(mat_mul(&b.relabel(k), &b.impact(k)), mat_mul(&b.impact(0), &b.relabel(k)));
        }
    }
}

#[test]
fn mirror_step_maps_share_their_characteristic_polynomial() {
    for b in bodies() {
        let last = b.n() as i64 - 1;
        assert_eq!(
            char_poly(&b.step(1)),
            char_poly(&b.step(last)),
            "n={} kappa={} gamma={}",
            b.n(),
            b.kappa(),
            b.gamma()
        );
    }
}

/// The paper's U_0 (equation U0) with rho^2 = kappa.
fn paper_u0(kappa: &Q, gamma: &Q) -> Mat3<Q> {
    let one = Q::int(1);
    let a = (&one + gamma) / (&one + kappa);
    let z = Q::int(0);
    [[one.clone(), z.clone(), z.clone()], [z.clone(), &one - &a, a.clone()], [z, kappa * &a, &a - gamma]]
}

/// The paper's P_alpha for alpha = quarter * pi / 2 (exact).
fn paper_rotation(quarter: i64) -> Mat3<Q> {
    let (c, s) = match quarter.rem_euclid(4) {
        0 => (1, 0),
        1 => (0, 1),
        2 => (-1, 0),
        _ => (0, -1),
    };
    let (c, s, z, o) = (Q::int(c), Q::int(s), Q::int(0), Q::int(1));
    [[c.clone(), -&s, z.clone()], [s, c, z.clone()], [z.clone(), z, o]]
}

#[test]
fn square_step_maps_are_the_papers_u0_p_minus_2j_pi_over_n() {
    let m = square_paper_to_contact::<Q>();
    let m_inv = inverse(&m);
    for k in KAPPAS {
        for g in GAMMAS {
            let b = body(4, k, g);
            for j in 1..4 {
                let in_paper = mat_mul(&m_inv, &mat_mul(&b.step(j), &m));
                let paper = mat_mul(&paper_u0(b.kappa(), b.gamma()), &paper_rotation(-j));
                assert_eq!(in_paper, paper, "kappa={k} gamma={g} j={j}");
            }
        }
    }
}

#[test]
fn step_maps_match_the_paper_for_triangles_and_hexagons_in_floats() {
    use nalgebra::Matrix3;
    for n in [3u64, 6] {
        for (k, g) in [("3/20", "1/20"), ("1/3", "3/10")] {
            let b = body(n, k, g);
            let th = 2.0 * std::f64::consts::PI / n as f64;
            let m = Matrix3::new(0.0, -1.0, 1.0, th.sin(), -th.cos(), 1.0, 0.0, 0.0, 1.0);
            let (kf, gf) = (b.kappa().to_f64(), b.gamma().to_f64());
            let a = (1.0 + gf) / (1.0 + kf);
            let u0 = Matrix3::new(1.0, 0.0, 0.0, 0.0, 1.0 - a, a, 0.0, kf * a, a - gf);
            for j in 1..n as i64 {
                let al = -th * j as f64;
                let p = Matrix3::new(al.cos(), -al.sin(), 0.0, al.sin(), al.cos(), 0.0, 0.0, 0.0, 1.0);
                let ours = m.try_inverse().unwrap() * chatter::model::mat_f64(&b.step(j)) * m;
                assert!((ours - u0 * p).abs().max() < 1e-12, "n={n} j={j}");
            }
        }
    }
}

#[test]
fn step_maps_are_impact_after_relabelling() {
    for b in bodies() {
        for j in 1..b.n() as i64 {
            assert_eq!(b.step(j), mat_mul(&b.impact(0), &b.relabel(j)));
            // After S_j the last impact is again at contact 0: u0 >= 0 whenever contact j was approaching.
            let p = [Q::int(1), Q::int(-2), Q::int(-1)];
            let uj = dot(b.contact(j), &p);
            let after = mat_vec(&b.step(j), &p);
            assert_eq!(after[0], -(b.gamma() * &uj));
        }
    }
}

#[test]
fn the_beta_factor_is_one_plus_gamma_over_one_plus_kappa() {
    let b = body(4, "1/6", "1/100");
    assert_eq!(b.beta(), q("101/100") / q("7/6"));
    assert_eq!(b.impact_direction(0), [q("7/6"), q("1/6"), q("1/6")]);
    assert_eq!(<Q as chatter_kernel::exact::OrderedField>::from_ratio(3, 6), q("1/2"));
}
