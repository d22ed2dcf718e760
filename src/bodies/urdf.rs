//! URDF body files (docs/bodies.md "URDF"): one link's `<inertial>` block (origin xyz, mass,
//! inertia ixx..izz about that origin) and contacts at the origins of fixed joints whose parent
//! is that link, named with `--contacts NAME,NAME,...` (a joint's or its child link's name; a
//! name ending in `*` takes every such joint whose name or child starts with the rest, ordered
//! counter-clockwise about the centre of mass exactly). The link's frame must have z up when the
//! body rests flat; rotations (`rpy`) of the inertial frame are refused (they would make the tensor
//! irrational), joint rotations do not matter (only the frames' origins are contacts).

use super::file::{BodyFile, Point};
use crate::exact::{Q, Ring, parse_user_number};
use roxmltree::{Document, Node};
use std::cmp::Ordering;

/// Whether `text` looks like URDF (XML) rather than RON or JSON.
pub fn is_urdf(text: &str) -> bool {
    let t = text.trim_start();
    t.starts_with("<?xml") || t.starts_with("<robot")
}

fn numbers(what: &str, s: &str, count: usize) -> Result<Vec<Q>, String> {
    let v: Vec<Q> = s
        .split_whitespace()
        .map(|x| parse_user_number(x).map_err(|e| format!("{what}: {e}")))
        .collect::<Result<_, _>>()?;
    if v.len() != count {
        return Err(format!("{what}: expected {count} numbers, found {}", v.len()));
    }
    Ok(v)
}

fn child<'a, 'i>(n: Node<'a, 'i>, tag: &str) -> Option<Node<'a, 'i>> {
    n.children().find(|c| c.has_tag_name(tag))
}

/// An `<origin xyz=...>` (default 0 0 0), with `rpy` refused unless all zero when `no_rpy`.
fn origin(n: Option<Node>, what: &str, no_rpy: bool) -> Result<[Q; 3], String> {
    let Some(o) = n else { return Ok([Q::int(0), Q::int(0), Q::int(0)]) };
    let rpy = if no_rpy { o.attribute("rpy") } else { None };
    if let Some(rpy) = rpy
        && numbers(&format!("{what} rpy"), rpy, 3)?.iter().any(|x| !x.is_zero())
    {
        return Err(format!(
            "{what}: a rotated inertial frame (rpy != 0) is not supported: give the tensor in the link's frame"
        ));
    }
    let v = numbers(&format!("{what} xyz"), o.attribute("xyz").unwrap_or("0 0 0"), 3)?;
    Ok([v[0].clone(), v[1].clone(), v[2].clone()])
}

/// The link carrying the body's `<inertial>`: the only one with an inertial of positive mass.
fn body_link<'a, 'i>(robot: Node<'a, 'i>) -> Result<Node<'a, 'i>, String> {
    let massive: Vec<Node> = robot
        .children()
        .filter(|l| l.has_tag_name("link"))
        .filter(|l| {
            let m = child(*l, "inertial").and_then(|i| child(i, "mass")).and_then(|m| m.attribute("value"));
            m.and_then(|v| parse_user_number(v).ok()).is_some_and(|m| m.is_positive())
        })
        .collect();
    match massive.as_slice() {
        [l] => Ok(*l),
        [] => Err("no link has an <inertial> with a mass > 0".into()),
        _ => Err(format!(
            "{} links have mass ({}): combine them into one link's <inertial> (only one rigid body is supported)",
            massive.len(),
            massive.iter().filter_map(|l| l.attribute("name")).collect::<Vec<_>>().join(", ")
        )),
    }
}

/// A contact: its name and position in the body link's frame.
struct Frame {
    name: String,
    child: String,
    at: [Q; 3],
}

/// The fixed joints whose parent is `link`.
fn fixed_frames(robot: Node, link: &str) -> Result<Vec<Frame>, String> {
    let mut out = vec![];
    for j in robot.children().filter(|j| j.has_tag_name("joint")) {
        let parent = child(j, "parent").and_then(|p| p.attribute("link"));
        if parent != Some(link) || j.attribute("type") != Some("fixed") {
            continue;
        }
        let name = j.attribute("name").unwrap_or("").to_string();
        let child_link = child(j, "child").and_then(|c| c.attribute("link")).unwrap_or("").to_string();
        let at = origin(child(j, "origin"), &format!("joint {name}"), false)?;
        out.push(Frame { name, child: child_link, at });
    }
    Ok(out)
}

