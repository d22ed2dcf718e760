//! The description of a general convex body in the JSON reports of `simulate` and `classify`
//! (docs/model.md §11): an optional field, `null` for the rod and regular polygons.

use super::Number;
use crate::exact::Q;
use chatter_kernel::model::ConvexBody;
use schemars::JsonSchema;
use serde::Serialize;

/// A general convex body (docs/model.md §11): states are in the paper's coordinates
/// (phi_x, phi_y, h) and (omega_x, omega_y, v); `kappa` of the report is 0 for it.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct GeneralBodyReport {
    /// How the body was given (e.g. `rectangle 2 x 1 (uniform plate)`).
    pub description: String,
    /// Contact points (x_k, y_k) relative to the centre of mass, counter-clockwise.
    pub contacts: Vec<[Number; 2]>,
    /// J_xx, J_xy, J_yy: the horizontal inertia tensor per unit mass about the centre of mass.
    pub inertia: [Number; 3],
}

impl GeneralBodyReport {
    pub fn of(description: &str, body: &ConvexBody<Q>) -> GeneralBodyReport {
        let j = body.inertia();
        GeneralBodyReport {
            description: description.to_string(),
            contacts: body.contacts().iter().map(|c| [Number::of(&c[0]), Number::of(&c[1])]).collect(),
            inertia: [Number::of(&j[0][0]), Number::of(&j[0][1]), Number::of(&j[1][1])],
        }
    }
}
