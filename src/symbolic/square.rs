//! The square-case lemmas of the paper (section "A semi-analytic construction for squares"),
//! written as a proof that the kernel's proof checker re-checks from the file alone
//! (`chatter_kernel::proof`). Coordinates are the paper's (omega_x, omega_y, v), related to the
//! model's by p_model = M p_paper with M's rows f_0 = (0, -1, 1), f_1 = (1, 0, 1), (0, 0, 1);
//! points of the plane v = -1 are written (x, y). The paper's U_0 P_{pi/2} is the model's S_3.
//!
//! Hypotheses: 0 < gamma < 1, kappa > 0, lambda > 0 a root of chi (an eigenvalue of S_3, e.g. its
//! dominant one when that is real and positive, as the paper assumes). Dominance is never used.

use super::builder::{Builder, Header};
use super::cert::Cert;
use super::terms::lenient;
use crate::exact::{Q, Ring};
use chatter_kernel::proof::{
    Coeffs, Failure, Frac, Oracle, PMat, Point, Poly, Step, clip, det, mat_mul, parallel, sturm_sequence,
};

const VARS: [&str; 6] = ["g", "k", "l", "s", "e1", "e2"];

/// The facets of K = [-e1, e1] x [-e2, -1], covectors (a, b, c) with a x + b y - c >= 0 on v = -1.
const FACETS: [(&str, [&str; 3]); 4] = [
    ("left", ["1", "0", "-e1"]),
    ("bottom", ["0", "1", "-e2"]),
    ("right", ["-1", "0", "-e1"]),
    ("top", ["0", "-1", "1"]),
];

/// K's vertices, counter-clockwise: facet i joins vertices i and i + 1.
const VERTICES: [&str; 4] = ["s3", "p3", "p1", "s1"];

fn header() -> Header {
    Header {
        name: "square".into(),
        statement: "For the square (n = 4), every kappa > 0, 0 < gamma < 1 and every positive eigenvalue lambda of S_3 = U_0 P_{pi/2}: K = cone(p1, p3, s1, s3) satisfies conditions 1 and 2 of the paper's Theorem on effectively invariant cones and contains I_0(D), so every drop with all vertices moving down ends in CC or PCC; where moreover p^2 - 4q < 0 (the quadratic factor of det(tI - S_3 S_1)) PCC is excluded and the drop ends in CC. At gamma = 1/1000, kappa = 1/6 the discriminant is positive although S_3 has a positive eigenvalue, so the paper's claim that PCC is never possible for n >= 4 fails.".into(),
        n: 4,
        variables: VARS.to_vec(),
        gamma: "g",
        kappa: "k",
        lambda: "l",
        map: 3,
        coordinates: [[0, -1, 1], [1, 0, 1], [0, 0, 1]],
        hypotheses: vec![("g", "g"), ("1-g", "-g + 1"), ("k", "k"), ("l", "l")],
    }
}

/// `p / d` in variable `v` when `d` is monic in `v` (up to a constant) and divides `p`.
pub fn div_exact(p: &Poly<Q>, v: usize, d: &Poly<Q>) -> Option<Poly<Q>> {
    let (n, nv) = (d.degree_in(v), p.nvars());
    let lc = d.coeff_in(v, n).as_constant().filter(|c| !c.is_zero())?;
    let (mut quot, mut r) = (Poly::zero(nv), p.clone());
    while !r.is_zero() && r.degree_in(v) >= n {
        let deg = r.degree_in(v);
        let t = r.coeff_in(v, deg).scale(&(Q::int(1) / lc.clone())).mul(&Poly::var(nv, v).pow(deg - n));
        quot = quot.add(&t);
        r = r.sub(&t.mul(d));
    }
    r.is_zero().then_some(quot)
}

/// det(t (1 + kappa)^e I - m) for a matrix scaled by (1 + kappa)^e.
fn char_det(m: &PMat<Q>, t: &Poly<Q>, scale: &Poly<Q>) -> Poly<Q> {
    let nv = t.nvars();
    det(&std::array::from_fn(|r| {
        std::array::from_fn(|c| {
            let diag = if r == c { scale.mul(t) } else { Poly::zero(nv) };
            diag.sub(&m[r][c])
        })
    }))
}

