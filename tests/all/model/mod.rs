//! Tests of `chatter::model`: the float model of a regular n-gon.

mod float;
