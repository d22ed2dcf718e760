//! Tests of `chatter::symbolic`.

mod engine;
mod proof;
mod square;
