//! Tests of `kernel::check`.
