//! The producer's helpers: hand-written polynomials, the linear sign method, exact division.

use chatter::exact::{ParseLimits, Q};
use chatter::symbolic::cert::{LinearVars, linear};
use chatter::symbolic::square::div_exact;
use chatter::symbolic::terms::lenient;
use chatter_kernel::proof::{Context, Frac, Poly};
use std::cmp::Ordering;

fn names() -> Vec<String> {
    ["g", "k", "l", "s", "e1", "e2"].iter().map(|s| s.to_string()).collect()
}

#[test]
fn hand_written_terms_in_any_order_give_the_canonical_polynomial() {
    let n = names();
    let p = lenient("1 - l + k + k l^2", &n);
    assert_eq!(p.text(&n), "k l^2 + k - l + 1");
    assert_eq!(lenient("e2 l + l", &n).text(&n), "l e2 + l");
    assert_eq!(lenient("-2 g k + 1/2 g k", &n).text(&n), "-3/2 g k");
    assert_eq!(lenient("g - g", &n).text(&n), "0");
}

#[test]
fn exact_division_in_one_variable() {
    let n = names();
    let d = lenient("k + 1", &n);
    let p = d.pow(3).mul(&lenient("l", &n));
    assert_eq!(div_exact(&p, 1, &d.pow(2)), Some(d.mul(&lenient("l", &n))));
    assert_eq!(div_exact(&p.add(&lenient("1", &n)), 1, &d), None, "not a multiple");
}

/// A context where e1 > e2 > 1 are atoms (as in the square's proof).
fn context() -> Context<Q> {
    let n = names();
    let chi = lenient("l - 1/2", &n);
    let mut c = Context::new(n.clone(), ParseLimits::default(), 2, chi);
    for (name, e) in [("e1-e2", "e1 - e2"), ("e2-1", "e2 - 1"), ("l", "l")] {
        c.add_atom(name, Frac::poly(lenient(e, &n))).unwrap();
    }
    c
}

#[test]
fn the_linear_method_decides_signs_on_the_region_and_its_certificates_are_identities() {
    let n = names();
    let c = context();
    let v = LinearVars { l: 2, e1: 4, e2: 5 };
    for (e, want) in [
        ("2 e1 - 2", Some(Ordering::Greater)),
        ("e2 - e1", Some(Ordering::Less)),
        ("3 + e2 - 2 e1", None),
        ("g e1", None),
    ] {
        let f = Frac::poly(lenient(e, &n));
        let got = linear(&f, v);
        assert_eq!(got.as_ref().map(|x| x.0), want, "{e}");
        if let Some((sign, cert)) = got {
            let target = if sign == Ordering::Less { f.neg() } else { f.clone() };
            let sum = cert.terms.iter().fold(Frac::poly(Poly::zero(6)), |acc, (q, atoms)| {
                let t = atoms.iter().fold(Frac::poly(Poly::constant(6, q.clone())), |t, a| {
                    c.mul(&t, c.atom(a).unwrap()).unwrap()
                });
                c.add(&acc, &t).unwrap()
            });
            assert!(c.equal(&target, &sum).unwrap(), "{e}: the certificate is an identity");
        }
    }
    // e1 l is read as e2 (the definition e2 = lambda e1).
    let f = Frac { num: lenient("l e1 - 1", &n), den: vec!["l".into()] };
    assert_eq!(linear(&f, v).map(|x| x.0), Some(Ordering::Greater));
}
