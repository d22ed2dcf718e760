//! Time-to-rest certificates of an affine image of a regular polygon, by transport (untrusted:
//! the kernel re-checks the file like any other; docs/time-to-rest.md §5, "General bodies").
//!
//! A regular polygon's graph lives in contact coordinates relabelled at the last contact: a node
//! holds velocities p with (u_0, u_1, v) in K_r, its virtual time is (a_r·q)/(−b_r·p) with q in
//! the same coordinates (h_0, h_1, h), and an edge (j, s) says that contact j (counted from the
//! last one) lands next. For the image body u'_k(T p) = u_k(p), h'_k(T q) = h_k(q), and T keeps v
//! and h (docs/model.md §11.7), so each node r becomes n nodes (i, r), one per contact i of the
//! last impact: K'_{i,r} = W_i⁻¹ K_r, b' = W_iᵀ b_r, a' = W_iᵀ a_r, where W_i has rows f_i,
//! f_{i+1}, (0, 0, 1) (u_i = f_i·p, h_i = f_i·q), and the edge (j, s) leads to ((i + j) mod n,
//! s). The all-down drops and B are the regular body's.

use super::{Config, NotProduced, Produced, Region, family_file, generator, produce_on, produced};
use crate::certify::transport::{RegularPreimage, from_contact_speeds};
use crate::exact::{Q, Ring};
use chatter_kernel::certificate::{Encoding, Generator};
use chatter_kernel::exact::ParseLimits;
use chatter_kernel::model::ConvexBody;
use chatter_kernel::model::linalg::Vec3;
use chatter_kernel::rest::{Node, TimeToRest};
use chatter_kernel::rest_family::{FamilyNode, FamilyTimeToRest};
use chatter_kernel::verify::{Backend, verify_rest_family_text_in};

/// The `producer` field of a transported file.
pub(super) const PRODUCER: &str =
    "chatter certify --time-to-rest (the regular polygon's certificate, transported to its affine image)";

/// The regular polygon `pre`'s time-to-rest certificate over the γ of `ends` (one body, or the
/// two ends of an interval), transported to the body and accepted by the kernel on `backends`.
pub(super) fn transported(
    ends: &[ConvexBody<Q>],
    pre: &RegularPreimage,
    tensor: Option<&[Q; 6]>,
    cfg: &Config,
    backends: &[Backend],
) -> Result<Produced<FamilyTimeToRest>, NotProduced> {
    let (lo, hi) = (&ends[0], &ends[ends.len() - 1]);
    let region = Region {
        kappa: [pre.kappa.clone(), pre.kappa.clone()],
        gamma: [lo.gamma(), hi.gamma()].map(Q::clone),
    };
    let regular = produce_on(pre.n as u64, &region, cfg, backends)?;
    let bad = |what: &str| NotProduced::Failed(format!("the regular certificate's {what} is not rational"));
    let nodes = (0..lo.n())
        .map(|i| copies(lo, i, &regular.cert))
        .collect::<Option<Vec<_>>>()
        .ok_or_else(|| bad("graph"))?;
    let bound: Q = regular.cert.bound.parse().map_err(|_| bad("bound"))?;
    let interval = (lo.gamma() != hi.gamma()).then(|| hi.gamma());
    let count = regular.cert.nodes.len();
    let entries = (0..lo.n()).map(|i| i * count).collect();
    let cert =
        family_file((lo, interval), tensor, regular.cert.claim, &bound, (entries, nodes.concat()), PRODUCER);
    let text = crate::write::write_rest_family(&cert);
    let v = verify_rest_family_text_in(&text, Encoding::Ron, ParseLimits::default(), backends);
    produced(v, cert, text, regular.edges * lo.n())
}

/// The regular graph's nodes as the nodes (i, r), r = 0..N−1, of the last contact i (node
/// i N + r of the file); `None` if a number of the file is not rational (or a numerator is
/// missing).
fn copies(body: &ConvexBody<Q>, i: usize, rest: &TimeToRest) -> Option<Vec<FamilyNode>> {
    let (n, count) = (body.n(), rest.nodes.len());
    let c = body.contacts();
    let node = |x: &Node| {
        let cone =
            x.cone.iter().map(|g| Some(generator(&from_contact_speeds(&c[i], &c[(i + 1) % n], &vector(g)?))));
        // The producer writes versions 2 and 3, which give the numerator a_r itself.
        let (b, a) = (vector(&x.weight)?, vector(&x.numerator)?);
        let next = x.next.iter().map(|&(j, s)| {
            let to = (i + j as usize) % n;
            (to as u64, to * count + s)
        });
        Some(FamilyNode {
            contact: i,
            cone: cone.collect::<Option<_>>()?,
            weight: generator(&pulled_back(body, i, &b)),
            numerator: generator(&pulled_back(body, i, &a)),
            next: next.collect(),
        })
    };
    rest.nodes.iter().map(node).collect()
}

/// A generator's three rational numbers.
fn vector(g: &Generator) -> Option<Vec3<Q>> {
    let x: Vec<Q> = g.0.iter().map(|s| s.parse().ok()).collect::<Option<_>>()?;
    x.try_into().ok()
}

/// W_iᵀ x = x_0 f_i + x_1 f_{i+1} + x_2 (0, 0, 1): a covector on the coordinates relabelled at
/// contact i as a covector on the paper's coordinates.
fn pulled_back(body: &ConvexBody<Q>, i: usize, x: &Vec3<Q>) -> Vec3<Q> {
    let (f, g) = (body.covector(i as i64), body.covector(i as i64 + 1));
    std::array::from_fn(|k| {
        let e = if k == 2 { x[2].clone() } else { Q::int(0) };
        x[0].times(&f[k]).plus(&x[1].times(&g[k])).plus(&e)
    })
}
