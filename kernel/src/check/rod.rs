//! The rod's acceptance rules (docs/certificate-format.md §8). A generator (u0, u1) with
//! w = -(u0 + u1) = -2v > 0 projects to s = u0 / w on the line v = -1/2; K is the interval
//! between the extreme generators. C_1 and D come from the rod's model; R4 holds trivially (with
//! two contacts PCC is CC).

use super::region::{Corner, Region};
use super::show;
use super::{Accepted, Generators};
use crate::certificate::{Boundary, Claim, Code, Locus, Rejection};
use crate::exact::{Field, ParseLimits, Ring, scale_to_ints};
use crate::model::{Mat2, Rod, Shape, Vec2, mat2_vec};
use std::cmp::Ordering;

/// w = -(u0 + u1) = -2v, positive below the floor's plane.
fn w<Z: Ring>(g: &Vec2<Z>) -> Z {
    g[0].plus(&g[1]).negated()
}

/// Compares s = u0 / w of two points with w > 0: a0 w(b) against b0 w(a).
fn cmp<Z: Ring>(a: &Vec2<Z>, b: &Vec2<Z>) -> Ordering {
    a[0].times(&w(b)).cmp(&b[0].times(&w(a)))
}

/// A positive integer multiple of a rational 2-vector or 2x2 matrix (flattened).
fn ints<F: Field>(xs: &[F]) -> Vec<F::Int> {
    scale_to_ints(xs)
}

fn int_vec<F: Field>(v: &Vec2<F>) -> Vec2<F::Int> {
    let z = ints(v);
    [z[0].clone(), z[1].clone()]
}

fn int_mat<F: Field>(m: &Mat2<F>) -> Mat2<F::Int> {
    let z = ints(&[m[0][0].clone(), m[0][1].clone(), m[1][0].clone(), m[1][1].clone()]);
    [[z[0].clone(), z[1].clone()], [z[2].clone(), z[3].clone()]]
}

/// The point (u0, u1)/(-v) of a generator, as text.
fn shown<F: Field>(g: &Vec2<F::Int>) -> String {
    let half_w = F::from_int(&w(g)).over(&F::from_i64(2)).expect("2 != 0");
    let c: Vec<String> =
        g.iter().map(|x| show::number(&F::from_int(x).over(&half_w).expect("w > 0"))).collect();
    format!("({}, {})", c[0], c[1])
}

/// Clips the cone spanned by the points of `seg` (at most two, in order of s) by l . p >= 0:
/// the kept ends and, where l changes sign, the crossing (l.a) b - (l.b) a (times the sign of
/// l.a), a positive combination of a and b.
fn clip<Z: Ring>(seg: &[Vec2<Z>], l: &Vec2<Z>) -> Vec<Vec2<Z>> {
    let d: Vec<Z> = seg.iter().map(|p| l[0].times(&p[0]).plus(&l[1].times(&p[1]))).collect();
    let mut out = Vec::new();
    for (i, p) in seg.iter().enumerate() {
        if !d[i].is_negative() {
            out.push(p.clone());
        }
        if i + 1 < seg.len()
            && d[i].sign() != Ordering::Equal
            && d[i + 1].sign() != Ordering::Equal
            && d[i].sign() != d[i + 1].sign()
        {
            let (a, b) = (p, &seg[i + 1]);
            let x: Vec2<Z> = std::array::from_fn(|k| d[i].times(&b[k]).minus(&d[i + 1].times(&a[k])));
            out.push(if d[i].is_negative() { x.map(|c| c.negated()) } else { x });
        }
    }
    out
}

/// K = [a, b] in s, with the indices of its end generators.
struct Interval<Z> {
    ends: [Vec2<Z>; 2],
    index: [usize; 2],
}

impl<Z: Ring> Interval<Z> {
    fn contains(&self, q: &Vec2<Z>) -> bool {
        cmp(&self.ends[0], q) != Ordering::Greater && cmp(q, &self.ends[1]) != Ordering::Greater
    }
}

/// R1: generators below, and two distinct rays.
fn interval<F: Field>(gens: &Generators<'_, F::Int>) -> Result<Interval<F::Int>, Rejection> {
    let v: Vec<Vec2<F::Int>> = gens.vectors.iter().map(|g| [g[0].clone(), g[1].clone()]).collect();
    if let Some(i) = v.iter().position(|g| !w(g).is_positive()) {
        return Err(gens.not_below(i));
    }
    let Some(lo) = (0..v.len()).min_by(|&i, &j| cmp(&v[i], &v[j]).then(i.cmp(&j))) else {
        let msg = "field `cone` is empty: K must be a 2-D cone";
        return Err(Rejection::new(Code::DegenerateCone, Locus::Cone, msg));
    };
    let hi = (0..v.len()).max_by(|&i, &j| cmp(&v[i], &v[j]).then(j.cmp(&i))).expect("non-empty");
    if cmp(&v[lo], &v[hi]) == Ordering::Equal {
        let msg = "the generators span a single ray: K must be a 2-D cone (two distinct rays)";
        return Err(Rejection::new(Code::DegenerateCone, Locus::Cone, msg));
    }
    Ok(Interval { ends: [v[lo].clone(), v[hi].clone()], index: [lo, hi] })
}

