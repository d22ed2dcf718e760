//! The number systems the polygon rules run in: the rationals of a backend (geometry on
//! integer-scaled vectors) and the fields Q(cos 2 pi/n) (geometry on the elements themselves).
//! Rules R1 to R4 are written once over [`Scalar`].

use super::region::Region;
use super::show;
use crate::certificate::{Code, Locus, Rejection};
use crate::exact::{Algebraic, Field, OrderedField, Ring, scale_to_ints, to_canonical};
use crate::model::Polygon;

/// An exact ordered field with a ring R in which homogeneous vectors are kept: every vector of
/// the field has a positive multiple in R^k, and R embeds back into the field.
pub(crate) trait Scalar: OrderedField {
    /// The ring of scaled coordinates.
    type R: Ring;
    /// A positive multiple of `xs` with coordinates in R.
    fn scaled(xs: &[Self]) -> Vec<Self::R>;
    /// An element of R as an element of the field.
    fn lift(r: &Self::R) -> Self;
    /// The canonical text of an element.
    fn text(&self) -> String;
    /// Rule R4 on a box of parameters: the number of Bernstein sub-boxes examined.
    fn pcc_on_box(body: &Polygon<Self>, region: &Region<Self>) -> Result<usize, Rejection>;
}

impl<F: Field> Scalar for F {
    type R = F::Int;
    fn scaled(xs: &[F]) -> Vec<F::Int> {
        scale_to_ints(xs)
    }
    fn lift(r: &F::Int) -> F {
        F::from_int(r)
    }
    fn text(&self) -> String {
        to_canonical(self)
    }
    fn pcc_on_box(body: &Polygon<F>, region: &Region<F>) -> Result<usize, Rejection> {
        super::polygon::pcc_on_box(body, region)
    }
}

impl<F: Field> Scalar for Algebraic<F> {
    type R = Algebraic<F>;
    fn scaled(xs: &[Self]) -> Vec<Self> {
        xs.to_vec()
    }
    fn lift(r: &Self) -> Self {
        r.clone()
    }
    fn text(&self) -> String {
        self.to_string()
    }
    fn pcc_on_box(_: &Polygon<Self>, _: &Region<Self>) -> Result<usize, Rejection> {
        let msg = "parameter intervals are not supported where cos(2 pi/n) is irrational";
        Err(Rejection::new(Code::UnsupportedBody, Locus::Nowhere, msg))
    }
}

/// The canonical text of an element, abbreviated when long.
pub(crate) fn number<E: Scalar>(x: &E) -> String {
    show::abbreviate(&x.text())
}

/// A point (a_0/w, ..., a_k/w) of a projection plane, from scaled coordinates and w > 0.
pub(crate) fn point<E: Scalar>(coords: &[E::R], w: &E::R) -> String {
    let w = E::lift(w);
    let c: Vec<String> = coords.iter().map(|x| number(&E::lift(x).over(&w).expect("w > 0"))).collect();
    format!("({})", c.join(", "))
}
