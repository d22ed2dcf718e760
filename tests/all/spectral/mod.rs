//! Tests of `chatter::spectral`.

mod criteria;
mod eigen;
mod number_field;
mod pcc_sign;
mod poly;
