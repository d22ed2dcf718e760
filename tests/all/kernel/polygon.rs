//! Tests of `kernel::polygon`.
