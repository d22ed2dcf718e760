//! The catalogue of bodies: kappa from geometry and mass distribution (never typed in), the
//! exact CC and PCC thresholds in gamma, the rod's Goyal threshold, and the paper's stated
//! values beside ours; [`convex`]: general convex bodies (plates, rectangles, boxes, regular
//! polygons) as exact data for the model of docs/model.md §11.

pub mod convex;
pub mod file;
pub mod general;
pub mod inertia;
pub mod solids;
pub mod urdf;

use crate::exact::{OrderedField, Q, QExt, QField, Ring, Rounding};
use crate::spectral::criteria::{Family, Profile, Sup, cc_profile, goyal_threshold, pcc_profile};
use crate::spectral::number_field::{Nf, NumberField};
use crate::spectral::roots::RealRoot;
use chatter_kernel::exact::OrderedField as _;
use chatter_kernel::model::linalg::Vec3;
use chatter_kernel::model::rational_cos as cos_step;
use serde::Serialize;
use solids::{prism_kappa, solid_kappa};

/// A value the paper states for a body: the criterion holds for gamma below `value` (given
/// with `decimals` decimals), or never. JSON: `{"kind": "below", "value": 0.04, "decimals": 2}`
/// or `{"kind": "never"}`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, schemars::JsonSchema)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum PaperValue {
    Below { value: f64, decimals: u32 },
    Never,
}

/// A body of the catalogue (or defined by the user).
#[derive(Clone, Debug)]
pub struct Entry {
    pub name: String,
    /// Number of contacts (2 for the rod).
    pub n: u64,
    /// cos(2 pi/n), exact.
    pub c1: Nf,
    pub kappa: Nf,
    /// How kappa was obtained.
    pub derivation: String,
    pub paper_cc: Option<PaperValue>,
    pub paper_pcc: Option<PaperValue>,
}

impl Entry {
    /// The number field the body lives in, if its numbers are irrational.
    pub fn field(&self) -> Option<String> {
        let k = |x: &Nf| x.as_rational().is_none();
        (k(&self.c1) || k(&self.kappa)).then(|| self.kappa_text())
    }

    /// kappa as text: canonical p/q, or a polynomial in the field's generator with its meaning.
    pub fn kappa_text(&self) -> String {
        match self.kappa.as_rational() {
            Some(q) => q.to_string(),
            None => format!("{} with {}", self.kappa, self.kappa.field_meaning().unwrap_or_default()),
        }
    }
}

impl Entry {
    /// kappa as the canonical text of an element of Q(cos 2 pi/n) (docs/certificate-format.md
    /// §12), when certificates can name it: a rational, or an element of the body's own field.
    /// `None` when kappa lies in another field (the icosahedron: n = 3, kappa in Q(sqrt 5)) or the
    /// body has more contacts than the kernel models.
    pub fn certificate_kappa(&self) -> Option<String> {
        if let Some(q) = self.kappa.as_rational() {
            return Some(q.to_string());
        }
        let n = self.n;
        let own = format!("c{n} = cos(2*pi/{n})");
        if self.kappa.field_meaning()? != own {
            return None;
        }
        let field = crate::exact::CosField::<Q>::new(n)?;
        Some(field.element(self.kappa.coeffs().to_vec()).to_string())
    }

    /// Why certificates cannot name this body's kappa, if they cannot.
    pub fn why_not_certifiable(&self) -> Option<String> {
        if self.certificate_kappa().is_some() {
            return None;
        }
        Some(format!(
            "kappa = {} is not in Q(cos 2 pi/{}), the field of the body's contacts",
            self.kappa_text(),
            self.n
        ))
    }
}

