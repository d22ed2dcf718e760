//! General convex bodies (docs/model.md §11): the model in the paper's coordinates, rules K1-K4,
//! and the virtual-time graph of their time-to-rest certificates.

pub mod model;
pub mod rules;
pub mod virtual_time;
