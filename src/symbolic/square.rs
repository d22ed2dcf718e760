//! The square-case lemmas of the paper (section "A semi-analytic construction for squares"),
//! proved symbolically for all parameters at once. Coordinates are the paper's (omega_x,
//! omega_y, v); points of the projection plane S (v = -1) are written (x, y).
//!
//! Hypotheses: 0 < gamma < 1, kappa > 0, and lambda a positive real root of the characteristic
//! polynomial chi of U_0 P_{pi/2} (for instance its dominant eigenvalue when that is real and
//! positive, as the paper assumes). Dominance is never used, so the results hold for every
//! positive eigenvalue.

use super::mpoly::{E1, E2, G, K, L, MPoly, S};
use super::proof::{Proof, Term};
use super::ratfn::RatFn;
use crate::exact::{Q, Ring};
use crate::model::square_paper_to_contact;
use chatter_kernel::model::Polygon as Body;
use chatter_kernel::model::linalg::mat_vec;
use std::cmp::Ordering;

type V3 = [RatFn; 3];
type M3 = [[RatFn; 3]; 3];

fn c(i: i64) -> RatFn {
    RatFn::int(i)
}
fn var(i: usize) -> RatFn {
    RatFn::var(i)
}
fn q_of(x: &Q) -> RatFn {
    RatFn::q(x.clone())
}
fn pt(x: RatFn, y: RatFn) -> V3 {
    [x, y, c(-1)]
}
fn mat_vec3(m: &M3, x: &V3) -> V3 {
    std::array::from_fn(|r| m[r][0].mul(&x[0]).add(&m[r][1].mul(&x[1])).add(&m[r][2].mul(&x[2])))
}
fn mat_mul3(a: &M3, b: &M3) -> M3 {
    std::array::from_fn(|r| {
        std::array::from_fn(|col| (0..3).fold(c(0), |acc, i| acc.add(&a[r][i].mul(&b[i][col]))))
    })
}
fn det3(m: &M3) -> RatFn {
    let t = |a: usize, b: usize, cc: usize| m[0][a].mul(&m[1][b]).mul(&m[2][cc]);
    t(0, 1, 2).add(&t(1, 2, 0)).add(&t(2, 0, 1)).sub(&t(2, 1, 0)).sub(&t(0, 2, 1)).sub(&t(1, 0, 2))
}
fn rot(quarter: i64) -> M3 {
    let (co, si) = match quarter.rem_euclid(4) {
        0 => (1, 0),
        1 => (0, 1),
        2 => (-1, 0),
        _ => (0, -1),
    };
    [[c(co), c(-si), c(0)], [c(si), c(co), c(0)], [c(0), c(0), c(1)]]
}
fn t_mat() -> M3 {
    [[c(-1), c(0), c(0)], [c(0), c(1), c(0)], [c(0), c(0), c(1)]]
}

/// The named points of the construction (formal e1, e2).
struct Points {
    named: Vec<(&'static str, V3)>,
}

impl Points {
    fn new() -> Self {
        let (e1, e2) = (var(E1), var(E2));
        let inv_l = c(1).div(&var(L));
        let named = vec![
            ("s1", pt(e1.clone(), c(-1))),
            ("s3", pt(e1.neg(), c(-1))),
            ("p1", pt(e1.clone(), e2.neg())),
            ("p3", pt(e1.neg(), e2.neg())),
            ("s01", pt(c(1), c(-1))),
            ("s12", pt(c(1), c(1))),
            ("s23", pt(c(-1), c(1))),
            ("s30", pt(c(-1), c(-1))),
            ("q1", pt(c(-1), e2.neg())),
            ("q3", pt(c(1), e2.neg())),
            ("k1", pt(e2.clone(), c(-1))),
            ("k3", pt(e2.neg(), c(-1))),
            ("r+", pt(e2.clone(), e2.neg())),
            ("r-", pt(e2.neg(), e2.neg())),
            ("w1", pt(inv_l.clone(), e2.neg())),
            ("w3", pt(inv_l.neg(), e2.neg())),
        ];
        Points { named }
    }
    fn get(&self, n: &str) -> V3 {
        self.named.iter().find(|(m, _)| *m == n).map(|(_, v)| v.clone()).expect("named point")
    }
    /// The name of a projected point equal to (x, y), if any.
    fn name_of(&self, x: &RatFn, y: &RatFn) -> Option<&'static str> {
        self.named.iter().find(|(_, v)| v[0].equals(x) && v[1].equals(y)).map(|(n, _)| *n)
    }
}

