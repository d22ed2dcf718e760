//! `chatter.bodies/1`: the catalogue of bodies (or given bodies) with kappa from geometry, the
//! exact CC and PCC thresholds in gamma and the paper's values beside ours. Build it with
//! [`bodies()`] or [`catalogue`].

use super::convex::GeneralBodyReport;
use super::{Number, Report};
use crate::bodies::general::general_catalogue;
use crate::bodies::{self, Entry, PaperValue, Threshold, compare, kappa_decimal, kappa_f64};
use crate::exact::Q;
use rayon::prelude::*;
use schemars::JsonSchema;
use serde::Serialize;

/// The CC and PCC values of one kind (the PCC one is absent for the rod).
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct Pair<T> {
    pub cc: Option<T>,
    pub pcc: Option<T>,
}

/// One body.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct BodyRow {
    pub name: String,
    /// Number of contacts (2: the rod).
    pub n: u64,
    /// kappa exactly: canonical `p/q`, or a polynomial in a number field's generator with its meaning.
    pub kappa: String,
    pub kappa_f64: f64,
    /// How kappa was derived from the geometry.
    pub kappa_derivation: String,
    /// kappa as a certificate writes it (canonical text of an element of Q(cos 2 pi/n),
    /// docs/certificate-format.md §12); null when no certificate can name it (the icosahedron:
    /// its kappa lies in Q(sqrt 5), its faces are triangles).
    pub certificate_kappa: Option<String>,
    /// Why no certificate can name kappa (null when one can).
    #[serde(skip)]
    pub why_not_certifiable: Option<String>,
    /// The CC criterion holds for gamma below this (midpoint of the enclosure; 1.0: every
    /// gamma in (0, 1); null: never).
    pub cc_gamma_max: Option<f64>,
    /// The same for the PCC criterion (null also for the rod).
    pub pcc_gamma_max: Option<f64>,
    /// Exact enclosure of the CC threshold, canonical `p/q` texts (null unless `below`).
    pub cc_gamma_interval: Option<[String; 2]>,
    pub pcc_gamma_interval: Option<[String; 2]>,
    pub cc: Threshold,
    pub pcc: Option<Threshold>,
    /// The paper's stated values.
    pub paper: Pair<PaperValue>,
    /// Ours against the paper's: `agrees` (within its rounding), `close` (within 5 %) or `disagrees`.
    pub paper_status: Pair<&'static str>,
    /// kappa to 6 decimals (text output only).
    #[serde(skip)]
    pub kappa_decimal: String,
}

/// One general convex body of the catalogue (docs/model.md §11, docs/bodies.md): gamma is not
/// a property of the body and is not listed.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct GeneralBodyRow {
    pub name: &'static str,
    /// Number of contacts.
    pub n: usize,
    /// Contact points (x_k, y_k) relative to the centre of mass, counter-clockwise.
    pub contacts: Vec<[Number; 2]>,
    /// J_xx, J_xy, J_yy of the planar model: J_eff = J - b b^T / I_zz, b = (I_xz, I_yz), per
    /// unit mass about the centre of mass (docs/model.md §11.1).
    pub inertia: [Number; 3],
    /// The full inertia tensor per unit mass about the centre of mass, in URDF's order I_xx,
    /// I_xy, I_xz, I_yy, I_yz, I_zz (products with the tensor's minus sign).
    pub inertia_tensor: [Number; 6],
    /// How the contacts and the tensor were obtained.
    pub derivation: &'static str,
}

/// `chatter bodies --json`.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct BodiesReport {
    /// `chatter.bodies/1`.
    pub schema: &'static str,
    pub bodies: Vec<BodyRow>,
    /// The general convex bodies of the catalogue (phone, brick, table, lander; empty with
    /// `--only`).
    pub general: Vec<GeneralBodyRow>,
}

impl Report for BodiesReport {
    const SCHEMA: &'static str = "chatter.bodies/1";
}

fn gamma_max(t: &Threshold) -> Option<f64> {
    match t.kind {
        "below" => t.midpoint,
        "up-to-one" => Some(1.0),
        _ => None,
    }
}

/// The row of one body, with enclosures of `digits` decimals.
pub fn row(e: &Entry, digits: usize) -> BodyRow {
    let (cc, pcc) = bodies::thresholds(e, digits);
    let cmp_cc = compare(e.paper_cc, &cc).map(|c| c.status);
    let cmp_pcc = pcc.as_ref().and_then(|p| compare(e.paper_pcc, p)).map(|c| c.status);
    BodyRow {
        name: e.name.clone(),
        n: e.n,
        kappa: e.kappa_text(),
        kappa_f64: kappa_f64(e),
        kappa_derivation: e.derivation.clone(),
        certificate_kappa: e.certificate_kappa(),
        why_not_certifiable: e.why_not_certifiable(),
        cc_gamma_max: gamma_max(&cc),
        pcc_gamma_max: pcc.as_ref().and_then(gamma_max),
        cc_gamma_interval: cc.interval.clone(),
        pcc_gamma_interval: pcc.as_ref().and_then(|p| p.interval.clone()),
        cc,
        pcc,
        paper: Pair { cc: e.paper_cc, pcc: e.paper_pcc },
        paper_status: Pair { cc: cmp_cc, pcc: cmp_pcc },
        kappa_decimal: kappa_decimal(e, 6),
    }
}

