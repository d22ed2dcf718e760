//! Tree leaves of basin certificates, version 2 (docs/certificate-format.md §15, issue 27): the
//! schema of `Tree(next: [(contact: INT, then: Icc | Cc | Rest(node: INT) | Impacts(next: [...]))])`
//! (RON, and its JSON twin) and rule B1 on a tree, in the kernel's order.

use super::{MAX_PREFIX, out_of_range, too_large};
use crate::basin::tree::{Impact, Then};
use crate::read::Value;
use crate::read::schema::{integer, list, variant, walk};
use crate::verdict::{Checked, Fail};

/// The most impacts of one tree (`max-basin-tree`).
const MAX_TREE: usize = 4096;

/// The fields of `Tree(next: [...])`: its root list.
pub(super) fn read_tree(fields: &Value) -> Checked<Vec<Impact>> {
    let mut next = vec![];
    walk(fields, &[("next", true)], |_, v| {
        next = impacts(v)?;
        Ok(())
    })?;
    Ok(next)
}

fn impacts(v: &Value) -> Checked<Vec<Impact>> {
    list(v)?.iter().map(impact).collect()
}

/// `(contact: INT, then: THEN)`.
fn impact(v: &Value) -> Checked<Impact> {
    let mut out = Impact { contact: 0, then: Then::Icc };
    walk(v, &[("contact", true), ("then", true)], |f, v| {
        if f == "contact" {
            out.contact = integer(v)?;
        } else {
            out.then = then(v)?;
        }
        Ok(())
    })?;
    Ok(out)
}

/// `Icc | Cc | Rest(node: INT) | Impacts(next: [...])`.
fn then(v: &Value) -> Checked<Then> {
    match variant(v)? {
        ("Icc", None) => Ok(Then::Icc),
        ("Cc", None) => Ok(Then::Cc),
        ("Rest", Some(fields)) => {
            let mut node = 0;
            walk(fields, &[("node", true)], |_, v| {
                node = integer(v)?;
                Ok(())
            })?;
            Ok(Then::Rest(node))
        }
        ("Impacts", Some(fields)) => read_tree(fields).map(Then::Impacts),
        ("Icc" | "Cc" | "Rest" | "Impacts", _) => {
            Err(Fail::new("syntax", "an impact's `then` has the wrong form"))
        }
        (name, _) => Err(Fail::new("unknown-variant", format!("unknown end `{name}`"))),
    }
}

/// Whether a tree (with no mixed ends, rule B1) is an ICC leaf: its first end is `Icc`.
pub(super) fn icc(next: &[Impact]) -> bool {
    match next.first().map(|i| &i.then) {
        Some(Then::Impacts(below)) => icc(below),
        end => end == Some(&Then::Icc),
    }
}

/// Whether a tree has a `Rest` end.
pub(super) fn has_rest(next: &[Impact]) -> bool {
    next.iter().any(|i| match &i.then {
        Then::Rest(_) => true,
        Then::Impacts(below) => has_rest(below),
        _ => false,
    })
}

/// What rule B1 needs to know of the file for a tree leaf.
pub(super) struct Context {
    /// The file's version (trees need 2).
    pub version: u64,
    /// n.
    pub n: u64,
    /// Whether the file has an orbit certificate.
    pub orbit: bool,
    /// The time-to-rest certificate's number of nodes, if it has one.
    pub rest_nodes: Option<usize>,
}

/// Rule B1 on tree leaf i: the version, then a depth-first pre-order walk of its lists, then
/// mixed ends.
pub(super) fn tree_rules(i: usize, next: &[Impact], c: &Context) -> Checked<()> {
    if c.version < 2 {
        return Err(Fail::new("unsupported-version", "version: a tree leaf needs version 2"));
    }
    let mut walk = Walk { i, c, count: 0, ends: [false; 2] };
    walk.list(next, 0)?;
    if walk.ends == [true; 2] {
        return Err(out_of_range(format!(
            "leaves[{i}].verdict: the tree's ends are Icc and Cc/Rest (mixed ends)"
        )));
    }
    Ok(())
}

/// The walk's state: the impacts counted so far, and which ends were seen (ICC, CC).
struct Walk<'a> {
    i: usize,
    c: &'a Context,
    count: usize,
    ends: [bool; 2],
}

impl Walk<'_> {
    /// A list at depth d: (1) not empty, (2) the tree's impacts so far within `max-basin-tree`,
    /// (3) d + 1 within `max-basin-prefix`, (4) each contact in range, then not repeated, (5) each
    /// `then`.
    fn list(&mut self, next: &[Impact], depth: usize) -> Checked<()> {
        let i = self.i;
        if next.is_empty() {
            return Err(out_of_range(format!("leaves[{i}].verdict: a list of the tree is empty")));
        }
        if self.count + next.len() > MAX_TREE {
            return Err(too_large("max-basin-tree: a tree with more impacts than max-basin-tree"));
        }
        self.count += next.len();
        if depth + 1 > MAX_PREFIX {
            return Err(too_large("max-basin-prefix: a path of the tree longer than max-basin-prefix"));
        }
        for (k, imp) in next.iter().enumerate() {
            self.contact(imp.contact, depth)?;
            if next[..k].iter().any(|e| e.contact == imp.contact) {
                let why = format!("leaves[{i}].verdict: contact {} is listed twice", imp.contact);
                return Err(out_of_range(why));
            }
        }
        for imp in next {
            match &imp.then {
                Then::Impacts(below) => self.list(below, depth + 1)?,
                end => self.end(end)?,
            }
        }
        Ok(())
    }

    /// A contact's range: 0..n-1 at the root (path `first`), 1..n-1 deeper (path `steps`).
    fn contact(&self, contact: u64, depth: usize) -> Checked<()> {
        let (i, n) = (self.i, self.c.n);
        if depth == 0 && contact >= n {
            return Err(out_of_range(format!("leaves[{i}].first: first contact {contact} of n = {n}")));
        }
        if depth > 0 && (contact == 0 || contact >= n) {
            return Err(out_of_range(format!("leaves[{i}].steps: step {contact} of n = {n}")));
        }
        Ok(())
    }

    /// An end: `Cc` needs an orbit certificate, `Rest(r)` a time-to-rest certificate with node r.
    fn end(&mut self, end: &Then) -> Checked<()> {
        let i = self.i;
        match end {
            Then::Cc if !self.c.orbit => {
                return Err(out_of_range(format!("leaves[{i}]: a Cc end without an orbit certificate")));
            }
            Then::Rest(r) => {
                let Some(count) = self.c.rest_nodes else {
                    let why = format!("leaves[{i}]: a Rest end without a time-to-rest certificate");
                    return Err(out_of_range(why));
                };
                if usize::try_from(*r).map_or(true, |r| r >= count) {
                    return Err(out_of_range(format!(
                        "leaves[{i}].node: a Rest end names node {r} of {count}"
                    )));
                }
            }
            _ => {}
        }
        self.ends[usize::from(*end != Then::Icc)] = true;
        Ok(())
    }
}
