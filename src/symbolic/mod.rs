//! The producer of the square-case proof (the paper's section "A semi-analytic construction for
//! squares"): a builder that writes steps for the kernel's proof checker, positivity
//! certificates, the lemmas themselves, the proof files, and an untrusted numerical cross-check.

pub mod builder;
pub mod cert;
pub mod crosscheck;
pub mod report;
pub mod square;
pub mod terms;
