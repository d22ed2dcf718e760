//! Tests of `exactify`.
