//! Tests of `kernel::impact`.