/// The catalogue body whose name contains `name` (case-insensitive), if exactly one does.
pub fn find(name: &str) -> Result<Entry, String> {
    let all = catalogue()?;
    let want = name.trim().to_lowercase();
    let hits: Vec<&Entry> = all.iter().filter(|e| e.name.to_lowercase().contains(&want)).collect();
    let names = || all.iter().map(|e| format!("'{}'", e.name)).collect::<Vec<_>>().join(", ");
    match hits.as_slice() {
        [e] => Ok((*e).clone()),
        [] => Err(format!("no catalogue body is named {name:?}; the catalogue: {}", names())),
        _ => {
            let exact: Vec<&&Entry> = hits.iter().filter(|e| e.name.to_lowercase() == want).collect();
            match exact.as_slice() {
                [e] => Ok((**e).clone()),
                _ => Err(format!(
                    "{name:?} names {} catalogue bodies ({}): be more precise",
                    hits.len(),
                    hits.iter().map(|e| format!("'{}'", e.name)).collect::<Vec<_>>().join(", ")
                )),
            }
        }
    }
}

/// cos(2 pi/n) exactly: rational for n = 2, 3, 4, 6, else the generator of Q(cos 2 pi/n).
pub fn cosine(n: usize) -> Nf {
    match n {
        2 => Nf::from_i64(-1),
        _ => match cos_step::<Q>(n as u64) {
            Some(c) => Nf::from_q(&c),
            None => NumberField::cos_2pi_over(n).generator(),
        },
    }
}

fn plate_name(n: usize) -> &'static str {
    ["", "", "", "triangle", "square", "pentagon", "hexagon", "heptagon", "octagon"]
        .get(n)
        .copied()
        .unwrap_or("polygon")
}

/// A homogeneous prism (height h, circumradius 1) over the regular n-gon landing on its base;
/// h = 0 is the flat plate.
pub fn prism(n: usize, h: &Q) -> Result<Entry, String> {
    if n < 3 {
        return Err("a polygon needs at least 3 vertices".into());
    }
    let c1 = cosine(n);
    let kappa = prism_kappa(n, &c1, &Nf::from_q(h))?;
    let what = if h.is_zero() {
        format!("flat {} plate", plate_name(n))
    } else {
        format!("{} prism, height {h}", plate_name(n))
    };
    Ok(Entry {
        name: what,
        n: n as u64,
        c1,
        kappa,
        derivation: "polygon second-moment formula (exact), plus h^2/12 for the thickness".into(),
        paper_cc: None,
        paper_pcc: None,
    })
}

/// A body given directly by n and kappa.
pub fn user(n: u64, kappa: &Q) -> Result<Entry, String> {
    if !(2..=64).contains(&n) {
        return Err(format!("n = {n}: a body needs between 2 and 64 contacts"));
    }
    if !kappa.is_positive() {
        return Err("kappa must be > 0".into());
    }
    Ok(Entry {
        name: format!("n = {n}, kappa = {kappa}"),
        n,
        c1: cosine(n as usize),
        kappa: Nf::from_q(kappa),
        derivation: "given".into(),
        paper_cc: None,
        paper_pcc: None,
    })
}

/// The uniform rod: rho^2 / R^2 = (int_{-1}^{1} x^2 dx / 2) = 1/3.
pub fn uniform_rod() -> Entry {
    // int_{-1}^{1} x^2 dx = 2/3 over the length 2.
    let kappa = Q::new(2, 3) / Q::int(2);
    Entry {
        name: "uniform rod".into(),
        n: 2,
        c1: cosine(2),
        kappa: Nf::from_q(&kappa),
        derivation: "int x^2 dx over the half-length, exact".into(),
        paper_cc: None,
        paper_pcc: None,
    }
}