/// Decides the sign of an expression linear in e1, e2 from e1 > e2 > 1: writes
/// a + b e1 + c e2 = b (e1 - e2) + (b + c)(e2 - 1) + (a + b + c) and checks the certificate.
fn linear_sign(p: &mut Proof, id: &str, statement: &str, e: &RatFn, uses: &[&str]) -> Option<Ordering> {
    let num = &e.num;
    let den = e.den.as_constant()?;
    let coef = |v: Option<usize>| -> Q {
        let mut m = num.clone();
        for x in [G, K, L, S] {
            if m.degree_in(x) > 0 {
                return Q::int(i64::MAX);
            }
            m = m.coeff_in(x, 0);
        }
        let m = match v {
            Some(v) => m.coeff_in(v, 1).coeff_in(if v == E1 { E2 } else { E1 }, 0),
            None => m.coeff_in(E1, 0).coeff_in(E2, 0),
        };
        m.as_constant().map_or(Q::int(i64::MAX), |x| x / den.clone())
    };
    let (a, b, cc) = (coef(None), coef(Some(E1)), coef(Some(E2)));
    if [&a, &b, &cc].iter().any(|x| **x == Q::int(i64::MAX)) || num.degree_in(E1) > 1 || num.degree_in(E2) > 1
    {
        p.fact(id, statement, "linear sign in e1, e2", false, format!("{e} is not linear in e1, e2"), uses);
        return None;
    }
    let (alpha, beta, delta) = (b.clone(), &b + &cc, &(&a + &b) + &cc);
    let zero = Q::int(0);
    if alpha == zero && beta == zero && delta == zero {
        p.identity(id, statement, e, &c(0), false, uses);
        return Some(Ordering::Equal);
    }
    let (sign, e_pos, (al, be, de)) = if alpha >= zero && beta >= zero && delta >= zero {
        (Ordering::Greater, e.clone(), (alpha, beta, delta))
    } else if alpha <= zero && beta <= zero && delta <= zero {
        (Ordering::Less, e.neg(), (-alpha, -beta, -delta))
    } else {
        p.fact(
            id,
            statement,
            "linear sign in e1, e2",
            false,
            format!("the sign of {e} is not determined by e1 > e2 > 1"),
            uses,
        );
        return None;
    };
    let owned: Vec<(Q, Vec<&str>)> = [(al, vec!["e1-e2"]), (be, vec!["e2-1"]), (de, vec![])]
        .into_iter()
        .filter(|(x, _)| *x > zero)
        .collect();
    let terms: Vec<Term<'_>> = owned.iter().map(|(x, v)| (x.clone(), v.as_slice())).collect();
    p.positive(id, statement, &e_pos, &terms, &[], uses).then_some(sign)
}

/// Clips a polygon (named vertices) by the half-plane a x + b y + c >= 0, deciding every sign
/// with a certificate and naming every crossing point.
fn clip(
    p: &mut Proof,
    pts: &Points,
    poly: &[&'static str],
    hp: &[Q; 3],
    label: &str,
) -> Option<Vec<&'static str>> {
    let val = |v: &V3| q_of(&hp[0]).mul(&v[0]).add(&q_of(&hp[1]).mul(&v[1])).add(&q_of(&hp[2]));
    let mut signs = Vec::new();
    for n in poly {
        let id = format!("{label}.sign.{n}");
        let st = format!("sign of {}*x + {}*y + {} at {n}", hp[0], hp[1], hp[2]);
        signs.push(linear_sign(p, &id, &st, &val(&pts.get(n)), &["e1-e2", "e2-1"])?);
    }
    let mut out = Vec::new();
    let m = poly.len();
    for i in 0..m {
        let (a, b) = (poly[i], poly[(i + 1) % m]);
        let (sa, sb) = (signs[i], signs[(i + 1) % m]);
        if sa != Ordering::Less {
            out.push(a);
        }
        if sa != Ordering::Equal && sb != Ordering::Equal && sa != sb {
            let (va, vb) = (pts.get(a), pts.get(b));
            let (da, db) = (val(&va), val(&vb));
            let t = da.div(&da.sub(&db));
            let x = va[0].add(&t.mul(&vb[0].sub(&va[0])));
            let y = va[1].add(&t.mul(&vb[1].sub(&va[1])));
            let name = pts.name_of(&x, &y);
            let id = format!("{label}.cross.{a}-{b}");
            let st = format!("the edge {a}-{b} crosses the line at {}", name.unwrap_or("an unnamed point"));
            p.fact(
                id.as_str(),
                &st,
                "exact intersection, matched to a named point",
                name.is_some(),
                format!("({x}, {y})"),
                &[],
            );
            out.push(name?);
        }
    }
    Some(out)
}

/// Whether the projected point lies in K = [-e1, e1] x [-e2, -1] (four certified signs).
fn in_k(p: &mut Proof, pts: &Points, name: &str, uses: &[&str]) -> bool {
    let v = pts.get(name);
    let (x, y) = (v[0].clone(), v[1].clone());
    let checks = [
        ("x>=-e1", x.add(&var(E1))),
        ("x<=e1", var(E1).sub(&x)),
        ("y>=-e2", y.add(&var(E2))),
        ("y<=-1", c(-1).sub(&y)),
    ];
    let mut ok = true;
    for (what, e) in checks {
        let id = format!("in-K.{name}.{what}");
        let st = format!("{name} satisfies {what}");
        ok &= if name.starts_with('w') {
            // x = +-1/lambda: e1 -+ x = (e2 - 1)/lambda or e1 + 1/lambda, with e2 = lambda e1.
            let terms_owned: Vec<(Q, Vec<&str>)> = match what {
                "x>=-e1" | "x<=e1" if (what == "x<=e1") == (name == "w1") => vec![(Q::int(1), vec!["e2-1"])],
                "x>=-e1" | "x<=e1" => vec![(Q::int(1), vec!["e2-1"]), (Q::int(2), vec![])],
                _ => vec![],
            };
            if terms_owned.is_empty() {
                linear_sign(p, &id, &st, &e, uses).is_some_and(|s| s != Ordering::Less)
            } else {
                let terms: Vec<Term<'_>> =
                    terms_owned.iter().map(|(q, v)| (q.clone(), v.as_slice())).collect();
                p.positive(&id, &st, &e, &terms, &["l"], uses)
            }
        } else {
            linear_sign(p, &id, &st, &e, uses).is_some_and(|s| s != Ordering::Less)
        };
    }
    ok
}

