//! Tests of `exact::backends`.
