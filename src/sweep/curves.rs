//! The exact curves of the paper's maps (figure "sajatertekek", solid curves; figure
//! "simulations", dashed curves): for each column of the plane (fixed kappa), the gammas where
//! S_1's dominant eigenvalue changes sign or becomes complex, where the CC criterion changes, and
//! where the PCC criterion changes, isolated exactly ([`crate::spectral::criteria::profile`]) and
//! then linked column to column into polylines for drawing.

use super::grid::Variable;
use crate::bodies::cosine;
use crate::exact::{OrderedField, Q, QExt};
use crate::spectral::criteria::{Family, Profile, Threshold, dominant_candidates, pcc_profile, profile};
use crate::spectral::eigen::{Dominant, Spectrum};
use crate::spectral::number_field::Nf;

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

/// A crossing of a curve with a column: gamma (to f64 accuracy) and a tag naming the change.
#[derive(Clone, Debug, PartialEq)]
pub struct Crossing {
    pub gamma: f64,
    pub tag: String,
}

/// The crossings of one column (one kappa).
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

fn crossings<F: OrderedField>(p: &Profile<F>, name: &str) -> Vec<Crossing> {
    p.thresholds
        .iter()
        .map(|t| Crossing { gamma: to_f64(t), tag: format!("{name}:{}>{}", t.below, t.above) })
        .collect()
}

fn column_in<F: OrderedField>(fam: &Family<F>) -> Column {
    let cands = dominant_candidates(fam);
    let of = |g: &Q| kind(Spectrum::of3(&fam.at(g).step(1)).dominant());
    let positive = profile(&cands, |g| of(g) == DominantKind::Positive);
    let complex = profile(&cands, |g| of(g) == DominantKind::Complex);
    let cc = crossings(&positive, "cc");
    let mut all = cc.clone();
    all.extend(crossings(&complex, "complex"));
    all.sort_by(|a, b| a.gamma.total_cmp(&b.gamma));
    all.dedup_by(|a, b| (a.gamma - b.gamma).abs() < 1e-12);
    Column { kind: all, cc, pcc: crossings(&pcc_profile(fam), "pcc") }
}

/// The crossings at one kappa, exact over Q (n = 3, 4, 6) or in Q(cos 2 pi/n).
pub fn column(n: u64, kappa: &Q) -> Column {
    let c1 = cosine(n as usize);
    match c1.as_rational() {
        Some(c) => column_in(&Family { n, c1: c, kappa: kappa.clone() }),
        None => column_in(&Family { n, c1, kappa: Nf::from_q(kappa) }),
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

/// Links crossings of neighbouring columns with the same tag, nearest first, into polylines.
fn link(columns: &[(f64, Vec<Crossing>)]) -> Vec<Polyline> {
    let mut done: Vec<Polyline> = Vec::new();
    let mut open: Vec<(String, Polyline)> = Vec::new();
    for (x, cs) in columns {
        let mut next: Vec<(String, Polyline)> = Vec::new();
        for c in cs {
            let best = open
                .iter()
                .enumerate()
                .filter(|(_, (tag, _))| *tag == c.tag)
                .min_by(|a, b| {
                    let da = (a.1.1.last().expect("non-empty").1 - c.gamma).abs();
                    let db = (b.1.1.last().expect("non-empty").1 - c.gamma).abs();
                    da.total_cmp(&db)
                })
                .map(|(i, _)| i);
            let mut line = match best {
                Some(i) => open.swap_remove(i).1,
                None => Vec::new(),
            };
            line.push((*x, c.gamma));
            next.push((c.tag.clone(), line));
        }
        done.extend(open.drain(..).map(|(_, l)| l));
        open = next;
    }
    done.extend(open.into_iter().map(|(_, l)| l));
    done
}

/// The curves over `columns` equally spaced values of the map's variable in [lo, hi].
pub fn curves(n: u64, variable: Variable, lo: &Q, hi: &Q, columns: u32) -> Curves {
    use rayon::prelude::*;
    let xs: Vec<Q> = (0..=columns).map(|i| lo + &((hi - lo) * Q::new(i as i64, columns as i64))).collect();
    let cols: Vec<(f64, Column)> = xs
        .par_iter()
        .filter(|x| **x > Q::int(0))
        .map(|x| {
            let kappa = if variable == Variable::Rho { x * x } else { x.clone() };
            (x.to_f64(), column(n, &kappa))
        })
        .collect();
    let pick = |f: fn(&Column) -> &Vec<Crossing>| -> Vec<(f64, Vec<Crossing>)> {
        cols.iter().map(|(x, c)| (*x, f(c).clone())).collect()
    };
    Curves { kind: link(&pick(|c| &c.kind)), cc: link(&pick(|c| &c.cc)), pcc: link(&pick(|c| &c.pcc)) }
}
