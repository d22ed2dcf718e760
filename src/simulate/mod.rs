//! Direct simulation of falling bodies (issue 4): event-driven, in f64 and in exact rationals.