/// The rows of `entries` (in parallel, in order), calling `tick` after each.
pub fn bodies(entries: &[Entry], digits: usize, tick: &(dyn Fn() + Sync)) -> BodiesReport {
    let bodies = entries
        .par_iter()
        .map(|e| {
            let r = row(e, digits);
            tick();
            r
        })
        .collect();
    BodiesReport { schema: BodiesReport::SCHEMA, bodies, general: Vec::new() }
}

/// The rows of the general catalogue (docs/bodies.md), listed without gamma.
pub fn general_rows() -> Result<Vec<GeneralBodyRow>, String> {
    let all = general_catalogue(&Q::int(0)).map_err(|e| format!("general catalogue: {e}"))?;
    Ok(all
        .into_iter()
        .map(|e| {
            let b = GeneralBodyReport::of(e.name, &e.body);
            GeneralBodyRow {
                name: e.name,
                n: e.body.n(),
                contacts: b.contacts,
                inertia: b.inertia,
                inertia_tensor: e.tensor.urdf().map(|x| Number::of(&x)),
                derivation: e.derivation,
            }
        })
        .collect())
}

/// The whole catalogue (`chatter bodies --json`) with enclosures of `digits` decimals.
pub fn catalogue(digits: usize) -> Result<BodiesReport, String> {
    let mut r = bodies(&bodies::catalogue()?, digits, &|| {});
    r.general = general_rows()?;
    Ok(r)
}

fn paper_text(p: &Option<PaperValue>) -> String {
    match p {
        None => "-".into(),
        Some(PaperValue::Never) => "never".into(),
        Some(PaperValue::Below { value, decimals }) => format!("< {value:.*}", *decimals as usize),
    }
}

fn ours_text(t: &Threshold) -> String {
    match (t.kind, &t.decimal) {
        ("below", Some([lo, hi])) => format!("< [{lo}, {hi}]"),
        ("up-to-one", _) => "all gamma".into(),
        _ => "never".into(),
    }
}

fn flag(status: Option<&str>) -> &'static str {
    match status {
        Some("agrees") => " (agrees)",
        Some("close") => " (close: within 5%, outside the paper's rounding)",
        Some(_) => " (DISAGREES)",
        None => "",
    }
}

impl BodyRow {
    /// The text output of the row.
    pub fn lines(&self) -> Vec<String> {
        let pcc_text = self.pcc.as_ref().map_or("n/a (two contacts)".to_string(), ours_text);
        let mut lines = vec![
            format!("{} (n = {}, kappa = {} = {})", self.name, self.n, self.kappa, self.kappa_decimal),
            format!(
                "  CC  criterion: {:<36} paper: {}{}",
                ours_text(&self.cc),
                paper_text(&self.paper.cc),
                flag(self.paper_status.cc)
            ),
            format!(
                "  PCC criterion: {:<36} paper: {}{}",
                pcc_text,
                paper_text(&self.paper.pcc),
                flag(self.paper_status.pcc)
            ),
        ];
        if let Some(p) = &self.cc.polynomial {
            lines.push(format!("  CC threshold is a root of {p}"));
        }
        if let Some(p) = self.pcc.as_ref().and_then(|p| p.polynomial.clone()) {
            lines.push(format!("  PCC threshold is a root of {p}"));
        }
        lines.push(format!("  decided {}; kappa by {}", self.cc.method, self.kappa_derivation));
        lines.push(self.certificates_line());
        lines
    }

    /// Whether certificates can be made for the body, and how.
    fn certificates_line(&self) -> String {
        match &self.certificate_kappa {
            Some(k) if k.contains(crate::exact::GENERATOR) => format!(
                "  certificates: kappa = \"{k}\" in Q(c), c = cos(2 pi/{}): chatter certify --body '{}' --gamma G",
                self.n, self.name
            ),
            Some(_) => format!("  certificates: chatter certify --body '{}' --gamma G", self.name),
            None => {
                format!("  certificates: none ({})", self.why_not_certifiable.clone().unwrap_or_default())
            }
        }
    }
}

impl GeneralBodyRow {
    /// The text output of a general body (docs/bodies.md).
    pub fn lines(&self) -> Vec<String> {
        let pts: Vec<String> =
            self.contacts.iter().map(|c| format!("({}, {})", c[0].exact, c[1].exact)).collect();
        let j = &self.inertia;
        let t: Vec<&str> = self.inertia_tensor.iter().map(|x| x.exact.as_str()).collect();
        vec![
            format!("{} (general body, {} contacts; gamma is not a property of the body)", self.name, self.n),
            format!("  contacts (about the centre of mass, counter-clockwise): {}", pts.join(" ")),
            format!(
                "  inertia tensor (I_xx, I_xy, I_xz, I_yy, I_yz, I_zz) = ({}) per unit mass",
                t.join(", ")
            ),
            format!(
                "  J = J_eff = [[{}, {}], [{}, {}]] per unit mass",
                j[0].exact, j[1].exact, j[1].exact, j[2].exact
            ),
            format!("  derivation: {}", self.derivation),
            format!("  use: chatter classify --body {} --gamma G (also simulate, certify)", self.name),
        ]
    }
}
