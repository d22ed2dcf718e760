//! Rules K1 to K4 of docs/certificate-format.md §13 for a family K_0, ..., K_{n-1}.

use super::model::{Body, V3};
use crate::claim::Claim;
use crate::plane::{HalfPlane, clip_vertices, lift};
use crate::regular::pcc::quadratic_factor;
use crate::regular::rules::{Polygon2, cone_polygon, misses};
use crate::verdict::{Checked, Fail, Report};

/// K1 for every cone, in order.
pub fn polygons(cones: &[Vec<V3>]) -> Checked<Vec<Polygon2>> {
    cones
        .iter()
        .enumerate()
        .map(|(i, c)| cone_polygon(c).map_err(|f| Fail { codes: f.codes, why: format!("K_{i}: {}", f.why) }))
        .collect()
}

/// K2: I_j(K_i ∩ C_ij) ⊆ K_j for all i ≠ j; the piece sizes in the order (i, j).
pub fn transitions(b: &Body, ks: &[Polygon2]) -> Checked<Vec<usize>> {
    let mut pieces = vec![];
    for i in 0..ks.len() {
        for j in (0..ks.len()).filter(|&j| j != i) {
            let c: Vec<HalfPlane> =
                b.next_contact_facets(i as i64, j as i64).iter().map(HalfPlane::of_covector).collect();
            let piece = clip_vertices(&ks[i].vertices, &c);
            let mut codes = vec![];
            for p in &piece {
                match misses(&ks[j], &b.impact(j as i64, &lift(p))) {
                    Some(true) if !codes.contains(&"image-not-below") => codes.push("image-not-below"),
                    Some(false) if !codes.contains(&"image-outside") => codes.push("image-outside"),
                    _ => {}
                }
            }
            if !codes.is_empty() {
                return Err(Fail { codes, why: format!("I_{j}(K_{i} ∩ C_({i},{j})) is not in K_{j}") });
            }
            pieces.push(piece.len());
        }
    }
    Ok(pieces)
}

/// K3: I_i(-m_{k,k+1}) ∈ K_i for all i, k.
pub fn all_down(b: &Body, ks: &[Polygon2]) -> Checked<()> {
    for (i, k) in ks.iter().enumerate() {
        for g in b.all_down() {
            if misses(k, &b.impact(i as i64, &g)).is_some() {
                return Err(Fail::new("initial-outside", format!("I_{i}(D) is not in K_{i}")));
            }
        }
    }
    Ok(())
}

/// K1-K4 (the body and the file's rules already checked).
pub fn check_family(b: &Body, claim: Claim, cones: &[Vec<V3>], bits: u64) -> Checked<Report> {
    let ks = polygons(cones)?;
    let pieces = transitions(b, &ks)?;
    if claim >= Claim::CcOrPccFromAllDown {
        all_down(b, &ks)?;
    }
    if claim >= Claim::CompleteChatterFromAllDown {
        for k in 0..b.n() as i64 {
            if !quadratic_factor(&b.pair_matrix(k)).excludes_pcc() {
                return Err(Fail::new(
                    "pcc-not-excluded",
                    format!("PCC of contacts {k} and {} is possible", k + 1),
                ));
            }
        }
    }
    let mut redundant = vec![];
    let mut offset = 0;
    for (c, k) in cones.iter().zip(&ks) {
        redundant.extend(k.redundant.iter().map(|r| r + offset));
        offset += c.len();
    }
    let f = b.gamma.field.clone();
    let down = [crate::arith::Num::int(&f, 0), crate::arith::Num::int(&f, 0), crate::arith::Num::int(&f, -1)];
    let translation = ks.iter().enumerate().all(|(i, k)| misses(k, &b.impact(i as i64, &down)).is_none());
    Ok(Report {
        claim: claim.name().into(),
        n: b.n() as u64,
        generators: Some(offset),
        redundant: Some(redundant),
        pieces: Some(pieces),
        max_denominator_bits: Some(bits),
        pcc: None,
        contains_translation: Some(translation),
        region: None,
        refutation: None,
        basin: None,
        rest_nodes: None,
    })
}