/// chi = (kappa + 1) det(lambda I - S_3), from the kernel's model of the square.
fn chi() -> Poly<Q> {
    let names: Vec<String> = VARS.iter().map(|s| s.to_string()).collect();
    let m = [[0, -1, 1], [1, 0, 1], [0, 0, 1]].map(|r| r.map(Q::int));
    let model = chatter_kernel::proof::SymbolicModel::new(4, 6, 0, 1, &m).expect("the square");
    let one_k = lenient("k + 1", &names);
    let d = char_det(&model.steps[2], &Poly::var(6, 2), &one_k);
    div_exact(&d, 1, &one_k.pow(2)).expect("(1 + kappa)^2 divides the scaled determinant")
}

/// The proof, step by step.
pub fn prove() -> Builder {
    let mut b = Builder::new(header(), chi());
    let p = |b: &Builder, t: &str| Frac::poly(lenient(t, &b.ctx.names));
    setting(&mut b, &p);
    eigenvalue_below_one(&mut b, &p);
    auxiliary(&mut b, &p);
    eigenvector(&mut b, &p);
    ordering(&mut b, &p);
    named_points(&mut b, &p);
    images(&mut b, &p);
    cone(&mut b);
    for j in [3, 1, 2] {
        invariance(&mut b, j);
    }
    all_down(&mut b, &p);
    pcc(&mut b, &p);
    b
}

type P<'a> = dyn Fn(&Builder, &str) -> Frac<Q> + 'a;

fn setting(b: &mut Builder, p: &P<'_>) {
    b.section("Setting");
    let e = p(b, "k + 1");
    b.positive(
        "1+k",
        &e,
        &Cert::sum(&[(1, &[]), (1, &["k"])]),
        "1 + kappa > 0: every map of the model is scaled by it",
    );
}

fn eigenvalue_below_one(b: &mut Builder, _p: &P<'_>) {
    b.section("Lemma 0: every positive eigenvalue is below 1");
    let (l, s) = (b.var("l"), b.var("s"));
    let nv = b.ctx.nvars();
    let shifted = b
        .ctx
        .chi
        .subst_fraction(
            l,
            &Poly::constant(nv, Q::int(1)).add(&Poly::var(nv, s)),
            &Poly::constant(nv, Q::int(1)),
        )
        .expect("a cubic");
    let certs: [&[(i64, &[&str])]; 4] = [
        &[(2, &["g", "k"]), (2, &["k"])],
        &[(4, &["k"]), (2, &["g", "k"]), (1, &["1-g"])],
        &[(3, &["k"]), (2, &[]), (1, &["g", "k"])],
        &[(1, &["k"]), (1, &[])],
    ];
    for (d, cert) in certs.iter().enumerate() {
        let c = Frac::poly(shifted.coeff_in(s, d as u32));
        b.positive(
            &format!("1-l.{d}"),
            &c,
            &Cert::sum(cert),
            &format!("the coefficient of s^{d} in chi(1 + s) is positive"),
        );
    }
    b.raw(
        Step::RootBound { id: "1-l".into(), below: "1".into(), variable: "s".into() },
        "chi(1 + s) > 0 for s >= 0: every real root of chi is below 1, so 1 - lambda > 0",
    );
    let one_minus_l = Frac::poly(lenient("-l + 1", &b.ctx.names));
    b.ctx.add_atom("1-l", one_minus_l).expect("new atom");
}

fn auxiliary(b: &mut Builder, p: &P<'_>) {
    b.section("Auxiliary quantities");
    let e = p(b, "l^2 + 1");
    b.positive("1+l^2", &e, &Cert::sum(&[(1, &[]), (1, &["l", "l"])]), "1 + lambda^2 > 0");
    let d = p(b, "k l^2 + k - l + 1");
    b.positive(
        "D",
        &d,
        &Cert::sum(&[(1, &["k"]), (1, &["k", "l", "l"]), (1, &["1-l"])]),
        "D := kappa (1 + lambda^2) + 1 - lambda > 0",
    );
    let (gd, la) = (p(b, "g k l^2 + g k - g l + g"), p(b, "-k l^3 - k l - l^3 + l^2"));
    b.identity(
        "gD",
        &gd,
        &la,
        "gamma D = lambda A with A := lambda (1 - lambda) - kappa (1 + lambda^2): chi = 0 solved for gamma",
    );
    let a = p(b, "-k l^2 - k - l^2 + l");
    b.positive("A", &a, &Cert::atoms(&["g", "D"]).over(&["l"]), "A > 0, as A = gamma D / lambda");
}

