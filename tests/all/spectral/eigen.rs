//! Tests of `spectral::eigen`: exact spectra and dominance decisions.

use crate::common::{NS, body};
use chatter::exact::Q;
use chatter::spectral::eigen::{Dominant, Spectrum};
use chatter_kernel::model::linalg::Mat3;
use proptest::prelude::*;

fn m(rows: [[i64; 3]; 3]) -> Mat3<Q> {
    rows.map(|r| r.map(Q::int))
}

#[test]
fn dominance_cases() {
    let cases: [([[i64; 3]; 3], Dominant); 7] = [
        ([[3, 0, 0], [0, 1, 0], [0, 0, -2]], Dominant::Positive),
        ([[-3, 0, 0], [0, 1, 0], [0, 0, 2]], Dominant::Negative),
        ([[2, 0, 0], [0, -2, 0], [0, 0, 1]], Dominant::PlusMinus { plus: 1, minus: 1 }),
        ([[2, 0, 0], [0, 2, 0], [0, 0, -2]], Dominant::PlusMinus { plus: 2, minus: 1 }),
        // A rotation by 90 degrees scaled by 2 (eigenvalues +-2i) and a real 1: complex dominant.
        ([[0, -2, 0], [2, 0, 0], [0, 0, 1]], Dominant::NonReal),
        // The same rotation with a real 2: modulus tie between 2 and +-2i.
        ([[0, -2, 0], [2, 0, 0], [0, 0, 2]], Dominant::RealAndNonReal { real_positive: true }),
        ([[0, 1, 0], [0, 0, 1], [0, 0, 0]], Dominant::Zero),
    ];
    for (rows, want) in cases {
        let mut s = Spectrum::of3(&m(rows));
        assert_eq!(s.dominant(), want, "{rows:?}");
    }
    assert!(Dominant::PlusMinus { plus: 2, minus: 1 }.real_positive());
    assert!(!Dominant::PlusMinus { plus: 1, minus: 2 }.real_positive());
    assert!(Dominant::PlusMinus { plus: 1, minus: 1 }.real_positive());
}

#[test]
fn square_plate_spectra() {
    // gamma = 1/100: real positive dominant (0.6076...); gamma = 3/100: complex dominant.
    let mut s = Spectrum::of3(&body(4, "1/6", "1/100").step(1));
    assert_eq!(s.dominant(), Dominant::Positive);
    let text = s.describe(6);
    assert!(text.iter().any(|t| t.starts_with("[0.607")), "{text:?}");
    let mut s = Spectrum::of3(&body(4, "1/6", "3/100").step(1));
    assert_eq!(s.dominant(), Dominant::NonReal);
    assert!(s.describe(6).iter().any(|t| t.contains("complex pair")));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(60))]

    /// The exact decisions agree with floating-point eigenvalues away from the boundaries.
    #[test]
    fn exact_decisions_agree_with_floats(n in prop::sample::select(NS.to_vec()), k in 1i64..60, g in 1i64..99) {
        let b = chatter_kernel::model::Polygon::<Q>::new(n, Q::new(k, 40), Q::new(g, 100)).unwrap();
        let mut s = Spectrum::of3(&b.step(1));
        let ev = chatter::model::mat_f64(&b.step(1)).complex_eigenvalues();
        let reals: Vec<f64> = ev.iter().filter(|z| z.im.abs() < 1e-9).map(|z| z.re).collect();
        let rho_c = ev.iter().filter(|z| z.im.abs() >= 1e-9).map(|z| z.norm()).fold(0.0, f64::max);
        let top = reals.iter().copied().max_by(|a, b| a.abs().total_cmp(&b.abs())).unwrap_or(0.0);
        let rho_r = top.abs();
        // Away from the boundaries: no near-ties of moduli, no near-real complex pairs.
        let ties = reals.iter().filter(|r| (r.abs() - rho_r).abs() < 1e-6).count();
        prop_assume!((rho_r - rho_c).abs() > 1e-6 && ties == 1);
        prop_assume!(ev.iter().all(|z| z.im.abs() < 1e-9 || z.im.abs() > 1e-6));
        let float_real_positive = rho_r > rho_c && top > 0.0;
        prop_assert_eq!(s.dominant().real_positive(), float_real_positive, "eigenvalues {:?}", ev);
        let mods: Vec<f64> = ev.iter().map(|z| z.im).collect();
        prop_assert_eq!(s.all_real(), mods.iter().all(|im| im.abs() < 1e-9));
    }
}
