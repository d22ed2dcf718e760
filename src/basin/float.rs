//! The producer's `f64` walk of a drop (untrusted; docs/basin-certificates.md §5): the same
//! impacts as the kernel's rule B4 (docs/orbit-certificates.md §3 condition 1), from the
//! paper's drop coordinates, with the first contact to land chosen by the smallest flight time.

use crate::exact::{Q, QExt};
use chatter_kernel::orbit::{Iv, Maps, Orbit};
use malachite::rational::Rational;

/// An impact prefix and where it ends.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Plan {
    /// The contact that lands first (absolute).
    pub first: usize,
    /// The later steps (relative, 1..n-1).
    pub steps: Vec<u64>,
    /// Whether it ends in X (CC) rather than at v > 0 (ICC).
    pub cc: bool,
    /// Impact counts after which the kernel re-encloses the state in X's parameters.
    pub cuts: Vec<u64>,
    /// With `cc`: it ends in the cone of this node of the time-to-rest certificate, not in X.
    pub rest: Option<usize>,
}

/// The body and the set X in `f64`.
#[derive(Clone, Debug)]
pub struct Walker {
    contacts: Vec<[f64; 3]>,
    impact0: [[f64; 3]; 3],
    cos_sin: (f64, f64),
    /// X as (x*, A^-1, δ), if there is an orbit certificate.
    x: Option<([f64; 3], [[f64; 3]; 3], f64)>,
    /// The longest prefix tried.
    pub max_prefix: usize,
    /// A CC prefix ends once the walk's state is within this share of δ in X's parameters.
    pub entry: f64,
    /// A CC prefix is cut every this many impacts, counted back from its end (0: no cuts).
    pub cut_every: usize,
    /// ... but only where the walk's state is within this many δ of x* in X's parameters.
    pub cut_within: f64,
    /// The cones of the time-to-rest certificate's nodes: their facets' unit inner normals.
    pub cones: Vec<Vec<[f64; 3]>>,
    /// A prefix ends in a node's cone once the velocity's direction is at least this far inside
    /// every facet (cosine of the angle to the facet's plane).
    pub cone_margin: f64,
}

fn f(x: &Rational) -> f64 {
    Q::from_rational(x.clone()).to_f64()
}

fn mid(x: &Iv<Rational>) -> f64 {
    (f(&x.lo) + f(&x.hi)) / 2.0
}

fn dot(f: &[f64; 3], x: &[f64; 3]) -> f64 {
    f[0] * x[0] + f[1] * x[1] + f[2] * x[2]
}

impl Walker {
    /// From the kernel's body and the checked content of the orbit certificate (if any).
    pub fn new(maps: &Maps<Iv<Rational>>, orbit: Option<&Orbit<Rational>>, max_prefix: usize) -> Self {
        let contacts: Vec<[f64; 3]> = maps.contacts.iter().map(|r| r.each_ref().map(mid)).collect();
        let impact0 = maps.impact0.each_ref().map(|r| r.each_ref().map(mid));
        let c = contacts[2][1] / 2.0;
        Walker {
            contacts,
            impact0,
            cos_sin: (c, (1.0 - c * c).max(0.0).sqrt()),
            x: orbit.map(|o| {
                (o.centre.each_ref().map(f), o.a_inv.each_ref().map(|r| r.each_ref().map(f)), f(&o.delta))
            }),
            max_prefix,
            entry: 0.5,
            cut_every: 0,
            cut_within: f64::INFINITY,
            cones: Vec::new(),
            cone_margin: 1e-3,
        }
    }

    /// The nodes' cones from their exact facets (docs/basin-certificates.md §4, `Rest`).
    pub fn with_cones(mut self, facets: &[Vec<[Rational; 3]>]) -> Self {
        let unit = |g: &[Rational; 3]| {
            let v = g.each_ref().map(f);
            let norm = dot(&v, &v).sqrt();
            v.map(|x| x / norm)
        };
        self.cones = facets.iter().map(|fs| fs.iter().map(unit).collect()).collect();
        self
    }

    /// How far inside node r's cone the velocity p is: the least cosine over its facets (v < 0).
    fn margin(&self, r: usize, p: &[f64; 3]) -> f64 {
        let norm = dot(p, p).sqrt();
        if p[2] >= 0.0 || norm == 0.0 {
            return f64::NEG_INFINITY;
        }
        self.cones[r].iter().map(|fc| dot(fc, p) / norm).fold(f64::INFINITY, f64::min)
    }

    /// The node whose cone holds p deepest, if by at least [`Walker::cone_margin`].
    fn in_cone(&self, p: &[f64; 3]) -> Option<usize> {
        let best = (0..self.cones.len()).map(|r| (r, self.margin(r, p))).max_by(|a, b| a.1.total_cmp(&b.1));
        best.filter(|&(_, m)| m >= self.cone_margin).map(|(r, _)| r)
    }

    /// (q, p) in our coordinates of the drop y = (ω_x, ω_y, φ_x, φ_y, h), v = -1.
    fn start(&self, y: &[f64; 5]) -> ([f64; 3], [f64; 3]) {
        let (c, s) = self.cos_sin;
        let p = [-1.0 - y[1], -1.0 + s * y[0] - c * y[1], -1.0];
        let q = [y[4] - y[3], y[4] + s * y[2] - c * y[3], y[4]];
        (q, p)
    }

    /// The contact that lands first from (q, p) (absolute), if one approaches.
    fn next(&self, q: &[f64; 3], p: &[f64; 3]) -> Option<usize> {
        let mut best: Option<(f64, usize)> = None;
        for (k, fk) in self.contacts.iter().enumerate() {
            let (h, u) = (dot(fk, q), dot(fk, p));
            if u < 0.0 && h > 0.0 {
                let t = h / -u;
                if best.is_none_or(|(b, _)| t < b) {
                    best = Some((t, k));
                }
            }
        }
        best.map(|(_, k)| k)
    }

