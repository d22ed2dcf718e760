//! One clipping pass (Sutherland-Hodgman) of a polygon of named points by a half-plane, shared
//! by the checker and the producer. The signs and the names of the crossings come from the
//! caller: the checker looks them up in the proof, the producer finds and writes them.

use super::context::{Context, Frac};
use super::failure::Failure;
use crate::exact::Field;
use std::cmp::Ordering;

/// A point of the plane v = -1 as expressions.
pub type Point<F> = [Frac<F>; 3];

/// How a pass learns what it needs.
pub trait Oracle<F> {
    /// The sign of `value`, the covector at the named point `point`.
    fn sign(&mut self, point: &str, value: &Frac<F>) -> Result<Ordering, Failure>;
    /// The name of a point parallel to the crossing `x` of the edge `from -> to`.
    fn crossing(&mut self, x: &Point<F>, from: &str, to: &str) -> Result<String, Failure>;
    /// The named point.
    fn point(&self, name: &str) -> Result<&Point<F>, Failure>;
}

/// Whether `x` and `w` are parallel at every point of the region (x × w = 0).
pub fn parallel<F: Field>(ctx: &Context<F>, x: &Point<F>, w: &Point<F>) -> Result<bool, Failure> {
    for (r, s) in [(1, 2), (2, 0), (0, 1)] {
        if !ctx.equal(&ctx.mul(&x[r], &w[s])?, &ctx.mul(&x[s], &w[r])?)? {
            return Ok(false);
        }
    }
    Ok(true)
}

/// Clips the polygon `poly` (named vertices in cyclic order) by `l . p >= 0`: keeps the vertices
/// with a non-negative value and adds, on every edge P -> N with values of opposite strict
/// signs, the point named by the oracle for the crossing (l.P) N - (l.N) P.
pub fn clip<F: Field>(
    ctx: &Context<F>,
    poly: &[String],
    l: &Point<F>,
    oracle: &mut impl Oracle<F>,
) -> Result<Vec<String>, Failure> {
    let mut d = Vec::with_capacity(poly.len());
    let mut signs = Vec::with_capacity(poly.len());
    for p in poly {
        let v = ctx.dot(l, oracle.point(p)?)?;
        signs.push(oracle.sign(p, &v)?);
        d.push(v);
    }
    let mut out = Vec::new();
    for i in 0..poly.len() {
        let j = (i + 1) % poly.len();
        if !signs[i].is_lt() {
            out.push(poly[i].clone());
        }
        if signs[i].is_ne() && signs[j].is_ne() && signs[i] != signs[j] {
            let (a, b) = (oracle.point(&poly[i])?, oracle.point(&poly[j])?);
            let coord = |k: usize| ctx.add(&ctx.mul(&d[i], &b[k])?, &ctx.mul(&d[j], &a[k])?.neg());
            let x: Point<F> = [coord(0)?, coord(1)?, coord(2)?];
            out.push(oracle.crossing(&x, &poly[i], &poly[j])?);
        }
    }
    Ok(out)
}
