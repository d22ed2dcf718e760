//! Box certificates (docs/certificate-format.md §9): one cone for every (κ, γ) of
//! [κ_lo, κ_hi] × [γ_lo, γ_hi]. The oracle checks R2 and R3 at the four corners (every inequality
//! is affine in κ and in γ once multiplied by 1 + κ, docs/kernel-soundness.md §2 "Boxes") and then
//! tests that argument by brute force at interior rational points, where R2 and R3 must hold too.
//! R4 on the box is decided from the closed form of docs/model.md §11.6: the discriminant has the
//! sign of f(κ, γ) = (1 + γ)²(κ + c_1)² - 4γ(1 + κ)² when κ ≠ -c_1, and f is convex in γ (leading
//! coefficient (κ + c_1)² ≥ 0) and in κ (leading coefficient (1 - γ)² ≥ 0), so its maximum over
//! the box is at a corner: R4 holds on the box iff f < 0 at the four corners and -c_1 is not in
//! [κ_lo, κ_hi] (q = γ² < 1 needs γ_hi < 1, a rule of the claim). The closed form is checked
//! against the matrix computation at every point the oracle visits.

use super::model::{Polygon, V3};
use super::pcc::pcc_quadratic;
use super::rod::{Rod, V2, check_rod};
use super::rules::{Polygon2, all_down, check_point, cone_polygon, contains_translation, invariance};
use crate::arith::{Field, Num, Rat};
use crate::claim::Claim;
use crate::verdict::{Checked, Fail, Report};
use num_traits::{One, Signed};
use std::sync::Arc;

/// The generators of a box certificate: the rod's or a polygon's.
pub enum Gens<'a> {
    /// (u0, u1).
    Rod(&'a [V2]),
    /// (u0, u1, v), rational.
    Polygon(&'a [V3]),
}

/// Interior sample points (fractions of the sides) at which the corner argument is tested.
const SAMPLES: [(i64, i64, i64, i64); 2] = [(1, 3, 5, 7), (6, 7, 2, 9)];

/// Which rules [`at`] checks at a point.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Rules {
    /// R2.
    Invariance,
    /// R3.
    AllDown,
    /// R2 and R3.
    Both,
}

/// R2 and/or R3 at one point, for the rod or a polygon; whether K contains the post-impact
/// translation there.
fn at(n: usize, kappa: &Rat, gamma: &Rat, k: &Shape, rules: Rules, bits: u64) -> Checked<bool> {
    match k {
        Shape::Rod(g) => {
            let claim = if rules == Rules::Invariance {
                Claim::EffectivelyInvariant
            } else {
                Claim::CcOrPccFromAllDown
            };
            let r = check_rod(&Rod { kappa: kappa.clone(), gamma: gamma.clone() }, claim, g, bits)?;
            Ok(r.contains_translation == Some(true))
        }
        Shape::Polygon(p) => {
            let b = polygon(n, kappa, gamma);
            if rules != Rules::AllDown {
                invariance(&b, p)?;
            }
            if rules != Rules::Invariance {
                all_down(&b, p)?;
            }
            Ok(contains_translation(&b, p))
        }
    }
}

/// The cone, checked once (R1 does not depend on the parameters).
enum Shape<'a> {
    Rod(&'a [V2]),
    Polygon(Polygon2),
}

fn polygon(n: usize, kappa: &Rat, gamma: &Rat) -> Polygon {
    let f: Arc<Field> = Field::cos(n as u32);
    Polygon::new(n, Num::rational(&f, kappa.clone()), Num::rational(&f, gamma.clone()))
}

/// f(κ, γ) of the module documentation, with c_1 = cos 2π/n.
fn closed_form(n: usize, kappa: &Rat, gamma: &Rat) -> Rat {
    let c1 = Num::generator(&Field::cos(n as u32)).as_rational().expect("rational cos").clone();
    let one = Rat::one();
    let (a, b) = (&one + gamma, kappa + &c1);
    &a * &a * &b * &b - Rat::from_integer(4.into()) * gamma * (&one + kappa) * (&one + kappa)
}

/// R4 at one point from the matrix, cross-checked with the closed form's sign.
fn pcc_at(n: usize, kappa: &Rat, gamma: &Rat) -> bool {
    let quad = pcc_quadratic(&polygon(n, kappa, gamma));
    let f = closed_form(n, kappa, gamma);
    let c1 = Num::generator(&Field::cos(n as u32)).as_rational().expect("rational").clone();
    if *kappa != -c1 {
        assert_eq!(quad.discriminant.signum(), f.cmp(&Rat::from_integer(0.into())), "closed form of R4");
    }
    quad.excludes_pcc()
}

/// The four corners in the kernel's order, without repeats.
pub fn corners(k: &[Rat; 2], g: &[Rat; 2]) -> Vec<(Rat, Rat)> {
    let mut out: Vec<(Rat, Rat)> = vec![];
    for (ki, gi) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
        let c = (k[ki].clone(), g[gi].clone());
        if !out.contains(&c) {
            out.push(c);
        }
    }
    out
}

