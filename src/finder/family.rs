//! The family finder (untrusted): a floating-point search for a family of cones K_0, ..., K_{n-1}
//! of a general convex body, one per last contact, with I_j(K_i ∩ C_ij) ⊆ K_j for all i != j
//! (docs/model.md §11.5, §11.9). It is the regular finder's iteration ([`super::find_cone`]) with
//! one polygon per contact on the plane v = -1: clip K_i by each C_ij, map the pieces by I_j,
//! and take the convex hull of K_j and every image, until no image leaves its target.

use super::geometry::{P2, clip, hull, lift, outside_distance, project, scale, simplify};
use super::{FinderConfig, Search, Seed};
use crate::exact::{Q, QExt};
use chatter_kernel::model::ConvexBody;
use chatter_kernel::model::linalg::{Mat3, Vec3};
use nalgebra::{Matrix3, Vector3};

/// The `f64` data of a general body that the search needs.
#[derive(Clone, Debug)]
pub struct FloatFamily {
    /// I_k, k = 0..n-1, at each value of gamma the family must serve (one, or the two ends of an
    /// interval: the images of both are taken, docs/certificate-format.md §13).
    impacts: Vec<Vec<Matrix3<f64>>>,
    /// cones[i][j]: the four covectors of C_ij (empty for i = j).
    cones: Vec<Vec<Vec<Vector3<f64>>>>,
    /// Generators -m_{k,k+1} of the all-down cone D.
    all_down: Vec<Vector3<f64>>,
}

fn vec_f64(v: &Vec3<Q>) -> Vector3<f64> {
    Vector3::new(v[0].to_f64(), v[1].to_f64(), v[2].to_f64())
}

fn mat_f64(m: &Mat3<Q>) -> Matrix3<f64> {
    Matrix3::from_fn(|r, c| m[r][c].to_f64())
}

impl FloatFamily {
    /// The rounded maps, cones and all-down generators of `body`.
    pub fn of(body: &ConvexBody<Q>) -> FloatFamily {
        FloatFamily::of_ends(std::slice::from_ref(body))
    }

    /// The same for one body at several values of gamma (the ends of an interval): C_ij and D do
    /// not depend on gamma, the maps I_k do.
    pub fn of_ends(bodies: &[ConvexBody<Q>]) -> FloatFamily {
        let body = &bodies[0];
        let n = body.n() as i64;
        let cone =
            |i, j| body.next_contact_cone(i, j).map_or_else(Vec::new, |c| c.iter().map(vec_f64).collect());
        FloatFamily {
            impacts: bodies.iter().map(|b| (0..n).map(|k| mat_f64(&b.impact(k))).collect()).collect(),
            cones: (0..n).map(|i| (0..n).map(|j| cone(i, j)).collect()).collect(),
            all_down: body.all_down_generators().iter().map(vec_f64).collect(),
        }
    }

    /// Number of contacts.
    pub fn n(&self) -> usize {
        self.impacts[0].len()
    }

    /// The seed of each K_i on the plane v = -1: I_i of the downward translation (0, 0, -1), or
    /// of every generator of D (the velocities just after a first impact at i of an all-down
    /// drop). Images with v >= 0 are left out (the exact side reports them).
    pub fn seeds(&self, seed: Seed) -> Vec<Vec<P2>> {
        let down = [Vector3::new(0.0, 0.0, -1.0)];
        let starts: &[Vector3<f64>] = match seed {
            Seed::Translation => &down,
            Seed::AllDown => &self.all_down,
        };
        (0..self.n())
            .map(|k| {
                let at = |m: &Vec<Matrix3<f64>>| starts.iter().map(|g| m[k] * g).collect::<Vec<_>>();
                self.impacts.iter().flat_map(at).filter(|p| p.z < 0.0).map(|p| project(&p)).collect()
            })
            .collect()
    }
}

