//! The exact curves of the paper's maps (figure "sajatertekek", solid curves; figure
//! "simulations", dashed curves): for each column of the plane (fixed kappa), the gammas where
//! S_1's dominant eigenvalue changes sign or becomes complex, where the CC criterion changes, and
//! where the PCC criterion changes, isolated exactly ([`crate::spectral::criteria::profile`]) and
//! then linked column to column into polylines for drawing.

use super::grid::Variable;
use crate::bodies::cosine;
use crate::exact::{OrderedField, Q, QExt, QField};
use crate::spectral::criteria::{
    Family, Profile, Threshold, candidates_of, char_coefficients_at, discriminant_of, dominant_candidates,
    pcc_criterion, pcc_profile, profile,
};
use crate::spectral::eigen::{Dominant, Spectrum};
use crate::spectral::number_field::Nf;
use crate::spectral::poly::Poly;
use chatter_kernel::model::Polygon;
use chatter_kernel::model::linalg::{Mat3, mat_mul};

/// The three kinds of S_1's dominant eigenvalue the paper's left panels separate.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DominantKind {
    /// Real and positive (the CC criterion, Elsner-Vandergraft).
    Positive,
    /// A complex pair dominates.
    Complex,
    /// Real and negative dominates (or a tie that the criterion rejects).
    Negative,
}

/// The kind of a dominant eigenvalue.
pub fn kind(d: Dominant) -> DominantKind {
    match d {
        _ if d.real_positive() => DominantKind::Positive,
        Dominant::NonReal | Dominant::RealAndNonReal { .. } => DominantKind::Complex,
        _ => DominantKind::Negative,
    }
}

/// A crossing of a curve with a column (at gamma) or a row (at kappa / kappa_max), to f64
/// accuracy, and a tag naming the change.
#[derive(Clone, Debug, PartialEq)]
pub struct Crossing {
    pub at: f64,
    pub tag: String,
}

/// The crossings of one column (one kappa) or one row (one gamma).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Column {
    /// Where the dominant eigenvalue's kind changes.
    pub kind: Vec<Crossing>,
    /// Where the CC criterion changes (a subset of `kind`).
    pub cc: Vec<Crossing>,
    /// Where the PCC criterion changes.
    pub pcc: Vec<Crossing>,
}

fn to_f64<F: OrderedField>(t: &Threshold<F>) -> f64 {
    let mut r = t.gamma.clone();
    while !r.is_exact() && r.width() > Q::new(1, 1 << 40) {
        r.bisect();
    }
    ((&r.lo + &r.hi) / Q::int(2)).to_f64()
}

pub(crate) fn crossings<F: OrderedField>(p: &Profile<F>, name: &str) -> Vec<Crossing> {
    p.thresholds
        .iter()
        .map(|t| Crossing { at: to_f64(t), tag: format!("{name}:{}>{}", t.below, t.above) })
        .collect()
}

