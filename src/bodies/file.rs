//! Body files (docs/bodies.md, docs/model.md §11): a general convex body in RON, every number a
//! string read exactly by [`parse_user_number`] (1/6, 0.01 = 1/100, 1e-2).
//!
//! ```text
//! (
//!     contacts: [("0.8", "0"), ("-0.4", "0.7"), ("-0.4", "-0.7")],
//!     inertia: ("0.5", "0", "0.5"),   // J_xx, J_xy, J_yy per unit mass, about the centre of mass
//!     centre: Some(("0", "0")),       // optional: the centre of mass's projection (default 0, 0)
//!     gamma: Some("1/20"),            // optional: else --gamma
//! )
//! ```
//!
//! Contacts are listed counter-clockwise in any horizontal frame; they are shifted by `centre`.

use crate::exact::{Q, parse_user_number};
use chatter_kernel::model::{Mat2, Vec2};
use serde::Deserialize;

/// A body file as written: numbers as strings.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BodyFile {
    pub contacts: Vec<(String, String)>,
    pub inertia: (String, String, String),
    #[serde(default)]
    pub centre: Option<(String, String)>,
    #[serde(default)]
    pub gamma: Option<String>,
}

/// A body file read exactly: contacts relative to the centre, J, and gamma if given.
#[derive(Clone, Debug, PartialEq)]
pub struct BodyData {
    pub contacts: Vec<Vec2<Q>>,
    pub inertia: Mat2<Q>,
    pub gamma: Option<Q>,
}

fn num(what: &str, s: &str) -> Result<Q, String> {
    parse_user_number(s).map_err(|e| format!("{what}: {e}"))
}

impl BodyFile {
    /// Parses RON text (errors name the line and column).
    pub fn parse(text: &str) -> Result<BodyFile, String> {
        ron::from_str(text).map_err(|e| format!("not a body file: {e}"))
    }

    /// The numbers, read exactly, contacts shifted to the centre.
    pub fn data(&self) -> Result<BodyData, String> {
        let centre = match &self.centre {
            None => [Q::int(0), Q::int(0)],
            Some((x, y)) => [num("centre", x)?, num("centre", y)?],
        };
        let contacts = self
            .contacts
            .iter()
            .enumerate()
            .map(|(k, (x, y))| {
                let what = format!("contact {k}");
                Ok([&num(&what, x)? - &centre[0], &num(&what, y)? - &centre[1]])
            })
            .collect::<Result<Vec<_>, String>>()?;
        let (a, b, c) = &self.inertia;
        let (jxx, jxy, jyy) = (num("inertia", a)?, num("inertia", b)?, num("inertia", c)?);
        let gamma = self.gamma.as_deref().map(|g| num("gamma", g)).transpose()?;
        Ok(BodyData { contacts, inertia: [[jxx, jxy.clone()], [jxy, jyy]], gamma })
    }
}
