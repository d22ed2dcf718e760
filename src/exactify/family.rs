//! The exactifier for a family of cones of a general convex body (untrusted; docs/model.md
//! §11.5, §11.9): the regular exactifier's rounds ([`super::exactify`]) with one outer
//! approximation per contact. Each round computes the exact images under I_j of the vertices of
//! every K_i ∩ C_ij and raises K_j's offsets that an image (or a seed of K_j) exceeds, until no
//! image leaves its target. Over Q only: a body with rational contacts and inertia has rational
//! maps (docs/model.md §11.2).

use super::{ExactifyConfig, ExactifyError, HPoly, Offsets, generators_of, int_mat, int_vec, primitive};
use crate::exact::Q;
use crate::finder::geometry::P2;
use chatter_kernel::geometry::clip;
use chatter_kernel::model::ConvexBody;
use chatter_kernel::model::linalg::{Mat3, Vec3, mat_vec};
use malachite::Integer;

/// The exact family: the generators of each K_i on the plane v = -1, and the rounds used.
#[derive(Clone, Debug)]
pub struct FamilyExactified {
    pub cones: Vec<Vec<[Q; 3]>>,
    pub rounds: usize,
}

/// The integer covectors of C_ij and the integer maps I_j of a body (positive multiples).
struct IntBody {
    cones: Vec<Vec<Vec<Vec3<Integer>>>>,
    /// I_k at each value of gamma the family must serve.
    impacts: Vec<Vec<Mat3<Integer>>>,
}

impl IntBody {
    fn of(bodies: &[ConvexBody<Q>]) -> IntBody {
        let body = &bodies[0];
        let n = body.n() as i64;
        let cone =
            |i, j| body.next_contact_cone(i, j).map_or_else(Vec::new, |c| c.iter().map(int_vec).collect());
        IntBody {
            cones: (0..n).map(|i| (0..n).map(|j| cone(i, j)).collect()).collect(),
            impacts: bodies.iter().map(|b| (0..n).map(|k| int_mat(&b.impact(k))).collect()).collect(),
        }
    }

    /// The exact images grouped by target j, or the transition (i, j) of an image with v >= 0.
    fn images(&self, polys: &[HPoly]) -> Result<Vec<Vec<Vec3<Integer>>>, (usize, usize)> {
        let n = polys.len();
        let mut out = vec![Vec::new(); n];
        for (i, poly) in polys.iter().enumerate() {
            for j in (0..n).filter(|&j| j != i) {
                let mut piece = poly.clone();
                for l in &self.cones[i][j] {
                    piece = clip(&piece, l).into_iter().map(primitive).collect();
                }
                for (p, maps) in piece.iter().flat_map(|p| self.impacts.iter().map(move |m| (p, m))) {
                    let q = primitive(mat_vec(&maps[j], p));
                    if q.iter().all(|c| *c == 0u32) {
                        continue;
                    }
                    if q[2] >= 0u32 {
                        return Err((i, j));
                    }
                    out[j].push(q);
                }
            }
        }
        Ok(out)
    }
}

/// Exactifies the float polygons `family` (one per contact) for `bodies` (one body at each
/// value of gamma the family must serve); `seeds[i]` are exact points K_i must contain (e.g. I_i
/// of the generators of D).
pub fn exactify_family(
    bodies: &[ConvexBody<Q>],
    family: &[Vec<P2>],
    seeds: &[Vec<Vec3<Q>>],
    cfg: &ExactifyConfig,
) -> Result<FamilyExactified, ExactifyError> {
    let body = &bodies[0];
    if family.len() != body.n() || seeds.len() != body.n() {
        return Err(ExactifyError::BadInput(format!("{} polygons for {} contacts", family.len(), body.n())));
    }
    let mut offsets: Vec<Offsets> = family.iter().map(|p| Offsets::new(p, cfg)).collect::<Result<_, _>>()?;
    let seeds: Vec<Vec<Vec3<Integer>>> =
        seeds.iter().map(|s| s.iter().map(|g| primitive(int_vec(g))).collect()).collect();
    let int_body = IntBody::of(bodies);
    let mut worst_excess = 0.0;
    for round in 0..cfg.max_rounds {
        let polys: Vec<HPoly> = offsets.iter().map(Offsets::polygon).collect();
        let mut pts = int_body.images(&polys).map_err(|(from, to)| ExactifyError::TransitionAbove {
            round,
            from,
            to,
        })?;
        let mut changed = false;
        worst_excess = 0.0;
        for ((o, p), s) in offsets.iter_mut().zip(&mut pts).zip(&seeds) {
            p.extend(s.iter().cloned());
            let (c, w) = o.raise::<Q>(p);
            changed |= c;
            worst_excess = f64::max(worst_excess, w);
        }
        if !changed {
            let cones = polys.iter().map(generators_of).collect();
            return Ok(FamilyExactified { cones, rounds: round + 1 });
        }
    }
    Err(ExactifyError::NoConvergence { rounds: cfg.max_rounds, worst_excess })
}