fn eigenvector(b: &mut Builder, p: &P<'_>) {
    b.section("Lemma l:r2, first part: the eigenvector p1 = (e1, -e2)");
    let den = p(b, "k l^2 + l^2 + k - g");
    let lhs = Frac::poly(den.num.mul(&lenient("-l + 1", &b.ctx.names)));
    let rhs = p(b, "g k l^2 + g k + k l^2 + k");
    b.identity(
        "den",
        &lhs,
        &rhs,
        "(1 - lambda)(lambda^2 kappa + lambda^2 + kappa - gamma) = (gamma + 1) kappa (1 + lambda^2)",
    );
    let cert = Cert::sum(&[(1, &["g", "k"]), (1, &["g", "k", "l", "l"]), (1, &["k"]), (1, &["k", "l", "l"])])
        .over(&["1-l"]);
    b.positive("den+", &den, &cert, "the denominator of e1 is positive");
    let g1 = lenient("g + 1", &b.ctx.names);
    b.define(
        "e1",
        &g1,
        &den.num,
        Some("den+"),
        "e1 := (gamma + 1)/(lambda^2 kappa + lambda^2 + kappa - gamma), the paper's formula",
    );
    let e2 = lenient("l e1", &b.ctx.names);
    b.define("e2", &e2, &lenient("1", &b.ctx.names), None, "e2 := lambda e1");
    let simple = b.frac("(-l + 1) / [k] [1+l^2]");
    let e1 = p(b, "e1");
    b.identity("e1=", &e1, &simple, "e1 = (1 - lambda)/(kappa (1 + lambda^2))");
}

fn ordering(b: &mut Builder, p: &P<'_>) {
    b.section("Lemma l:r2: e1 > e2 > 1 for all parameters (the paper checked e2 > 1 numerically)");
    let e = p(b, "e1");
    b.positive("e1>0", &e, &Cert::atoms(&["1-l"]).over(&["k", "1+l^2"]), "e1 > 0");
    let e = p(b, "e1 - e2");
    b.positive(
        "e1-e2",
        &e,
        &Cert::atoms(&["1-l", "1-l"]).over(&["k", "1+l^2"]),
        "e1 - e2 = (1 - lambda)^2/(kappa (1 + lambda^2)) > 0",
    );
    let e = p(b, "e2 - 1");
    b.positive(
        "e2-1",
        &e,
        &Cert::atoms(&["g", "D"]).over(&["k", "l", "1+l^2"]),
        "e2 - 1 = gamma D/(kappa lambda (1 + lambda^2)) > 0: e2 > 1 is equivalent to gamma > 0",
    );
    let e = p(b, "e1 + 1");
    b.positive("e1+1", &e, &Cert::sum(&[(1, &["e1-e2"]), (1, &["e2-1"]), (2, &[])]), "e1 + 1 > 0");
}

fn named_points(b: &mut Builder, p: &P<'_>) {
    b.section("Named points of the plane v = -1 (paper's coordinates)");
    let pts: [(&str, &str, &str); 14] = [
        ("s1", "e1", "-1"),
        ("s3", "-e1", "-1"),
        ("p1", "e1", "-e2"),
        ("p3", "-e1", "-e2"),
        ("s01", "1", "-1"),
        ("s12", "1", "1"),
        ("s23", "-1", "1"),
        ("s30", "-1", "-1"),
        ("q1", "-1", "-e2"),
        ("q3", "1", "-e2"),
        ("k1", "e2", "-1"),
        ("k3", "-e2", "-1"),
        ("r+", "e2", "-e2"),
        ("r-", "-e2", "-e2"),
    ];
    for (name, x, y) in pts {
        let (x, y) = (p(b, x), p(b, y));
        b.point(name, &x, &y);
    }
    let y = p(b, "-e2");
    for (name, x) in [("w1", "(1) / [l]"), ("w3", "(-1) / [l]")] {
        let x = b.frac(x);
        b.point(name, &x, &y);
    }
}

/// The coefficients of the S_2 decompositions, as atoms.
fn combination_atoms(b: &mut Builder) {
    let atoms = [
        ("t", "(2) / [e1+1]", Cert::sum(&[(2, &[])]).over(&["e1+1"])),
        ("1-t", "(e1 - 1) / [e1+1]", Cert::sum(&[(1, &["e1-e2"]), (1, &["e2-1"])]).over(&["e1+1"])),
        ("u", "(e2 + 1) / [e1+1]", Cert::sum(&[(1, &["e2-1"]), (2, &[])]).over(&["e1+1"])),
        ("1-u", "(e1 - e2) / [e1+1]", Cert::atoms(&["e1-e2"]).over(&["e1+1"])),
    ];
    for (id, e, cert) in atoms {
        let e = b.frac(e);
        b.positive(id, &e, &cert, "");
    }
}

