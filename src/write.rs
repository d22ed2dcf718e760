//! The deterministic RON writers of every kind of file the tool writes (docs/certificate-format.md
//! §2, §10, §13, §14): one generator, contact, vector or derived point per line, in the strict
//! syntax. Untrusted: the kernel judges whatever a writer wrote on its own terms.

use chatter_kernel::certificate::{
    Body, Certificate, ConvexBodyText, ConvexCertificate, OrbitBody, OrbitCertificate, OrbitSet, Param,
    Triple,
};
use chatter_kernel::refute::{Refutation, Step};

/// A string in the strict syntax: quoted, without escapes. Characters the syntax does not allow
/// in strings (`"`, `\`, control characters) become spaces; they can only come from the free-text
/// `producer` field (numbers and names never contain them).
pub fn quoted(s: &str) -> String {
    let clean: String =
        s.chars().map(|c| if c == '"' || c == '\\' || c.is_control() { ' ' } else { c }).collect();
    format!("\"{clean}\"")
}

/// A parameter: `"x"` or `["lo", "hi"]`.
fn param(p: &Param) -> String {
    match p {
        Param::Point(x) => quoted(x),
        Param::Interval(a, b) => format!("[{}, {}]", quoted(a), quoted(b)),
    }
}

/// Writes a cone certificate as RON, one generator per line (deterministic).
pub fn write(c: &Certificate) -> String {
    let q = |s: &str| quoted(s);
    let Body::RegularPolygon { n, kappa, gamma } = &c.body;
    let mut out = String::new();
    out.push_str("Certificate(\n");
    out.push_str(&format!("    format: {},\n", q(&c.format)));
    out.push_str(&format!("    version: {},\n", c.version));
    out.push_str(&format!(
        "    body: RegularPolygon(n: {n}, kappa: {}, gamma: {}),\n",
        param(kappa),
        param(gamma)
    ));
    out.push_str("    coordinates: ContactVelocities,\n");
    out.push_str(&format!("    claim: {},\n", c.claim.name()));
    out.push_str("    cone: [\n");
    for g in &c.cone {
        let coords: Vec<String> = g.0.iter().map(|s| q(s)).collect();
        out.push_str(&format!("        ({}),\n", coords.join(", ")));
    }
    out.push_str("    ],\n");
    if let Some(b) = &c.time_to_rest_bound {
        out.push_str(&format!("    time_to_rest_bound: Some({}),\n", q(b)));
    }
    out.push_str(&format!("    producer: {},\n", q(&c.producer)));
    out.push_str(")\n");
    out
}

/// Writes a family certificate as RON (deterministic): one contact per line, one generator
/// per line, cones in order.
pub fn write_convex(c: &ConvexCertificate) -> String {
    let q = |s: &str| quoted(s);
    let mut out = String::new();
    out.push_str("Certificate(\n");
    out.push_str(&format!("    format: {},\n", q(&c.format)));
    out.push_str(&format!("    version: {},\n", c.version));
    write_convex_body(&c.body, &mut out);
    out.push_str("    coordinates: PaperVelocities,\n");
    out.push_str(&format!("    claim: {},\n", c.claim.name()));
    out.push_str("    cones: [\n");
    for cone in &c.cones {
        out.push_str("        [\n");
        for g in cone {
            let coords: Vec<String> = g.0.iter().map(|s| q(s)).collect();
            out.push_str(&format!("            ({}),\n", coords.join(", ")));
        }
        out.push_str("        ],\n");
    }
    out.push_str("    ],\n");
    out.push_str(&format!("    producer: {},\n", q(&c.producer)));
    out.push_str(")\n");
    out
}

/// The `body: ConvexPolygon(...)` field of a general body's file.
fn write_convex_body(body: &ConvexBodyText, out: &mut String) {
    let q = |s: &str| quoted(s);
    let ConvexBodyText::ConvexPolygon { contacts, inertia, gamma, inertia_tensor } = body;
    out.push_str("    body: ConvexPolygon(\n        contacts: [\n");
    for (x, y) in contacts {
        out.push_str(&format!("            ({}, {}),\n", q(x), q(y)));
    }
    out.push_str("        ],\n");
    out.push_str(&format!("        inertia: ({}, {}, {}),\n", q(&inertia.0), q(&inertia.1), q(&inertia.2)));
    out.push_str(&format!("        gamma: {},\n", param(gamma)));
    if let Some(t) = inertia_tensor {
        let six = [&t.0, &t.1, &t.2, &t.3, &t.4, &t.5].map(|x| q(x)).join(", ");
        out.push_str(&format!("        inertia_tensor: Some(({six})),\n"));
    }
    out.push_str("    ),\n");
}