/// A Platonic solid (tetrahedron, cube, octahedron, dodecahedron, icosahedron) landing on a
/// face with `n_face` vertices: vertices, the dual's vertices as face directions, kappa.
pub fn platonic(name: &str, n_face: usize) -> Result<Entry, String> {
    let k5 = NumberField::cos_2pi_over(5);
    let c5 = k5.generator();
    let i = |x: i64| Nf::from_i64(x);
    // The golden ratio phi = (1 + sqrt 5)/2 = 2 cos(2 pi/5) + 1 and 1/phi = phi - 1.
    let phi = c5.times(&i(2)).plus(&i(1));
    let iphi = phi.minus(&i(1));
    let signs = [1i64, -1];
    let mut cube: Vec<Vec3<Nf>> = Vec::new();
    for a in signs {
        for b in signs {
            for c in signs {
                cube.push([i(a), i(b), i(c)]);
            }
        }
    }
    let octa: Vec<Vec3<Nf>> = (0..3)
        .flat_map(|k| signs.iter().map(move |&s| std::array::from_fn(|j| if j == k { i(s) } else { i(0) })))
        .collect();
    let tetra: Vec<Vec3<Nf>> = cube
        .iter()
        .filter(|v| v.iter().fold(Nf::from_i64(1), |acc, x| acc.times(x)) == i(1))
        .cloned()
        .collect();
    let cyc = |a: &Nf, b: &Nf| -> Vec<Vec3<Nf>> {
        // (0, +-a, +-b) and its cyclic permutations.
        let mut out = Vec::new();
        for s in signs {
            for t in signs {
                let (x, y) = (a.times(&i(s)), b.times(&i(t)));
                out.push([i(0), x.clone(), y.clone()]);
                out.push([x.clone(), y.clone(), i(0)]);
                out.push([y, i(0), x]);
            }
        }
        out
    };
    // Dual pairs: the icosahedron cyc(1, phi) has face directions cube + cyc(phi, 1/phi); the
    // dodecahedron cube + cyc(1/phi, phi) has face directions cyc(phi, 1).
    let icosa = cyc(&i(1), &phi);
    let mut icosa_faces = cube.clone();
    icosa_faces.extend(cyc(&phi, &iphi));
    let mut dodeca = cube.clone();
    dodeca.extend(cyc(&iphi, &phi));
    let dodeca_faces = cyc(&phi, &i(1));
    let neg = |v: &Vec3<Nf>| v.clone().map(|x| x.negated());
    let (verts, dual, c_paper): (Vec<Vec3<Nf>>, Vec<Vec3<Nf>>, Nf) = match name {
        "tetrahedron" => (tetra.clone(), tetra.iter().map(neg).collect(), Nf::from_ratio(1, 20)),
        "cube" => (cube.clone(), octa.clone(), Nf::from_ratio(1, 6)),
        "octahedron" => (octa, cube, Nf::from_ratio(1, 10)),
        // c = (95 + 39 sqrt 5)/300 and (3 + sqrt 5)/20 with sqrt 5 = 4 c5 + 1.
        "dodecahedron" => (dodeca, dodeca_faces, {
            let s5 = c5.times(&i(4)).plus(&i(1));
            i(95).plus(&i(39).times(&s5)).over(&i(300)).expect("300")
        }),
        "icosahedron" => (icosa, icosa_faces, {
            let s5 = c5.times(&i(4)).plus(&i(1));
            i(3).plus(&s5).over(&i(20)).expect("20")
        }),
        _ => return Err(format!("unknown solid {name}")),
    };
    let s = solid_kappa(&verts, &dual)?;
    if s.face_vertices != n_face {
        return Err(format!("{name}: faces have {} vertices, expected {n_face}", s.face_vertices));
    }
    // The model's closed form kappa = 4 c sin^2(pi/n) = 2 c (1 - cos(2 pi/n)), c = I/(m a^2).
    let c1 = cosine(n_face);
    let closed = i(2).times(&c_paper).times(&i(1).minus(&c1));
    let check =
        if closed == s.kappa { "equals 4 c sin^2(pi/n) exactly" } else { "DIFFERS from 4 c sin^2(pi/n)" };
    Ok(Entry {
        name: format!("{name} (on a face)"),
        n: n_face as u64,
        c1,
        kappa: s.kappa,
        derivation: format!("tetrahedral decomposition of the solid, exact; {check}"),
        paper_cc: None,
        paper_pcc: None,
    })
}

