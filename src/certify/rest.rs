//! The rod's bound on the time to rest (docs/time-to-rest.md §2, Theorem), computed exactly in
//! untrusted code; the kernel's rule T1 re-checks it (kernel/src/rules/rod.rs).

use super::Request;
use crate::exact::{Q, QExt};
use chatter_kernel::certificate::Claim;

/// σ = (1 + γ)(1 − κ)/(1 + κ): the rod's step map has characteristic polynomial λ² − σλ + γ
/// (docs/time-to-rest.md §2 (a)).
pub fn sigma(kappa: &Q, gamma: &Q) -> Q {
    let one = Q::int(1);
    &(&(&one + gamma) * &(&one - kappa)) / &(&one + kappa)
}

/// The least rational B found with B ≥ 1/λ_1 (λ_1 the larger root of λ² − σλ + γ), within a
/// relative 2^-40 of 1/λ_1, the sharp constant of T ≤ B h/|v| (docs/time-to-rest.md §2);
/// `None` outside the theorem's hypotheses (0 < γ < 1, 0 < κ < 1, σ² − 4γ ≥ 0).
pub fn rod_bound(kappa: &Q, gamma: &Q) -> Option<Q> {
    let (zero, one) = (Q::int(0), Q::int(1));
    if !(kappa > &zero && kappa < &one && gamma > &zero && gamma < &one) {
        return None;
    }
    let s = sigma(kappa, gamma);
    let delta = &(&s * &s) - &(&Q::int(4) * gamma);
    if delta < zero {
        return None;
    }
    let half = &s / &Q::int(2);
    if delta == zero {
        return Some(&one / &half);
    }
    let q = |x: &Q| &(&(x * x) - &(&s * x)) + gamma;
    // λ_1 is often rational (Δ a square): try the small rational nearest its f64 value.
    let (sf, df) = (QExt::to_f64(&s), QExt::to_f64(&delta));
    if let Some(x) = small_rational_near(0.5 * (sf + df.sqrt()))
        && x > half
        && q(&x) == zero
    {
        return Some(&one / &x);
    }
    // q(σ/2) = −Δ/4 < 0 and q(1) = 1 − σ + γ > 0 (docs/time-to-rest.md, note on λ_1 < 1): bisect
    // keeping q(lo) ≤ 0 < q(hi), so lo ≤ λ_1 < hi.
    let (mut lo, mut hi) = (half, one.clone());
    for _ in 0..40 {
        let mid = &(&lo + &hi) / &Q::int(2);
        if q(&mid) <= zero { lo = mid } else { hi = mid }
    }
    Some(&one / &lo)
}

/// The continued-fraction convergent of `x` with denominator at most 10^6 nearest to it (a guess,
/// checked exactly by the caller).
fn small_rational_near(x: f64) -> Option<Q> {
    if !x.is_finite() || x <= 0.0 {
        return None;
    }
    let (mut h0, mut h1, mut k0, mut k1) = (0i64, 1i64, 1i64, 0i64);
    let mut r = x;
    for _ in 0..40 {
        let a = r.floor();
        let (h2, k2) = (a as i64 * h1 + h0, a as i64 * k1 + k0);
        if k2 > 1_000_000 {
            break;
        }
        (h0, h1, k0, k1) = (h1, h2, k1, k2);
        if (r - a).abs() < 1e-12 {
            break;
        }
        r = 1.0 / (r - a);
    }
    (k1 > 0).then(|| Q::new(h1, k1))
}

/// B for a certificate the pipeline writes: rod point certificates with a claim about drops.
pub fn bound_for(req: &Request, claim: Claim) -> Option<Q> {
    if req.n != 2 || req.upper.is_some() || claim < Claim::CcOrPccFromAllDown {
        return None;
    }
    rod_bound(&req.kappa, &req.gamma)
}