/// How S_j maps each vertex of K ∩ C_j: coefficients (as text and as atoms) and named points.
pub fn decomposition(j: usize, w: &str) -> Vec<(&'static str, &'static [&'static str], &'static str)> {
    match (j, w) {
        (3, "s30") => vec![("1", &[], "s01")],
        (3, "q1") => vec![("1", &[], "k1")],
        (3, "p1") => vec![("l", &["l"], "p1")],
        (3, "s1") => vec![("l", &["l"], "w1")],
        (1, "s01") => vec![("1", &[], "s30")],
        (1, "q3") => vec![("1", &[], "k3")],
        (1, "p3") => vec![("l", &["l"], "p3")],
        (1, "s3") => vec![("l", &["l"], "w3")],
        (2, "s30") => vec![("(e1 - 1) / [e1+1]", &["1-t"], "s01"), ("(2 l) / [e1+1]", &["t", "l"], "w1")],
        (2, "s01") => vec![("(e1 - 1) / [e1+1]", &["1-t"], "s30"), ("(2 l) / [e1+1]", &["t", "l"], "w3")],
        (2, "r-") => vec![("(e1 - e2) / [e1+1]", &["1-u"], "k1"), ("(e2 l + l) / [e1+1]", &["u", "l"], "p1")],
        (2, "r+") => vec![("(e1 - e2) / [e1+1]", &["1-u"], "k3"), ("(e2 l + l) / [e1+1]", &["u", "l"], "p3")],
        _ => vec![],
    }
}

fn images(b: &mut Builder, _p: &P<'_>) {
    b.section("Lemmas l:r1, l:r4 and the eigenvector, with their mirror images and the map S_2");
    combination_atoms(b);
    let notes = [
        (3, "s30", "Lemma l:r1: U_0 P_{pi/2} s30 = s01"),
        (3, "q1", "Lemma l:r1: U_0 P_{pi/2} q1 = k1"),
        (3, "p1", "Lemma l:r2: p1 is an eigenvector of U_0 P_{pi/2} for lambda"),
        (3, "s1", "Lemma l:r4: U_0 P_{pi/2} s1 = lambda w1"),
        (1, "s01", "mirror image: S_1 s01 = s30"),
        (1, "q3", "mirror image: S_1 q3 = k3"),
        (1, "p3", "mirror image: p3 is an eigenvector of S_1 for lambda"),
        (1, "s3", "mirror image: S_1 s3 = lambda w3"),
        (
            2,
            "s30",
            "S_2 s30 = S_3 s01 = (1 - t) s01 + t lambda w1 with t = 2/(e1 + 1) (s01 = (1 - t) s30 + t s1)",
        ),
        (2, "s01", "S_2 s01 = (1 - t) s30 + t lambda w3 (mirror image)"),
        (
            2,
            "r-",
            "S_2 r- = S_3 r+ = (1 - u) k1 + u lambda p1 with u = (e2 + 1)/(e1 + 1) (r+ = (1 - u) q1 + u p1)",
        ),
        (2, "r+", "S_2 r+ = (1 - u) k3 + u lambda p3 (mirror image)"),
    ];
    for (j, w, note) in notes {
        let equals: Vec<(Frac<Q>, &str)> =
            decomposition(j, w).iter().map(|(c, _, pt)| (b.frac(c), *pt)).collect();
        b.image(&format!("S{j}.{w}"), &format!("S{j}"), w, &equals, note);
    }
}

/// The covector of a facet.
fn facet(b: &Builder, i: usize) -> [Frac<Q>; 3] {
    FACETS[i].1.map(|t| Frac::poly(lenient(t, &b.ctx.names)))
}

/// The sign steps K.{facet}.{point} (positive facet values) of a point in K.
fn membership(b: &mut Builder, point: &str) {
    for (i, (name, _)) in FACETS.iter().enumerate() {
        let v = b.dot(&facet(b, i), b.pt(point));
        if b.sign_step(&format!("K.{name}.{point}"), &v).is_lt() {
            b.problems.push((format!("K.{name}.{point}"), format!("{point} is outside K")));
        }
    }
}

fn cone(b: &mut Builder) {
    b.section("The cone K = cone(s3, p3, p1, s1): the rectangle [-e1, e1] x [-e2, -1]");
    for v in VERTICES {
        membership(b, v);
    }
    let facets = FACETS.iter().map(|(n, c)| (n.to_string(), c.map(str::to_string))).collect();
    let vertices = VERTICES.iter().map(|s| s.to_string()).collect();
    b.raw(
        Step::Cone { id: "K".into(), vertices, facets },
        "K is the convex cone over the rectangle; its facets: x >= -e1, y >= -e2, x <= e1, y <= -1",
    );
    b.section("Points in K (four certified inequalities each)");
    for w in ["s01", "s30", "k1", "k3", "w1", "w3"] {
        membership(b, w);
    }
}

/// The producer's oracle for the kernel's clipping: signs decided and written as steps under
/// `{key}.{point}`, crossings named by searching the named points.
struct Writer<'b> {
    b: &'b mut Builder,
    key: String,
    crossings: &'b mut Vec<String>,
}

