//! Tests of `exact::q`.
