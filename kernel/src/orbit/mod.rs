//! Orbit certificates' machinery (feature `orbit`; docs/orbit-certificates.md): the return map
//! of an impact pattern on the section Σ ([`map`]), written once over exact scalars and over
//! exact interval enclosures with gradients ([`interval`]), the body's constants as rational
//! enclosures for every n ([`constants`]). The acceptance rules are [`crate::rules::orbit`].

pub mod constants;
pub mod interval;
pub mod map;

pub use crate::rules::orbit::{
    MAX_BOXES, MAX_DEPTH, MAX_PATTERN, Orbit, check as check_orbit, cover, read_orbit_values,
};
pub use interval::{Centred, Dual, Iv, PRECISION, round_down, round_up};
pub use map::{Maps, Period, Quantity, Stop, period, step};

use crate::exact::OrderedField;
use crate::model::polygon::Polygon;
pub use constants::enclosed_maps;

/// The return map of the pattern at an exact point x = (a, b, c) of Σ (rationals, or elements
/// of Q(cos 2π/n)): `Err` names the first quantity of conditions 1-2 that is not positive there.
pub fn return_map<K: OrderedField>(
    body: &Polygon<K>,
    pattern: &[usize],
    x: &[K; 3],
) -> Result<Period<K>, Quantity> {
    let maps = Maps::new(body);
    if pattern.iter().any(|&j| j == 0 || j >= maps.n) {
        return Err(Quantity::Approach { step: 0, contact: 0 });
    }
    let mut check = |q: Quantity, v: &K| if v.is_positive() { Ok(()) } else { Err(Stop::Failed(q)) };
    period(&maps, pattern, x, &mut check).map_err(|s| match s {
        Stop::Failed(q) | Stop::Division(q) => q,
    })
}
