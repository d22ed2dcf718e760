//! The oracle's own arithmetic and model against docs/model.md and docs/certificate-format.md,
//! with no kernel involved: numbers, the number fields, the model's documented examples and
//! identities, the geometry helpers.

use chatter_oracle::arith::cyclotomic::cos_minimal_polynomial;
use chatter_oracle::arith::enclosure::cos_bounds;
use chatter_oracle::arith::rational::{NumberFault, Rat, parse_rational, ratio, rational_text};
use chatter_oracle::arith::text::{element_text, parse_number};
use chatter_oracle::arith::{Field, Num};
use chatter_oracle::cone3::dot;
use chatter_oracle::plane::{HalfPlane, Pt, clip_vertices, hull};
use chatter_oracle::regular::model::Polygon;
use chatter_oracle::regular::pcc::pcc_quadratic;
use chatter_oracle::regular::rod::Rod;

fn r(s: &str) -> Rat {
    parse_rational(s, 10_000).expect("canonical")
}

fn body(n: usize, kappa: &str, gamma: &str) -> Polygon {
    let f = Field::cos(n as u32);
    Polygon::new(n, Num::rational(&f, r(kappa)), Num::rational(&f, r(gamma)))
}

fn v(b: &Polygon, x: [i64; 3]) -> [Num; 3] {
    x.map(|k| Num::int(&b.kappa.field, k))
}

#[test]
fn numbers_follow_the_canonical_rules() {
    for ok in ["0", "1", "-1", "1/2", "-3/4", "10", "123456789012345678901234567890/11"] {
        assert_eq!(parse_rational(ok, 10_000).map(|x| rational_text(&x)).as_deref(), Ok(ok));
    }
    for bad in [
        "", "-", "+1", "01", "-0", "1/0", "1/1", "2/4", "0/5", " 1", "1 ", "1.5", "1e3", "1/", "/2", "1/-2",
        "--1", "1/01",
    ] {
        assert!(parse_rational(bad, 10_000).is_err(), "{bad:?}");
    }
    let long = format!("1{}/3", "0".repeat(9998));
    assert!(parse_rational(&long, 10_000).is_ok());
    assert!(parse_rational(&format!("1{long}"), 10_000).is_err());
}

/// max-digits bounds a whole element: its coefficients' digits together, the exponents of c not
/// counted, checked before the terms are read (as the kernel does; before, the oracle counted the
/// exponents and checked last).
#[test]
fn the_digit_limit_counts_the_coefficients_of_a_whole_element() {
    let f = Field::cos(7);
    let half = format!("1/{}", "3".repeat(4_999));
    let at_limit = format!("{half} + {half}*c^2");
    assert!(parse_number(&at_limit, &f, 10_000).is_ok(), "10,000 coefficient digits and an exponent");
    assert_eq!(parse_number(&at_limit, &f, 9_999).err(), Some(NumberFault::TooLong));
    let not_canonical = format!("{half}*c^2 + {half}");
    assert_eq!(parse_number(&not_canonical, &f, 9_999).err(), Some(NumberFault::TooLong));
    assert_eq!(parse_number(&not_canonical, &f, 10_000).err(), Some(NumberFault::Bad));
}

#[test]
fn field_elements_have_one_text_and_exact_inverses() {
    let f = Field::cos(5);
    for ok in ["0", "1/2", "c", "-c", "1/40 + 1/100*c", "-2 + 2*c", "3/7 - c"] {
        assert_eq!(parse_number(ok, &f, 10_000).map(|x| element_text(&x)).as_deref(), Ok(ok), "{ok}");
    }
    for bad in ["c + 1/2", "1*c", "c^1", "1/2 + 0*c", "2/4*c", "1/2+c", "1/2 + -c", "c^2", "1/2 + c + c"] {
        assert!(parse_number(bad, &f, 10_000).is_err(), "{bad:?}");
    }
    for n in [5u32, 7, 8, 9, 12, 17, 60, 64] {
        let f = Field::cos(n);
        let x = Num::from_poly(&f, (0..f.degree()).map(|k| ratio(k as i64 * 3 - 2, 7 + k as i64)).collect());
        let one = &x * &x.inverse();
        assert_eq!(element_text(&one), "1", "n = {n}");
        // c² = (1 + cos 4π/n)/2 and 2c² - 1 = cos 4π/n > 0 exactly when 4π/n < π/2.
        let c = Num::generator(&f);
        let double = &(&Num::int(&f, 2) * &(&c * &c)) - &Num::int(&f, 1);
        assert_eq!(double.is_positive(), n > 8, "cos 4π/{n}");
    }
}

#[test]
fn the_minimal_polynomial_has_degree_phi_over_two_and_cos_as_a_root() {
    let phi = |n: u32| (1..=n).filter(|k| num_integer::gcd(*k, n) == 1).count();
    for n in [5u32, 7, 8, 9, 10, 11, 12, 15, 16, 24, 30, 64] {
        let psi = cos_minimal_polynomial(n);
        assert_eq!(psi.len() - 1, phi(n) / 2, "n = {n}");
        let at = |x: &Rat| psi.iter().rev().fold(Rat::from_integer(0.into()), |acc, a| acc * x + a);
        let (lo, hi) = cos_bounds(n, 64);
        assert!(lo < hi && &hi - &lo < ratio(1, 1 << 40), "n = {n}");
        assert!(at(&lo) * at(&hi) <= Rat::from_integer(0.into()), "a root of Ψ_{n} in the enclosure");
    }
}

