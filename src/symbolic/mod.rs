//! Symbolic proofs of the square-case lemmas (the paper's section "A semi-analytic construction
//! for squares"): a small engine for polynomials and rational functions over Q with normal forms
//! modulo the characteristic polynomial chi(lambda), a step checker with positivity
//! certificates, and the lemmas themselves.

pub mod crosscheck;
pub mod mpoly;
pub mod proof;
pub mod ratfn;
pub mod report;
pub mod square;