/// Checks that `img` lies in K (or is 0); `locus` builds the locus from the violated end.
fn check_image<F: Field>(
    k: &Interval<F::Int>,
    img: &Vec2<F::Int>,
    what: &dyn Fn() -> String,
    locus: &dyn Fn(Option<Boundary>) -> Locus,
    codes: (Code, Code),
) -> Result<(), Rejection> {
    if img.iter().all(Ring::is_zero) || (w(img).is_positive() && k.contains(img)) {
        return Ok(());
    }
    if !w(img).is_positive() {
        return Err(Rejection::new(codes.1, locus(None), format!("{} to a velocity with v >= 0", what())));
    }
    let end = if cmp(img, &k.ends[0]) == Ordering::Less { 0 } else { 1 };
    let s = |g: &Vec2<F::Int>| F::from_int(&g[0]).over(&F::from_int(&w(g))).expect("w > 0");
    let by = s(img).minus(&s(&k.ends[end]));
    let generator = k.index[end];
    let msg = format!(
        "{} to {} outside K, beyond generator {generator}, by {} in u0/(-2v)",
        what(),
        shown::<F>(img),
        show::number(&by)
    );
    Err(Rejection::new(codes.0, locus(Some(Boundary::End { generator })), msg))
}

/// The rod's model at each corner.
fn rods<F: Field>(region: &Region<F>) -> Vec<&Rod<F>> {
    region
        .corners
        .iter()
        .map(|c| match &c.shape {
            Shape::Rod(r) => r,
            Shape::Polygon(_) => unreachable!("every corner has n = 2"),
        })
        .collect()
}

/// R2 for the rod at one corner, on the ends of the piece K ∩ C_1.
fn invariance<F: Field>(
    rod: &Rod<F>,
    corner: &Corner<F>,
    k: &Interval<F::Int>,
    piece: &[Vec2<F::Int>],
) -> Result<(), Rejection> {
    let step = int_mat(&rod.step());
    for (i, p) in piece.iter().enumerate() {
        let what = || corner.say(format!("vertex {i} of K∩C_1, at {}, maps under S_1", shown::<F>(p)));
        let locus = |outside| Locus::Piece { piece: 1, vertex: i, outside, corner: corner.index };
        check_image::<F>(k, &mat2_vec(&step, p), &what, &locus, (Code::ImageOutside, Code::ImageNotBelow))?;
    }
    Ok(())
}

/// R3 for the rod at one corner, on the generators of D.
fn all_down<F: Field>(rod: &Rod<F>, corner: &Corner<F>, k: &Interval<F::Int>) -> Result<(), Rejection> {
    let i0 = int_mat(&rod.impact(0));
    for (m, g) in rod.all_down_generators().iter().enumerate() {
        let g = int_vec(g);
        let what = || corner.say(format!("I_0 maps the all-down generator {m} = {}", shown::<F>(&g)));
        let locus = |outside| Locus::AllDown { generator: m, outside, corner: corner.index };
        let codes = (Code::InitialOutside, Code::InitialOutside);
        check_image::<F>(k, &mat2_vec(&i0, &g), &what, &locus, codes)?;
    }
    Ok(())
}

/// Rules R1 to R3 for the rod (R4 holds trivially), at a point or on a box. C_1 does not depend
/// on kappa or gamma, so the piece K ∩ C_1 is computed once.
pub(super) fn check<F: Field>(
    region: &Region<F>,
    gens: &Generators<'_, F::Int>,
    claim: Claim,
    limits: ParseLimits,
) -> Result<Accepted, Rejection> {
    let rods = rods(region);
    let k = interval::<F>(gens)?;
    super::in_time(limits, "building K")?;
    let cone = rods[0].next_contact_cone();
    if rods.iter().any(|r| r.next_contact_cone() != cone) {
        let msg = "model error: C_1 differs between the corners of the box";
        return Err(Rejection::new(Code::Internal, Locus::Nowhere, msg));
    }
    let piece = cone.iter().fold(k.ends.to_vec(), |p, l| clip(&p, &int_vec(l)));
    for (rod, corner) in rods.iter().zip(&region.corners) {
        invariance(rod, corner, &k, &piece)?;
    }
    if claim >= Claim::CcOrPccFromAllDown {
        for (rod, corner) in rods.iter().zip(&region.corners) {
            all_down(rod, corner, &k)?;
        }
    }
    let contains_translation = rods.iter().all(|rod| {
        let t = mat2_vec(&int_mat(&rod.impact(0)), &[F::Int::from_i64(-1), F::Int::from_i64(-1)]);
        w(&t).is_positive() && k.contains(&t)
    });
    Ok(Accepted {
        claim,
        n: 2,
        generators: gens.vectors.len(),
        redundant: (0..gens.vectors.len()).filter(|i| !k.index.contains(i)).collect(),
        pieces: vec![piece.len()],
        max_denominator_bits: gens.max_denominator_bits,
        pcc: None,
        contains_translation,
        region: None,
        pcc_boxes: None,
        orbit_boxes: None,
    })
}