/// The built-in catalogue, with the paper's stated values where it gives them: the CC and PCC
/// values of section "Comparison with direct simulation" (the cube and the dodecahedron "always
/// undergo ICC"), and its statement that the PCC condition is never met for n >= 4.
pub fn catalogue() -> Result<Vec<Entry>, String> {
    let zero = Q::int(0);
    let below = |value: f64, decimals: u32| Some(PaperValue::Below { value, decimals });
    let mut out = vec![uniform_rod()];
    for n in 3..=8 {
        let mut e = prism(n, &zero)?;
        match n {
            3 => (e.paper_cc, e.paper_pcc) = (below(0.04, 2), below(0.01, 2)),
            4 => e.paper_cc = below(0.03, 2),
            _ => {}
        }
        out.push(e);
    }
    for (name, n, cc, pcc) in [
        ("tetrahedron", 3, below(0.116, 3), below(0.025, 3)),
        ("cube", 4, Some(PaperValue::Never), None),
        ("octahedron", 3, below(0.025, 3), below(0.006, 3)),
        ("dodecahedron", 5, Some(PaperValue::Never), None),
        ("icosahedron", 3, None, None),
    ] {
        let mut e = platonic(name, n)?;
        (e.paper_cc, e.paper_pcc) = (cc, pcc);
        out.push(e);
    }
    // The paper (section "Partial complete chatter"): the PCC Lemma's condition "is never
    // satisfied if n >= 4", a statement about the criterion for every such body.
    for e in out.iter_mut().filter(|e| e.n >= 4) {
        e.paper_pcc = Some(PaperValue::Never);
    }
    Ok(out)
}

/// A criterion's threshold in gamma as reported: the supremum of the gammas where it holds.
#[derive(Clone, Debug, Serialize, schemars::JsonSchema)]
pub struct Threshold {
    /// "never", "below", or "up-to-one".
    pub kind: &'static str,
    /// Exact rational enclosure [lo, hi] of the threshold (for "below"), canonical `p/q` texts.
    pub interval: Option<[String; 2]>,
    /// Decimal enclosure rounded outwards (for "below").
    pub decimal: Option<[String; 2]>,
    /// The midpoint of the enclosure as f64 (for "below").
    pub midpoint: Option<f64>,
    /// A polynomial in gamma vanishing at the threshold.
    pub polynomial: Option<String>,
    /// Whether the criterion holds on (0, threshold) and nowhere else in (0, 1).
    pub initial_interval: bool,
    /// How it was decided.
    pub method: String,
}

/// The agreement of our threshold with the paper's stated one.
#[derive(Clone, Debug, Serialize)]
pub struct Comparison {
    pub paper: PaperValue,
    /// "agrees" (within the paper's rounding), "close" (within 5%), or "disagrees".
    pub status: &'static str,
}

impl Comparison {
    pub fn agrees(&self) -> bool {
        self.status == "agrees"
    }
}

fn summarise<F: OrderedField + std::fmt::Display>(
    root: Option<&mut RealRoot<F>>,
    poly: Option<String>,
    up_to_one: bool,
    initial: bool,
    method: &str,
    digits: usize,
) -> Threshold {
    let Some(r) = root else {
        let kind = if up_to_one { "up-to-one" } else { "never" };
        return Threshold {
            kind,
            interval: None,
            decimal: None,
            midpoint: None,
            polynomial: None,
            initial_interval: initial,
            method: method.into(),
        };
    };
    let (lo, hi) = r.decimal_enclosure(digits);
    Threshold {
        kind: "below",
        interval: Some([r.lo.to_string(), r.hi.to_string()]),
        decimal: Some([lo, hi]),
        midpoint: Some(r.approx()),
        polynomial: poly,
        initial_interval: initial,
        method: method.into(),
    }
}

