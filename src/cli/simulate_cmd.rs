//! `chatter simulate` (issue 4).

use clap::Args;

/// Raw arguments of `chatter simulate`.
#[derive(Args, Debug)]
pub struct SimulateArgs {}

pub fn run(_a: SimulateArgs) -> u8 {
    super::usage_error("chatter simulate is being written (issue 4)")
}