impl Oracle<Q> for Writer<'_> {
    fn sign(&mut self, point: &str, value: &Frac<Q>) -> Result<std::cmp::Ordering, Failure> {
        Ok(self.b.sign_step(&format!("{}.{point}", self.key), value))
    }

    fn crossing(&mut self, x: &Point<Q>, from: &str, to: &str) -> Result<String, Failure> {
        let b = &self.b;
        let found =
            b.points.iter().find(|(_, w)| parallel(&b.ctx, x, w).unwrap_or(false)).map(|(n, _)| n.clone());
        let name = found.ok_or_else(|| Failure::UnknownPoint(format!("the crossing of {from} -> {to}")))?;
        self.crossings.push(name.clone());
        Ok(name)
    }

    fn point(&self, name: &str) -> Result<&Point<Q>, Failure> {
        self.b.points.get(name).ok_or_else(|| Failure::UnknownPoint(name.to_string()))
    }
}

/// S_j(K ∩ C_j) ⊆ K: the clipping's sign steps, then a certificate for every facet at the image
/// of every vertex of the piece, from the decomposition of the image.
fn invariance(b: &mut Builder, j: usize) {
    b.section(&format!("S_{j}(K ∩ C_{j}) ⊆ K"));
    let mut poly: Vec<String> = VERTICES.iter().map(|s| s.to_string()).collect();
    let mut crossings = Vec::new();
    for (m, l) in b.model.cones[j - 1].clone().iter().enumerate() {
        let ctx = b.ctx.clone();
        let mut writer = Writer { b, key: format!("K.C{j}.h{m}"), crossings: &mut crossings };
        match clip(&ctx, &poly, &l.clone().map(Frac::poly), &mut writer) {
            Ok(p) => poly = p,
            Err(e) => b.problems.push((format!("inv.S{j}"), e.to_string())),
        }
    }
    for w in &poly {
        let img = b.apply(b.map(&format!("S{j}")), b.pt(w));
        for (i, (name, _)) in FACETS.iter().enumerate() {
            let f = facet(b, i);
            facet_obligation(
                b,
                &format!("K.S{j}.{w}.{name}"),
                &b.dot(&f, &img),
                &f,
                &decomposition(j, w),
                name,
            );
        }
    }
    let note = format!("K ∩ C_{j} = conv({}), and S_{j} maps each of these vertices into K", poly.join(", "));
    b.raw(Step::Invariant { id: format!("inv.S{j}"), cone: "K".into(), map: j as u64, crossings }, &note);
}

/// The certificate of `e = f . (1 + kappa) sum c_i w_i >= 0` from the facet atoms of the w_i.
fn facet_obligation(
    b: &mut Builder,
    key: &str,
    e: &Frac<Q>,
    f: &[Frac<Q>; 3],
    dec: &[(&str, &[&str], &str)],
    facet: &str,
) {
    if b.is_zero(e) {
        return;
    }
    let mut cert: Option<Cert> = None;
    for (_, atoms, w) in dec {
        if b.is_zero(&b.dot(f, b.pt(w))) {
            continue;
        }
        let mut names = vec!["1+k"];
        names.extend_from_slice(atoms);
        let fw = format!("K.{facet}.{w}");
        names.push(&fw);
        let t = Cert::atoms(&names);
        cert = Some(cert.map_or(t.clone(), |x| x.plus(t)));
    }
    match cert {
        Some(cert) => b.positive(key, e, &cert, ""),
        None => b.problems.push((key.into(), "no decomposition of the image".into())),
    }
}

