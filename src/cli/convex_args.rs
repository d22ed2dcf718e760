//! The general-body options of `simulate` and `classify` (docs/model.md §11, docs/bodies.md):
//! `--rectangle A,B`, `--box A,B,C`, `--polygon "x0,y0 x1,y1 ..."` with `--plate` or with
//! `--inertia Jxx,Jxy,Jyy` or the full tensor `--inertia Ixx,Ixy,Ixz,Iyy,Iyz,Izz` (then the
//! planar model uses J_eff, docs/model.md §11.1) (and `--centre X,Y`), and `--body FILE`. The raw strings are read
//! exactly here; the body itself is validated by the kernel ([`ConvexBody::new`]), whose typed
//! errors become messages naming the option.

use crate::bodies::convex::{polygon_plate, rectangle_plate, uniform_box};
use crate::bodies::file::{BodyFile, effective_inertia};
use crate::bodies::general::{GeneralEntry, general_catalogue};
use crate::bodies::inertia::Tensor;
use crate::bodies::urdf;
use crate::exact::{Q, Ring, parse_user_number};
use chatter_kernel::model::{ConvexBody, ConvexBodyError, Mat2, Vec2};
use clap::Args;
use std::path::Path;

/// Raw general-body options.
#[derive(Args, Debug, Clone, Default)]
pub struct ConvexArgs {
    /// A uniform rectangular plate A x B (general body, docs/model.md §11).
    #[arg(long, value_name = "A,B", allow_hyphen_values = true, conflicts_with_all = ["n", "kappa"])]
    pub rectangle: Option<String>,
    /// A uniform box A x B x C standing on its A x B face (a phone, a brick).
    #[arg(long = "box", value_name = "A,B,C", allow_hyphen_values = true, conflicts_with_all = ["n", "kappa"])]
    pub box_: Option<String>,
    /// Contacts of a convex polygon, counter-clockwise, "x0,y0 x1,y1 ..."; needs --plate or --inertia.
    #[arg(long, value_name = "\"X0,Y0 X1,Y1 ...\"", allow_hyphen_values = true, conflicts_with_all = ["n", "kappa"])]
    pub polygon: Option<String>,
    /// With --polygon: the uniform flat plate of that polygon (shifted to its centroid).
    #[arg(long)]
    pub plate: bool,
    /// With --polygon: the inertia per unit mass about the centre of mass, either its horizontal
    /// block JXX,JXY,JYY or the full tensor IXX,IXY,IXZ,IYY,IYZ,IZZ (URDF's order; checked
    /// positive definite with principal moments obeying the triangle inequalities; the model uses
    /// J_eff = J - b b^T / IZZ, b = (IXZ, IYZ), exact at first order, docs/model.md §11.1).
    #[arg(long, value_name = "JXX,JXY,JYY|IXX,IXY,IXZ,IYY,IYZ,IZZ", allow_hyphen_values = true)]
    pub inertia: Option<String>,
    /// With --polygon --inertia: the centre of mass's projection in the polygon's frame (default 0,0).
    #[arg(long, value_name = "X,Y", allow_hyphen_values = true)]
    pub centre: Option<String>,
    /// A general body of the catalogue (phone, brick, table, lander; `chatter bodies`) or a body
    /// file (RON or JSON, docs/bodies.md: contacts, inertia or the full inertia_tensor, optional
    /// mass, inertia_origin, centre and gamma; --gamma overrides the file's gamma).
    #[arg(long, value_name = "NAME|FILE", conflicts_with_all = ["n", "kappa"])]
    pub body: Option<String>,
    /// With --body FILE.urdf: the contacts, fixed joints of the body link (or their child links)
    /// counter-clockwise, or PREFIX* for every such joint whose name starts with PREFIX, ordered
    /// counter-clockwise (docs/bodies.md "URDF").
    #[arg(long, value_name = "NAME,NAME,...|PREFIX*", requires = "body")]
    pub contacts: Option<String>,
}

/// The general catalogue's body named `name` (exactly, ignoring case), with restitution `gamma`.
fn general_entry(name: &str, gamma: &Q) -> Result<Option<GeneralEntry>, String> {
    let all = general_catalogue(gamma).map_err(|e| format!("--body: {e}"))?;
    Ok(all.into_iter().find(|e| e.name.eq_ignore_ascii_case(name.trim())))
}

