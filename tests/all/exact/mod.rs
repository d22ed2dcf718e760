//! Tests of `chatter::exact`.
