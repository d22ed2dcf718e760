//! The schema of family certificates (docs/certificate-format.md §13): a general convex body
//! (`ConvexPolygon`: contacts in strictly convex position around the centre of mass, any
//! horizontal inertia tensor) with a family of cones K_0, ..., K_{n-1}, one per last contact
//! (docs/model.md §11.5). Format `"chatter-family-certificate"`, version 1 (2 when gamma is an interval); the legacy header
//! `("chatter-certificate", 4)` is read as an alias. The numbers stay text here.

use crate::syntax::cone::{Claim, Generator, Param};
use crate::syntax::{Kind, Schema};
use serde::Deserialize;

/// Value of the `format` field.
pub const FORMAT: &str = "chatter-family-certificate";
/// The version of a certificate for one gamma.
pub const VERSION: u64 = 1;
/// The version that may give gamma as a closed interval (docs/certificate-format.md §13).
pub const INTERVAL_VERSION: u64 = 2;

/// A family certificate of a general convex body.
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
#[serde(rename = "Certificate", deny_unknown_fields)]
pub struct ConvexCertificate {
    /// [`FORMAT`] (or the legacy `"chatter-certificate"`).
    pub format: String,
    /// [`VERSION`] or [`INTERVAL_VERSION`] (4 with the legacy format).
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

/// The body of a family certificate.
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
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
        /// Newton's coefficient of restitution: a number, or a closed interval (version 2).
        gamma: Param,
        /// Optional: the full inertia tensor per unit mass about the centre of mass, in URDF's
        /// order (Ixx, Ixy, Ixz, Iyy, Iyz, Izz), of which `inertia` must be J_eff (rule K0,
        /// docs/model.md Proposition 11.0).
        #[serde(default)]
        inertia_tensor: Option<TensorText>,
    },
}

/// Six canonical numbers: a full inertia tensor in URDF's order (Ixx, Ixy, Ixz, Iyy, Iyz, Izz).
pub type TensorText = (String, String, String, String, String, String);

/// The coordinates of a family certificate's generators.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
pub enum ConvexCoordinates {
    /// The paper's (omega_x, omega_y, v): horizontal angular velocity and the centre of mass's
    /// vertical velocity (docs/model.md §11.1).
    PaperVelocities,
}

impl Schema for ConvexCertificate {
    const KIND: Kind = Kind::Family;
}

impl ConvexCertificate {
    /// Every number of the file as text, in order (for `max-total-digits`).
    pub fn numbers(&self) -> impl Iterator<Item = &str> {
        self.body.numbers().chain(self.cones.iter().flatten().flat_map(|g| g.0.iter().map(String::as_str)))
    }
}

impl ConvexBodyText {
    /// Every number of the body as text, in order: contacts, inertia, gamma, the tensor.
    pub fn numbers(&self) -> impl Iterator<Item = &str> {
        let ConvexBodyText::ConvexPolygon { contacts, inertia, gamma, inertia_tensor } = self;
        let body = contacts.iter().flat_map(|(x, y)| [x.as_str(), y.as_str()]).chain([
            inertia.0.as_str(),
            inertia.1.as_str(),
            inertia.2.as_str(),
        ]);
        let tensor =
            inertia_tensor.iter().flat_map(|t| [&t.0, &t.1, &t.2, &t.3, &t.4, &t.5].map(String::as_str));
        body.chain(gamma.texts()).chain(tensor)
    }
}