/// Whether `--body VALUE` names a general body: a name of the general catalogue or an existing
/// file (`certify` otherwise looks the name up in the regular catalogue).
pub fn names_general_body(value: &str) -> bool {
    let named = general_catalogue(&Q::int(0))
        .is_ok_and(|all| all.iter().any(|e| e.name.eq_ignore_ascii_case(value.trim())));
    named || Path::new(value).is_file()
}

/// A general body and how it was given.
#[derive(Clone, Debug)]
pub struct GeneralBody {
    pub body: ConvexBody<Q>,
    /// E.g. "rectangle 2 x 1 (uniform plate)".
    pub description: String,
    /// The full inertia tensor per unit mass about the centre of mass, when the body was given
    /// by one (its J_eff is `body`'s J; certificates record it for rule K0).
    pub tensor: Option<Tensor>,
}

fn numbers(flag: &str, s: &str, count: usize) -> Result<Vec<Q>, String> {
    let v = all_numbers(flag, s)?;
    if v.len() != count {
        return Err(format!("{flag}: expected {count} comma-separated numbers, found {}", v.len()));
    }
    Ok(v)
}

fn all_numbers(flag: &str, s: &str) -> Result<Vec<Q>, String> {
    s.split(',').map(|x| parse_user_number(x).map_err(|e| format!("{flag}: {e}"))).collect()
}

/// `--inertia`: three numbers (J) or six (the full tensor in URDF's order, reduced to J_eff).
fn inertia(s: &str) -> Result<(Mat2<Q>, &'static str, Option<Tensor>), String> {
    let v = all_numbers("--inertia", s)?;
    match v.as_slice() {
        [a, b, c] => Ok(([[a.clone(), b.clone()], [b.clone(), c.clone()]], "given inertia", None)),
        [_, _, _, _, _, _] => {
            let t = Tensor::from_urdf(&std::array::from_fn(|k| v[k].clone()));
            Ok((effective_inertia("--inertia", &t)?, "given inertia tensor, J_eff", Some(t)))
        }
        _ => Err(format!(
            "--inertia: expected 3 numbers (JXX,JXY,JYY) or 6 (IXX,IXY,IXZ,IYY,IYZ,IZZ), found {}",
            v.len()
        )),
    }
}

fn positive(flag: &str, v: &[Q]) -> Result<(), String> {
    match v.iter().find(|x| !x.is_positive()) {
        Some(x) => Err(format!("{flag}: every side must be > 0 (found {x})")),
        None => Ok(()),
    }
}

fn points(s: &str) -> Result<Vec<Vec2<Q>>, String> {
    s.split_whitespace().map(|pt| numbers("--polygon", pt, 2).map(|v| [v[0].clone(), v[1].clone()])).collect()
}

/// The kernel's verdict on a body as a message naming the option.
fn body_error(flag: &str, e: ConvexBodyError) -> String {
    let hint = match e {
        ConvexBodyError::OriginOutside { .. } | ConvexBodyError::OriginOnEdge { .. } => {
            " (the contact polygon must contain the centre of mass strictly inside)"
        }
        _ => "",
    };
    format!("{flag}: {e}{hint}")
}

fn flags_given(a: &ConvexArgs) -> Vec<&'static str> {
    let mut f = vec![];
    if a.rectangle.is_some() {
        f.push("--rectangle");
    }
    if a.box_.is_some() {
        f.push("--box");
    }
    if a.polygon.is_some() {
        f.push("--polygon");
    }
    if a.body.is_some() {
        f.push("--body");
    }
    f
}

impl ConvexArgs {
    /// A body file's text read as URDF (with --contacts) or RON/JSON.
    fn body_file(&self, text: &str) -> Result<BodyFile, String> {
        let names: Vec<String> =
            self.contacts.as_deref().map(|c| c.split(',').map(str::to_string).collect()).unwrap_or_default();
        if urdf::is_urdf(text) {
            return urdf::read(text, &names);
        }
        if self.contacts.is_some() {
            return Err("--contacts is for URDF files: a RON or JSON body file lists its contacts".into());
        }
        BodyFile::parse(text)
    }

    /// Whether a general body was asked for.
    pub fn given(&self) -> bool {
        !flags_given(self).is_empty() || self.plate || self.inertia.is_some() || self.centre.is_some()
    }

