//! Tests of `chatter::symbolic`, the producer of the square-case proof (the checker's own tests
//! are in kernel/tests/).

mod engine;
mod square;
