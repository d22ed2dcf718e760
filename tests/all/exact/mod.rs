//! Tests of `chatter::exact`.

mod cos_field;
mod q;
mod user;
