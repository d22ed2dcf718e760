//! Regular polygons and the rod (docs/model.md §2-§7): the model, the cone rules R1-R4, boxes, the
//! rod's rule T1 on the time to rest, the virtual-time graph of time-to-rest certificates.

pub mod boxes;
pub mod model;
pub mod pcc;
pub mod rest;
pub mod rod;
pub mod rules;
pub mod virtual_time;
