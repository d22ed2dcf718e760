//! `chatter convert` (docs/certificate-format.md §11): a certificate or refutation from RON to
//! its JSON twin and back, losslessly. The file is read by the kernel's reader (strict syntax,
//! header, schema: the rules `chatter verify` applies before any arithmetic), then written by the
//! deterministic RON writer ([`crate::write`]) or by the JSON writer here, so RON -> JSON -> RON
//! gives the RON writer's text byte for byte. A legacy header (`"chatter-certificate"` version 4
//! or 5) is written in its current form. Content rules (numbers, body, cone) are not checked: an
//! invalid certificate converts to an equally invalid one.

use crate::write::{quoted, write, write_convex, write_orbit, write_refutation, write_rest};
use chatter_kernel::certificate::{
    Body, Certificate, ConvexBodyText, ConvexCertificate, Encoding, OrbitBody, OrbitCertificate, OrbitSet,
    Param, Rejection,
};
use chatter_kernel::refute::{Refutation, Step};
use chatter_kernel::rest::TimeToRest;
use chatter_kernel::rest_family::FamilyTimeToRest;
use chatter_kernel::syntax::basin::{BasinCertificate, LeafVerdict};
use chatter_kernel::syntax::{self, Kind, kind_of, schema};

/// The encoding to convert to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Target {
    /// The JSON twin (docs/certificate-format.md §11).
    Json,
    /// RON, as written by the kernel's writer.
    Ron,
}

/// A parameter: `"x"` or `["lo", "hi"]`.
fn param(p: &Param) -> String {
    match p {
        Param::Point(x) => quoted(x),
        Param::Interval(a, b) => format!("[{}, {}]", quoted(a), quoted(b)),
    }
}

/// The JSON lines of a list, one element per line (`[]` when empty).
fn list(items: &[String]) -> String {
    if items.is_empty() {
        return "[]".into();
    }
    let lines: Vec<String> = items.iter().map(|s| format!("        {s}")).collect();
    format!("[\n{}\n    ]", lines.join(",\n"))
}

/// The fields shared by certificates and refutations, up to and including `coordinates`.
fn head(format: &str, version: u64, body: &Body) -> String {
    let Body::RegularPolygon { n, kappa, gamma } = body;
    format!(
        "{{\n    \"format\": {},\n    \"version\": {version},\n    \"body\": {{\"RegularPolygon\": {{\"n\": {n}, \"kappa\": {}, \"gamma\": {}}}}},\n    \"coordinates\": \"ContactVelocities\",\n",
        quoted(format),
        param(kappa),
        param(gamma)
    )
}

/// Writes a certificate as its JSON twin, one generator per line (deterministic).
pub fn certificate_to_json(c: &Certificate) -> String {
    let cone: Vec<String> = c
        .cone
        .iter()
        .map(|g| format!("[{}]", g.0.iter().map(|s| quoted(s)).collect::<Vec<_>>().join(", ")))
        .collect();
    let bound = c
        .time_to_rest_bound
        .as_ref()
        .map_or(String::new(), |b| format!("    \"time_to_rest_bound\": {},\n", quoted(b)));
    format!(
        "{}    \"claim\": \"{}\",\n    \"cone\": {},\n{bound}    \"producer\": {}\n}}\n",
        head(&c.format, c.version, &c.body),
        c.claim.name(),
        list(&cone),
        quoted(&c.producer)
    )
}

/// Writes a refutation as its JSON twin, one point per line (deterministic).
pub fn refutation_to_json(r: &Refutation) -> String {
    let points: Vec<String> = r
        .points
        .iter()
        .map(|s| match s {
            Step::Seed { index } => format!("{{\"Seed\": {{\"index\": {index}}}}}"),
            Step::Combination { terms } => {
                let t: Vec<String> = terms.iter().map(|(i, c)| format!("[{i}, {}]", quoted(c))).collect();
                format!("{{\"Combination\": {{\"terms\": [{}]}}}}", t.join(", "))
            }
            Step::Image { step, of } => format!("{{\"Image\": {{\"step\": {step}, \"of\": {of}}}}}"),
        })
        .collect();
    format!(
        "{}    \"refutes\": \"{}\",\n    \"points\": {},\n    \"producer\": {}\n}}\n",
        head(&r.format, r.version, &r.body),
        r.refutes.name(),
        list(&points),
        quoted(&r.producer)
    )
}