    /// The general body, if one was asked for, with restitution `gamma`; a body file's own gamma
    /// is used instead unless `gamma_given` (--gamma was on the command line). Errors are
    /// messages for exit status 2.
    pub fn parse(&self, gamma: &Q, gamma_given: bool) -> Result<Option<GeneralBody>, String> {
        let given = flags_given(self);
        if given.len() > 1 {
            return Err(format!("{} describe different bodies: give one", given.join(" and ")));
        }
        if self.polygon.is_none() && (self.plate || self.inertia.is_some() || self.centre.is_some()) {
            return Err("--plate, --inertia and --centre go with --polygon".into());
        }
        let g = || gamma.clone();
        if let Some(s) = &self.rectangle {
            let v = numbers("--rectangle", s, 2)?;
            positive("--rectangle", &v)?;
            let body = rectangle_plate(&v[0], &v[1], g()).map_err(|e| body_error("--rectangle", e))?;
            let description = format!("rectangle {} x {} (uniform plate)", v[0], v[1]);
            return Ok(Some(GeneralBody { body, description, tensor: None }));
        }
        if let Some(s) = &self.box_ {
            let v = numbers("--box", s, 3)?;
            positive("--box", &v)?;
            let body = uniform_box(&v[0], &v[1], &v[2], g()).map_err(|e| body_error("--box", e))?;
            let description =
                format!("box {} x {} x {} (uniform, on its {} x {} face)", v[0], v[1], v[2], v[0], v[1]);
            return Ok(Some(GeneralBody { body, description, tensor: None }));
        }
        if let Some(s) = &self.polygon {
            let pts = points(s)?;
            return match (self.plate, &self.inertia) {
                (true, Some(_)) => Err("--plate computes the inertia: drop --inertia (or --plate)".into()),
                (true, None) if self.centre.is_some() => {
                    Err("--plate puts the centre at the centroid: drop --centre".into())
                }
                (true, None) => {
                    let body = polygon_plate(&pts, g()).map_err(|e| body_error("--polygon", e))?;
                    let description = format!("uniform plate of a polygon with {} corners", pts.len());
                    Ok(Some(GeneralBody { body, description, tensor: None }))
                }
                (false, None) => {
                    Err("--polygon needs --plate or --inertia JXX,JXY,JYY (or IXX,IXY,IXZ,IYY,IYZ,IZZ)"
                        .into())
                }
                (false, Some(j)) => {
                    let (inertia, how, tensor) = inertia(j)?;
                    let c = match &self.centre {
                        None => vec![Q::int(0), Q::int(0)],
                        Some(c) => numbers("--centre", c, 2)?,
                    };
                    let pts = pts.into_iter().map(|p| [&p[0] - &c[0], &p[1] - &c[1]]).collect();
                    let body = ConvexBody::new(pts, inertia, g())
                        .map_err(|e| body_error("--polygon/--inertia", e))?;
                    let description = format!("polygon with {} contacts, {how}", body.n());
                    Ok(Some(GeneralBody { body, description, tensor }))
                }
            };
        }
        if let Some(value) = &self.body {
            if let Some(entry) = general_entry(value, gamma)? {
                if self.contacts.is_some() {
                    return Err("--contacts is for URDF files, not for the catalogue's bodies".into());
                }
                let description = format!("{} (general catalogue)", entry.name);
                return Ok(Some(GeneralBody { body: entry.body, description, tensor: Some(entry.tensor) }));
            }
            let path = Path::new(value);
            let flag = format!("--body {}", path.display());
            let text = std::fs::read_to_string(path).map_err(|e| format!("{flag}: cannot read: {e}"))?;
            let data = self.body_file(&text).and_then(|f| f.data()).map_err(|e| format!("{flag}: {e}"))?;
            let gamma = match data.gamma {
                Some(own) if !gamma_given => own,
                _ => g(),
            };
            let body =
                ConvexBody::new(data.contacts, data.inertia, gamma).map_err(|e| body_error(&flag, e))?;
            let how = if data.tensor.is_some() { ", inertia tensor, J_eff" } else { "" };
            let description = format!("body file {} ({} contacts{how})", path.display(), body.n());
            return Ok(Some(GeneralBody { body, description, tensor: data.tensor }));
        }
        Ok(None)
    }
}
