//! General convex bodies (docs/model.md §11): the model in the paper's coordinates and rules K1-K4.

pub mod model;
pub mod rules;
