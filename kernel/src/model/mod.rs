//! The exact impact model (docs/model.md): 3-vectors and matrices, the regular-polygon body with
//! its impact, relabelling and step maps, the cones C_j and D, the PCC quadratic, and the rod.

mod cones;
pub mod linalg;
mod pcc;
mod polygon;
mod rod;

pub use pcc::{PccExclusion, PccQuadratic, pcc_quadratic};
pub use polygon::{BodyError, Polygon, rational_cos};
pub use rod::{Mat2, Rod, Vec2, mat2_mul, mat2_vec};
