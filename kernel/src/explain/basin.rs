//! The words of the rejections of basin certificates.

use crate::basin::tree::TreeError;
use crate::orbit::map::Quantity;
use crate::reject::{KindLocus, Locus};
use crate::rules::basin::{Failure, LeafQuantity};

/// The words of a failure of a basin certificate (at a locus).
pub(super) fn words(f: &Failure, locus: &Locus) -> String {
    match f {
        Failure::OrbitBody => "the orbit certificate names another body (n, kappa or gamma)".into(),
        Failure::Unsupported(n) => format!("n = {n} is not modelled"),
        Failure::NoOrbit => "a Cc leaf, or cuts, need an orbit certificate (field `orbit`)".into(),
        Failure::Coordinates(l) => {
            format!("{l} coordinates; a corner of the box has 5 (omega_x, omega_y, phi_x, phi_y, h)")
        }
        Failure::Flat(4) => "the box is empty or flat in h, or its lower h is <= 0".into(),
        Failure::Flat(i) => format!("lo >= hi in coordinate {i}: the box is empty or flat"),
        Failure::First { first, n } => {
            format!("the first contact {first} is not in 0..{}", n.saturating_sub(1))
        }
        Failure::Step { step, n } => format!("step {step} is not in 1..{}", n.saturating_sub(1)),
        Failure::Tree(e) => tree(e),
        Failure::Cuts => "the cuts must be strictly increasing impact counts within the prefix".into(),
        Failure::NoRest => "a Rest leaf needs a time-to-rest certificate (field `rest`)".into(),
        Failure::RestBody => {
            "the time-to-rest certificate names another body (n, kappa or gamma, at a point)".into()
        }
        Failure::RestClaim(c) => {
            format!(
                "the time-to-rest certificate's claim is {c:?}; Rest leaves need CompleteChatterFromAllDown"
            )
        }
        Failure::Node { node, nodes } => {
            format!("node {node} is not a node of the time-to-rest certificate ({nodes} nodes)")
        }
        Failure::Leaf { quantity, wrong } => leaf(*quantity, *wrong, locus),
        Failure::TreeVersion => "a Tree leaf needs version 2 of the basin format".into(),
        Failure::EmptyBranch => "a list of impacts of the Tree leaf is empty".into(),
        Failure::RepeatedContact { contact } => {
            format!("contact {contact} is listed twice in one list of impacts of the Tree leaf")
        }
        Failure::MixedEnds => {
            "the Tree leaf ends in Icc on one path and in Cc or Rest on another: no single verdict".into()
        }
        Failure::InTree { impacts, failure } => {
            let path: Vec<String> = impacts.iter().map(u64::to_string).collect();
            let at = match path.is_empty() {
                true => "at the root of the tree".to_string(),
                false => format!("after the impacts {} of the tree", path.join(", ")),
            };
            format!("{at}: {}", words(failure, locus))
        }
    }
}

fn tree(e: &TreeError) -> String {
    match e {
        TreeError::Digit(l, p) => format!("leaf {l}: character {p} of its path is not a digit 0..9"),
        TreeError::Overlap(l) => format!("leaf {l} overlaps an earlier leaf"),
        TreeError::Axis(l) => {
            format!("leaf {l} halves another coordinate than an earlier path at the same node")
        }
        TreeError::Uncovered => "part of the box is in no leaf".into(),
    }
}

fn leaf(q: LeafQuantity, wrong: bool, locus: &Locus) -> String {
    let at = match locus {
        Locus::Kind(KindLocus::BasinLeaf { leaf, path }) => format!("leaf {leaf} (path \"{path}\")"),
        _ => "a leaf".into(),
    };
    let how = if wrong { "fails at the centre of" } else { "is not shown (interval bounds) on" };
    format!("{} {how} {at}", describe(q))
}

fn describe(q: LeafQuantity) -> String {
    match q {
        LeafQuantity::Start { contact } => {
            format!("contact {contact} is up before the first impact (h_{contact} > 0)")
        }
        LeafQuantity::Prefix(Quantity::Approach { step, contact }) => {
            format!("at impact {step}, the target contact {contact} approaches the floor")
        }
        LeafQuantity::Prefix(Quantity::Up { step, contact }) => {
            format!("at impact {step}, the target contact {contact} is up")
        }
        LeafQuantity::Prefix(Quantity::Clear { step, contact }) => {
            format!("at impact {step}, contact {contact} is still up when the target lands")
        }
        LeafQuantity::Prefix(other) | LeafQuantity::Entry(other) => match other {
            Quantity::PositionScale => "after the prefix, hc > 0".into(),
            Quantity::VelocityScale => "after the prefix, v < 0".into(),
            Quantity::Inside { coordinate, upper } => {
                format!(
                    "after the prefix, y_{coordinate} {} delta (the state lies in X)",
                    if upper { "<=" } else { ">= -" }
                )
            }
            _ => format!("{other:?}"),
        },
        LeafQuantity::Separates => "after the prefix, v > 0".into(),
        LeafQuantity::InCone { node, facet } => {
            format!(
                "after the prefix, the velocity is on the inner side of facet {facet} of node {node}'s cone"
            )
        }
        LeafQuantity::RestTime { node } => {
            format!("after the prefix, -b.p > 0 for node {node}'s weight b (the virtual time)")
        }
        LeafQuantity::Excluded { step, contact } => {
            format!("at impact {step}, contact {contact} (not listed) rises or lands after a listed contact")
        }
        LeafQuantity::Cut { impacts, quantity } => {
            format!("at the cut after {impacts} impacts, {}", describe(LeafQuantity::Entry(quantity)))
        }
    }
}
