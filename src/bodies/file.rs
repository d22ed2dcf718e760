//! Body files (docs/bodies.md, docs/model.md §11): a general convex body in RON or JSON, every
//! number a string read exactly by [`parse_user_number`] (1/6, 0.01 = 1/100, 1e-2).
//!
//! ```text
//! (
//!     contacts: [("0.8", "0"), ("-0.4", "0.7"), ("-0.4", "-0.7")],  // (x, y) or (x, y, z)
//!     inertia: ("0.5", "0", "0.5"),   // J_xx, J_xy, J_yy per unit mass about the centre of mass
//!     // or the full tensor in URDF's order (then J_eff = J - b bᵀ / I_zz is used):
//!     // inertia_tensor: ("ixx", "ixy", "ixz", "iyy", "iyz", "izz"),
//!     // mass: "m",                      // optional: the tensor is the body's (m × length²)
//!     // inertia_origin: ("x", "y", "z"), // optional: the tensor is about this point
//!     centre: ("0", "0"),             // optional: the centre of mass, (x, y) or (x, y, z)
//!     gamma: "1/20",                  // optional: used when --gamma is not given
//! )
//! ```
//!
//! Contacts are listed counter-clockwise in any frame with z up; they are shifted by `centre`.
//! Contacts given with z must all have the same z (they lie in the floor's plane when the body
//! rests flat). `Some(..)` around optional values is allowed in RON.

use super::inertia::{Tensor, Vec3};
use crate::exact::{Q, parse_user_number};
use chatter_kernel::model::{Mat2, Vec2};
use serde::Deserialize;

/// A point as written: (x, y) or (x, y, z).
#[derive(Clone, Debug, Deserialize)]
#[serde(untagged)]
pub enum Point {
    Xyz(String, String, String),
    Xy(String, String),
}

/// A body file as written: numbers as strings.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BodyFile {
    pub contacts: Vec<Point>,
    #[serde(default)]
    pub inertia: Option<(String, String, String)>,
    #[serde(default)]
    pub inertia_tensor: Option<(String, String, String, String, String, String)>,
    #[serde(default)]
    pub mass: Option<String>,
    #[serde(default)]
    pub inertia_origin: Option<(String, String, String)>,
    #[serde(default)]
    pub centre: Option<Point>,
    #[serde(default)]
    pub gamma: Option<String>,
}

/// A body file read exactly: contacts relative to the centre, the planar model's J (J_eff when
/// a full tensor was given), the full tensor per unit mass about the centre if given, and gamma.
#[derive(Clone, Debug, PartialEq)]
pub struct BodyData {
    pub contacts: Vec<Vec2<Q>>,
    pub inertia: Mat2<Q>,
    pub tensor: Option<Tensor>,
    pub gamma: Option<Q>,
}

fn num(what: &str, s: &str) -> Result<Q, String> {
    parse_user_number(s).map_err(|e| format!("{what}: {e}"))
}

/// A point read exactly: (x, y) and z if given.
fn point(what: &str, p: &Point) -> Result<(Vec2<Q>, Option<Q>), String> {
    match p {
        Point::Xy(x, y) => Ok(([num(what, x)?, num(what, y)?], None)),
        Point::Xyz(x, y, z) => Ok(([num(what, x)?, num(what, y)?], Some(num(what, z)?))),
    }
}

/// The planar model's inertia from a full tensor per unit mass about the centre of mass: the
/// tensor is checked ([`Tensor::check`]) and reduced to J_eff (docs/model.md §11.1).
pub fn effective_inertia(what: &str, t: &Tensor) -> Result<Mat2<Q>, String> {
    t.check().map_err(|e| format!("{what}: {e}"))?;
    t.effective().ok_or_else(|| format!("{what}: I_zz = 0"))
}