/// Writes a time-to-rest certificate as its JSON twin, one node per line (docs/certificate-format.md
/// §16).
pub fn rest_to_json(c: &TimeToRest) -> String {
    let arr = |xs: &[String]| format!("[{}]", xs.iter().map(|x| quoted(x)).collect::<Vec<_>>().join(", "));
    let nodes: Vec<String> = c
        .nodes
        .iter()
        .map(|n| {
            let cone: Vec<String> = n.cone.iter().map(|g| arr(&g.0)).collect();
            let next: Vec<String> = n.next.iter().map(|(j, s)| format!("[{j}, {s}]")).collect();
            // Version 1 has a scale c_r, version 2 a numerator a_r (§16).
            let own = match n.scale.is_empty() {
                true => format!("\"numerator\": {}", arr(&n.numerator.0)),
                false => format!("\"scale\": {}", quoted(&n.scale)),
            };
            format!(
                "{{\"cone\": [{}], \"weight\": {}, {own}, \"next\": [{}]}}",
                cone.join(", "),
                arr(&n.weight.0),
                next.join(", ")
            )
        })
        .collect();
    format!(
        "{}    \"claim\": \"{}\",\n    \"bound\": {},\n    \"nodes\": {},\n    \"producer\": {}\n}}\n",
        head(&c.format, c.version, &c.body),
        c.claim.name(),
        quoted(&c.bound),
        list(&nodes),
        quoted(&c.producer)
    )
}

/// Writes a family certificate (a general convex body, docs/certificate-format.md §13) as its
/// JSON twin: one contact per line, each cone as a list of generators one per line.
pub fn convex_to_json(c: &ConvexCertificate) -> String {
    let tuple = |xs: &[&String]| format!("[{}]", xs.iter().map(|s| quoted(s)).collect::<Vec<_>>().join(", "));
    let cones: Vec<String> = c
        .cones
        .iter()
        .map(|k| {
            let gens: Vec<String> =
                k.iter().map(|g| format!("    {}", tuple(&g.0.iter().collect::<Vec<_>>()))).collect();
            list(&gens).replace("\n    ]", "\n        ]")
        })
        .collect();
    format!(
        "{{\n    \"format\": {},\n    \"version\": {},\n    \"body\": {},\n    \"coordinates\": \"PaperVelocities\",\n    \"claim\": \"{}\",\n    \"cones\": {},\n    \"producer\": {}\n}}\n",
        quoted(&c.format),
        c.version,
        convex_body_json(&c.body),
        c.claim.name(),
        list(&cones),
        quoted(&c.producer)
    )
}

/// The `body` of a general body's JSON twin: one contact per line.
fn convex_body_json(body: &ConvexBodyText) -> String {
    let ConvexBodyText::ConvexPolygon { contacts, inertia, gamma, inertia_tensor } = body;
    let tuple = |xs: &[&String]| format!("[{}]", xs.iter().map(|s| quoted(s)).collect::<Vec<_>>().join(", "));
    let contacts: Vec<String> = contacts.iter().map(|(x, y)| format!("    {}", tuple(&[x, y]))).collect();
    format!(
        "{{\"ConvexPolygon\": {{\n        \"contacts\": {},\n        \"inertia\": {},\n        \"gamma\": {}{}\n    }}}}",
        list(&contacts).replace("\n    ]", "\n        ]"),
        tuple(&[&inertia.0, &inertia.1, &inertia.2]),
        param(gamma),
        inertia_tensor.as_ref().map_or(String::new(), |t| {
            format!(",\n        \"inertia_tensor\": {}", tuple(&[&t.0, &t.1, &t.2, &t.3, &t.4, &t.5]))
        }),
    )
}

