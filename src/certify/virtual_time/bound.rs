//! The bound B of (G5) (docs/time-to-rest.md §5, Theorem 5.1 (f)): the least B with
//! B (−b_e·I_i(−m_{k,k+1})) ≥ a_e·m for every entry node e (of contact i: node 0 and i = 0 for a
//! regular polygon), every k and m ∈ {m_{i,i+1}, m_{i−1,i}}, rounded up to a multiple of 2^-bits.
//! Untrusted: the kernel checks (G5).

use super::Num;
use super::exactify::Node;
use super::frames::Frames;
use crate::exact::{Q, QExt};
use chatter_kernel::exact::{OrderedField as _, Ring as _};
use chatter_kernel::model::linalg::{Vec3, dot, mat_vec};

/// B for the numerators `a` (a_r = c_r b_r for scales), rounded up to a multiple of 2^-`bits`;
/// `Err` if some −b_e·I_i(−m_{k,k+1}) is not positive.
pub fn bound<B: Frames>(body: &B, nodes: &[Node<B::E>], a: &[Vec3<B::E>], bits: u64) -> Result<Q, String> {
    let mut need = B::E::zero();
    for (e, i) in body.entries().into_iter().enumerate() {
        let map = body.impact(i);
        let height = body.heights(i).iter().map(|m| dot(&a[e], m)).max().unwrap_or_else(B::E::zero);
        for (k, g) in body.all_down().iter().enumerate() {
            let d = dot(&nodes[e].weight, &mat_vec(&map, g)).negated();
            if !d.is_positive() {
                return Err(format!("(G5): -b_{e}·I_{i}(-m_{{{k},{}}}) is not positive", (k + 1) % body.n()));
            }
            let b = height.over(&d).unwrap_or_else(B::E::zero);
            if b > need {
                need = b;
            }
        }
    }
    Ok(need.upper().ceil_dyadic(bits))
}
