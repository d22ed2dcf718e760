//! The generators of a cone as integer vectors (docs/certificate-format.md §4, §6): each
//! coordinate a canonical number, the right number of coordinates (`wrong-arity`), and the vector
//! (p_0/q_0, ..., p_k/q_k) replaced by its positive multiple with coordinate i
//! p_i prod_{j != i} q_j: cones do not change under positive scaling.

use crate::exact::{Field, Int, ParseLimits};
use crate::reject::{Code, Detail, Rejection};
use crate::syntax::cone::Generator;
use crate::syntax::numbers::{in_time, parts};

/// The generators as integer vectors, with the largest denominator in bits.
pub struct Generators<'a, Z> {
    /// Integer coordinates, positive multiples of the generators.
    pub vectors: Vec<Vec<Z>>,
    /// Largest denominator, in bits.
    pub max_denominator_bits: u64,
    /// The generators as written (for a rejection).
    pub written: &'a [Generator],
}

/// Reads `written`, whose coordinates are named `names`; `path(i)` is the path of generator i.
pub fn read<'a, F: Field>(
    written: &'a [Generator],
    names: &'static [&'static str],
    path: impl Fn(usize) -> String,
    limits: ParseLimits,
) -> Result<Generators<'a, F::Int>, Rejection> {
    let mut vectors = Vec::with_capacity(written.len());
    let mut bits = 0;
    for (i, g) in written.iter().enumerate() {
        in_time(limits, "reading the generators")?;
        if g.0.len() != names.len() {
            let detail = Detail::Arity(names, g.0.len());
            return Err(Rejection::at(Code::WrongArity, path(i), detail));
        }
        let mut coords = Vec::with_capacity(names.len());
        for (c, name) in g.0.iter().zip(names) {
            let (p, q) = parts::<F::Int>(|| format!("{}.{name}", path(i)), c, limits)?;
            bits = bits.max(q.bit_length());
            coords.push((p, q));
        }
        vectors.push(common_denominator(&coords));
    }
    Ok(Generators { vectors, max_denominator_bits: bits, written })
}

/// (p_0/q_0, ..., p_k/q_k) times prod q_j: integers, a positive multiple (all q_j > 0).
fn common_denominator<Z: Int>(parts: &[(Z, Z)]) -> Vec<Z> {
    let factor = |k: usize, j: usize, (p, q): &(Z, Z)| if j == k { p.clone() } else { q.clone() };
    (0..parts.len())
        .map(|k| parts.iter().enumerate().fold(Z::one(), |acc, (j, pq)| acc.times(&factor(k, j, pq))))
        .collect()
}
