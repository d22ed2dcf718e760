//! Tree leaves of basin certificates, version 2 (docs/certificate-format.md §15, issue 27): a leaf
//! lists, at each node, the contacts that may land next, each with what follows its impact. Rule
//! B4 at one drop, exactly: at every node of the tree the conditions the kernel shows over the
//! whole leaf (every listed contact approaches, every other one rises or lands after a listed
//! one), at every end its condition; then the drop's real motion, which must follow one path of
//! the tree (the soundness argument, checked at the drop), and its time to rest at that path's end.

use super::{End, all_up, ended, land, not_shown};
use crate::arith::Num;
use crate::regular::model::{Polygon, V3};
use crate::verdict::{Checked, Fail};

/// An impact of a tree leaf: a contact of its node's list (absolute at the root, relative to the
/// contact that landed last deeper down, as `steps`) and what follows its impact.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Impact {
    /// The contact.
    pub contact: u64,
    /// What follows.
    pub then: Then,
}

/// What follows an impact of a tree leaf: an end (v > 0, the state in X, the velocity in node
/// r's cone) or the list of the contacts that may land next.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Then {
    /// v > 0.
    Icc,
    /// The normalised state in the orbit certificate's X.
    Cc,
    /// The velocity in the cone K_r of node r of the time-to-rest certificate.
    Rest(u64),
    /// The contacts that may land next.
    Impacts(Vec<Impact>),
}

/// Rule B4 on a tree leaf at one drop (q0, p0): every contact up at the start, the conditions at
/// every node and end (`Walk::node`), then the real motion (`real`): the drop's time to rest
/// over h at its end (CC ends), `None` for an ICC end or a drop meeting a simultaneous impact.
/// `end` gives the end of `Icc`, `Cc` and `Rest(r)`.
pub fn follow_tree<'a>(
    body: &Polygon,
    q0: &V3,
    p0: &V3,
    next: &[Impact],
    end: &dyn Fn(&Then) -> End<'a>,
) -> Checked<Option<Num>> {
    all_up(body, q0)?;
    let walk = Walk { body, h: &q0[2], end };
    walk.node(q0, p0, &Num::int(&q0[2].field, 0), next, &mut vec![])?;
    real(&walk, q0, p0, next)
}

/// A failure at the node reached by the impacts `path`.
fn in_tree(path: &[u64], f: Fail) -> Fail {
    Fail { codes: f.codes, why: format!("in the tree after the impacts {path:?}: {}", f.why) }
}

struct Walk<'a, 'b> {
    body: &'b Polygon,
    h: &'b Num,
    end: &'b dyn Fn(&Then) -> End<'a>,
}

impl Walk<'_, '_> {
    /// The node with state (q, p) (after the impacts `path`, their flights summing to `time`) and
    /// list `next`: its conditions, then every child (an end's condition, or a node).
    fn node(&self, q: &V3, p: &V3, time: &Num, next: &[Impact], path: &mut Vec<u64>) -> Checked<()> {
        listed(self.body, q, p, next).map_err(|f| in_tree(path, f))?;
        for i in next {
            let (q1, p1, t) = land(self.body, q, p, i.contact as i64);
            let time = time + &t;
            path.push(i.contact);
            match &i.then {
                Then::Impacts(next) => self.node(&q1, &p1, &time, next, path)?,
                e => drop(ended(&q1, &p1, &time, self.h, (self.end)(e)).map_err(|f| in_tree(path, f))?),
            }
            path.pop();
        }
        Ok(())
    }
}

/// A node's conditions at (q, p) with list J = `next`: every j in J approaches (−u_j > 0); every
/// other contact m rises (u_m > 0) or lands after some j in J (h_m (−u_j) + h_j u_m > 0).
fn listed(body: &Polygon, q: &V3, p: &V3, next: &[Impact]) -> Checked<()> {
    if let Some(i) = next.iter().find(|i| !body.speed(i.contact as i64, p).is_negative()) {
        return Err(not_shown(format!("contact {} of the list does not approach", i.contact)));
    }
    for m in (0..body.n as i64).filter(|&m| next.iter().all(|i| i.contact as i64 != m)) {
        let (hm, um) = (body.speed(m, q), body.speed(m, p));
        let after = |i: &Impact| {
            let j = i.contact as i64;
            (&(&hm * &body.speed(j, p).neg()) + &(&body.speed(j, q) * &um)).is_positive()
        };
        if !um.is_positive() && !next.iter().any(after) {
            return Err(not_shown(format!("contact {m} may land before every contact of the list")));
        }
    }
    Ok(())
}

/// The contact that really lands first from (q, p): the smallest h_k/(−u_k) over the approaching
/// contacts; `None` when two land together (or none approaches).
fn first_landing(body: &Polygon, q: &V3, p: &V3) -> Option<i64> {
    let approaching = (0..body.n as i64).filter(|&k| body.speed(k, p).is_negative());
    let times: Vec<(i64, Num, Num)> =
        approaching.map(|k| (k, body.speed(k, q), body.speed(k, p).neg())).collect();
    // t_a < t_b iff h_a (−u_b) < h_b (−u_a), both −u positive.
    let before = |a: &(i64, Num, Num), b: &(i64, Num, Num)| &a.1 * &b.2 < &b.1 * &a.2;
    let first = times.iter().reduce(|a, b| if before(b, a) { b } else { a })?;
    times.iter().all(|b| b.0 == first.0 || before(first, b)).then_some(first.0)
}

/// The drop's real motion through the tree: at each node the contact that really lands first must
/// be in the list (else the certificate is false at this drop); at the end its condition, and the
/// time to rest over h. `None` for an ICC end or where two contacts land together.
fn real(walk: &Walk, q0: &V3, p0: &V3, mut next: &[Impact]) -> Checked<Option<Num>> {
    let (mut q, mut p, mut time, mut path) = (q0.clone(), p0.clone(), Num::int(&q0[2].field, 0), vec![]);
    loop {
        let Some(j) = first_landing(walk.body, &q, &p) else { return Ok(None) };
        let Some(i) = next.iter().find(|i| i.contact as i64 == j) else {
            let f = not_shown(format!("contact {j} lands first, and the list does not have it"));
            return Err(in_tree(&path, f));
        };
        let (q1, p1, t) = land(walk.body, &q, &p, j);
        (q, p, time) = (q1, p1, &time + &t);
        path.push(i.contact);
        match &i.then {
            Then::Impacts(below) => next = below,
            e => return ended(&q, &p, &time, walk.h, (walk.end)(e)).map_err(|f| in_tree(&path, f)),
        }
    }
}
