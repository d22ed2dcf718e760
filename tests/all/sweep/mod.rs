//! `chatter map` and the sweep library (src/sweep/): grids, shards, byte-identical output across
//! threads and shard processes, merging, the CSV and the summary.

mod cli;
mod curves;
mod family;
mod grid;
mod proofs;
