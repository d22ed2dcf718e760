//! Tests of `chatter::exact`.

mod backends;
mod canonical;
mod q;
mod user;
