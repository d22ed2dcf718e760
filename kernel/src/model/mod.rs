//! The exact impact model (docs/model.md): 3-vectors and matrices, the regular-polygon body with
//! its impact, relabelling and step maps, the cones C_j and D, the PCC quadratic, the rod, and
//! (feature `family`) general convex bodies (docs/model.md §11) with their impact maps, cones
//! C_{ij} and pair PCC quadratics.

#[cfg(feature = "family")]
pub mod convex;
pub mod linalg;
pub mod pcc;
#[cfg(feature = "boxes")]
pub mod pcc_polynomials;
pub mod polygon;
pub mod rod;

#[cfg(feature = "family")]
pub use convex::{ConvexBody, ConvexBodyError, MAX_CONTACTS, check_convex_polygon};
pub use pcc::{PccExclusion, PccQuadratic, pcc_quadratic};
#[cfg(feature = "boxes")]
pub use pcc_polynomials::{PccPolynomials, pcc_polynomials};
pub use polygon::{BodyError, Polygon, rational_cos};
pub use rod::{Mat2, Rod, Vec2, mat2_mul, mat2_vec};

use crate::exact::OrderedField;

/// A body the kernel models exactly: the rod (n = 2) or a regular polygon (n >= 3). This is the
/// one place where the number of contacts decides which model applies.
#[derive(Clone, Debug)]
pub enum Shape<F> {
    /// The planar rod: two contacts, velocities (u0, u1).
    Rod(Rod<F>),
    /// A regular n-gon of contacts, velocities (u0, u1, v).
    Polygon(Polygon<F>),
}

impl<F: OrderedField> Shape<F> {
    /// The rod for n = 2, else the regular polygon (n in {3, 4, 6}: rational cos(2 pi/n)).
    pub fn new(n: u64, kappa: F, gamma: F) -> Result<Self, BodyError> {
        if n == 2 {
            Rod::new(kappa, gamma).map(Shape::Rod)
        } else {
            Polygon::new(n, kappa, gamma).map(Shape::Polygon)
        }
    }

    /// Number of contacts.
    pub fn n(&self) -> usize {
        match self {
            Shape::Rod(_) => 2,
            Shape::Polygon(p) => p.n(),
        }
    }

    /// kappa = rho^2 / R^2.
    pub fn kappa(&self) -> &F {
        match self {
            Shape::Rod(r) => r.kappa(),
            Shape::Polygon(p) => p.kappa(),
        }
    }

    /// The coefficient of restitution.
    pub fn gamma(&self) -> &F {
        match self {
            Shape::Rod(r) => r.gamma(),
            Shape::Polygon(p) => p.gamma(),
        }
    }

    /// Names of the velocity coordinates of a generator: (u0, u1) for the rod, (u0, u1, v) else.
    pub fn coordinates(&self) -> &'static [&'static str] {
        match self {
            Shape::Rod(_) => &["u0", "u1"],
            Shape::Polygon(_) => &["u0", "u1", "v"],
        }
    }
}
