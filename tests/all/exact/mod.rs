//! Tests of `chatter::exact`.

mod backends;
mod canonical;
mod cos_field;
mod q;
mod user;
