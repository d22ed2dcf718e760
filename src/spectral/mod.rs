//! Exact spectral criteria (the paper's conjectures and its rod theorem): polynomials, Sturm
//! sequences and real-root isolation, exact number fields, eigenvalue decisions, and the CC and
//! PCC criteria with their thresholds in gamma.

pub mod convex;
pub mod criteria;
pub mod cycle;
pub mod eigen;
pub mod number_field;
pub mod pcc_sign;
pub mod poly;
pub mod roots;