impl BodyFile {
    /// Parses JSON (text starting with `{`) or RON (errors name the line and column).
    pub fn parse(text: &str) -> Result<BodyFile, String> {
        if text.trim_start().starts_with('{') {
            return serde_json::from_str(text).map_err(|e| format!("not a body file (JSON): {e}"));
        }
        let options =
            ron::Options::default().with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME);
        options.from_str(text).map_err(|e| format!("not a body file: {e}"))
    }

    /// The contacts read exactly (x, y), and their common z if they have one.
    fn contacts(&self) -> Result<(Vec<Vec2<Q>>, Option<Q>), String> {
        let read: Vec<(Vec2<Q>, Option<Q>)> = self
            .contacts
            .iter()
            .enumerate()
            .map(|(k, p)| point(&format!("contact {k}"), p))
            .collect::<Result<_, _>>()?;
        let zs: Vec<&Q> = read.iter().filter_map(|(_, z)| z.as_ref()).collect();
        if !zs.is_empty() && zs.len() != read.len() {
            return Err("contacts: give z for every contact or for none".into());
        }
        if let Some(k) = zs.iter().position(|z| *z != zs[0]) {
            return Err(format!(
                "contacts: contact {k} has z = {} but contact 0 has z = {}: the contacts must lie in one horizontal \
                 plane (the floor when the body rests flat)",
                zs[k], zs[0]
            ));
        }
        let z = zs.first().map(|z| (*z).clone());
        Ok((read.into_iter().map(|(xy, _)| xy).collect(), z))
    }

    /// The full tensor per unit mass about the centre `c` (if given), from `inertia_tensor`,
    /// `mass` and `inertia_origin`.
    fn tensor(&self, c: &Option<Vec3>) -> Result<Option<Tensor>, String> {
        let Some((a, b, cc, d, e, f)) = &self.inertia_tensor else {
            if self.mass.is_some() || self.inertia_origin.is_some() {
                return Err("mass and inertia_origin go with inertia_tensor".into());
            }
            return Ok(None);
        };
        let w = "inertia_tensor";
        let six = [num(w, a)?, num(w, b)?, num(w, cc)?, num(w, d)?, num(w, e)?, num(w, f)?];
        let mut t = Tensor::from_urdf(&six);
        if let Some(m) = &self.mass {
            let m = num("mass", m)?;
            if !crate::exact::Ring::is_positive(&m) {
                return Err(format!("mass: must be > 0 (found {m})"));
            }
            t = t.scaled(&(Q::int(1) / m));
        }
        if let Some((x, y, z)) = &self.inertia_origin {
            let w = "inertia_origin";
            let p = [num(w, x)?, num(w, y)?, num(w, z)?];
            let Some(c) = c else {
                return Err("inertia_origin needs the centre of mass in 3-D: centre: (x, y, z)".into());
            };
            t = t.to_centre(&std::array::from_fn(|k| &c[k] - &p[k]));
        }
        Ok(Some(t))
    }

    /// The numbers, read exactly, contacts shifted to the centre.
    pub fn data(&self) -> Result<BodyData, String> {
        let (centre, centre_z) = match &self.centre {
            None => ([Q::int(0), Q::int(0)], None),
            Some(p) => point("centre", p)?,
        };
        let (contacts, _) = self.contacts()?;
        let contacts = contacts.into_iter().map(|p| [&p[0] - &centre[0], &p[1] - &centre[1]]).collect();
        let centre3 = centre_z.map(|z| [centre[0].clone(), centre[1].clone(), z]);
        let tensor = self.tensor(&centre3)?;
        let inertia = match (&self.inertia, &tensor) {
            (Some(_), Some(_)) => {
                return Err("give inertia (J_xx, J_xy, J_yy) or inertia_tensor, not both".into());
            }
            (None, None) => {
                return Err("missing inertia (J_xx, J_xy, J_yy) or inertia_tensor (six numbers)".into());
            }
            (Some((a, b, c)), None) => {
                let (jxx, jxy, jyy) = (num("inertia", a)?, num("inertia", b)?, num("inertia", c)?);
                [[jxx, jxy.clone()], [jxy, jyy]]
            }
            (None, Some(t)) => effective_inertia("inertia_tensor", t)?,
        };
        let gamma = self.gamma.as_deref().map(|g| num("gamma", g)).transpose()?;
        Ok(BodyData { contacts, inertia, tensor, gamma })
    }
}
