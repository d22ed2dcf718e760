//! The polynomial and rational-function engine.

use chatter::exact::Q;
use chatter::symbolic::mpoly::{E1, G, K, L, MPoly, S};
use chatter::symbolic::ratfn::{RatFn, prem_lambda, zero_mod_chi};

fn v(i: usize) -> MPoly {
    MPoly::var(i)
}

#[test]
fn polynomial_arithmetic_and_printing() {
    let p = v(G).mul(&v(K)).add(&v(L).pow(2)).sub(&MPoly::int(3)); // g k + l^2 - 3
    assert_eq!(p.to_string(), "g k + l^2 - 3");
    assert_eq!(p.sub(&p), MPoly::zero());
    assert_eq!(p.degree_in(L), 2);
    assert_eq!(p.coeff_in(L, 2), MPoly::int(1));
    assert_eq!(p.coeff_in(L, 0), v(G).mul(&v(K)).sub(&MPoly::int(3)));
    let at = [Q::int(2), Q::int(5), Q::int(-1), Q::int(0), Q::int(0), Q::int(0)];
    assert_eq!(p.eval(&at), Q::int(8));
    // (l + 1)^2 with l := g - 1 is g^2.
    assert_eq!(v(L).add(&MPoly::int(1)).pow(2).subst(L, &v(G).sub(&MPoly::int(1))), v(G).pow(2));
    // Exact division in kappa by a monic divisor.
    let d = v(K).add(&MPoly::int(1));
    let (q, r) = d.pow(3).mul(&v(L)).add(&MPoly::int(2)).div_rem_in(K, &d).unwrap();
    assert_eq!(q, d.pow(2).mul(&v(L)));
    assert_eq!(r, MPoly::int(2));
    assert!(v(G).mul(&v(K)).div_rem_in(K, &v(G).mul(&v(K))).is_none(), "non-constant leading coefficient");
}

#[test]
fn rational_functions_compare_by_cross_multiplication() {
    let x = RatFn::var(G);
    let a = x.div(&x.add(&RatFn::int(1)));
    let b = RatFn::int(1).sub(&RatFn::int(1).div(&x.add(&RatFn::int(1))));
    assert!(a.equals(&b), "g/(g+1) = 1 - 1/(g+1)");
    assert!(!a.equals(&RatFn::int(1)));
    // Substituting e1 := (1 - l)/k into e1 k + l gives 1.
    let e = RatFn::var(E1).mul(&RatFn::var(K)).add(&RatFn::var(L));
    let by = RatFn::int(1).sub(&RatFn::var(L)).div(&RatFn::var(K));
    assert!(e.subst(E1, &by).equals(&RatFn::int(1)));
    let at = [Q::int(1), Q::int(2), Q::new(1, 2), Q::int(0), Q::int(0), Q::int(0)];
    assert_eq!(a.eval(&at), Some(Q::new(1, 2)));
}

#[test]
fn normal_forms_modulo_a_cubic() {
    // chi = (k + 1) l^3 - g: l^3 = g/(k + 1) at every root.
    let chi = v(K).add(&MPoly::int(1)).mul(&v(L).pow(3)).sub(&v(G));
    let l4 = v(L).pow(4);
    // (k + 1) l^4 - g l vanishes at every root; l^4 - g l does not.
    assert!(prem_lambda(&v(K).add(&MPoly::int(1)).mul(&l4).sub(&v(G).mul(&v(L))), &chi).is_zero());
    assert!(!prem_lambda(&l4.sub(&v(G).mul(&v(L))), &chi).is_zero());
    let e = RatFn::new(v(L).pow(3).mul(&v(K).add(&MPoly::int(1))).sub(&v(G)), v(S).add(&MPoly::int(2)));
    assert!(zero_mod_chi(&e, &chi));
}