#[test]
fn contact_speeds_are_the_documented_ones() {
    // docs/model.md §2: square u2 = -u0 + 2v; triangle u2 = -u0 - u1 + 3v; hexagon u5 = u0 - u1 + v.
    for (n, k, want) in
        [(4, 2, [-1, 0, 2]), (4, 3, [0, -1, 2]), (3, 2, [-1, -1, 3]), (6, 2, [-1, 1, 1]), (6, 5, [1, -1, 1])]
    {
        let b = body(n, "1/6", "1/10");
        let got: Vec<Num> =
            (0..3).map(|i| b.speed(k, &v(&b, std::array::from_fn(|j| i64::from(i == j))))).collect();
        assert_eq!(got, v(&b, want).to_vec(), "n = {n}, u_{k}");
    }
}

#[test]
fn impacts_cones_and_d_satisfy_the_model() {
    for n in [3, 4, 5, 6, 7, 8, 12] {
        let f = Field::cos(n as u32);
        let b = Polygon::new(n, parse_number("1/8", &f, 99).unwrap(), parse_number("1/20", &f, 99).unwrap());
        let p = v(&b, [-3, 2, -5]);
        for k in 0..n as i64 {
            // u_k⁺ = -γ u_k⁻ and Δv = -(1+γ) κ u_k/(1+κ) (§3).
            let after = b.impact(k, &p);
            assert_eq!(b.speed(k, &after), (&b.gamma * &b.speed(k, &p)).neg());
        }
        // D: each -m_{k,k+1} has u_k = u_{k+1} = 0, every other u_j < 0, v = -1.
        for (k, g) in b.all_down().iter().enumerate() {
            for j in 0..n {
                let u = b.speed(j as i64, g);
                assert!(if j == k || j == (k + 1) % n { u.is_zero() } else { u.is_negative() }, "n = {n}");
            }
        }
        // C_j (§4): u0 ≥ 0 and v ≤ 0 on its generators; it has 3 or 4 facets.
        for j in 1..n as i64 {
            let gens = b.next_contact_generators(j);
            assert!(gens.iter().all(|g| !b.speed(0, g).is_negative() && !g[2].is_positive()));
            let facets = b.next_contact_facets(j);
            assert!((3..=4).contains(&facets.len()), "n = {n}, j = {j}: {}", facets.len());
            assert!(facets.iter().all(|l| gens.iter().all(|g| !dot(l, g).is_negative())));
        }
    }
}

#[test]
fn the_pcc_quadratic_has_the_documented_values_and_closed_form() {
    let text = |b: &Polygon| {
        let q = pcc_quadratic(b);
        (element_text(&q.p), element_text(&q.q))
    };
    assert_eq!(text(&body(4, "1/6", "1")), ("94/49".into(), "1".into()));
    assert_eq!(text(&body(4, "1/6", "1/1000")), ("-18449/1000000".into(), "1/1000000".into()));
    assert_eq!(text(&body(3, "1/8", "1/100")), ("-8401/90000".into(), "1/10000".into()));
    assert!(!pcc_quadratic(&body(4, "1/6", "1")).excludes_pcc(), "q = 1 at gamma = 1");
    assert!(pcc_quadratic(&body(4, "1/6", "1/100")).excludes_pcc());
    // q = γ², p = 2γ - (1 + γ)² μ² with μ = (κ + c_1)/(1 + κ) (§11.6).
    for (n, c1) in [(3, "-1/2"), (4, "0"), (6, "1/2")] {
        for kappa in ["1/40", "1/8", "1/3", "2"] {
            for gamma in ["0", "1/100", "3/10", "1"] {
                let q = pcc_quadratic(&body(n, kappa, gamma));
                let (k, g, c) = (r(kappa), r(gamma), r(c1));
                let mu = (&k + &c) / (ratio(1, 1) + &k);
                let p = ratio(2, 1) * &g - (ratio(1, 1) + &g) * (ratio(1, 1) + &g) * &mu * &mu;
                assert_eq!((q.p.as_rational(), q.q.as_rational()), (Some(&p), Some(&(&g * &g))));
            }
        }
    }
}

#[test]
fn the_rod_follows_section_7() {
    // κ = 1/3 (c = -1/2), γ = 1/20: I_0(-3, 1) = (3/20, -23/40), S_1 (1, -3) = (3/20, -23/40).
    let rod = Rod { kappa: r("1/3"), gamma: r("1/20") };
    assert_eq!(rod.impact(0, &[r("-3"), r("1")]), [r("3/20"), r("-23/40")]);
    assert_eq!(rod.step(&[r("1"), r("-3")]), [r("3/20"), r("-23/40")]);
}

#[test]
fn hulls_and_clips_on_a_square() {
    let f = Field::rationals();
    let p = |x: i64, y: i64| -> Pt { (Num::int(&f, x), Num::int(&f, y)) };
    let pts = vec![p(0, 0), p(1, 1), p(2, 0), p(1, 0), p(2, 2), p(0, 2), p(2, 2)];
    assert_eq!(hull(&pts), vec![0, 2, 4, 5]);
    let sq: Vec<Pt> = [0, 2, 4, 5].iter().map(|&i| pts[i].clone()).collect();
    // x + y ≤ 1 leaves the triangle (0,0), (1,0), (0,1).
    let cut = HalfPlane { a: Num::int(&f, -1), b: Num::int(&f, -1), c: Num::int(&f, 1) };
    let mut got = clip_vertices(&sq, &[cut]);
    got.sort_by(|a, b| a.0.cmp(&b.0).then(a.1.cmp(&b.1)));
    assert_eq!(got, vec![p(0, 0), p(0, 1), p(1, 0)]);
    // A constant false constraint empties it.
    let never = HalfPlane { a: Num::int(&f, 0), b: Num::int(&f, 0), c: Num::int(&f, -1) };
    assert!(clip_vertices(&sq, &[never]).is_empty());
}
