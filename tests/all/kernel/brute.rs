//! Tests of `kernel::brute`.
