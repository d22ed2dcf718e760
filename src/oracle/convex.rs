//! The oracle for version-4 certificates (general convex bodies, docs/certificate-format.md §13):
//! rules K1 to K4 evaluated by brute force on the plane v = -1 with the oracle's own geometry
//! (gift wrapping, pairwise intersections of constraint lines, the PCC quadratic from the
//! characteristic polynomial of I_k I_{k+1} computed by hand), sharing nothing with
//! `chatter_kernel::geometry` or `chatter_kernel::check`. Only the model (`ConvexBody::impact`,
//! `next_contact_cone`, `all_down_generators`, validated by `ConvexBody::new`) comes from the
//! kernel; it is tested against Newton's laws and brute-force sampling in tests/all/kernel/convex.

use super::{
    HalfPlane, Pt, Verdict, clipped_vertices, full_dimensional, jarvis, lift, mat_mul, mat_vec, max_bits,
    parse_number, project, zero,
};
use crate::exact::Q;
use chatter_kernel::certificate::{Claim, Code, ConvexBodyText, ConvexCertificate};
use chatter_kernel::exact::ParseLimits;
use chatter_kernel::model::ConvexBody;

/// The PCC quadratic t^2 + p t + q of det(tI - I_k I_{k+1}) = (t - 1)(t^2 + p t + q).
pub fn pair_quadratic(b: &ConvexBody<Q>, k: i64) -> super::Quadratic {
    let m = mat_mul(&b.impact(k), &b.impact(k + 1));
    let tr = &m[0][0] + &m[1][1] + &m[2][2];
    let det = &m[0][0] * (&m[1][1] * &m[2][2] - &m[1][2] * &m[2][1])
        - &m[0][1] * (&m[1][0] * &m[2][2] - &m[1][2] * &m[2][0])
        + &m[0][2] * (&m[1][0] * &m[2][1] - &m[1][1] * &m[2][0]);
    // (t - 1)(t^2 + p t + q) = t^3 + (p - 1) t^2 + (q - p) t - q: p = 1 - tr, q = det.
    let p = Q::int(1) - &tr;
    let discriminant = &p * &p - Q::int(4) * &det;
    super::Quadratic { p, q: det, discriminant }
}

/// One cone: its counter-clockwise vertices and edge half-planes, or the K1 code.
fn cone(gens: &[[Q; 3]]) -> Result<(Vec<Pt>, Vec<HalfPlane>), Code> {
    let pts: Vec<Pt> = gens.iter().map(project).collect::<Option<_>>().ok_or(Code::GeneratorNotBelow)?;
    if !full_dimensional(&pts) {
        return Err(Code::DegenerateCone);
    }
    let ccw = jarvis(&pts);
    let m = ccw.len();
    let k = (0..m).map(|i| HalfPlane::left_of(&ccw[i], &ccw[(i + 1) % m])).collect();
    Ok((ccw, k))
}

/// Whether `img` lies in the cone (the zero vector does; v >= 0 does not).
fn inside(k: &[HalfPlane], img: &[Q; 3]) -> Result<(), bool> {
    if img.iter().all(|c| *c == zero()) {
        return Ok(());
    }
    match project(img) {
        None => Err(true),
        Some(p) if k.iter().all(|h| h.contains(&p)) => Ok(()),
        Some(_) => Err(false),
    }
}

/// Rules K1-K4 for a body, a claim and a family of cones (already parsed).
pub fn evaluate_convex_parts(b: &ConvexBody<Q>, claim: Claim, cones: &[Vec<[Q; 3]>]) -> Verdict {
    let mut v = Verdict::new(max_bits(cones.iter().flatten().flatten()));
    let g = b.gamma();
    if claim > Claim::EffectivelyInvariant && (*g == zero() || *g == Q::int(1)) {
        v.stage(vec![Code::ParameterOutOfRange]);
        return v;
    }
    if cones.len() != b.n() {
        v.stage(vec![Code::WrongArity]);
        return v;
    }
    let mut ks = Vec::with_capacity(cones.len());
    for c in cones {
        match cone(c) {
            Ok(k) => ks.push(k),
            Err(code) => {
                v.stage(vec![code]);
                return v;
            }
        }
    }
    // K2: I_j(K_i ∩ C_ij) ⊆ K_j.
    for (i, (ccw, k)) in ks.iter().enumerate() {
        for (j, (_, target)) in ks.iter().enumerate().filter(|(j, _)| *j != i) {
            let c = b.next_contact_cone(i as i64, j as i64).expect("i != j");
            let extra: Vec<HalfPlane> = c.iter().map(HalfPlane::from_covector).collect();
            let verts = clipped_vertices(ccw, k, &extra);
            v.pieces.push(verts.len());
            let m = b.impact(j as i64);
            let mut codes = vec![];
            for p in &verts {
                if let Err(above) = inside(target, &mat_vec(&m, &lift(p))) {
                    let c = if above { Code::ImageNotBelow } else { Code::ImageOutside };
                    if !codes.contains(&c) {
                        codes.push(c);
                    }
                }
            }
            if !codes.is_empty() {
                v.stage(codes);
            }
        }
    }
    // K3: I_i(D) ⊆ K_i.
    if claim >= Claim::CcOrPccFromAllDown {
        let bad = ks.iter().enumerate().any(|(i, (_, k))| {
            let m = b.impact(i as i64);
            b.all_down_generators().iter().any(|g| inside(k, &mat_vec(&m, g)).is_err())
        });
        if bad {
            v.stage(vec![Code::InitialOutside]);
        }
    }
    // K4: PCC excluded for every adjacent pair.
    if claim >= Claim::CompleteChatterFromAllDown
        && (0..b.n() as i64).any(|k| !pair_quadratic(b, k).excludes_pcc())
    {
        v.stage(vec![Code::PccNotExcluded]);
    }
    v
}

/// Every rule of a version-4 certificate, from its numbers (the header is the reader's).
pub fn evaluate_convex(cert: &ConvexCertificate, limits: ParseLimits) -> Verdict {
    let ConvexBodyText::ConvexPolygon { contacts, inertia, gamma } = &cert.body;
    let num = |s: &str| parse_number(s, limits);
    let parsed = (|| {
        let pts: Vec<[Q; 2]> =
            contacts.iter().map(|(x, y)| Some([num(x)?, num(y)?])).collect::<Option<_>>()?;
        let (xx, xy, yy) = (num(&inertia.0)?, num(&inertia.1)?, num(&inertia.2)?);
        Some((pts, [[xx, xy.clone()], [xy, yy]], num(gamma)?))
    })();
    let Some((pts, j, g)) = parsed else { return Verdict::stopped(Code::BadNumber) };
    let body = match ConvexBody::new(pts, j, g) {
        Ok(b) => b,
        Err(chatter_kernel::model::ConvexBodyError::GammaOutOfRange) => {
            return Verdict::stopped(Code::ParameterOutOfRange);
        }
        Err(_) => return Verdict::stopped(Code::UnsupportedBody),
    };
    let mut cones = Vec::with_capacity(cert.cones.len());
    for c in &cert.cones {
        let mut gens = Vec::with_capacity(c.len());
        for g in c {
            let xs: Vec<Q> = match g.0.iter().map(|s| num(s)).collect::<Option<_>>() {
                Some(xs) => xs,
                None => return Verdict::stopped(Code::BadNumber),
            };
            match <[Q; 3]>::try_from(xs) {
                Ok(x) => gens.push(x),
                Err(_) => return Verdict::stopped(Code::WrongArity),
            }
        }
        cones.push(gens);
    }
    evaluate_convex_parts(&body, cert.claim, &cones)
}
