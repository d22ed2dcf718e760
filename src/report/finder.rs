//! The float finder's verdict as reported by `classify` and `certify`.

use crate::finder::Search;
use schemars::JsonSchema;
use serde::Serialize;

/// The float finder's verdict on one seed.
#[derive(Clone, Debug, PartialEq, Serialize, JsonSchema)]
pub struct FinderReport {
    /// `found`, `no-cone` or `inconclusive`.
    pub outcome: &'static str,
    /// Iterations run (for `no-cone`: the iteration where an image left v < 0).
    pub iterations: usize,
    /// Vertices of the cone's polygon on v = -1 (`found`).
    pub vertices: Option<usize>,
    /// The step map S_step whose image has v >= 0 (`no-cone`).
    pub step: Option<usize>,
    /// Why the search stopped (`inconclusive`).
    pub reason: Option<String>,
}

impl FinderReport {
    /// The report of a search whose cone is given by its number of vertices.
    pub fn of(s: &Search<usize>) -> FinderReport {
        let base =
            FinderReport { outcome: s.label(), iterations: 0, vertices: None, step: None, reason: None };
        match s {
            Search::Found { cone, iterations } => {
                FinderReport { iterations: *iterations, vertices: Some(*cone), ..base }
            }
            Search::NoCone { iteration, step } => {
                FinderReport { iterations: *iteration, step: Some(*step), ..base }
            }
            Search::Inconclusive { iterations, reason } => {
                FinderReport { iterations: *iterations, reason: Some(reason.clone()), ..base }
            }
        }
    }

    /// The search again (for its one-line text).
    pub fn search(&self) -> Search<usize> {
        match (self.vertices, self.step) {
            (Some(cone), _) => Search::Found { cone, iterations: self.iterations },
            (None, Some(step)) => Search::NoCone { iteration: self.iterations, step },
            (None, None) => Search::Inconclusive {
                iterations: self.iterations,
                reason: self.reason.clone().unwrap_or_default(),
            },
        }
    }
}
