//! Cones of R³ given by generators: their facets by brute force (a pair of generators spans a
//! facet when every generator lies on one side of the plane through them).

use crate::arith::Num;

/// a × b.
pub fn cross(a: &[Num; 3], b: &[Num; 3]) -> [Num; 3] {
    [
        &(&a[1] * &b[2]) - &(&a[2] * &b[1]),
        &(&a[2] * &b[0]) - &(&a[0] * &b[2]),
        &(&a[0] * &b[1]) - &(&a[1] * &b[0]),
    ]
}

/// a · b.
pub fn dot(a: &[Num; 3], b: &[Num; 3]) -> Num {
    &(&(&a[0] * &b[0]) + &(&a[1] * &b[1])) + &(&a[2] * &b[2])
}

/// The inward facet covectors ℓ (ℓ · g ≥ 0 on every generator) of a 3-D pointed cone, one per
/// facet.
pub fn facets(gens: &[[Num; 3]]) -> Vec<[Num; 3]> {
    let mut out = vec![];
    for (i, a) in gens.iter().enumerate() {
        for b in &gens[i + 1..] {
            let l = cross(a, b);
            if l.iter().all(Num::is_zero) {
                continue;
            }
            let values: Vec<Num> = gens.iter().map(|g| dot(&l, g)).collect();
            let facet = if values.iter().all(|x| !x.is_negative()) {
                l
            } else if values.iter().all(|x| !x.is_positive()) {
                l.map(|x| x.neg())
            } else {
                continue;
            };
            // The same facet from another pair of its generators: a positive multiple.
            let seen = out.iter().any(|m: &[Num; 3]| {
                cross(m, &facet).iter().all(Num::is_zero) && dot(m, &facet).is_positive()
            });
            if !seen {
                out.push(facet);
            }
        }
    }
    out
}
