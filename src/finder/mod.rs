//! The floating-point cone finder (untrusted): the paper's iteration of section "A numerical
//! construction for arbitrary n" on the projection plane v = -1. Starting from a seed, clip the
//! candidate polygon by each C_j, map the pieces by S_j, and take the convex hull of the union,
//! until no image leaves the polygon. The polygon is kept to a bounded number of vertices by
//! outer approximation, so a curved limit cone does not drown the search in vertices.

pub mod family;
pub mod geometry;
pub mod rod;

use crate::model::FloatBody;
use geometry::{P2, clip, hull, outside_distance, project, scale, simplify};
use nalgebra::Vector3;

/// Where the search starts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Seed {
    /// The post-impact velocity of a pure downward translation, I_0(-1, -1, -1) (the paper's
    /// -U_0 u_3).
    Translation,
    /// The whole post-impact cone I_0(D) of drops with every contact moving down.
    AllDown,
}

/// Budgets and tolerances of the search.
#[derive(Clone, Copy, Debug)]
pub struct FinderConfig {
    pub max_iterations: usize,
    /// Vertex budget of the candidate polygon (outer approximation beyond it).
    pub max_vertices: usize,
    /// Convergence tolerance, relative to the polygon's size.
    pub tolerance: f64,
}

impl Default for FinderConfig {
    fn default() -> Self {
        FinderConfig { max_iterations: 60_000, max_vertices: 40, tolerance: 1e-10 }
    }
}

/// The verdict of a search for a cone of type `T`.
#[derive(Clone, Debug, PartialEq)]
pub enum Search<T> {
    /// No image leaves the cone (within the tolerance, for the float search).
    Found { cone: T, iterations: usize },
    /// An image under S_step has v >= 0: no effectively invariant cone contains the seed.
    NoCone { iteration: usize, step: usize },
    /// The budget ran out (or the numbers broke down) before a conclusion.
    Inconclusive { iterations: usize, reason: String },
}

/// The float search's verdict: a polygon on the plane v = -1.
pub type FinderOutcome = Search<Vec<P2>>;

impl<T> Search<T> {
    /// "found", "no-cone" or "inconclusive".
    pub fn label(&self) -> &'static str {
        match self {
            Search::Found { .. } => "found",
            Search::NoCone { .. } => "no-cone",
            Search::Inconclusive { .. } => "inconclusive",
        }
    }

    /// The same verdict with the cone replaced by `f(cone)` (e.g. its number of vertices).
    pub fn map<U>(&self, f: impl FnOnce(&T) -> U) -> Search<U> {
        match self {
            Search::Found { cone, iterations } => Search::Found { cone: f(cone), iterations: *iterations },
            Search::NoCone { iteration, step } => Search::NoCone { iteration: *iteration, step: *step },
            Search::Inconclusive { iterations, reason } => {
                Search::Inconclusive { iterations: *iterations, reason: reason.clone() }
            }
        }
    }
}

impl std::fmt::Display for Search<usize> {
    /// One line, e.g. "found a cone (5 vertices, 12 iterations)".
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Search::Found { cone, iterations } => {
                write!(f, "found a cone ({cone} vertices, {iterations} iterations)")
            }
            Search::NoCone { iteration, step } => {
                write!(f, "no cone (an image under S_{step} has v >= 0 at iteration {iteration})")
            }
            Search::Inconclusive { reason, .. } => write!(f, "inconclusive: {reason}"),
        }
    }
}

/// The seed points on the plane v = -1.
pub fn seed_points(body: &FloatBody, seed: Seed) -> Vec<P2> {
    let down = Vector3::new(-1.0, -1.0, -1.0);
    let impacts = std::iter::once(&body.impact0).chain(&body.more_impacts);
    match seed {
        Seed::Translation => impacts.map(|i| project(&(i * down))).collect(),
        Seed::AllDown => impacts.flat_map(|i| body.all_down.iter().map(move |g| project(&(i * g)))).collect(),
    }
}

/// Images S_j(vertex) of the vertices of every piece K ∩ C_j, as plane points; `Err(j)` if an
/// image has v >= 0.
pub fn images(body: &FloatBody, poly: &[P2]) -> Result<Vec<P2>, usize> {
    let mut out = Vec::new();
    for (j, (s, c)) in body.steps.iter().zip(&body.cones).enumerate() {
        let mut piece = poly.to_vec();
        for l in c {
            piece = clip(&piece, l);
        }
        for p in &piece {
            let q = s * geometry::lift(p);
            if q.z >= 0.0 {
                return Err(j % (body.n - 1) + 1);
            }
            out.push(project(&q));
        }
    }
    Ok(out)
}

/// Runs the search.
pub fn find_cone(body: &FloatBody, seed: Seed, cfg: &FinderConfig) -> FinderOutcome {
    let mut poly = hull(&seed_points(body, seed), 0.0);
    for it in 0..cfg.max_iterations {
        let imgs = match images(body, &poly) {
            Ok(imgs) => imgs,
            Err(step) => return Search::NoCone { iteration: it, step },
        };
        let sc = scale(&poly);
        if !sc.is_finite() || sc > 1e12 {
            return Search::Inconclusive { iterations: it, reason: format!("polygon grew to size {sc:e}") };
        }
        let tol = cfg.tolerance * sc;
        let worst = imgs.iter().map(|q| outside_distance(&poly, q)).fold(f64::NEG_INFINITY, f64::max);
        // A converged segment is fine too: at gamma = 0 every image has u0 = 0, so the cone is
        // flat; the exactifier's slack gives it an interior.
        if poly.len() >= 2 && worst <= tol {
            return Search::Found { cone: poly, iterations: it };
        }
        let mut all = poly;
        all.extend(imgs);
        poly = simplify(&hull(&all, 1e-14 * sc), cfg.max_vertices);
    }
    Search::Inconclusive {
        iterations: cfg.max_iterations,
        reason: format!("no convergence within {} iterations", cfg.max_iterations),
    }
}
