//! The bound B of (G5) (docs/time-to-rest.md §5, Theorem 5.1 (f)): the least B with
//! B (−b_0·I_0(−m_{k,k+1})) ≥ c_0 (b_0·m) for every k and m ∈ {m_{0,1}, m_{n−1,0}}, rounded up
//! to a multiple of 2^-20. Untrusted: the kernel checks (G5).

use super::Num;
use super::exactify::{Node, rest};
use crate::exact::{Q, QExt};
use chatter_kernel::model::Polygon;
use chatter_kernel::model::linalg::{dot, mat_vec};

/// Bits of B's dyadic rounding.
const BITS: u64 = 20;

/// B from node 0 and its scale c_0; `Err` if some −b_0·I_0(−m_{k,k+1}) is not positive.
pub fn bound<E: Num>(body: &Polygon<E>, entry: &Node<E>, c0: &Q) -> Result<Q, String> {
    let i0 = body.impact(0);
    let height =
        [rest(body, 0), rest(body, -1)].iter().map(|m| dot(&entry.weight, m)).max().unwrap_or_else(E::zero);
    let mut need = E::zero();
    for (k, g) in body.all_down_generators().iter().enumerate() {
        let d = dot(&entry.weight, &mat_vec(&i0, g)).negated();
        if !d.is_positive() {
            return Err(format!("(G5): -b_0·I_0(-m_{{{k},{}}}) is not positive", k + 1));
        }
        let b = E::from_q(c0).times(&height).over(&d).unwrap_or_else(E::zero);
        if b > need {
            need = b;
        }
    }
    Ok(need.upper().ceil_dyadic(BITS))
}