/// RON text of a general body's time-to-rest certificate (docs/certificate-format.md §17).
pub fn write_rest_family(c: &chatter_kernel::rest_family::FamilyTimeToRest) -> String {
    let mut out = String::from("FamilyTimeToRest(\n");
    out.push_str(&format!("    format: {},\n    version: {},\n", quoted(&c.format), c.version));
    write_convex_body(&c.body, &mut out);
    out.push_str(&format!("    coordinates: PaperVelocities,\n    claim: {},\n", c.claim.name()));
    let entries: Vec<String> = c.entries.iter().map(ToString::to_string).collect();
    out.push_str(&format!(
        "    bound: {},\n    entries: [{}],\n    nodes: [\n",
        quoted(&c.bound),
        entries.join(", ")
    ));
    for node in &c.nodes {
        let cone: Vec<String> = node.cone.iter().map(|g| ron_tuple(&g.0)).collect();
        let next: Vec<String> = node.next.iter().map(|(j, s)| format!("({j}, {s})")).collect();
        out.push_str(&format!(
            "        (\n            contact: {},\n            cone: [{}],\n            weight: {},\n            numerator: {},\n            next: [{}],\n        ),\n",
            node.contact,
            cone.join(", "),
            ron_tuple(&node.weight.0),
            ron_tuple(&node.numerator.0),
            next.join(", ")
        ));
    }
    out.push_str(&format!("    ],\n    producer: {},\n)\n", quoted(&c.producer)));
    out
}

fn triple(t: &Triple) -> String {
    format!("({}, {}, {})", quoted(&t.0), quoted(&t.1), quoted(&t.2))
}

/// Writes an orbit certificate as RON (deterministic, one vector per line).
pub fn write_orbit(c: &OrbitCertificate) -> String {
    let q = |s: &str| quoted(s);
    let OrbitBody::RegularPolygon { n, kappa, gamma } = &c.body;
    let mut out = String::new();
    out.push_str("Certificate(\n");
    out.push_str(&format!("    format: {},\n", q(&c.format)));
    out.push_str(&format!("    version: {},\n", c.version));
    out.push_str(&format!("    body: RegularPolygon(n: {n}, kappa: {}, gamma: {}),\n", q(kappa), q(gamma)));
    out.push_str(&format!("    claim: {},\n", c.claim.name()));
    let steps: Vec<String> = c.pattern.iter().map(u64::to_string).collect();
    out.push_str(&format!("    pattern: [{}],\n", steps.join(", ")));
    match &c.set {
        OrbitSet::Parallelepiped { centre, axes, delta } => {
            out.push_str("    set: Parallelepiped(\n");
            out.push_str(&format!("        centre: {},\n", triple(centre)));
            out.push_str("        axes: (\n");
            for a in [&axes.0, &axes.1, &axes.2] {
                out.push_str(&format!("            {},\n", triple(a)));
            }
            out.push_str("        ),\n");
            out.push_str(&format!("        delta: {},\n", q(delta)));
            out.push_str("    ),\n");
        }
        OrbitSet::Box { lo, hi } => {
            out.push_str("    set: Box(\n");
            out.push_str(&format!("        lo: {},\n", triple(lo)));
            out.push_str(&format!("        hi: {},\n", triple(hi)));
            out.push_str("    ),\n");
        }
    }
    out.push_str(&format!("    subdivision: {},\n", c.subdivision));
    out.push_str(&format!("    rho: {},\n", q(&c.rho)));
    out.push_str(&format!("    lambda: {},\n", q(&c.lambda)));
    out.push_str(&format!("    period: {},\n", q(&c.period)));
    out.push_str(&format!("    producer: {},\n", q(&c.producer)));
    out.push_str(")\n");
    out
}