/// Writes a general body's time-to-rest certificate (docs/certificate-format.md §17) as its JSON
/// twin: one node per line.
pub fn rest_family_to_json(c: &FamilyTimeToRest) -> String {
    let arr = |xs: &[String]| format!("[{}]", xs.iter().map(|x| quoted(x)).collect::<Vec<_>>().join(", "));
    let node = |n: &chatter_kernel::rest_family::FamilyNode| {
        let cone: Vec<String> = n.cone.iter().map(|g| arr(&g.0)).collect();
        let next: Vec<String> = n.next.iter().map(|(j, s)| format!("[{j}, {s}]")).collect();
        format!(
            "{{\"contact\": {}, \"cone\": [{}], \"weight\": {}, \"numerator\": {}, \"next\": [{}]}}",
            n.contact,
            cone.join(", "),
            arr(&n.weight.0),
            arr(&n.numerator.0),
            next.join(", ")
        )
    };
    let entries: Vec<String> = c.entries.iter().map(ToString::to_string).collect();
    format!(
        "{{\n    \"format\": {},\n    \"version\": {},\n    \"body\": {},\n    \"coordinates\": \"PaperVelocities\",\n    \"claim\": \"{}\",\n    \"bound\": {},\n    \"entries\": [{}],\n    \"nodes\": {},\n    \"producer\": {}\n}}\n",
        quoted(&c.format),
        c.version,
        convex_body_json(&c.body),
        c.claim.name(),
        quoted(&c.bound),
        entries.join(", "),
        list(&c.nodes.iter().map(node).collect::<Vec<_>>()),
        quoted(&c.producer)
    )
}

/// Writes an orbit certificate (docs/certificate-format.md §14) as its JSON twin:
/// one vector per line, in the order of the RON writer's fields.
pub fn orbit_to_json(c: &OrbitCertificate) -> String {
    let OrbitBody::RegularPolygon { n, kappa, gamma } = &c.body;
    let triple =
        |t: &(String, String, String)| format!("[{}, {}, {}]", quoted(&t.0), quoted(&t.1), quoted(&t.2));
    let steps: Vec<String> = c.pattern.iter().map(u64::to_string).collect();
    let set = match &c.set {
        OrbitSet::Parallelepiped { centre, axes, delta } => format!(
            "{{\"Parallelepiped\": {{\n        \"centre\": {},\n        \"axes\": [\n            {},\n            {},\n            {}\n        ],\n        \"delta\": {}\n    }}}}",
            triple(centre),
            triple(&axes.0),
            triple(&axes.1),
            triple(&axes.2),
            quoted(delta)
        ),
        OrbitSet::Box { lo, hi } => format!(
            "{{\"Box\": {{\n        \"lo\": {},\n        \"hi\": {}\n    }}}}",
            triple(lo),
            triple(hi)
        ),
    };
    format!(
        "{{\n    \"format\": {},\n    \"version\": {},\n    \"body\": {{\"RegularPolygon\": {{\"n\": {n}, \"kappa\": {}, \"gamma\": {}}}}},\n    \"claim\": \"{}\",\n    \"pattern\": [{}],\n    \"set\": {set},\n    \"subdivision\": {},\n    \"rho\": {},\n    \"lambda\": {},\n    \"period\": {},\n    \"producer\": {}\n}}\n",
        quoted(&c.format),
        c.version,
        quoted(kappa),
        quoted(gamma),
        c.claim.name(),
        steps.join(", "),
        c.subdivision,
        quoted(&c.rho),
        quoted(&c.lambda),
        quoted(&c.period),
        quoted(&c.producer)
    )
}