/// The verdict of the family search.
#[derive(Clone, Debug, PartialEq)]
pub enum FamilyOutcome {
    /// No image leaves its target (within the tolerance): the polygons K_0..K_{n-1}.
    Found { cones: Vec<Vec<P2>>, iterations: usize },
    /// A vertex of K_from ∩ C_(from,to) maps under I_to to v >= 0: no family contains the seeds.
    NoCone { iteration: usize, from: usize, to: usize },
    /// The budget ran out (or the numbers broke down).
    Inconclusive { iterations: usize, reason: String },
}

impl FamilyOutcome {
    /// The verdict in the regular finder's terms (Found: total vertices; NoCone: the target).
    pub fn summary(&self) -> Search<usize> {
        match self {
            FamilyOutcome::Found { cones, iterations } => {
                Search::Found { cone: cones.iter().map(Vec::len).sum(), iterations: *iterations }
            }
            FamilyOutcome::NoCone { iteration, to, .. } => {
                Search::NoCone { iteration: *iteration, step: *to }
            }
            FamilyOutcome::Inconclusive { iterations, reason } => {
                Search::Inconclusive { iterations: *iterations, reason: reason.clone() }
            }
        }
    }
}

/// The images I_j(vertex) of the vertices of every K_i ∩ C_ij, grouped by target j; `Err((i, j))`
/// if an image has v >= 0.
pub fn family_images(f: &FloatFamily, polys: &[Vec<P2>]) -> Result<Vec<Vec<P2>>, (usize, usize)> {
    let n = f.n();
    let mut out = vec![Vec::new(); n];
    for (i, poly) in polys.iter().enumerate() {
        for j in (0..n).filter(|&j| j != i) {
            let mut piece = poly.clone();
            for l in &f.cones[i][j] {
                piece = clip(&piece, l);
            }
            for (p, maps) in piece.iter().flat_map(|p| f.impacts.iter().map(move |m| (p, m))) {
                let q = maps[j] * lift(p);
                if q.z >= 0.0 {
                    return Err((i, j));
                }
                out[j].push(project(&q));
            }
        }
    }
    Ok(out)
}

/// Runs the search from `seed`.
pub fn find_family(f: &FloatFamily, seed: Seed, cfg: &FinderConfig) -> FamilyOutcome {
    let mut polys: Vec<Vec<P2>> = f.seeds(seed).iter().map(|s| hull(s, 0.0)).collect();
    for it in 0..cfg.max_iterations {
        let imgs = match family_images(f, &polys) {
            Ok(imgs) => imgs,
            Err((from, to)) => return FamilyOutcome::NoCone { iteration: it, from, to },
        };
        let sc = polys.iter().map(|p| scale(p)).fold(1.0, f64::max);
        if !sc.is_finite() || sc > 1e12 {
            let reason = format!("a polygon grew to size {sc:e}");
            return FamilyOutcome::Inconclusive { iterations: it, reason };
        }
        let tol = cfg.tolerance * sc;
        // A point or a segment is fine too: at gamma = 0 the family is flat (every image of K_i
        // has u_j = 0), and the exactifier's slack gives it an interior.
        let inside = polys
            .iter()
            .zip(&imgs)
            .all(|(poly, img)| !poly.is_empty() && img.iter().all(|q| outside_distance(poly, q) <= tol));
        if inside {
            return FamilyOutcome::Found { cones: polys, iterations: it };
        }
        let next: Vec<Vec<P2>> = polys
            .iter()
            .zip(imgs)
            .map(|(poly, img)| {
                let mut all = poly.clone();
                all.extend(img);
                simplify(&hull(&all, 1e-14 * sc), cfg.max_vertices)
            })
            .collect();
        // A thin polygon (gamma near 0) can stall with an image a rounding error outside that
        // the hull drops again: the float search can do no better, and the exactifier, which
        // is exact, decides.
        if next == polys && polys.iter().all(|p| !p.is_empty()) {
            return FamilyOutcome::Found { cones: polys, iterations: it };
        }
        polys = next;
    }
    let reason = format!("no convergence within {} iterations", cfg.max_iterations);
    FamilyOutcome::Inconclusive { iterations: cfg.max_iterations, reason }
}