/// Writes a refutation in the strict syntax, one point per line (deterministic).
pub fn write_refutation(r: &Refutation) -> String {
    let Body::RegularPolygon { n, kappa, gamma } = &r.body;
    let mut out = String::from("Refutation(\n");
    out.push_str(&format!("    format: {},\n    version: {},\n", quoted(&r.format), r.version));
    out.push_str(&format!(
        "    body: RegularPolygon(n: {n}, kappa: {}, gamma: {}),\n",
        param(kappa),
        param(gamma)
    ));
    out.push_str(&format!(
        "    coordinates: ContactVelocities,\n    refutes: {},\n    points: [\n",
        r.refutes.name()
    ));
    for s in &r.points {
        let line = match s {
            Step::Seed { index } => format!("Seed(index: {index})"),
            Step::Combination { terms } => {
                let t: Vec<String> = terms.iter().map(|(i, c)| format!("({i}, {})", quoted(c))).collect();
                format!("Combination(terms: [{}])", t.join(", "))
            }
            Step::Image { step, of } => format!("Image(step: {step}, of: {of})"),
        };
        out.push_str(&format!("        {line},\n"));
    }
    out.push_str(&format!("    ],\n    producer: {},\n)\n", quoted(&r.producer)));
    out
}

/// The oldest version of the cone format that can express a certificate or its body
/// (docs/certificate-format.md §9, §12): a file is written with it.
pub trait VersionNeeded {
    /// 3 when a number is an element of a number field (its text names the generator c), 2 with a
    /// parameter interval, else 1.
    fn version_needed(&self) -> u64;
}

impl VersionNeeded for Body {
    fn version_needed(&self) -> u64 {
        let Body::RegularPolygon { kappa, gamma, .. } = self;
        if matches!(kappa, Param::Interval(..)) || matches!(gamma, Param::Interval(..)) { 2 } else { 1 }
    }
}

impl VersionNeeded for Certificate {
    fn version_needed(&self) -> u64 {
        let Body::RegularPolygon { kappa, gamma, .. } = &self.body;
        let params = kappa.texts().into_iter().chain(gamma.texts());
        let mut texts = params.chain(self.cone.iter().flat_map(|g| g.0.iter().map(String::as_str)));
        if texts.any(|t| t.contains(chatter_kernel::exact::GENERATOR)) {
            3
        } else {
            self.body.version_needed()
        }
    }
}

/// A tuple of canonical numbers, RON: `("a", "b", "c")`.
fn ron_tuple(xs: &[String]) -> String {
    format!("({})", xs.iter().map(|x| quoted(x)).collect::<Vec<_>>().join(", "))
}

/// Writes a time-to-rest certificate as RON, one node per block (deterministic;
/// docs/certificate-format.md §16).
pub fn write_rest(c: &chatter_kernel::rest::TimeToRest) -> String {
    let Body::RegularPolygon { n, kappa, gamma } = &c.body;
    let mut out = String::from("TimeToRest(\n");
    out.push_str(&format!("    format: {},\n    version: {},\n", quoted(&c.format), c.version));
    out.push_str(&format!(
        "    body: RegularPolygon(n: {n}, kappa: {}, gamma: {}),\n",
        param(kappa),
        param(gamma)
    ));
    out.push_str(&format!("    coordinates: ContactVelocities,\n    claim: {},\n", c.claim.name()));
    out.push_str(&format!("    bound: {},\n    nodes: [\n", quoted(&c.bound)));
    for node in &c.nodes {
        let cone: Vec<String> = node.cone.iter().map(|g| ron_tuple(&g.0)).collect();
        let next: Vec<String> = node.next.iter().map(|(j, s)| format!("({j}, {s})")).collect();
        // Version 1 has a scale c_r, version 2 a numerator a_r (docs/certificate-format.md §16).
        let own = match node.scale.is_empty() {
            true => format!("numerator: {}", ron_tuple(&node.numerator.0)),
            false => format!("scale: {}", quoted(&node.scale)),
        };
        out.push_str(&format!(
            "        (\n            cone: [{}],\n            weight: {},\n            {own},\n            next: [{}],\n        ),\n",
            cone.join(", "),
            ron_tuple(&node.weight.0),
            next.join(", ")
        ));
    }
    out.push_str(&format!("    ],\n    producer: {},\n)\n", quoted(&c.producer)));
    out
}