/// Runs every lemma; the returned proof records every step and whether it checked.
pub fn prove() -> Proof {
    let (g, k, l) = (var(G), var(K), var(L));
    let one = c(1);
    let a = g.add(&one).div(&k.add(&one));
    let u0: M3 = [[c(1), c(0), c(0)], [c(0), one.sub(&a), a.clone()], [c(0), k.mul(&a), a.sub(&g)]];
    let m = mat_mul3(&u0, &rot(1));
    let lam_i: M3 = [[l.clone(), c(0), c(0)], [c(0), l.clone(), c(0)], [c(0), c(0), l.clone()]];
    let char_m: M3 = std::array::from_fn(|r| std::array::from_fn(|col| lam_i[r][col].sub(&m[r][col])));
    // (kappa + 1) det(lambda I - M) is a polynomial: divide out the denominator, a power of
    // kappa + 1 (monic in kappa), exactly.
    let det = det3(&char_m);
    let scaled = det.num.mul(&k.add(&one).num);
    let (chi, chi_rem) = scaled.div_rem_in(K, &det.den).expect("the denominator is monic in kappa");
    let chi_ok = chi_rem.is_zero() && chi.degree_in(L) == 3;
    let den_e1 = l.pow(2).mul(&k).add(&l.pow(2)).add(&k).sub(&g);
    let e1_paper = g.add(&one).div(&den_e1);
    let e1_simple = one.sub(&l).div(&k.mul(&one.add(&l.pow(2))));
    let e2_def = l.mul(&e1_paper);
    let mut p = Proof::new(chi.clone(), e1_paper.clone(), e2_def);
    let pts = Points::new();

    // --- Setting ---------------------------------------------------------------------------
    p.lemma("Setting");
    p.assume("H1", "0 < gamma < 1 and kappa > 0 (atoms g, 1-g, k)");
    p.assume("H2", "lambda > 0 is a real root of chi, e.g. the dominant eigenvalue of U_0 P_{pi/2} when it is real and positive (atom l)");
    p.atom("g", g.clone(), "H1");
    p.atom("1-g", one.sub(&g), "H1");
    p.atom("k", k.clone(), "H1");
    p.atom("l", l.clone(), "H2");
    p.fact(
        "chi",
        &format!("chi(lambda) = (kappa + 1) det(lambda I - U_0 P_{{pi/2}}) = {chi}"),
        "determinant of the paper's U_0 (equation U0, rho^2 = kappa) times P_{pi/2}, expanded exactly",
        chi_ok,
        String::new(),
        &[],
    );
    // The paper's U_0 P_{pi/2} is the kernel's S_3 (MODEL.md): same characteristic polynomial.
    let mut agree = true;
    for (gg, kk) in
        [(Q::new(1, 100), Q::new(1, 6)), (Q::new(3, 10), Q::int(2)), (Q::new(1, 20), Q::new(1, 10))]
    {
        let b = Body::new(4, kk.clone(), gg.clone()).expect("valid body");
        let (c2, c1, c0) = chatter_kernel::model::linalg::char_poly(&b.step(3));
        let at = |lam: &Q| (lam * lam * lam) - &(&c2 * &(lam * lam)) + &(&c1 * lam) - &c0;
        for lam in [Q::int(0), Q::int(1), Q::int(-2), Q::new(1, 3)] {
            let mine = chi.eval(&[gg.clone(), kk.clone(), lam.clone(), Q::int(0), Q::int(0), Q::int(0)]);
            agree &= mine == at(&lam) * (&kk + &Q::int(1));
        }
    }
    p.fact("model", "chi agrees with the characteristic polynomial of the kernel's exact step map S_3 at sample parameters", "exact evaluation at (gamma, kappa) in {(1/100, 1/6), (3/10, 2), (1/20, 1/10)}", agree, String::new(), &["chi"]);

    // --- lambda < 1 ---------------------------------------------------------------------------
    p.lemma("Lemma 0 (every positive eigenvalue is below 1)");
    let shifted = chi.subst(L, &MPoly::int(1).add(&MPoly::var(S)));
    let certs: [&[Term<'_>]; 4] = [
        &[(Q::int(2), &["g", "k"]), (Q::int(2), &["k"])],
        &[(Q::int(4), &["k"]), (Q::int(2), &["g", "k"]), (Q::int(1), &["1-g"])],
        &[(Q::int(3), &["k"]), (Q::int(2), &[]), (Q::int(1), &["g", "k"])],
        &[(Q::int(1), &["k"]), (Q::int(1), &[])],
    ];
    let mut coeff_ids = Vec::new();
    for (d, cert) in certs.iter().enumerate() {
        let id = format!("L0.s{d}");
        let coeff = RatFn::poly(shifted.coeff_in(S, d as u32));
        p.positive(
            &id,
            &format!("the coefficient of s^{d} in chi(1 + s) is positive"),
            &coeff,
            cert,
            &[],
            &["H1"],
        );
        coeff_ids.push(id);
    }
    let deg_ok = shifted.degree_in(S) == 3;
    let uses: Vec<&str> = coeff_ids.iter().map(String::as_str).collect();
    p.fact(
        "L0",
        "chi(1 + s) > 0 for every s >= 0, so every real root of chi is below 1: 0 < lambda < 1 (atom 1-l)",
        "all coefficients of the cubic chi(1 + s) in s are positive",
        deg_ok,
        String::new(),
        &uses,
    );
    p.atom("1-l", one.sub(&l), "L0");

    // --- auxiliary quantities ----------------------------------------------------------------------
    p.lemma("Auxiliary quantities");
    let d = k.mul(&one.add(&l.pow(2))).add(&one.sub(&l));
    let a_q = l.mul(&one.sub(&l)).sub(&k.mul(&one.add(&l.pow(2))));
    p.positive(
        "sq",
        "1 + lambda^2 > 0 (atom 1+l^2)",
        &one.add(&l.pow(2)),
        &[(Q::int(1), &[]), (Q::int(1), &["l", "l"])],
        &[],
        &[],
    );
    p.atom("1+l^2", one.add(&l.pow(2)), "sq");
    p.positive(
        "D",
        "D := kappa (1 + lambda^2) + 1 - lambda > 0 (atom D)",
        &d,
        &[(Q::int(1), &["k"]), (Q::int(1), &["k", "l", "l"]), (Q::int(1), &["1-l"])],
        &[],
        &[],
    );
    p.atom("D", d.clone(), "D");
    p.identity("gD", "gamma D = lambda A at every root, with A := lambda (1 - lambda) - kappa (1 + lambda^2): chi is linear in gamma and this is gamma solved from chi = 0", &g.mul(&d), &l.mul(&a_q), true, &["chi"]);
    p.positive(
        "A",
        "A > 0 (atom A): A = gamma D / lambda",
        &a_q,
        &[(Q::int(1), &["g", "D"])],
        &["l"],
        &["gD"],
    );
    p.atom("A", a_q.clone(), "A");

    // --- the eigenvector -------------------------------------------------------------------------
    p.lemma("Lemma l:r2, first part (the eigenvector p1)");
    p.identity("den", "(1 - lambda)(lambda^2 kappa + lambda^2 + kappa - gamma) = (gamma + 1) kappa (1 + lambda^2) at every root", &one.sub(&l).mul(&den_e1), &g.add(&one).mul(&k).mul(&one.add(&l.pow(2))), true, &["chi"]);
    p.positive(
        "den+",
        "the denominator lambda^2 kappa + lambda^2 + kappa - gamma of e1 is positive, so e1 is well defined",
        &den_e1,
        &[
            (Q::int(1), &["g", "k"]),
            (Q::int(1), &["g", "k", "l", "l"]),
            (Q::int(1), &["k"]),
            (Q::int(1), &["k", "l", "l"]),
        ],
        &["1-l"],
        &["den"],
    );
    p.identity("e1", "e1 = (gamma + 1)/(lambda^2 kappa + lambda^2 + kappa - gamma) equals (1 - lambda)/(kappa (1 + lambda^2))", &var(E1), &e1_simple, true, &["den"]);
    let p1 = pts.get("p1");
    let mp1 = mat_vec3(&m, &p1);
    let lp1: V3 = std::array::from_fn(|i| l.mul(&p1[i]));
    let mut ev_ok = true;
    for (i, axis) in ["omega_x", "omega_y", "v"].iter().enumerate() {
        ev_ok &= p.identity(
            &format!("eig.{i}"),
            &format!("component {axis} of U_0 P_{{pi/2}} p1 = lambda p1, p1 = [e1, -e2, -1], e2 = lambda e1"),
            &mp1[i],
            &lp1[i],
            true,
            &["chi"],
        );
    }
    p.fact(
        "eig",
        "p1 = [e1, -e2, -1] is an eigenvector of U_0 P_{pi/2} for lambda",
        "the three components above",
        ev_ok,
        String::new(),
        &["eig.0", "eig.1", "eig.2"],
    );

    // --- symmetry ------------------------------------------------------------------------------------
    p.lemma("Symmetry (equation tuk)");
    let t = t_mat();
    let m3 = mat_mul3(&u0, &rot(3));
    let tmt = mat_mul3(&t, &mat_mul3(&m, &t));
    let mut sym_ok = true;
    for r in 0..3 {
        for col in 0..3 {
            sym_ok &= m3[r][col].equals(&tmt[r][col]);
        }
    }
    p.fact(
        "tuk",
        "U_0 P_{3pi/2} = T U_0 P_{pi/2} T with T = diag(-1, 1, 1)",
        "entrywise identity of rational functions",
        sym_ok,
        String::new(),
        &[],
    );
    let m2 = mat_mul3(&u0, &rot(2));
    let tm2t = mat_mul3(&t, &mat_mul3(&m2, &t));
    let sym2 = (0..3).all(|r| (0..3).all(|col| m2[r][col].equals(&tm2t[r][col])));
    p.fact(
        "tuk2",
        "U_0 P_pi = T U_0 P_pi T",
        "entrywise identity of rational functions",
        sym2,
        String::new(),
        &[],
    );
    let tk = ["p1", "s1", "s01", "q1", "k1", "w1"].iter().zip(["p3", "s3", "s30", "q3", "k3", "w3"]).all(
        |(a, b)| {
            let ta = mat_vec3(&t, &pts.get(a));
            (0..3).all(|i| ta[i].equals(&pts.get(b)[i]))
        },
    );
    p.fact(
        "T",
        "T swaps p1/p3, s1/s3, s01/s30, q1/q3, k1/k3, w1/w3, so T K = K",
        "exact",
        tk,
        String::new(),
        &[],
    );

    // --- e1 > e2 > 1 ----------------------------------------------------------------------------------
    p.lemma("Lemma l:r2 (e1 > e2 > 1), proved for all parameters (the paper checked e2 > 1 numerically)");
    p.positive("e1>0", "e1 > 0", &var(E1), &[(Q::int(1), &["1-l"])], &["k", "1+l^2"], &["e1"]);
    p.positive(
        "e1>e2",
        "e1 - e2 = (1 - lambda)^2 / (kappa (1 + lambda^2)) > 0",
        &var(E1).sub(&var(E2)),
        &[(Q::int(1), &["1-l", "1-l"])],
        &["k", "1+l^2"],
        &["e1"],
    );
    p.positive(
        "e2>1",
        "e2 - 1 = gamma D / (kappa lambda (1 + lambda^2)) > 0: e2 > 1 is equivalent to gamma > 0",
        &var(E2).sub(&one),
        &[(Q::int(1), &["g", "D"])],
        &["k", "l", "1+l^2"],
        &["e1", "gD"],
    );
    p.atom("e1", var(E1), "e1>0");
    p.atom("e1-e2", var(E1).sub(&var(E2)), "e1>e2");
    p.atom("e2-1", var(E2).sub(&one), "e2>1");
    p.positive("1/l>1", "1/lambda > 1", &one.div(&l).sub(&one), &[(Q::int(1), &["1-l"])], &["l"], &["L0"]);
    p.positive(
        "e1>1/l",
        "e1 > 1/lambda (as e2 = lambda e1 > 1)",
        &var(E1).sub(&one.div(&l)),
        &[(Q::int(1), &["e2-1"])],
        &["l"],
        &["e2>1"],
    );
    p.fact("order", "along the line F0 (y = -1): s3, k3, s30, s01, k1, s1 in this order (x = -e1 < -e2 < -1 < 1 < e2 < e1); along F_e (y = -e2): p3, r-, q1, q3, r+, p1; w1 lies between q3 and p1, w3 between p3 and q1", "from e1 > e2 > 1 and 1 < 1/lambda < e1", true, String::new(), &["e1>e2", "e2>1", "1/l>1", "e1>1/l"]);

    // --- Lemma l:r1 -------------------------------------------------------------------------------------
    p.lemma("Lemma l:r1 (images of s30 and q1)");
    let vec_identity =
        |p: &mut Proof, id: &str, st: &str, lhs: &V3, rhs: &V3, modulo: bool, uses: &[&str]| -> bool {
            let mut ok = true;
            for i in 0..3 {
                ok &= p.identity(
                    &format!("{id}.{i}"),
                    &format!("{st}, component {i}"),
                    &lhs[i],
                    &rhs[i],
                    modulo,
                    uses,
                );
            }
            ok
        };
    vec_identity(
        &mut p,
        "r1.s30",
        "U_0 P_{pi/2} s30 = s01",
        &mat_vec3(&m, &pts.get("s30")),
        &pts.get("s01"),
        false,
        &[],
    );
    vec_identity(
        &mut p,
        "r1.q1",
        "U_0 P_{pi/2} q1 = k1",
        &mat_vec3(&m, &pts.get("q1")),
        &pts.get("k1"),
        false,
        &[],
    );

    // --- Lemma l:r4 -------------------------------------------------------------------------------------
    p.lemma("Lemma l:r4 (images of p1 and s1)");
    let s1 = pts.get("s1");
    let dec: V3 = std::array::from_fn(|i| p1[i].add(&pts.get("s30")[i]).sub(&pts.get("q1")[i]));
    vec_identity(&mut p, "r4.dec", "s1 = p1 + s30 - q1", &s1, &dec, false, &[]);
    let lw1: V3 = std::array::from_fn(|i| l.mul(&pts.get("w1")[i]));
    vec_identity(
        &mut p,
        "r4.s1",
        "U_0 P_{pi/2} s1 = lambda w1",
        &mat_vec3(&m, &s1),
        &lw1,
        true,
        &["chi", "eig"],
    );

    // --- The cones C_j in the plane, from the kernel's model ------------------------------------------
    p.lemma("The cones C_j on the plane S (derived from the kernel's exact model, MODEL.md §4)");
    let body = Body::new(4, Q::new(1, 6), Q::new(1, 100)).expect("valid");
    let conv = square_paper_to_contact::<Q>();
    let mut halfplanes: Vec<Vec<[Q; 3]>> = Vec::new();
    for j in 1..=3i64 {
        let mut hs = Vec::new();
        for cov in body.next_contact_cone(j) {
            // l . (M p) = (M^T l) . p; on the plane v = -1: a x + b y - c >= 0.
            let lp: [Q; 3] =
                std::array::from_fn(|col| (0..3).fold(Q::int(0), |acc, r| &acc + &(&cov[r] * &conv[r][col])));
            let h = [lp[0].clone(), lp[1].clone(), -&lp[2]];
            if !(h[0].is_zero() && h[1].is_zero()) {
                hs.push(h);
            }
        }
        let text: Vec<String> =
            hs.iter().map(|h| format!("{} x + {} y + {} >= 0", h[0], h[1], h[2])).collect();
        p.fact(
            &format!("C{j}"),
            &format!("C_{j} on S: {}", text.join(", ")),
            "the kernel's covectors of C_j converted to the paper's coordinates (v <= 0 holds on S)",
            true,
            String::new(),
            &[],
        );
        halfplanes.push(hs);
    }
    let dg_ok = body.all_down_generators().iter().zip(["s01", "s12", "s23", "s30"]).all(|(gv, name)| {
        // p_paper = (u1 - v, v - u0, v).
        let paper = [&gv[1] - &gv[2], &gv[2] - &gv[0], gv[2].clone()];
        let want = pts.get(name);
        (0..3).all(|i| want[i].equals(&q_of(&paper[i])))
    });
    p.fact("Dgen", "the all-down cone D has generators s01, s12, s23, s30 (the kernel's -m_{k,k+1} in the paper's coordinates)", "exact conversion", dg_ok, String::new(), &[]);
    let _ = mat_vec::<Q>;

    // --- K ∩ C_j ---------------------------------------------------------------------------------------
    p.lemma("K ∩ C_j (the paper reads these off its figures)");
    let k_poly = ["s3", "p3", "p1", "s1"];
    let claims: [&[&str]; 3] =
        [&["s01", "q3", "p3", "s3"], &["s30", "r-", "r+", "s01"], &["s30", "q1", "p1", "s1"]];
    let mut pieces: Vec<Vec<&'static str>> = Vec::new();
    for (j, hs) in halfplanes.iter().enumerate() {
        let mut poly: Vec<&'static str> = k_poly.to_vec();
        let mut ok = true;
        for (h_i, h) in hs.iter().enumerate() {
            match clip(&mut p, &pts, &poly, h, &format!("KC{}.{h_i}", j + 1)) {
                Some(next) => poly = next,
                None => {
                    ok = false;
                    break;
                }
            }
        }
        poly.dedup();
        let mut got: Vec<&str> = poly.clone();
        let mut want: Vec<&str> = claims[j].to_vec();
        got.sort();
        want.sort();
        let matches = ok && got == want;
        p.fact(
            &format!("KC{}", j + 1),
            &format!("K ∩ C_{} is the convex hull of {}", j + 1, claims[j].join(", ")),
            "exact clipping of K = [-e1, e1] x [-e2, -1] with every sign certified",
            matches,
            format!("computed vertices {poly:?}"),
            &["e1>e2", "e2>1"],
        );
        pieces.push(poly);
    }

    // --- Lemma lem:square -------------------------------------------------------------------------------
    p.lemma("Lemma lem:square (K = cone(p1, p3, s1, s3) is effectively invariant)");
    p.fact(
        "cond1",
        "condition 1: every generator of K has v = -1 < 0",
        "by construction",
        true,
        String::new(),
        &[],
    );
    let mut members = Vec::new();
    for name in ["s01", "s30", "k1", "k3", "p1", "p3", "w1", "w3", "r+", "q1"] {
        let ok = in_k(&mut p, &pts, name, &["e1-e2", "e2-1"]);
        p.fact(
            &format!("K.{name}"),
            &format!("{name} lies in K"),
            "four certified inequalities",
            ok,
            String::new(),
            &[],
        );
        members.push(ok);
    }
    let m1 = mat_mul3(&u0, &rot(3));
    let images_c3 = [("s30", "s01", false), ("q1", "k1", false), ("p1", "p1", true), ("s1", "w1", true)];
    let images_c1 = [("s01", "s30", false), ("q3", "k3", false), ("p3", "p3", true), ("s3", "w3", true)];
    for (map, label, imgs) in
        [(&m, "U_0 P_{pi/2} on K ∩ C_3", &images_c3), (&m1, "U_0 P_{3pi/2} on K ∩ C_1", &images_c1)]
    {
        let mut ok = true;
        for (from, to, scaled) in imgs {
            let img = mat_vec3(map, &pts.get(from));
            let want = pts.get(to);
            let want: V3 = if *scaled { std::array::from_fn(|i| l.mul(&want[i])) } else { want };
            let id = format!("img.{from}");
            ok &= vec_identity(
                &mut p,
                &id,
                &format!("{label}: the image of {from} is {}{to}", if *scaled { "lambda " } else { "" }),
                &img,
                &want,
                *scaled,
                &["chi", "eig"],
            );
        }
        let c = if label.contains("C_3") { "inv.C3" } else { "inv.C1" };
        p.fact(c, &format!("{label}: every vertex maps into K (images s01/s30, k1/k3, lambda p1/p3, lambda w1/w3, all in K; lambda > 0)"), "identities above and membership in K", ok, String::new(), &["KC3", "KC1", "K.s01", "K.s30", "K.k1", "K.k3", "K.p1", "K.p3", "K.w1", "K.w3"]);
    }
    // C_2: U_0 P_pi = U_0 P_{pi/2} P_{pi/2}; P_{pi/2} s30 = s01 and P_{pi/2} r- = r+, points of
    // K ∩ C_3, on the segments s30-s1 and q1-p1.
    let pm = rot(1);
    let p_s30 = mat_vec3(&pm, &pts.get("s30"));
    let p_rm = mat_vec3(&pm, &pts.get("r-"));
    let rot_ok = (0..3).all(|i| p_s30[i].equals(&pts.get("s01")[i]) && p_rm[i].equals(&pts.get("r+")[i]));
    let e1v = var(E1);
    let t_s = c(2).div(&e1v.add(&one)); // s01 = (1 - t) s30 + t s1
    let comb_ok = (0..3)
        .all(|i| pts.get("s01")[i].equals(&one.sub(&t_s).mul(&pts.get("s30")[i]).add(&t_s.mul(&s1[i]))));
    p.fact(
        "C2.rot",
        "P_{pi/2} s30 = s01, P_{pi/2} r- = r+, and s01 = (1 - t) s30 + t s1 with t = 2/(e1 + 1)",
        "exact",
        rot_ok && comb_ok,
        String::new(),
        &[],
    );
    p.positive(
        "e1+1",
        "e1 + 1 > 0",
        &e1v.add(&one),
        &[(Q::int(1), &["e1-e2"]), (Q::int(1), &["e2-1"]), (Q::int(2), &[])],
        &[],
        &[],
    );
    p.atom("e1+1", e1v.add(&one), "e1+1");
    p.positive("C2.t", "t = 2/(e1 + 1) > 0", &t_s, &[(Q::int(2), &[])], &["e1+1"], &["e1+1"]);
    p.positive(
        "C2.1-t",
        "1 - t = (e1 - 1)/(e1 + 1) > 0",
        &one.sub(&t_s),
        &[(Q::int(1), &["e1-e2"]), (Q::int(1), &["e2-1"])],
        &["e1+1"],
        &["e1+1"],
    );
    let u_s = var(E2).add(&one).div(&e1v.add(&one)); // r+ = (1 - u) q1 + u p1
    let comb2 =
        (0..3).all(|i| pts.get("r+")[i].equals(&one.sub(&u_s).mul(&pts.get("q1")[i]).add(&u_s.mul(&p1[i]))));
    p.fact("C2.r+", "r+ = (1 - u) q1 + u p1 with u = (e2 + 1)/(e1 + 1)", "exact", comb2, String::new(), &[]);
    p.positive("C2.u", "u > 0", &u_s, &[(Q::int(1), &["e2-1"]), (Q::int(2), &[])], &["e1+1"], &["e1+1"]);
    p.positive(
        "C2.1-u",
        "1 - u = (e1 - e2)/(e1 + 1) > 0",
        &one.sub(&u_s),
        &[(Q::int(1), &["e1-e2"])],
        &["e1+1"],
        &["e1+1"],
    );
    p.fact(
        "inv.C2",
        "U_0 P_pi on K ∩ C_2 = conv(s30, r-, r+, s01): U_0 P_pi s30 = U_0 P_{pi/2} s01 and U_0 P_pi r- = U_0 P_{pi/2} r+ lie in cone(K) because s01 and r+ are non-negative combinations of vertices of K ∩ C_3, whose images lie in K; U_0 P_pi s01 = T U_0 P_pi s30 and U_0 P_pi r+ = T U_0 P_pi r- by the symmetry, and T K = K",
        "convexity and the symmetry",
        true,
        String::new(),
        &["KC2", "inv.C3", "C2.rot", "C2.1-t", "C2.r+", "C2.u", "C2.1-u", "tuk2", "T"],
    );
    p.fact("lem:square", "K = cone(p1, p3, s1, s3) satisfies conditions 1 and 2 of the paper's Theorem on effectively invariant cones", "the three maps above", true, String::new(), &["cond1", "inv.C1", "inv.C2", "inv.C3"]);

    // --- Lemma l:k0 -------------------------------------------------------------------------------------
    p.lemma("Lemma l:k0 (every all-down drop lands in K)");
    let fixed = ["s01", "s30"].iter().all(|n| {
        let img = mat_vec3(&u0, &pts.get(n));
        (0..3).all(|i| img[i].equals(&pts.get(n)[i]))
    });
    p.fact("k0.fix", "U_0 fixes s01 and s30 (vertex 0 is at rest there)", "exact", fixed, String::new(), &[]);
    let img12 = mat_vec3(&u0, &pts.get("s12"));
    let z = img12[2].clone();
    let zz = k.mul(&c(2).mul(&l).sub(&one)).mul(&one.add(&l.pow(2))).add(&one.sub(&l));
    p.positive(
        "Z",
        "Z := kappa (2 lambda - 1)(1 + lambda^2) + 1 - lambda > 0 (atom Z)",
        &zz,
        &[
            (Q::int(1), &["1-l", "1-l", "1-l"]),
            (Q::int(1), &["1-l", "l"]),
            (Q::int(1), &["1-l", "A"]),
            (Q::int(1), &["k", "l"]),
            (Q::int(1), &["k", "l", "l", "l"]),
        ],
        &[],
        &[],
    );
    p.atom("Z", zz.clone(), "Z");
    p.positive(
        "k0.z",
        "U_0 s12 = [1, 1 - 2a, z] has z < 0: -z = Z / D",
        &z.neg(),
        &[(Q::int(1), &["Z"])],
        &["D"],
        &["chi"],
    );
    let x12 = img12[0].div(&z.neg());
    let y12 = img12[1].div(&z.neg());
    p.positive(
        "k0.x",
        "its projection x = 1/(-z) satisfies x <= e1",
        &var(E1).sub(&x12),
        &[
            (Q::int(1), &["1-l", "1-l", "1-l", "1-l"]),
            (Q::int(1), &["A", "1-l"]),
            (Q::int(1), &["A", "1-l", "1-l"]),
            (Q::int(1), &["A", "k"]),
            (Q::int(1), &["A", "k", "l", "l"]),
        ],
        &["k", "1+l^2", "Z"],
        &["chi", "e1"],
    );
    p.positive(
        "k0.y1",
        "y = (1 - 2a)/(-z) satisfies y >= -e2",
        &y12.add(&var(E2)),
        &[(Q::int(1), &["1-l", "1-l", "A"]), (Q::int(1), &["A", "A"])],
        &["k", "1+l^2", "Z"],
        &["chi", "e1"],
    );
    p.positive("k0.y2", "and y <= -1", &c(-1).sub(&y12), &[(Q::int(2), &["l", "A"])], &["Z"], &["chi"]);
    p.positive(
        "k0.x-",
        "and x >= -e1 (x = D/Z > 0)",
        &var(E1).add(&x12),
        &[(Q::int(1), &["e1", "Z"]), (Q::int(1), &["D"])],
        &["Z"],
        &["chi"],
    );
    let t_s12 = mat_vec3(&t, &pts.get("s12"));
    let mirror = (0..3).all(|i| t_s12[i].equals(&pts.get("s23")[i]));
    p.fact(
        "k0.s23",
        "U_0 s23 = T U_0 s12 (T s12 = s23 and U_0 T = T U_0), which lies in T K = K",
        "symmetry",
        mirror && sym_ok,
        String::new(),
        &["T", "tuk"],
    );
    p.fact("l:k0", "U_0 maps the generators s01, s12, s23, s30 of D into cone(K): the velocity after the first impact of every drop with all vertices moving down lies in K", "the steps above", true, String::new(), &["Dgen", "k0.fix", "k0.z", "k0.x", "k0.x-", "k0.y1", "k0.y2", "k0.s23"]);

    // --- PCC and the theorem ---------------------------------------------------------------------
    p.lemma("Lemma noPCC and the theorem for the square");
    let u3 = mat_mul3(&u0, &rot(3)); // U_0 P_{-pi/2} = U_0 P_{3pi/2}
    let nmat = mat_mul3(&m, &u3); // S_3 S_1 = U_0 P_{pi/2} U_0 P_{-pi/2}
    let sv = var(S);
    let char_n: M3 = std::array::from_fn(|r| {
        std::array::from_fn(|col| if r == col { sv.sub(&nmat[r][col]) } else { nmat[r][col].neg() })
    });
    let detn = det3(&char_n);
    let (quad, rem) = detn.num.div_rem_in(S, &MPoly::var(S).sub(&MPoly::int(1))).expect("s - 1 is monic");
    p.fact(
        "pcc.1",
        "t = 1 is an eigenvalue of U_0 P_{pi/2} U_0 P_{-pi/2} (its char. polynomial is divisible by t - 1)",
        "exact division",
        rem.is_zero(),
        String::new(),
        &[],
    );
    let (c2q, c1q, c0q) = (quad.coeff_in(S, 2), quad.coeff_in(S, 1), quad.coeff_in(S, 0));
    let qq = RatFn::new(c0q.clone(), c2q.clone());
    p.identity(
        "pcc.q",
        "the quadratic factor t^2 + p t + q has q = gamma^2 < 1, so complex roots have modulus gamma < 1",
        &qq,
        &g.mul(&g),
        false,
        &["pcc.1"],
    );
    let disc = c1q.mul(&c1q).sub(&c0q.mul(&c2q).scale(&Q::int(4)));
    let disc_r = RatFn::new(disc.clone(), c2q.mul(&c2q));
    p.fact("pcc.disc", &format!("its discriminant is Delta(gamma, kappa) = {disc_r}; Lemma noPCC excludes PCC exactly where Delta < 0"), "exact", true, String::new(), &["pcc.1"]);
    // The paper's claim that Delta < 0 always holds for n >= 4 is false: a witness in the region.
    let (wg, wk) = (Q::new(1, 1000), Q::new(1, 6));
    let at = [wg.clone(), wk.clone(), Q::int(0), Q::int(0), Q::int(0), Q::int(0)];
    let disc_w = disc_r.eval(&at).expect("defined");
    let chi_w = crate::spectral::poly::Poly::new((0..=3).map(|d| chi.coeff_in(L, d).eval(&at)).collect());
    let positive_root =
        crate::spectral::roots::isolate(&chi_w).into_iter().any(|mut r| r.sign() == Ordering::Greater);
    p.fact(
        "pcc.witness",
        &format!("FINDING: at gamma = {wg}, kappa = {wk} (the square plate) U_0 P_{{pi/2}} has a positive eigenvalue but Delta = {disc_w} > 0: all eigenvalues of U_0 P_{{pi/2}} U_0 P_{{-pi/2}} are real, so Lemma noPCC does not exclude PCC there; the paper's claim that its condition is never met for n >= 4, on which its Theorem squarefinal relies, is false"),
        "exact evaluation and exact root isolation",
        positive_root && disc_w > Q::int(0),
        String::new(),
        &["pcc.disc"],
    );
    p.fact(
        "theorem",
        "THEOREM (as proved here). Let 0 < gamma < 1, kappa > 0, and let U_0 P_{pi/2} have a positive eigenvalue (e.g. a real positive dominant one). Then every drop of the square with all vertices moving down ends in CC or PCC; where moreover Delta(gamma, kappa) < 0 it ends in CC. The paper's Theorem squarefinal (CC without the condition Delta < 0) is not established by its proof where Delta >= 0",
        "Lemma lem:square and Lemma l:k0 with the paper's Theorem on effectively invariant cones; Lemma noPCC where Delta < 0",
        true,
        String::new(),
        &["lem:square", "l:k0", "pcc.q", "pcc.disc", "pcc.witness"],
    );
    let _ = (members, pieces, e1_simple);
    p
}
