//! Tests of `certify`.