fn all_down(b: &mut Builder, p: &P<'_>) {
    b.section("Lemma l:k0: every all-down drop lands in K");
    let gens: Vec<[Frac<Q>; 3]> = b.model.all_down.iter().map(|g| g.clone().map(Frac::poly)).collect();
    let img12 = b.apply(&b.model.impact, b.pt("s12"));
    let [x, y, z] = img12.map(|c| c.num);
    let zz = Frac::poly(lenient("2 k l^3 - k l^2 + 2 k l - k - l + 1", &b.ctx.names));
    b.positive(
        "Z",
        &zz,
        &Cert::sum(&[
            (1, &["1-l", "1-l", "1-l"]),
            (1, &["1-l", "l"]),
            (1, &["1-l", "A"]),
            (1, &["k", "l"]),
            (1, &["k", "l", "l", "l"]),
        ]),
        "Z := kappa (2 lambda - 1)(1 + lambda^2) + 1 - lambda > 0",
    );
    let minus_z = Frac::poly(z.neg());
    b.positive(
        "-Z~",
        &minus_z,
        &Cert::atoms(&["1+k", "Z"]).over(&["D"]),
        "(1 + kappa) U_0 s12 has v-coordinate Z~ < 0: -Z~ = (1 + kappa) Z / D",
    );
    let over = |n: &Poly<Q>| Frac { num: n.clone(), den: vec!["-Z~".to_string()] };
    let xp = over(&x);
    let yp = over(&y);
    let e1 = p(b, "e1");
    let e2 = p(b, "e2");
    let one = p(b, "1");
    let right = b.add(&e1, &xp.neg());
    b.positive(
        "k0.right",
        &right,
        &Cert::sum(&[
            (1, &["1-l", "1-l", "1-l", "1-l"]),
            (1, &["A", "1-l"]),
            (1, &["A", "1-l", "1-l"]),
            (1, &["A", "k"]),
            (1, &["A", "k", "l", "l"]),
        ])
        .over(&["k", "1+l^2", "Z"]),
        "U_0 s12 projects to (x, y) with x <= e1",
    );
    let left = b.add(&e1, &xp);
    b.positive(
        "k0.left",
        &left,
        &Cert::sum(&[(1, &["e1>0", "Z"]), (1, &["D"])]).over(&["Z"]),
        "and x >= -e1",
    );
    let bottom = b.add(&e2, &yp);
    b.positive(
        "k0.bottom",
        &bottom,
        &Cert::sum(&[(1, &["1-l", "1-l", "A"]), (1, &["A", "A"])]).over(&["k", "1+l^2", "Z"]),
        "and y >= -e2",
    );
    let top = b.add(&one.neg(), &yp.neg());
    b.positive("k0.top", &top, &Cert::sum(&[(2, &["l", "A"])]).over(&["Z"]), "and y <= -1");
    for (m, g) in gens.iter().enumerate() {
        let name = b
            .points
            .iter()
            .find(|(_, w)| (0..3).all(|i| b.equal(&w[i], &g[i])))
            .map(|(n, _)| n.clone())
            .expect("D's generators are named points");
        let img = b.apply(&b.model.impact, g);
        for (i, (facet_name, _)) in FACETS.iter().enumerate() {
            let f = facet(b, i);
            let key = format!("K.I0.{m}.{facet_name}");
            let e = b.dot(&f, &img);
            match name.as_str() {
                "s01" | "s30" => facet_obligation(
                    b,
                    &key,
                    &e,
                    &f,
                    &[("1", &[], if name == "s01" { "s01" } else { "s30" })],
                    facet_name,
                ),
                "s12" => b.positive(&key, &e, &Cert::atoms(&["-Z~", &format!("k0.{facet_name}")]), ""),
                _ => {
                    let mirror = match *facet_name {
                        "left" => "right",
                        "right" => "left",
                        other => other,
                    };
                    b.positive(&key, &e, &Cert::atoms(&["-Z~", &format!("k0.{mirror}")]), "");
                }
            }
        }
    }
    b.raw(Step::AllDown { id: "l:k0".into(), cone: "K".into() }, "I_0 maps the generators s01, s12, s23, s30 of D into K (s01 and s30 are fixed; s23 is the mirror image of s12)");
}

