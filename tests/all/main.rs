//! All integration tests, in one binary; modules mirror the source tree.

mod common;

mod bodies;
mod certificate;
mod certify;
mod certify_convex;
mod classify_general;
mod cli;
mod corpus;
mod cover;
mod docs;
mod exact;
mod exactify;
mod finder;
mod fuzz_smoke;
mod json;
mod kernel;
mod messages;
mod model;
mod orbit;
mod orbit_band;
mod orbit_classify;
mod orbit_cli;
mod plot;
mod plot_geometry;
mod readme;
mod refute;
mod regression;
mod reproduce;
mod schema;
mod simulate;
mod spectral;
mod sweep;
mod symbolic;
mod transport;
mod verify;
