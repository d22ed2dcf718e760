//! Read-outs of a state that do not depend on the arithmetic: numbers m · 2^e far outside
//! `f64`'s exponent range ([`Scaled`]) and the normalised state ([`Snapshot`]). Shared by the
//! engines, the PCC tests, the driver and the outputs; depends on no other simulator module.

use crate::exact::{Q, Ring};
use malachite::base::num::conversion::traits::SciMantissaAndExponent;

/// A non-negative number m · 2^e, for times and energies far outside `f64`'s exponent range.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Scaled {
    pub m: f64,
    pub e: i64,
}

/// log2 of the value returned for zero (so that sums and differences stay finite).
pub const LOG2_ZERO: f64 = -1e12;

impl Scaled {
    /// log2 of the value ([`LOG2_ZERO`] for 0).
    pub fn log2(self) -> f64 {
        if self.m > 0.0 { self.m.log2() + self.e as f64 } else { LOG2_ZERO }
    }

    /// log2 to within 0.09, from the bits of m (no `ln`: for the hot loop).
    #[inline]
    pub fn log2_fast(self) -> f64 {
        if self.m > 0.0 && self.m.is_normal() {
            let b = self.m.to_bits();
            let ex = ((b >> 52) & 0x7ff) as i64 - 1023;
            let frac = f64::from_bits((b & 0x000f_ffff_ffff_ffff) | 0x3ff0_0000_0000_0000) - 1.0;
            (ex + self.e) as f64 + frac
        } else {
            self.log2()
        }
    }

    /// The value as an `f64` (0 on underflow, infinity on overflow).
    pub fn to_f64(self) -> f64 {
        self.m * pow2(self.e)
    }
}

/// |x| as m · 2^e with m in [1, 2) (m = 0 for x = 0), rounded to nearest.
pub fn scaled(x: &Q) -> Scaled {
    if x.is_zero() {
        return Scaled { m: 0.0, e: 0 };
    }
    let (m, e): (f64, i64) = x.abs().as_rational().sci_mantissa_and_exponent();
    Scaled { m, e }
}

/// 2^e as an `f64` (0 below the normal range, infinity above), built from its bits.
#[inline]
pub fn pow2(e: i64) -> f64 {
    if e < -1022 {
        if e < -1074 { 0.0 } else { f64::from_bits(1u64 << (e + 1074)) }
    } else if e > 1023 {
        f64::INFINITY
    } else {
        f64::from_bits(((e + 1023) as u64) << 52)
    }
}

/// The state normalised for display: q = q_m · 2^q_e and p = p_m · 2^p_e with the largest
/// component of q_m and p_m in [1, 2) (physical coordinates, our convention).
#[derive(Clone, Debug, PartialEq)]
pub struct Snapshot {
    pub q: [f64; 3],
    pub q_exp: i64,
    pub p: [f64; 3],
    pub p_exp: i64,
    /// Kinetic energy.
    pub energy: Scaled,
}
