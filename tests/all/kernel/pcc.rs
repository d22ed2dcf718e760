//! Tests of `kernel::pcc`.
