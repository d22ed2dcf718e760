//! The rational points of [-δ, δ]³ at which the oracle evaluates an orbit certificate: the 27
//! points of the grid {-δ, 0, δ}³ (vertices, edge midpoints, face centres, centre), the centres
//! and vertices of the 8 octants' halves, and pseudo-random dyadic points (a fixed integer
//! generator, no floating point).

use crate::arith::{Num, Rat};
use crate::regular::model::V3;
use num_bigint::BigInt;

/// splitmix64.
fn next(state: &mut u64) -> u64 {
    *state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
    let mut z = *state;
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// δ · k / d for integers k, d.
fn frac(delta: &Num, k: i64, d: i64) -> Num {
    delta * &Num::rational(&delta.field, Rat::new(BigInt::from(k), BigInt::from(d)))
}

/// The sample points y, `random` of them pseudo-random.
pub fn samples(delta: &Num, random: usize) -> Vec<V3> {
    let mut out = vec![];
    for d in [1, 2] {
        for a in -1..=1 {
            for b in -1..=1 {
                for c in -1..=1 {
                    out.push([frac(delta, a, d), frac(delta, b, d), frac(delta, c, d)]);
                }
            }
        }
    }
    let mut state = 0x5eed_u64;
    for _ in 0..random {
        let mut coord = || frac(delta, (next(&mut state) % 2049) as i64 - 1024, 1024);
        out.push([coord(), coord(), coord()]);
    }
    out
}
