//! Full inertia tensors (docs/model.md §11.1, `bodies::inertia`): the planar model with
//! J_eff = J - b bᵀ / I_zz against an independent 3-D Newton-Euler impulse computation (a
//! 7×7 exact linear system: six velocity unknowns and the impulse), the tensor's checks, the
//! parallel-axis theorem, and the catalogue rebuilt from 3-D geometry.

use chatter::bodies::general::{general_catalogue, lander_parts, table_parts};
use chatter::bodies::inertia::{Part, Tensor, TensorError, Vec3, assemble};
use chatter::exact::{Q, Ring};
use chatter_kernel::model::linalg::mat_vec;
use chatter_kernel::model::{ConvexBody, Mat2};

/// A small deterministic generator of rationals (no shared state with the code under test).
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        self.0 >> 33
    }

    /// A rational in [-range, range] with denominator `den`.
    fn q(&mut self, range: i64, den: i64) -> Q {
        let span = (2 * range * den + 1) as u64;
        Q::new((self.next() % span) as i64 - range * den, den)
    }
}

/// Solves A x = b exactly by Gaussian elimination with pivoting on non-zero entries.
fn solve(mut a: Vec<Vec<Q>>, mut b: Vec<Q>) -> Vec<Q> {
    let n = b.len();
    for col in 0..n {
        let piv = (col..n).find(|&r| !a[r][col].is_zero()).expect("a regular system");
        a.swap(col, piv);
        b.swap(col, piv);
        for r in 0..n {
            if r == col || a[r][col].is_zero() {
                continue;
            }
            let f = &a[r][col] / &a[col][col];
            let pivot = a[col].clone();
            for (x, p) in a[r].iter_mut().zip(&pivot).skip(col) {
                *x = &*x - &(&f * p);
            }
            let d = &f * &b[col];
            b[r] = &b[r] - &d;
        }
    }
    (0..n).map(|i| &b[i] / &a[i][i]).collect()
}

/// The 3-D state of a body of unit mass: velocity of the centre and angular velocity.
#[derive(Clone, Debug)]
struct State {
    v: Vec3,
    w: Vec3,
}

/// The normal velocity of the point r: (v + ω × r)_z, computed in full (r's z included).
fn normal_velocity(s: &State, r: &Vec3) -> Q {
    &s.v[2] + &(&s.w[0] * &r[1] - &s.w[1] * &r[0])
}

/// Newton-Euler for a frictionless impulse P e_z at r with restitution gamma: unknowns Δv (3),
/// Δω (3), P; equations Δv = P e_z, I Δω = r × P e_z, (v⁺ + ω⁺ × r)_z = -γ (v⁻ + ω⁻ × r)_z.
fn impact_3d(inertia: &Tensor, s: &State, r: &Vec3, gamma: &Q) -> State {
    let (z, one) = (Q::int(0), Q::int(1));
    let mut a = vec![vec![z.clone(); 7]; 7];
    let mut b = vec![z.clone(); 7];
    for (i, row) in a.iter_mut().enumerate().take(3) {
        row[i] = one.clone();
    }
    a[2][6] = -&one;
    // r × e_z = (r_y, -r_x, 0).
    let torque = [r[1].clone(), -&r[0], z.clone()];
    for i in 0..3 {
        for j in 0..3 {
            a[3 + i][3 + j] = inertia.0[i][j].clone();
        }
        a[3 + i][6] = -&torque[i];
    }
    // (ω × r)_z = ω_x r_y - ω_y r_x: coefficients of Δv_z, Δω_x, Δω_y; right side -(1 + γ) u⁻.
    a[6][2] = one.clone();
    a[6][3] = r[1].clone();
    a[6][4] = -&r[0];
    b[6] = -(&(&one + gamma) * &normal_velocity(s, r));
    let x = solve(a, b);
    State { v: std::array::from_fn(|i| &s.v[i] + &x[i]), w: std::array::from_fn(|i| &s.w[i] + &x[3 + i]) }
}