    /// The impact at `j`: the state right after it, relabelled (as the kernel's `step`).
    fn impact(&self, j: usize, q: &[f64; 3], p: &[f64; 3]) -> ([f64; 3], [f64; 3]) {
        let n = self.contacts.len();
        let (hj, uj) = (dot(&self.contacts[j], q), dot(&self.contacts[j], p));
        let t = hj / -uj;
        let moved = [q[0] + t * p[0], q[1] + t * p[1], q[2] + t * p[2]];
        let next = &self.contacts[(j + 1) % n];
        let r = [uj, dot(next, p), p[2]];
        let p1 = [dot(&self.impact0[0], &r), dot(&self.impact0[1], &r), dot(&self.impact0[2], &r)];
        ([0.0, dot(next, &moved), moved[2]], p1)
    }

    /// X's parameters y = A^-1 (x - x*) of the normalised state, if hc > 0 and v < 0.
    fn in_x(&self, q: &[f64; 3], p: &[f64; 3]) -> Option<[f64; 3]> {
        let (centre, a_inv, delta) = self.x.as_ref()?;
        if q[2] <= 0.0 || p[2] >= 0.0 {
            return None;
        }
        let x = [q[1] / q[2], p[0] / -p[2], p[1] / -p[2]];
        let d = [x[0] - centre[0], x[1] - centre[1], x[2] - centre[2]];
        Some(std::array::from_fn(|i| dot(&a_inv[i], &d) / delta))
    }

    /// The walk from y until v > 0 (ICC) or the state lies well inside X (CC).
    pub fn plan(&self, y: &[f64; 5]) -> Option<Plan> {
        self.plan_after(y, &[])
    }

    /// The same walk, with its first impacts at the contacts `forced` (the first absolute, then
    /// steps) whether or not they land first (each must approach): a branch of a tree leaf whose
    /// drops the sample points missed (`super::tree`).
    pub fn plan_after(&self, y: &[f64; 5], forced: &[u64]) -> Option<Plan> {
        let (mut q, mut p) = self.start(y);
        let mut first = None;
        let mut steps = Vec::new();
        let mut near = Vec::new();
        for s in 0..self.max_prefix {
            // After an impact the landed contact is relabelled 0: k is the step j.
            let k = match forced.get(s) {
                Some(&k)
                    if (k as usize) < self.contacts.len() && dot(&self.contacts[k as usize], &p) < 0.0 =>
                {
                    k as usize
                }
                Some(_) => return None,
                None => self.next(&q, &p)?,
            };
            match first {
                None => first = Some(k),
                Some(_) => steps.push(k as u64),
            }
            (q, p) = self.impact(k, &q, &p);
            let first = first?;
            let y = self.in_x(&q, &p);
            near.push(y.is_some_and(|y| y.iter().all(|v| v.abs() <= self.cut_within)));
            if p[2] > 0.0 {
                return Some(Plan { first, steps, cc: false, cuts: Vec::new(), rest: None });
            }
            if let Some(r) = self.in_cone(&p) {
                return Some(Plan { first, steps, cc: true, cuts: Vec::new(), rest: Some(r) });
            }
            if let Some(y) = self.in_x(&q, &p)
                && y.iter().all(|v| v.abs() <= self.entry)
            {
                let len = steps.len() + 1;
                let cuts = match self.cut_every {
                    0 => Vec::new(),
                    m => (1..len)
                        .filter(|&c| (len - c).is_multiple_of(m) && near[c - 1])
                        .map(|c| c as u64)
                        .collect(),
                };
                return Some(Plan { first, steps, cc: true, cuts, rest: None });
            }
        }
        None
    }

    /// Whether the drop y follows `plan` (each impact the first to land) and ends where it says;
    /// the end: X's parameters over δ (CC), the direction of the velocity in the node's cone
    /// (CC by `rest`) or (v, 0, 0) (ICC).
    pub fn follow(&self, y: &[f64; 5], plan: &Plan) -> Option<[f64; 3]> {
        let (mut q, mut p) = self.start(y);
        for s in 0..=plan.steps.len() {
            let label = if s == 0 { plan.first } else { plan.steps[s - 1] as usize };
            if self.next(&q, &p)? != label {
                return None;
            }
            (q, p) = self.impact(label, &q, &p);
        }
        if !plan.cc {
            return (p[2] > 0.0).then_some([p[2], 0.0, 0.0]);
        }
        if let Some(r) = plan.rest {
            return (self.margin(r, &p) >= 0.0).then_some([p[0] / -p[2], p[1] / -p[2], 0.0]);
        }
        self.in_x(&q, &p).filter(|y| y.iter().all(|v| v.abs() <= 1.0))
    }
}

impl Walker {
    /// The first `impacts` impacts of the walk from y (evidence, for diagnostics): per impact the
    /// landed contact (absolute for the first, then the step), v after it, and X's parameters
    /// over δ when hc > 0 and v < 0.
    pub fn trace(&self, y: &[f64; 5], impacts: usize) -> Vec<(usize, f64, Option<[f64; 3]>)> {
        let (mut q, mut p) = self.start(y);
        let mut out = Vec::new();
        for _ in 0..impacts {
            let Some(k) = self.next(&q, &p) else { break };
            (q, p) = self.impact(k, &q, &p);
            out.push((k, p[2], self.in_x(&q, &p)));
        }
        out
    }
}
