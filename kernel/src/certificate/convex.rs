//! Certificate format version 4: a general convex body (`ConvexPolygon`: contacts anywhere in
//! strictly convex position around the centre of mass, any horizontal inertia tensor) with a
//! family of cones K_0, ..., K_{n-1}, one per last contact (docs/model.md §11.5,
//! docs/certificate-format.md §13). The numbers stay text here, as in versions 1-3; the kernel
//! parses them with the canonical rules on each backend (`crate::check::convex`).

use super::write::quoted;
use super::{Claim, Encoding, FORMAT, Generator, Rejection};
use serde::{Deserialize, Serialize};

/// The version that introduced (and alone carries) the `ConvexPolygon` body.
pub const CONVEX_VERSION: u64 = 4;

/// A certificate for a general convex body (format version 4).
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename = "Certificate", deny_unknown_fields)]
pub struct ConvexCertificate {
    /// Always [`FORMAT`].
    pub format: String,
    /// Always [`CONVEX_VERSION`].
    pub version: u64,
    /// The falling body.
    pub body: ConvexBodyText,
    /// The coordinates of the generators.
    pub coordinates: ConvexCoordinates,
    /// What the certificate proves (docs/model.md §11.5: the analogues of §5's three claims).
    pub claim: Claim,
    /// The cones K_0, ..., K_{n-1}: `cones[i]` lists the generators of K_i, the velocities
    /// allowed right after an impact at contact i.
    pub cones: Vec<Vec<Generator>>,
    /// Informational only, never trusted.
    #[serde(default)]
    pub producer: String,
}

/// The body of a version-4 certificate (the only body form of that version).
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum ConvexBodyText {
    /// Contacts r_k = (x_k, y_k), counter-clockwise, in a horizontal frame centred on the
    /// vertical projection of the centre of mass; the horizontal inertia tensor per unit mass
    /// J = [[Jxx, Jxy], [Jxy, Jyy]] about the centre of mass (docs/model.md §11.1); gamma.
    ConvexPolygon {
        /// (x_k, y_k) for k = 0..n-1.
        contacts: Vec<(String, String)>,
        /// (Jxx, Jxy, Jyy).
        inertia: (String, String, String),
        /// Newton's coefficient of restitution.
        gamma: String,
    },
}

/// The coordinates of a version-4 certificate's generators.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum ConvexCoordinates {
    /// The paper's (omega_x, omega_y, v): horizontal angular velocity and the centre of mass's
    /// vertical velocity (docs/model.md §11.1).
    PaperVelocities,
}

impl ConvexCertificate {
    /// Every number of the file as text, in order (for the size limit).
    pub fn numbers(&self) -> impl Iterator<Item = &str> {
        let ConvexBodyText::ConvexPolygon { contacts, inertia, gamma } = &self.body;
        let body = contacts.iter().flat_map(|(x, y)| [x.as_str(), y.as_str()]).chain([
            inertia.0.as_str(),
            inertia.1.as_str(),
            inertia.2.as_str(),
            gamma.as_str(),
        ]);
        body.chain(self.cones.iter().flatten().flat_map(|g| g.0.iter().map(String::as_str)))
    }
}

/// Reads version-4 certificate text (RON in the strict syntax, or its JSON twin): the header
/// first (`format`, `version` = 4), then the full schema with unknown fields denied.
pub fn read_convex(text: &str, encoding: Encoding) -> Result<ConvexCertificate, Rejection> {
    let v = CONVEX_VERSION..=CONVEX_VERSION;
    match encoding {
        Encoding::Ron => {
            super::strict::check(text)?;
            #[derive(Deserialize)]
            #[serde(rename = "Certificate")]
            struct Header {
                format: Option<String>,
                version: Option<u64>,
            }
            let lenient =
                ron::Options::default().with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME);
            let header: Header = lenient.from_str(text).map_err(super::ron_error)?;
            super::check_header(header.format.as_deref(), header.version, FORMAT, v)?;
            ron::Options::default().from_str(text).map_err(super::ron_error)
        }
        Encoding::Json => super::read_json(text, FORMAT, v),
    }
}

/// The header's `version`, other fields ignored.
#[derive(Deserialize)]
#[serde(rename = "Certificate")]
pub(crate) struct VersionOnly {
    pub(crate) version: Option<u64>,
}

/// The `version` field of certificate text, read leniently (other fields ignored); `None` if
/// it cannot be read (the full reader then reports why).
pub fn version_of(text: &str, encoding: Encoding) -> Option<u64> {
    type Version = VersionOnly;
    match encoding {
        Encoding::Ron => {
            let lenient =
                ron::Options::default().with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME);
            lenient.from_str::<Version>(text).ok().and_then(|h| h.version)
        }
        Encoding::Json => serde_json::from_str::<Version>(text).ok().and_then(|h| h.version),
    }
}

/// Writes a version-4 certificate as RON (deterministic): one contact per line, one generator
/// per line, cones in order.
pub fn write_convex(c: &ConvexCertificate) -> String {
    let q = |s: &str| quoted(s);
    let ConvexBodyText::ConvexPolygon { contacts, inertia, gamma } = &c.body;
    let mut out = String::new();
    out.push_str("Certificate(\n");
    out.push_str(&format!("    format: {},\n", q(&c.format)));
    out.push_str(&format!("    version: {},\n", c.version));
    out.push_str("    body: ConvexPolygon(\n");
    out.push_str("        contacts: [\n");
    for (x, y) in contacts {
        out.push_str(&format!("            ({}, {}),\n", q(x), q(y)));
    }
    out.push_str("        ],\n");
    out.push_str(&format!("        inertia: ({}, {}, {}),\n", q(&inertia.0), q(&inertia.1), q(&inertia.2)));
    out.push_str(&format!("        gamma: {},\n", q(gamma)));
    out.push_str("    ),\n");
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