/// A random physical tensor with products of inertia: point masses at random positions, and
/// contacts (a perturbed square about the centre of mass) at a common random depth below it.
fn random_body(g: &mut Lcg) -> (Tensor, Vec<Vec3>) {
    let parts: Vec<Part> = (0..5)
        .map(|_| {
            let m = Q::new(1 + (g.next() % 9) as i64, 4);
            Part::point(m, [g.q(2, 7), g.q(2, 5), g.q(2, 3)])
        })
        .collect();
    let a = assemble(&parts).expect("positive masses");
    let depth = -&Q::new(1 + (g.next() % 20) as i64, 10);
    let square = [(2, 0), (0, 2), (-2, 0), (0, -2)];
    let contacts =
        square.iter().map(|&(x, y)| [&Q::int(x) + &g.q(1, 4), &Q::int(y) + &g.q(1, 4), depth.clone()]);
    (a.tensor, contacts.collect())
}

fn planar(contacts: &[Vec3], j: Mat2<Q>, gamma: &Q) -> ConvexBody<Q> {
    let pts = contacts.iter().map(|r| [r[0].clone(), r[1].clone()]).collect();
    ConvexBody::new(pts, j, gamma.clone()).expect("a valid planar body")
}

/// Runs `impacts` impacts at random contacts in 3-D and in the planar model of `j`; returns
/// whether the contacts' normal velocities and (ω_x, ω_y, v_z) agreed after every impact.
fn agree(g: &mut Lcg, tensor: &Tensor, contacts: &[Vec3], j: Mat2<Q>, impacts: usize) -> bool {
    let gamma = Q::new(1 + (g.next() % 9) as i64, 10);
    let body = planar(contacts, j, &gamma);
    // v_z <= -1: the body falls (p != 0, so the impacts are not all trivial).
    let vz = &g.q(1, 3) - &Q::int(2);
    let mut s = State { v: [g.q(1, 3), g.q(1, 3), vz], w: [g.q(1, 3), g.q(1, 3), g.q(1, 3)] };
    let mut p = [s.w[0].clone(), s.w[1].clone(), s.v[2].clone()];
    let mut same = true;
    for _ in 0..impacts {
        let k = (g.next() % contacts.len() as u64) as usize;
        s = impact_3d(tensor, &s, &contacts[k], &gamma);
        p = mat_vec(&body.impact(k as i64), &p);
        let full: Vec<Q> = contacts.iter().map(|r| normal_velocity(&s, r)).collect();
        let flat: Vec<Q> = (0..contacts.len())
            .map(|c| chatter_kernel::model::linalg::dot(body.covector(c as i64), &p))
            .collect();
        same &= full == flat && p == [s.w[0].clone(), s.w[1].clone(), s.v[2].clone()];
    }
    same
}

#[test]
fn the_planar_map_with_j_eff_equals_the_3d_impulse_law_on_the_contacts() {
    let mut g = Lcg(25);
    for _ in 0..30 {
        let (t, contacts) = random_body(&mut g);
        assert!(!t.0[0][2].is_zero() && !t.0[1][2].is_zero(), "products with the vertical axis: {t:?}");
        t.check().expect("a physical tensor");
        let j = t.effective().expect("I_zz > 0");
        assert!(agree(&mut g, &t, &contacts, j, 6), "J_eff disagrees with 3-D: {t:?} {contacts:?}");
    }
}

#[test]
fn the_horizontal_block_alone_disagrees_with_the_3d_impulse_law() {
    let mut g = Lcg(26);
    for _ in 0..30 {
        let (t, contacts) = random_body(&mut g);
        let j = t.horizontal();
        assert!(!agree(&mut g, &t, &contacts, j, 6), "the horizontal block agreed: {t:?} {contacts:?}");
    }
}

#[test]
fn j_eff_inverts_the_upper_left_block_of_the_inverse_tensor() {
    let mut g = Lcg(27);
    for _ in 0..20 {
        let (t, _) = random_body(&mut g);
        let j = t.effective().unwrap();
        // Columns of I⁻¹ e_x, I⁻¹ e_y by the solver; their upper 2×2 block times J_eff is E.
        let cols: Vec<Vec<Q>> = (0..2)
            .map(|c| {
                let a = t.0.iter().map(|row| row.to_vec()).collect();
                solve(a, (0..3).map(|i| Q::int((i == c) as i64)).collect())
            })
            .collect();
        for (r, jr) in j.iter().enumerate() {
            for (c, col) in cols.iter().enumerate() {
                let e = &(&jr[0] * &col[0]) + &(&jr[1] * &col[1]);
                assert_eq!(e, Q::int((r == c) as i64));
            }
        }
    }
}