/// The crossings of the kind profiles (positive, complex) from their candidate polynomials, and
/// of a PCC profile.
fn crossings_of<F: OrderedField>(
    cands: &[(&'static str, Poly<F>)],
    kind_at: impl Fn(&Q) -> DominantKind,
    pcc: &Profile<F>,
) -> Column {
    let positive = profile(cands, |t| kind_at(t) == DominantKind::Positive);
    let complex = profile(cands, |t| kind_at(t) == DominantKind::Complex);
    let cc = crossings(&positive, "cc");
    let mut all = cc.clone();
    all.extend(crossings(&complex, "complex"));
    all.sort_by(|a, b| a.at.total_cmp(&b.at));
    all.dedup_by(|a, b| (a.at - b.at).abs() < 1e-12);
    Column { kind: all, cc, pcc: crossings(pcc, "pcc") }
}

fn column_in<F: OrderedField>(fam: &Family<F>) -> Column {
    let of = |g: &Q| kind(Spectrum::of3(&fam.at(g).step(1)).dominant());
    crossings_of(&dominant_candidates(fam), of, &pcc_profile(fam))
}

/// The crossings along a row (fixed gamma) in t = kappa / kappa_hi in (0, 1). (1 + kappa) S_1 is
/// affine in kappa and (1 + kappa)^2 S_{n-1} S_1 quadratic, and positive scaling keeps the
/// kind of the dominant eigenvalue and the reality of the spectrum, so the same exact profiles
/// apply in t.
fn row_in<F: OrderedField>(n: u64, c1: &F, gamma: &Q, kappa_hi: &Q) -> Column {
    let body = |t: &Q| {
        // A sample at t = 0 (a root isolated down to 0) is taken just above it: kappa > 0.
        let tiny = Q::new(1, 1 << 62);
        let kappa = kappa_hi * if *t > tiny { t } else { &tiny };
        let b = Polygon::with_cosine(n, c1.clone(), F::from_q(&kappa), F::from_q(gamma)).expect("kappa > 0");
        (b, F::from_q(&(Q::int(1) + &kappa)))
    };
    let scaled = |m: Mat3<F>, s: &F| m.map(|r| r.map(|x| x.times(s)));
    let s1 = |t: &Q| {
        let (b, s) = body(t);
        scaled(b.step(1), &s)
    };
    let pair = |t: &Q| {
        let (b, s) = body(t);
        scaled(mat_mul(&b.step(n as i64 - 1), &b.step(1)), &s.times(&s))
    };
    let pts = |k: i64| (1..=k).map(Q::int).collect::<Vec<_>>();
    let cands = candidates_of(char_coefficients_at(s1, &pts(4)));
    let pcc_poly = discriminant_of(&char_coefficients_at(pair, &pts(7)));
    let of = |t: &Q| kind(Spectrum::of3(&body(t).0.step(1)).dominant());
    let pcc = profile(&[("discriminant", pcc_poly)], |t| pcc_criterion(&body(t).0).0);
    crossings_of(&cands, of, &pcc)
}

/// The crossings at one kappa, exact over Q (n = 3, 4, 6) or in Q(cos 2 pi/n).
pub fn column(n: u64, kappa: &Q) -> Column {
    let c1 = cosine(n as usize);
    match c1.as_rational() {
        Some(c) => column_in(&Family { n, c1: c, kappa: kappa.clone() }),
        None => column_in(&Family { n, c1, kappa: Nf::from_q(kappa) }),
    }
}

/// The crossings at one gamma in t = kappa / kappa_hi, t in (0, 1).
pub fn row(n: u64, gamma: &Q, kappa_hi: &Q) -> Column {
    let c1 = cosine(n as usize);
    match c1.as_rational() {
        Some(c) => row_in(n, &c, gamma, kappa_hi),
        None => row_in(n, &c1, gamma, kappa_hi),
    }
}

/// A curve to draw: points (x, gamma) in the map's coordinates.
pub type Polyline = Vec<(f64, f64)>;

/// The three families of curves over an x range.
#[derive(Clone, Debug, Default)]
pub struct Curves {
    pub kind: Vec<Polyline>,
    pub cc: Vec<Polyline>,
    pub pcc: Vec<Polyline>,
}

/// Links crossings of neighbouring lines (columns or rows) with the same tag, nearest first and
/// at most `reach` apart, into polylines of (position along the lines, crossing).
fn link(lines: &[(f64, Vec<Crossing>)], reach: f64) -> Vec<Polyline> {
    let mut done: Vec<Polyline> = Vec::new();
    let mut open: Vec<(String, Polyline)> = Vec::new();
    for (x, cs) in lines {
        let mut next: Vec<(String, Polyline)> = Vec::new();
        for c in cs {
            let gap = |l: &Polyline| (l.last().expect("non-empty").1 - c.at).abs();
            let best = open
                .iter()
                .enumerate()
                .filter(|(_, (tag, l))| *tag == c.tag && gap(l) <= reach)
                .min_by(|a, b| gap(&a.1.1).total_cmp(&gap(&b.1.1)))
                .map(|(i, _)| i);
            let mut line = match best {
                Some(i) => open.swap_remove(i).1,
                None => Vec::new(),
            };
            line.push((*x, c.at));
            next.push((c.tag.clone(), line));
        }
        done.extend(open.drain(..).map(|(_, l)| l));
        open = next;
    }
    done.extend(open.into_iter().map(|(_, l)| l));
    done.retain(|l| l.len() >= 2);
    done
}

/// How many line spacings apart two crossings may be linked; steeper pieces are drawn from the
/// crossings of the other direction.
const REACH: f64 = 4.0;

/// How near (in grid cells, along gamma) a row crossing must lie to a column-linked piece over
/// its column strip to count as drawn by it.
const COVERED: f64 = 0.5;

/// How far (in grid cells) a row-linked run may be joined to the end of a column-linked piece.
const JOIN: f64 = 1.5;

/// A segment between two points of the plane.
type Segment = ((f64, f64), (f64, f64));

/// Distance in grid cells (`cell` = the spacings of columns and rows) from `p` to the segment a-b.
fn cells_to_segment(p: (f64, f64), (a, b): Segment, cell: (f64, f64)) -> f64 {
    let s = |q: (f64, f64)| (q.0 / cell.0, q.1 / cell.1);
    let (p, a, b) = (s(p), s(a), s(b));
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let len2 = dx * dx + dy * dy;
    let t = if len2 > 0.0 { (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / len2).clamp(0.0, 1.0) } else { 0.0 };
    (p.0 - a.0 - t * dx).hypot(p.1 - a.1 - t * dy)
}

/// Splits column-linked polylines (points (x, gamma)) where a link rises more than one cell:
/// there the curve is steeper than the grid's diagonal and the rows draw it.
fn shallow(cols: Vec<Polyline>, cell_g: f64) -> Vec<Polyline> {
    let mut out = Vec::new();
    for line in cols {
        let mut piece: Polyline = Vec::new();
        for p in line {
            if piece.last().is_some_and(|q| (p.1 - q.1).abs() > cell_g) {
                out.push(std::mem::take(&mut piece));
            }
            piece.push(p);
        }
        out.push(piece);
    }
    out.retain(|l| l.len() >= 2);
    out
}

/// Whether a segment of a column piece spans p's x and passes within [`COVERED`] cells of it
/// in gamma.
fn covered(p: (f64, f64), segs: &[Segment], cell_g: f64) -> bool {
    segs.iter().any(|&(a, b)| {
        let (lo, hi) = (a.0.min(b.0), a.0.max(b.0));
        hi > lo && (lo..=hi).contains(&p.0) && {
            let g = a.1 + (b.1 - a.1) * (p.0 - a.0) / (b.0 - a.0);
            (g - p.1).abs() <= COVERED * cell_g
        }
    })
}

/// Where a run of row crossings that ends at `p` meets the column pieces, if the row-linked line
/// goes on to `next`: the column piece end within [`JOIN`] cells of `p` nearest to the link from
/// `p` to `next`, else `next` itself. A run that ends the line is not joined (a column piece's
/// end near it belongs to another curve).
fn join(
    p: (f64, f64),
    next: Option<(f64, f64)>,
    ends: &[(f64, f64)],
    cell: (f64, f64),
) -> Option<(f64, f64)> {
    let q = next?;
    let to = |e: &(f64, f64)| cells_to_segment(*e, (q, p), cell);
    ends.iter()
        .copied()
        .filter(|&e| cells_to_segment(p, (e, e), cell) <= JOIN)
        .min_by(|a, b| to(a).total_cmp(&to(b)))
        .or(next)
}

/// Every stretch of a curve once (issue 26 §1: a curve seen by both columns and rows was drawn
/// twice, and dashed it looked solid): the column-linked pieces no steeper than the grid's
/// diagonal, and the runs of row-linked crossings that no such piece covers over its column strip
/// (`covered`), each run joined at its ends to the column pieces (`join`).
pub fn merge(cols: Vec<Polyline>, rows: Vec<Polyline>, cell: (f64, f64)) -> Vec<Polyline> {
    let cols = shallow(cols, cell.1);
    let segs: Vec<Segment> = cols.iter().flat_map(|l| l.windows(2)).map(|w| (w[0], w[1])).collect();
    let ends: Vec<(f64, f64)> = cols.iter().flat_map(|l| [l[0], l[l.len() - 1]]).collect();
    let mut out = cols.clone();
    for line in rows {
        let free: Vec<bool> = line.iter().map(|&p| !covered(p, &segs, cell.1)).collect();
        let mut i = 0;
        while i < line.len() {
            if !free[i] {
                i += 1;
                continue;
            }
            let j = (i..line.len()).take_while(|&k| free[k]).last().unwrap_or(i);
            let before = i.checked_sub(1).map(|k| line[k]);
            let mut run: Polyline = join(line[i], before, &ends, cell).into_iter().collect();
            run.extend_from_slice(&line[i..=j]);
            run.extend(join(line[j], line.get(j + 1).copied(), &ends, cell));
            if run.len() >= 2 {
                out.push(run);
            }
            i = j + 1;
        }
    }
    chain(out)
}

/// Appends to `line` the pieces that begin or end where it ends, while there is one.
fn extend_end(line: &mut Polyline, pieces: &mut Vec<Polyline>) {
    loop {
        let end = line[line.len() - 1];
        let Some(i) = pieces.iter().position(|p| p[0] == end || p[p.len() - 1] == end) else {
            return;
        };
        let mut next = pieces.swap_remove(i);
        if next[0] != end {
            next.reverse();
        }
        line.extend_from_slice(&next[1..]);
    }
}

/// Joins the pieces that share an end point into one polyline, so that a dash pattern runs on
/// across the joint.
fn chain(mut pieces: Vec<Polyline>) -> Vec<Polyline> {
    let mut out = Vec::new();
    while let Some(mut line) = pieces.pop() {
        extend_end(&mut line, &mut pieces);
        line.reverse();
        extend_end(&mut line, &mut pieces);
        out.push(line);
    }
    out
}

/// The curves from the crossings of columns (at x, gammas) and of rows (at gamma, xs), `cell`
/// apart: linked along each direction (`link`), then each stretch kept once ([`merge`]).
pub fn draw_crossings(
    cols: &[(f64, Vec<Crossing>)],
    rows: &[(f64, Vec<Crossing>)],
    cell: (f64, f64),
) -> Vec<Polyline> {
    let by_cols = link(cols, cell.1 * REACH);
    // Rows link in x; their points are stored as (gamma, x): swap to (x, gamma).
    let by_rows = link(rows, cell.0 * REACH)
        .into_iter()
        .map(|l| l.into_iter().map(|(g, x)| (x, g)).collect())
        .collect();
    merge(by_cols, by_rows, cell)
}

/// The curves over a window of the map's plane ([x_lo, x_hi] x [g_lo, g_hi]), from the exact
/// crossings of `lines` equally spaced columns (fixed kappa) and as many rows (fixed gamma).
pub fn curves(n: u64, variable: Variable, x: (&Q, &Q), g: (&Q, &Q), lines: u32) -> Curves {
    use rayon::prelude::*;
    let steps = |(lo, hi): (&Q, &Q)| -> Vec<Q> {
        (0..=lines)
            .map(|i| lo + &((hi - lo) * Q::new(i as i64, lines as i64)))
            .filter(|v| *v > Q::int(0))
            .collect()
    };
    let kappa_of = |x: &Q| if variable == Variable::Rho { x * x } else { x.clone() };
    let x_of = |t: f64, hi: f64| if variable == Variable::Rho { (hi * t).sqrt() } else { hi * t };
    let kappa_hi = kappa_of(x.1);
    let cols: Vec<(f64, Column)> =
        steps(x).par_iter().map(|x| (x.to_f64(), column(n, &kappa_of(x)))).collect();
    let rows: Vec<(f64, Column)> = steps(g)
        .par_iter()
        .filter(|g| **g < Q::int(1))
        .map(|g| {
            let mut c = row(n, g, &kappa_hi);
            let hi = kappa_hi.to_f64();
            for list in [&mut c.kind, &mut c.cc, &mut c.pcc] {
                for cr in list.iter_mut() {
                    cr.at = x_of(cr.at, hi);
                }
            }
            (g.to_f64(), c)
        })
        .collect();
    let spacing = |(lo, hi): (&Q, &Q)| (hi - lo).to_f64() / lines as f64;
    let cell = (spacing(x), spacing(g));
    let both = |f: fn(&Column) -> &Vec<Crossing>| -> Vec<Polyline> {
        let pick = |ls: &[(f64, Column)]| -> Vec<(f64, Vec<Crossing>)> {
            ls.iter().map(|(p, c)| (*p, f(c).clone())).collect()
        };
        draw_crossings(&pick(&cols), &pick(&rows), cell)
    };
    Curves { kind: both(|c| &c.kind), cc: both(|c| &c.cc), pcc: both(|c| &c.pcc) }
}
