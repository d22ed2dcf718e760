//! Tests of `exact::user`.