fn from_profile<F: OrderedField + std::fmt::Display>(
    p: &Profile<F>,
    method: &str,
    digits: usize,
) -> Threshold {
    let initial = p.is_initial_interval();
    match p.sup() {
        Sup::Never => summarise::<F>(None, None, false, initial, method, digits),
        Sup::UpToOne => summarise::<F>(None, None, true, initial, method, digits),
        Sup::At(t) => {
            let mut r = t.gamma.clone();
            summarise(
                Some(&mut r),
                Some(format!("{} (from the {})", t.factor.show("g"), t.source)),
                false,
                initial,
                method,
                digits,
            )
        }
    }
}

/// Thresholds of a body: (CC, PCC). PCC is `None` for the rod.
pub fn thresholds(e: &Entry, digits: usize) -> (Threshold, Option<Threshold>) {
    let exact_q = |x: &Nf| x.as_rational();
    if e.n == 2 {
        let method = "Goyal's condition, exact (the rod theorem)";
        let t = match exact_q(&e.kappa) {
            Some(k) => goyal_threshold(&k).map(|mut r| {
                let poly = r.poly.show("g");
                summarise(Some(&mut r), Some(poly), false, true, method, digits)
            }),
            None => goyal_threshold(&e.kappa).map(|mut r| {
                let poly = r.poly.show("g");
                summarise(Some(&mut r), Some(poly), false, true, method, digits)
            }),
        };
        return (t.unwrap_or_else(|| summarise::<Q>(None, None, false, true, method, digits)), None);
    }
    match (exact_q(&e.c1), exact_q(&e.kappa)) {
        (Some(c1), Some(kappa)) => {
            let fam = Family { n: e.n, c1, kappa };
            let m = "exact over Q (Sturm sequences)";
            (from_profile(&cc_profile(&fam), m, digits), Some(from_profile(&pcc_profile(&fam), m, digits)))
        }
        _ => {
            let fam = Family { n: e.n, c1: e.c1.clone(), kappa: e.kappa.clone() };
            let m = "exact over a real number field (Sturm sequences, signs by interval refinement)";
            (from_profile(&cc_profile(&fam), m, digits), Some(from_profile(&pcc_profile(&fam), m, digits)))
        }
    }
}

/// Compares with the paper's value: a stated "below x" (x with d decimals) agrees when our
/// threshold is within half a unit of the last decimal (|ours - x| <= 0.5 * 10^-d), is close
/// within 5% of x, and disagrees otherwise; "never" agrees only with never.
pub fn compare(paper: Option<PaperValue>, ours: &Threshold) -> Option<Comparison> {
    let paper = paper?;
    let status = match (paper, ours.kind) {
        (PaperValue::Never, "never") => "agrees",
        (PaperValue::Never, _) => "disagrees",
        (PaperValue::Below { value, decimals }, "below") => {
            let d = (ours.midpoint.unwrap_or(f64::NAN) - value).abs();
            if d <= 0.5 * 10f64.powi(-(decimals as i32)) + 1e-12 {
                "agrees"
            } else if d <= 0.05 * value {
                "close"
            } else {
                "disagrees"
            }
        }
        (PaperValue::Below { .. }, _) => "disagrees",
    };
    Some(Comparison { paper, status })
}

/// kappa as a decimal (display).
pub fn kappa_f64(e: &Entry) -> f64 {
    let (lo, hi) = e.kappa.enclose(&Q::pow10(-18));
    ((lo + hi) / Q::int(2)).to_f64()
}

/// kappa to `d` decimals, rounded to nearest (display).
pub fn kappa_decimal(e: &Entry, d: usize) -> String {
    let (lo, _) = e.kappa.enclose(&Q::pow10(-(d as i64) - 3));
    lo.decimal(d, Rounding::Nearest)
}
