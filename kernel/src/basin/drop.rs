//! A box of drops as interval enclosures in our coordinates (docs/basin-certificates.md §2):
//! the paper's velocity (ω_x, ω_y, -1) and position (φ_x, φ_y, h) map to ours by
//! u_k = v + sin θ_k ω_x - cos θ_k ω_y and h_k likewise (docs/model.md §2), so
//! p = (-1 - ω_y, -1 + s ω_x - c ω_y, -1), q = (h - φ_y, h + s φ_x - c φ_y, h) with
//! c = cos 2π/n and s = sin 2π/n, both enclosed by rational intervals.

use crate::exact::{Field, Int, Ring};
use crate::orbit::interval::{Centred, Iv, round_down, round_up};
use crate::orbit::map::Maps;
use std::sync::Arc;

/// The five coordinates of a drop: (ω_x, ω_y, φ_x, φ_y, h).
pub const DIMS: usize = 5;
/// Bits of the enclosure of sin 2π/n before outward rounding.
pub const SQRT_BITS: u64 = 96;

/// A quantity over a leaf of drops.
pub type Over<F> = Centred<F, DIMS>;

/// floor(sqrt(m)) for m >= 0, bit by bit from the top (exact integers).
fn isqrt<Z: Int>(m: &Z) -> Z {
    let two = Z::from_i64(2);
    let mut pows = vec![Z::one()];
    for _ in 0..m.bit_length() / 2 + 1 {
        let next = pows[pows.len() - 1].times(&two);
        pows.push(next);
    }
    let mut r = Z::zero();
    for bit in pows.iter().rev() {
        let cand = r.plus(bit);
        if cand.times(&cand) <= *m {
            r = cand;
        }
    }
    r
}

/// [l, u] with l <= sqrt(x) <= u for x >= 0: l = floor(sqrt(x 4^k))/2^k, u = l + 2^-k.
fn sqrt_bounds<F: Field>(x: &F) -> (F, F) {
    let scale = (0..2 * SQRT_BITS).fold(F::Int::one(), |acc, _| acc.times(&F::Int::from_i64(2)));
    let half = (0..SQRT_BITS).fold(F::Int::one(), |acc, _| acc.times(&F::Int::from_i64(2)));
    let m = x.numer().times(&scale).div_floor(&x.denom());
    let r = isqrt(&m);
    // r^2 <= floor(x 4^k) <= x 4^k < floor(x 4^k) + 1 <= (r + 1)^2.
    (F::from_fraction(&r, &half), F::from_fraction(&r.plus(&F::Int::one()), &half))
}

/// An enclosure of sqrt(x) for every x of the interval (lo >= 0): [sqrt(lo), sqrt(hi)], outward.
pub fn sqrt_enclosure<F: Field>(x: &Iv<F>) -> Iv<F> {
    let lo = if x.lo.is_positive() { sqrt_bounds(&x.lo).0 } else { F::zero() };
    let hi = sqrt_bounds(&x.hi).1;
    Iv { lo: round_down(&lo), hi: round_up(&hi) }
}

/// (c, s) = (cos 2π/n, sin 2π/n) enclosed, from the body's covector f_2 = (-1, 2c, 1 - 2c + 1)
/// (a_2 = -1, b_2 = 2c, docs/model.md §2) and s = sqrt(1 - c²) (s > 0 for n >= 3).
pub fn cos_sin<F: Field>(maps: &Maps<Iv<F>>) -> (Iv<F>, Iv<F>) {
    let c = maps.contacts[2][1].scaled(&F::from_ratio(1, 2));
    let one = Iv::exact(&F::one());
    let s2 = one.minus(&c.times(&c));
    let s2 = Iv { lo: s2.lo.max(F::zero()), hi: s2.hi };
    (c, sqrt_enclosure(&s2))
}

/// The leaf [lo, hi] of drops as the seeds y_k = c_k + (y_k - c_k), gradient e_k.
pub fn seeds<F: Field>(lo: &[F; DIMS], hi: &[F; DIMS]) -> [Over<F>; DIMS] {
    let two = F::from_i64(2);
    let half = |a: &F, b: &F| a.plus(b).over(&two).unwrap_or_else(F::zero);
    let r: [Iv<F>; DIMS] = std::array::from_fn(|k| {
        let w = half(&hi[k], &lo[k].negated());
        Iv { lo: w.negated(), hi: w }
    });
    let r = Arc::new(r);
    std::array::from_fn(|k| {
        let unit = std::array::from_fn(|i| if i == k { Iv::exact(&F::one()) } else { Iv::zero() });
        let c = Iv::point(&half(&lo[k], &hi[k]));
        Centred::seed(c, Iv { lo: lo[k].clone(), hi: hi[k].clone() }, unit, r.clone())
    })
}

/// (q, p) in our coordinates for the drops y = (ω_x, ω_y, φ_x, φ_y, h), v = -1.
pub fn state<F: Field>(y: &[Over<F>; DIMS], cs: &(Iv<F>, Iv<F>)) -> ([Over<F>; 3], [Over<F>; 3]) {
    let (c, s) = cs;
    let minus_one = Over::constant(&F::from_i64(-1));
    let p = [
        minus_one.minus(&y[1]),
        minus_one.plus(&y[0].scaled_by(s)).minus(&y[1].scaled_by(c)),
        minus_one.clone(),
    ];
    let h = &y[4];
    let q = [h.minus(&y[3]), h.plus(&y[2].scaled_by(s)).minus(&y[3].scaled_by(c)), h.clone()];
    (q, p)
}
