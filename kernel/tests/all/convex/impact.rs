//! Tests of `kernel/src/model/convex.rs`: covectors and impact maps I_k (docs/model.md §11.2).

use super::{Rng, bodies, fixed_bodies, height};
use chatter_kernel::model::ConvexBody;
use chatter_kernel::model::linalg::{Vec3, det3, mat_vec};
use malachite::rational::Rational as Q;
use proptest::prelude::*;

/// The impact at contact k from Newton's laws, without the kernel: a vertical impulse L at
/// r_k = (x, y, z*) changes v by L and J omega by r_k x (0, 0, L) = L (y, -x) (the horizontal
/// part; z* drops out), and L is fixed by u_k+ = -gamma u_k-.
fn newton_impact(b: &ConvexBody<Q>, k: usize, p: &Vec3<Q>) -> Vec3<Q> {
    let r = &b.contacts()[k];
    let j = b.inertia();
    let det = &j[0][0] * &j[1][1] - &j[0][1] * &j[1][0];
    let torque = [r[1].clone(), -&r[0]];
    // d omega per unit impulse = J^{-1} torque.
    let dw = [
        (&j[1][1] * &torque[0] - &j[0][1] * &torque[1]) / &det,
        (&j[0][0] * &torque[1] - &j[1][0] * &torque[0]) / &det,
    ];
    let per_unit = [dw[0].clone(), dw[1].clone(), Q::from(1)];
    let u = height(r, p);
    let du = height(r, &per_unit); // the speed change of contact k per unit impulse
    let impulse = -(Q::from(1) + b.gamma()) * u / du;
    [&p[0] + &impulse * &per_unit[0], &p[1] + &impulse * &per_unit[1], &p[2] + &impulse]
}

fn random_velocity(rng: &mut Rng) -> Vec3<Q> {
    [rng.ratio(-20, 20, 7), rng.ratio(-20, 20, 7), rng.ratio(-20, 20, 7)]
}

#[test]
fn covectors_are_the_papers_f_k() {
    for b in fixed_bodies() {
        for k in 0..b.n() {
            let r = &b.contacts()[k];
            assert_eq!(b.covector(k as i64), &[r[1].clone(), -&r[0], Q::from(1)]);
            assert_eq!(b.covector(k as i64 + b.n() as i64), b.covector(k as i64), "cyclic");
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(120))]

    /// I_k p equals the impact computed from Newton's laws; u_k+ = -gamma u_k-; the other
    /// contacts change by the impulse only; v never decreases; energy never increases, by
    /// exactly (1 - gamma^2) u_k^2 / (2 N_k); det I_k = -gamma.
    #[test]
    fn impact_maps_obey_the_impact_law(b in bodies(), seed in any::<u64>()) {
        let mut rng = Rng::new(seed);
        let one = Q::from(1);
        for k in 0..b.n() {
            let ki = k as i64;
            let m = b.impact(ki);
            prop_assert_eq!(det3(&m[0], &m[1], &m[2]), -b.gamma().clone(), "det I_{}", k);
            for _ in 0..6 {
                let p = random_velocity(&mut rng);
                let after = mat_vec(&m, &p);
                prop_assert_eq!(&after, &newton_impact(&b, k, &p));
                let r = &b.contacts()[k];
                let (u, u_after) = (height(r, &p), height(r, &after));
                prop_assert_eq!(&u_after, &(-b.gamma().clone() * &u));
                if u < 0 {
                    prop_assert!(after[2] >= p[2], "v never decreases at an impact");
                }
                let lost = b.kinetic_energy(&p) - b.kinetic_energy(&after);
                let n_k = b.effective_inverse_mass(ki);
                let expected = (&one - b.gamma() * b.gamma()) * &u * &u / (Q::from(2) * n_k);
                prop_assert_eq!(&lost, &expected);
                prop_assert!(lost >= 0);
            }
        }
    }

    /// The momentum change M (p+ - p-) is a multiple of f_k (M = diag(J, 1)), and the velocity
    /// change is along w_k = M^{-1} f_k / N_k.
    #[test]
    fn the_velocity_change_is_along_m_inverse_f_k(b in bodies(), seed in any::<u64>()) {
        let mut rng = Rng::new(seed);
        let j = b.inertia().clone();
        for k in 0..b.n() as i64 {
            let p = random_velocity(&mut rng);
            let after = mat_vec(&b.impact(k), &p);
            let d: Vec3<Q> = [&after[0] - &p[0], &after[1] - &p[1], &after[2] - &p[2]];
            let md = [&j[0][0] * &d[0] + &j[0][1] * &d[1], &j[1][0] * &d[0] + &j[1][1] * &d[1], d[2].clone()];
            let f = b.covector(k);
            let scaled: Vec3<Q> = [&d[2] * &f[0], &d[2] * &f[1], &d[2] * &f[2]];
            prop_assert_eq!(md, scaled, "M dp = dv f_k");
            let w = b.impact_direction(k);
            let u = height(b.contact_point(k), &p);
            let c = -(Q::from(1) + b.gamma()) * &u;
            prop_assert_eq!(d, [&c * &w[0], &c * &w[1], &c * &w[2]]);
            // f_k . w_k = 1 and N_k >= 1.
            let fw = &f[0] * &w[0] + &f[1] * &w[1] + &f[2] * &w[2];
            prop_assert_eq!(fw, Q::from(1));
            prop_assert!(*b.effective_inverse_mass(k) >= 1);
        }
    }
}

#[test]
fn elastic_impacts_conserve_energy_and_plastic_ones_stop_the_contact() {
    let p: Vec3<Q> = [Q::from_signeds(3, 2), Q::from_signeds(-5, 7), Q::from(-2)];
    for b in fixed_bodies() {
        let elastic = ConvexBody::new(b.contacts().to_vec(), b.inertia().clone(), Q::from(1)).unwrap();
        let plastic = ConvexBody::new(b.contacts().to_vec(), b.inertia().clone(), Q::from(0)).unwrap();
        for k in 0..b.n() as i64 {
            assert_eq!(elastic.kinetic_energy(&mat_vec(&elastic.impact(k), &p)), elastic.kinetic_energy(&p));
            let after = mat_vec(&plastic.impact(k), &p);
            assert_eq!(height(plastic.contact_point(k), &after), Q::from(0));
        }
    }
}

#[test]
fn isotropic_unit_circle_contacts_have_n_k_of_section_2() {
    // J = kappa I and |r_k| = 1: N_k = (1 + kappa) / kappa and <f_a, f_b> = (cos(a - b) + kappa) / kappa.
    let kappa = Q::from_signeds(1, 6);
    let contacts = vec![
        [Q::from(1), Q::from(0)],
        [Q::from_signeds(3, 5), Q::from_signeds(4, 5)],
        [Q::from(-1), Q::from(0)],
        [Q::from_signeds(5, 13), Q::from_signeds(-12, 13)],
    ];
    let iso = [[kappa.clone(), Q::from(0)], [Q::from(0), kappa.clone()]];
    let b = ConvexBody::new(contacts.clone(), iso, Q::from_signeds(1, 3)).unwrap();
    for a in 0..4 {
        assert_eq!(b.effective_inverse_mass(a), &((Q::from(1) + &kappa) / &kappa));
        for c in 0..4 {
            let (ra, rc) = (&contacts[a as usize], &contacts[c as usize]);
            let cos = &ra[0] * &rc[0] + &ra[1] * &rc[1];
            assert_eq!(b.inverse_inertia_product(a, c), (cos + &kappa) / &kappa);
        }
    }
}
