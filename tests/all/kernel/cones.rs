//! Tests of `kernel::cones`.
