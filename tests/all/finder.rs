//! Tests of `finder`.