/// Writes a basin certificate (docs/certificate-format.md §15) as its JSON twin: the embedded
/// orbit certificate as [`orbit_to_json`] writes it (indented; the member is absent when the RON
/// has none), one leaf per line, a leaf's verdict `"Undecided"` or `{"Cc": {...}}`.
pub fn basin_to_json(c: &BasinCertificate) -> String {
    let OrbitBody::RegularPolygon { n, kappa, gamma } = &c.body;
    let strings = |v: &[String]| v.iter().map(|s| quoted(s)).collect::<Vec<_>>().join(", ");
    let ints = |v: &[u64]| v.iter().map(u64::to_string).collect::<Vec<_>>().join(", ");
    let orbit = c.orbit.as_ref().map_or(String::new(), |o| {
        format!("    \"orbit\": {},\n", orbit_to_json(o).trim_end().replace('\n', "\n    "))
    });
    let rest = c.rest.as_ref().map_or(String::new(), |r| {
        format!("    \"rest\": {},\n", rest_to_json(r).trim_end().replace('\n', "\n    "))
    });
    let leaves: Vec<String> = c
        .leaves
        .iter()
        .map(|l| {
            let verdict = match &l.verdict {
                LeafVerdict::Cc { first, steps, cuts } | LeafVerdict::Icc { first, steps, cuts } => {
                    let name = if matches!(l.verdict, LeafVerdict::Cc { .. }) { "Cc" } else { "Icc" };
                    format!(
                        "{{\"{name}\": {{\"first\": {first}, \"steps\": [{}], \"cuts\": [{}]}}}}",
                        ints(steps),
                        ints(cuts)
                    )
                }
                LeafVerdict::Rest { first, steps, node } => {
                    format!(
                        "{{\"Rest\": {{\"first\": {first}, \"steps\": [{}], \"node\": {node}}}}}",
                        ints(steps)
                    )
                }
                LeafVerdict::Undecided => "\"Undecided\"".into(),
                LeafVerdict::Tree { next } => {
                    format!("{{\"Tree\": {{\"next\": {}}}}}", crate::basin::tree::write_json(next))
                }
            };
            format!("{{\"path\": {}, \"verdict\": {verdict}}}", quoted(&l.path))
        })
        .collect();
    format!(
        "{{\n    \"format\": {},\n    \"version\": {},\n    \"body\": {{\"RegularPolygon\": {{\"n\": {n}, \"kappa\": {}, \"gamma\": {}}}}},\n    \"drops\": {{\"lo\": [{}], \"hi\": [{}]}},\n{orbit}{rest}    \"leaves\": {},\n    \"producer\": {}\n}}\n",
        quoted(&c.format),
        c.version,
        quoted(kappa),
        quoted(gamma),
        strings(&c.drops.lo),
        strings(&c.drops.hi),
        list(&leaves),
        quoted(&c.producer)
    )
}

/// Converts certificate or refutation text in the encoding `from` to `target`; an error in words
/// (with the rejection code) when the text is not a readable certificate or refutation.
pub fn convert(text: &str, from: Encoding, target: Target) -> Result<String, String> {
    let unreadable = |r: Rejection| format!("not a readable certificate or refutation: {r}");
    let (kind, _) = kind_of(text, from, Kind::Cone).map_err(unreadable)?;
    let json = target == Target::Json;
    match kind {
        Kind::Proof => Err("a proof file (chatter-proof) has no JSON twin".into()),
        Kind::Basin => {
            let c: BasinCertificate = schema(text, from).map_err(unreadable)?;
            Ok(if json { basin_to_json(&c) } else { crate::basin::write_basin(&c) })
        }
        Kind::Rest => {
            let c: TimeToRest = schema(text, from).map_err(unreadable)?;
            Ok(if json { rest_to_json(&c) } else { write_rest(&c) })
        }
        Kind::RestFamily => {
            let c: FamilyTimeToRest = schema(text, from).map_err(unreadable)?;
            Ok(if json { rest_family_to_json(&c) } else { crate::write::write_rest_family(&c) })
        }
        Kind::Refutation => {
            let r: Refutation = schema(text, from).map_err(unreadable)?;
            Ok(if json { refutation_to_json(&r) } else { write_refutation(&r) })
        }
        Kind::Family => {
            let mut c: ConvexCertificate = schema(text, from).map_err(unreadable)?;
            if c.format != syntax::family::FORMAT {
                // The legacy header ("chatter-certificate", 4) is version 1 of the family format.
                (c.format, c.version) = (syntax::family::FORMAT.into(), syntax::family::VERSION);
            }
            Ok(if json { convex_to_json(&c) } else { write_convex(&c) })
        }
        Kind::Orbit => {
            let mut c: OrbitCertificate = schema(text, from).map_err(unreadable)?;
            (c.format, c.version) = (syntax::orbit::FORMAT.into(), syntax::orbit::VERSION);
            Ok(if json { orbit_to_json(&c) } else { write_orbit(&c) })
        }
        Kind::Cone => {
            let c: Certificate = schema(text, from).map_err(unreadable)?;
            Ok(if json { certificate_to_json(&c) } else { write(&c) })
        }
    }
}