/// R4 on the box (n >= 3), from the closed form (module documentation).
pub fn pcc_on_box(n: usize, k: &[Rat; 2], g: &[Rat; 2]) -> Checked<()> {
    let cs = corners(k, g);
    let c1 = Num::generator(&Field::cos(n as u32)).as_rational().expect("rational").clone();
    let crosses = k[0] <= -c1.clone() && -c1 <= k[1];
    let corners_ok = cs.iter().all(|(kappa, gamma)| closed_form(n, kappa, gamma).is_negative());
    let sampled_ok = cs.iter().all(|(kappa, gamma)| pcc_at(n, kappa, gamma));
    assert!(crosses || corners_ok == sampled_ok, "closed form and matrix disagree at a corner");
    if crosses || !corners_ok {
        return Err(Fail::new("pcc-not-excluded", "the PCC quadratic has real roots somewhere on the box"));
    }
    Ok(())
}

/// All rules on a box (the file's rules already checked).
pub fn check_box(
    n: usize,
    k: &[Rat; 2],
    g: &[Rat; 2],
    claim: Claim,
    gens: &Gens,
    bits: u64,
) -> Checked<Report> {
    let cs = corners(k, g);
    let drops = claim >= Claim::CcOrPccFromAllDown;
    // R1 once, with the report of the first corner (pieces and redundant generators are the same
    // at every corner).
    let mut report = match gens {
        Gens::Rod(g) => check_rod(
            &Rod { kappa: cs[0].0.clone(), gamma: cs[0].1.clone() },
            Claim::EffectivelyInvariant,
            g,
            bits,
        ),
        Gens::Polygon(g) => {
            check_point(&polygon(n, &cs[0].0, &cs[0].1), Claim::EffectivelyInvariant, g, bits)
        }
    }?;
    let shape = match gens {
        Gens::Rod(g) => Shape::Rod(g),
        Gens::Polygon(g) => Shape::Polygon(cone_polygon(g)?),
    };
    // R2 at every corner (the first one is done), then R3 at every corner (the kernel's order).
    for (kappa, gamma) in &cs[1..] {
        at(n, kappa, gamma, &shape, Rules::Invariance, bits)?;
    }
    let mut translation = true;
    for (kappa, gamma) in &cs {
        let rules = if drops { Rules::AllDown } else { Rules::Invariance };
        translation &= at(n, kappa, gamma, &shape, rules, bits)?;
    }
    let both = if drops { Rules::Both } else { Rules::Invariance };
    for (a, b, c, d) in SAMPLES {
        let kappa = &k[0] + (&k[1] - &k[0]) * Rat::new(a.into(), b.into());
        let gamma = &g[0] + (&g[1] - &g[0]) * Rat::new(c.into(), d.into());
        if let Err(f) = at(n, &kappa, &gamma, &shape, both, bits) {
            let why =
                format!("the corners pass but ({kappa}, {gamma}) fails ({}): {}", f.codes.join(", "), f.why);
            return Err(Fail::new("corner-argument-violated", why));
        }
    }
    if claim == Claim::CompleteChatterFromAllDown && n >= 3 {
        pcc_on_box(n, k, g)?;
    }
    report.claim = claim.name().into();
    report.contains_translation = Some(translation);
    let t = crate::arith::rational::rational_text;
    report.region = Some([[t(&k[0]), t(&k[1])], [t(&g[0]), t(&g[1])]]);
    Ok(report)
}

/// Every rule on a box evaluated on its own (R1 alone if it fails; then R2 at the corners, R3 at
/// the corners, R4), for [`crate::isolate`].
pub fn box_failures(
    n: usize,
    k: &[Rat; 2],
    g: &[Rat; 2],
    claim: Claim,
    gens: &Gens,
) -> Checked<Vec<&'static str>> {
    let cs = corners(k, g);
    let shape = match gens {
        Gens::Rod(g) => {
            super::rod::interval(g)?;
            Shape::Rod(g)
        }
        Gens::Polygon(g) => Shape::Polygon(cone_polygon(g)?),
    };
    let mut out = vec![];
    let mut add = |r: Checked<bool>| {
        if let Err(f) = r {
            out.extend(f.codes);
        }
    };
    for (kappa, gamma) in &cs {
        add(at(n, kappa, gamma, &shape, Rules::Invariance, 0));
    }
    if claim >= Claim::CcOrPccFromAllDown {
        for (kappa, gamma) in &cs {
            add(at(n, kappa, gamma, &shape, Rules::AllDown, 0));
        }
    }
    if claim == Claim::CompleteChatterFromAllDown && n >= 3 {
        let c1 = Num::generator(&Field::cos(n as u32)).as_rational().expect("rational").clone();
        let crosses = k[0] <= -c1.clone() && -c1 <= k[1];
        if crosses || !cs.iter().all(|(kappa, gamma)| closed_form(n, kappa, gamma).is_negative()) {
            out.push("pcc-not-excluded");
        }
    }
    out.sort_unstable();
    out.dedup();
    Ok(out)
}
