//! Tests of `chatter::simulate`: engines, outcomes, PCC tests, patterns and the CLI.

mod cli;
mod convex;
mod convex_cli;
mod criterion;
mod engines;
mod field;
mod outcomes;
mod pattern;
mod pcc;
mod proved;
mod regular;

use crate::common::q;
use chatter::exact::{Q, Ring};
use chatter::simulate::{Model, SplitMix64, Start, drop::check_start};
use chatter_kernel::model::Shape as Body;

/// The model of the body with n contacts (2 is the rod, as the kernel decides).
pub fn model(n: u64, kappa: &str, gamma: &str) -> Model {
    Model::from_body(&Body::new(n, q(kappa), q(gamma)).expect("valid test body"))
}

/// A random rational in [lo, hi] with denominator `den`.
fn rational(rng: &mut SplitMix64, lo: i64, hi: i64, den: i64) -> Q {
    let span = ((hi - lo) * den + 1) as u64;
    Q::new(lo * den + (rng.next_u64() % span) as i64, den)
}

/// A random valid start with small rational coordinates: every contact at or above the floor,
/// the centre of mass moving down.
pub fn random_rational_start(m: &Model, rng: &mut SplitMix64) -> Start<Q> {
    let dim = m.system().shape.dim();
    loop {
        let mut s = Start { q: std::array::from_fn(|_| Q::int(0)), p: std::array::from_fn(|_| Q::int(0)) };
        for i in 0..dim {
            s.q[i] = rational(rng, 0, 2, 97);
            s.p[i] = rational(rng, -2, 1, 89);
        }
        let v = m.system().centre.iter().zip(&s.p).fold(Q::int(0), |a, (c, x)| a + c * x);
        if check_start(m.system(), &s).is_ok() && v.is_negative() {
            return s;
        }
    }
}
