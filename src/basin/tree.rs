//! Tree leaves' producer (untrusted; docs/basin-certificates.md §5): where one impact prefix
//! does not hold on a whole sub-box (two contacts land in either order in it), the prefixes of
//! sample drops spread over the sub-box are merged into a tree of impacts, which the kernel's
//! rule B4 for trees (`kernel/src/rules/branches.rs`) then checks on the whole sub-box.

use super::float::Plan;
use chatter_kernel::rules::basin::{Failure, LeafQuantity};
use chatter_kernel::syntax::basin::{Impact, Then};

/// How many times a contact the kernel finds left out is added to a tree.
pub const ROUNDS: usize = 8;

/// The impacts to force for the branch that the kernel's failure says is left out: the path
/// to the node, then the contact that neither rises nor lands later there.
pub fn left_out(failure: &Failure) -> Option<Vec<u64>> {
    let Failure::InTree { impacts, failure } = failure else { return None };
    let Failure::Leaf { quantity: LeafQuantity::Excluded { contact, .. }, .. } = **failure else {
        return None;
    };
    Some([impacts.clone(), vec![contact as u64]].concat())
}

/// The end of a plan as a tree's end: v > 0, or a node's cone; `None` for an end in X (whose
/// long prefixes need cuts, which trees do not have).
fn end(plan: &Plan) -> Option<Then> {
    match (plan.cc, plan.rest) {
        (false, _) => Some(Then::Icc),
        (true, Some(node)) => Some(Then::Rest { node: node as u64 }),
        (true, None) => None,
    }
}

/// The plans' impacts merged into one tree, each list sorted by contact; `None` when a plan ends
/// in X, when one ends where another goes on or ends otherwise, or when the ends are not all
/// alike (ICC or cones: rule B1).
pub fn merge(plans: &[Plan]) -> Option<Vec<Impact>> {
    let mut root = Vec::new();
    let mut icc = None;
    for plan in plans {
        let then = end(plan)?;
        let is_icc = then == Then::Icc;
        if *icc.get_or_insert(is_icc) != is_icc {
            return None;
        }
        let contacts: Vec<u64> =
            std::iter::once(plan.first as u64).chain(plan.steps.iter().copied()).collect();
        insert(&mut root, &contacts, then)?;
    }
    sort(&mut root);
    Some(root)
}

/// Adds the impacts `contacts` ending in `then` to the list `next`; `None` on a conflict.
fn insert(next: &mut Vec<Impact>, contacts: &[u64], then: Then) -> Option<()> {
    let (&c, rest) = contacts.split_first()?;
    let Some(at) = next.iter().position(|imp| imp.contact == c) else {
        next.push(Impact { contact: c, then: chain(rest, then) });
        return Some(());
    };
    match (&mut next[at].then, rest.is_empty()) {
        (Then::Impacts { next }, false) => insert(next, rest, then),
        (old, true) => (*old == then).then_some(()),
        (_, false) => None,
    }
}

/// The impacts `contacts` in a row, then `then`.
fn chain(contacts: &[u64], then: Then) -> Then {
    contacts.iter().rev().fold(then, |then, &c| Then::Impacts { next: vec![Impact { contact: c, then }] })
}

fn sort(next: &mut [Impact]) {
    next.sort_by_key(|imp| imp.contact);
    for imp in next {
        if let Then::Impacts { next } = &mut imp.then {
            sort(next);
        }
    }
}

/// Whether some list of the tree has more than one impact.
pub fn branches(next: &[Impact]) -> bool {
    next.len() > 1 || next.iter().any(|imp| matches!(&imp.then, Then::Impacts { next } if branches(next)))
}

/// The tree as RON text (docs/certificate-format.md §15).
pub fn write(next: &[Impact]) -> String {
    text(next, false)
}

/// The tree in the JSON twin (docs/certificate-format.md §11, §15).
pub fn write_json(next: &[Impact]) -> String {
    text(next, true)
}

/// The tree in RON, or in JSON where `json`: a unit variant is a string there, a variant with
/// fields an object, a struct an object with quoted keys.
fn text(next: &[Impact], json: bool) -> String {
    let variant = |name: &str, fields: Option<(&str, String)>| match (json, fields) {
        (false, None) => name.to_string(),
        (true, None) => format!("\"{name}\""),
        (false, Some((key, value))) => format!("{name}({key}: {value})"),
        (true, Some((key, value))) => format!("{{\"{name}\": {{\"{key}\": {value}}}}}"),
    };
    let items: Vec<String> = next
        .iter()
        .map(|imp| {
            let then = match &imp.then {
                Then::Icc => variant("Icc", None),
                Then::Cc => variant("Cc", None),
                Then::Rest { node } => variant("Rest", Some(("node", node.to_string()))),
                Then::Impacts { next } => variant("Impacts", Some(("next", text(next, json)))),
            };
            match json {
                false => format!("(contact: {}, then: {then})", imp.contact),
                true => format!("{{\"contact\": {}, \"then\": {then}}}", imp.contact),
            }
        })
        .collect();
    format!("[{}]", items.join(", "))
}

/// The first end of a tree, in list order (a tree the kernel accepts ends alike everywhere).
pub fn first_end(next: &[Impact]) -> Option<&Then> {
    match &next.first()?.then {
        Then::Impacts { next } => first_end(next),
        end => Some(end),
    }
}
