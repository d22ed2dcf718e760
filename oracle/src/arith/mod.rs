//! Exact arithmetic written for the oracle: canonical rational text, the cyclotomic minimal
//! polynomial of cos 2π/n, rational enclosures of cos 2π/n from power series, and the number
//! field Q(cos 2π/n) as polynomials reduced modulo that minimal polynomial
//! (docs/certificate-format.md §2 "Numbers", §12). Rationals are num-rational's `BigRational`
//! (the kernel's main backend is malachite).

pub mod cyclotomic;
pub mod enclosure;
pub mod field;
pub mod rational;
pub mod text;

pub use field::{Field, Num};
pub use rational::Rat;