/// Counter-clockwise order of (x, y) about the origin, exactly: by half-plane, then by cross product.
fn ccw(a: &[Q; 2], b: &[Q; 2]) -> Ordering {
    let upper = |p: &[Q; 2]| p[1].is_positive() || (p[1].is_zero() && !p[0].is_negative());
    match (upper(a), upper(b)) {
        (true, false) => Ordering::Less,
        (false, true) => Ordering::Greater,
        _ => (&b[0] * &a[1]).cmp(&(&a[0] * &b[1])),
    }
}

/// The contacts named by `names` (in the order given, or counter-clockwise for a `prefix*`).
fn select(frames: &[Frame], names: &[String], centre: &[Q; 3]) -> Result<Vec<[Q; 3]>, String> {
    let mut out = vec![];
    for n in names {
        let n = n.trim();
        if let Some(prefix) = n.strip_suffix('*') {
            let mut hits: Vec<&Frame> =
                frames.iter().filter(|f| f.name.starts_with(prefix) || f.child.starts_with(prefix)).collect();
            if hits.is_empty() {
                return Err(format!("--contacts {n}: no fixed joint of the body link matches"));
            }
            let rel = |f: &Frame| [&f.at[0] - &centre[0], &f.at[1] - &centre[1]];
            hits.sort_by(|a, b| ccw(&rel(a), &rel(b)));
            out.extend(hits.iter().map(|f| f.at.clone()));
        } else {
            let f = frames.iter().find(|f| f.name == n || f.child == n).ok_or_else(|| {
                let known: Vec<&str> = frames.iter().map(|f| f.name.as_str()).collect();
                format!(
                    "--contacts: no fixed joint of the body link is named {n:?} (fixed joints: {})",
                    known.join(", ")
                )
            })?;
            out.push(f.at.clone());
        }
    }
    Ok(out)
}

/// A URDF text as a body file: the body link's inertial (mass, tensor about its origin, the
/// centre of mass) and the contacts named by `contacts`.
pub fn read(text: &str, contacts: &[String]) -> Result<BodyFile, String> {
    let doc = Document::parse(text).map_err(|e| format!("not URDF (XML): {e}"))?;
    let robot = doc.root_element();
    if !robot.has_tag_name("robot") {
        return Err("not URDF: the root element is not <robot>".into());
    }
    let link = body_link(robot)?;
    let link_name = link.attribute("name").unwrap_or("");
    let inertial = child(link, "inertial").ok_or("the body link has no <inertial>")?;
    let centre = origin(child(inertial, "origin"), &format!("link {link_name} inertial origin"), true)?;
    let mass =
        child(inertial, "mass").and_then(|m| m.attribute("value")).ok_or("<inertial> has no <mass value>")?;
    let i = child(inertial, "inertia").ok_or("<inertial> has no <inertia>")?;
    let attr = |k: &str| i.attribute(k).map(str::to_string).ok_or(format!("<inertia> has no {k}"));
    let tensor = (attr("ixx")?, attr("ixy")?, attr("ixz")?, attr("iyy")?, attr("iyz")?, attr("izz")?);
    if contacts.is_empty() {
        return Err(
            "a URDF body needs --contacts NAME,NAME,... (fixed joints of the body link, or PREFIX*)".into()
        );
    }
    let frames = fixed_frames(robot, link_name)?;
    let pts = select(&frames, contacts, &centre)?;
    let s = |q: &Q| q.to_string();
    Ok(BodyFile {
        contacts: pts.iter().map(|p| Point::Xyz(s(&p[0]), s(&p[1]), s(&p[2]))).collect(),
        inertia: None,
        inertia_tensor: Some(tensor),
        mass: Some(mass.to_string()),
        // URDF's inertia is about the inertial origin, which is the centre of mass.
        inertia_origin: None,
        centre: Some(Point::Xyz(s(&centre[0]), s(&centre[1]), s(&centre[2]))),
        gamma: None,
    })
}
