//! The minimal polynomial Ψ_n of cos 2π/n, derived from the cyclotomic polynomial Φ_n
//! (docs/certificate-format.md §12 says Ψ_n has degree φ(n)/2; the kernel derives it from
//! Chebyshev's T_n, the oracle from Φ_n): z^n - 1 = Π_{d | n} Φ_d(z) gives Φ_n by exact division;
//! Φ_n is palindromic of degree 2d, so Φ_n(z) = z^d P(z + 1/z) for a P of degree d, and
//! 2 cos 2π/n = ζ + 1/ζ (ζ = e^{2πi/n}) is a root of P; Ψ_n(x) = P(2x), made monic.

use super::rational::Rat;
use num_bigint::BigInt;
use num_traits::{One, Zero};

/// Integer polynomial, coefficients in increasing powers.
type Poly = Vec<BigInt>;

/// Exact division of integer polynomials (the divisor monic); panics if it does not divide.
fn divide_exact(num: &Poly, den: &Poly) -> Poly {
    let mut rem = num.clone();
    let (dn, dd) = (num.len() - 1, den.len() - 1);
    assert!(den[dd].is_one(), "monic divisor");
    let mut quo = vec![BigInt::zero(); dn - dd + 1];
    for k in (0..=dn - dd).rev() {
        let c = rem[k + dd].clone();
        for (i, d) in den.iter().enumerate() {
            rem[k + i] -= &c * d;
        }
        quo[k] = c;
    }
    assert!(rem.iter().all(Zero::is_zero), "cyclotomic division is exact");
    quo
}

/// Φ_n, the n-th cyclotomic polynomial (n ≥ 1).
pub fn cyclotomic(n: u32) -> Vec<BigInt> {
    let mut p: Poly = vec![BigInt::zero(); n as usize + 1];
    p[0] = -BigInt::one();
    p[n as usize] = BigInt::one();
    for d in (1..n).filter(|d| n.is_multiple_of(*d)) {
        p = divide_exact(&p, &cyclotomic(d));
    }
    p
}

/// Binomial coefficient C(m, i).
fn binomial(m: usize, i: usize) -> BigInt {
    (0..i).fold(BigInt::one(), |acc, k| acc * BigInt::from(m - k) / BigInt::from(k + 1))
}

/// P with Φ(z) = z^d P(z + 1/z) for a palindromic Φ of degree 2d: peel the top power, since
/// z^d (z + 1/z)^m = Σ C(m, i) z^{d+m-2i}.
fn palindromic_to_trace(phi: &Poly) -> Poly {
    let d = (phi.len() - 1) / 2;
    let mut rest = phi.clone();
    let mut p = vec![BigInt::zero(); d + 1];
    for m in (0..=d).rev() {
        let a = rest[d + m].clone();
        for i in 0..=m {
            rest[d + m - 2 * i] -= &a * binomial(m, i);
        }
        p[m] = a;
    }
    assert!(rest.iter().all(Zero::is_zero), "Φ_n is palindromic");
    p
}

/// Ψ_n, the monic minimal polynomial of cos 2π/n, for n ≥ 3 (coefficients in increasing powers).
pub fn cos_minimal_polynomial(n: u32) -> Vec<Rat> {
    assert!(n >= 3, "cos 2π/n for n ≥ 3");
    let p = palindromic_to_trace(&cyclotomic(n));
    // P(2x) = Σ p_m 2^m x^m, divided by its leading coefficient.
    let scaled: Vec<BigInt> = p.iter().enumerate().map(|(m, c)| c * (BigInt::one() << m)).collect();
    let lead = scaled.last().expect("non-empty").clone();
    scaled.into_iter().map(|c| Rat::new(c, lead.clone())).collect()
}