#[test]
fn tensor_checks_are_exact_and_name_the_failure() {
    let d = |a: i64, b: i64, c: i64| Tensor::diagonal(Q::int(a), Q::int(b), Q::int(c));
    // A flat plate has I_zz = I_xx + I_yy: the triangle inequality's boundary is accepted.
    assert_eq!(d(1, 1, 2).check(), Ok(()));
    assert!(matches!(d(1, 1, 3).check(), Err(TensorError::NotAMassDistribution { .. })));
    assert!(matches!(d(1, 0, 1).check(), Err(TensorError::NotPositiveDefinite { order: 2, .. })));
    let six = |v: [i64; 6]| Tensor::from_urdf(&v.map(Q::int));
    // ixy^2 > ixx iyy: not positive definite at order 2.
    assert!(matches!(
        six([1, 2, 0, 1, 0, 1]).check(),
        Err(TensorError::NotPositiveDefinite { order: 2, .. })
    ));
    let e = six([2, 0, 2, 2, 0, 2]).check().unwrap_err();
    assert!(matches!(e, TensorError::NotPositiveDefinite { order: 3, .. }), "{e}");
    assert!(e.to_string().contains("not positive definite"), "{e}");
    assert_eq!(six([2, 0, 2, 2, 0, 2]).urdf(), [2, 0, 2, 2, 0, 2].map(Q::int));
}

#[test]
fn the_parallel_axis_theorem_moves_a_tensor_to_the_centre_of_mass() {
    let mut g = Lcg(28);
    for _ in 0..10 {
        let parts: Vec<Part> = (0..4)
            .map(|_| Part::point(Q::new(1 + (g.next() % 5) as i64, 3), [g.q(2, 5), g.q(2, 5), g.q(2, 5)]))
            .collect();
        let a = assemble(&parts).unwrap();
        let p: Vec3 = [g.q(3, 2), g.q(3, 2), g.q(3, 2)];
        // The tensor about p, summed directly from the parts.
        let zero = Tensor::diagonal(Q::int(0), Q::int(0), Q::int(0));
        let about_p = parts.iter().fold(zero, |acc, part| {
            let d: Vec3 = std::array::from_fn(|k| &part.at[k] - &p[k]);
            acc.plus(&Tensor::point(&d).scaled(&part.mass))
        });
        let per_unit = about_p.scaled(&(Q::int(1) / &a.mass));
        let d: Vec3 = std::array::from_fn(|k| &a.centre[k] - &p[k]);
        assert_eq!(per_unit.to_centre(&d), a.tensor);
    }
}

#[test]
fn the_catalogue_is_built_from_its_3d_geometry() {
    let all = general_catalogue(&Q::new(1, 20)).unwrap();
    for e in &all {
        e.tensor.check().unwrap_or_else(|err| panic!("{}: {err}", e.name));
        assert_eq!(&e.tensor.effective().unwrap(), e.body.inertia(), "{}", e.name);
    }
    // The symmetric table has no products: its J is the horizontal block (74263/750000 and
    // 141263/750000 of the derivation written out by hand before the 3-D rebuild).
    let table = &all[2];
    assert_eq!(
        table.body.inertia(),
        &[[Q::new(74263, 750000), Q::int(0)], [Q::int(0), Q::new(141263, 750000)]]
    );
    let (parts, feet) = table_parts();
    assert_eq!(assemble(&parts).unwrap().centre[2], Q::new(83, 125));
    assert!(feet.iter().all(|f| f[2].is_zero()));
    // The lander's feet below its centre give I_xz != 0, so J_eff differs from the block.
    let lander = &all[3];
    assert_eq!(lander.tensor.urdf()[2], Q::new(4, 375));
    assert_ne!(&lander.tensor.horizontal(), lander.body.inertia());
    let (parts, _) = lander_parts();
    let a = assemble(&parts).unwrap();
    assert_eq!(a.centre, [Q::new(1, 75), Q::int(0), Q::new(-1, 5)]);
}
