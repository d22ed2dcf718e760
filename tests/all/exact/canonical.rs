//! Tests of `exact::canonical`.
