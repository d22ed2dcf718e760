//! `chatter.map/1`: the summary of a map over (rho or kappa, gamma), as `chatter map` writes it
//! to `summary.json` (docs/map.md). Build it with [`map`].

pub use crate::sweep::summary::Summary as MapSummary;
use crate::sweep::table::Row;
use crate::sweep::{Request, run};

/// Evaluates every point of `req`'s shard on the current rayon pool (nothing is written) and
/// returns the summary of the whole grid with the rows of points.csv, in index order.
pub fn map(req: &Request) -> (MapSummary, Vec<Row>) {
    let rows: Vec<Row> = run(req, &|| {}).into_iter().map(|d| d.row).collect();
    (MapSummary::new(&req.grid, &req.computed(), &rows), rows)
}