/// `p / (1 + kappa)^e` with `e` as small as exact division allows.
fn over_one_k(b: &Builder, p: &Poly<Q>, e: usize) -> Frac<Q> {
    let one_k = lenient("k + 1", &b.ctx.names);
    let (mut num, mut left) = (p.clone(), e);
    while left > 0 {
        match div_exact(&num, b.var("k"), &one_k) {
            Some(q) => {
                num = q;
                left -= 1;
            }
            None => break,
        }
    }
    Frac { num, den: vec!["1+k".to_string(); left] }
}

fn pcc(b: &mut Builder, p: &P<'_>) {
    b.section("Lemma noPCC and the finding against the paper");
    let (s, nv) = (b.var("s"), b.ctx.nvars());
    let one_k2 = lenient("k + 1", &b.ctx.names).pow(2);
    let m = mat_mul(&b.model.steps[2], &b.model.steps[0]);
    let d = char_det(&m, &Poly::var(nv, s), &one_k2);
    let quad = div_exact(&d, s, &lenient("s - 1", &b.ctx.names)).expect("1 is an eigenvalue of S_3 S_1");
    let (pp, qq) = (over_one_k(b, &quad.coeff_in(s, 1), 6), over_one_k(b, &quad.coeff_in(s, 0), 6));
    let note = "det(tI - S_3 S_1) = (t - 1)(t^2 + p t + q) (t written s): the Lemma excludes PCC where p^2 - 4q < 0 and q < 1";
    b.raw(Step::Pcc { id: "pcc".into(), variable: "s".into(), p: b.text(&pp), q: b.text(&qq) }, note);
    let g2 = p(b, "g^2");
    b.identity("pcc.q", &qq, &g2, "q = gamma^2");
    let e = p(b, "-g^2 + 1");
    b.positive(
        "1-q",
        &e,
        &Cert::sum(&[(1, &["1-g"]), (1, &["1-g", "g"])]),
        "q < 1: complex roots have modulus gamma < 1",
    );
    witness(b, &pp, &qq);
}

/// At gamma = 1/1000, kappa = 1/6: chi has roots in (1/10, 1] (positive eigenvalues of S_3, so
/// the region is not empty) and the discriminant p^2 - 4q is positive.
fn witness(b: &mut Builder, pp: &Frac<Q>, qq: &Frac<Q>) {
    let (g, k, l) = (b.var("g"), b.var("k"), b.var("l"));
    let (gv, kv) = (Q::new(1, 1000), Q::new(1, 6));
    let at = b.ctx.chi.subst_constant(g, &gv).subst_constant(k, &kv);
    let coeffs: Coeffs<Q> =
        (0..=at.degree_in(l)).map(|d| at.coeff_in(l, d).as_constant().expect("univariate")).collect();
    let seq = sturm_sequence(&coeffs);
    let nv = b.ctx.nvars();
    let text = |c: &Coeffs<Q>| {
        let p = c
            .iter()
            .enumerate()
            .fold(Poly::zero(nv), |acc, (i, x)| acc.add(&Poly::var(nv, l).pow(i as u32).scale(x)));
        p.text(&b.ctx.names)
    };
    let sequence: Vec<String> = seq.iter().map(text).collect();
    // Above 0, so that the hypothesis lambda > 0 holds on the whole interval: the witness then
    // also shows that the region is not empty.
    let (lo, hi) = (Q::new(1, 10), Q::int(1));
    let roots = chatter_kernel::proof::count_roots(&coeffs, &seq, &lo, &hi).expect("a Sturm sequence");
    let disc = b.add(&b.mul(pp, pp), &b.mul(qq, &Frac::poly(Poly::constant(nv, Q::int(-4)))));
    let step = Step::Witness {
        id: "pcc.witness".into(),
        at: vec![("g".into(), gv.to_string()), ("k".into(), kv.to_string())],
        interval: (lo.to_string(), hi.to_string()),
        sequence,
        roots,
        positive: vec![b.text(&disc)],
    };
    b.raw(step, "FINDING: at gamma = 1/1000, kappa = 1/6 (the square plate) S_3 has a positive eigenvalue but p^2 - 4q > 0: all eigenvalues of S_3 S_1 are real, so the Lemma does not exclude PCC there; the paper's claim that its condition is never met for n >= 4, on which its Theorem squarefinal relies, is false");
}
