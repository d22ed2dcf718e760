//! The independent brute-force evaluator of certificates now lives in the tool, as
//! `chatter::oracle` (src/oracle.rs), so that fuzz targets can use it too; it is re-exported here
//! under its old name for the kernel tests. The tests below check the evaluator itself on small
//! hand-made cases.

pub use chatter::oracle::*;

use crate::common::{GAMMAS, KAPPAS, NS, body, q};
use chatter_kernel::certificate::{Claim, Code};

// ---------------------------------------------------------------------------------------------
// Tests of the evaluator itself.

fn pt(x: &str, y: &str) -> Pt {
    (q(x), q(y))
}

fn sorted(mut v: Vec<Pt>) -> Vec<Pt> {
    v.sort();
    v
}

#[test]
fn hull_primitives_on_a_square_with_extra_points() {
    let sq = [pt("0", "0"), pt("2", "0"), pt("2", "2"), pt("0", "2")];
    let mut pts = sq.to_vec();
    pts.extend([pt("1", "1"), pt("1", "0"), pt("2", "2"), pt("1/2", "3/2")]);
    assert_eq!(sorted(extreme_points(&pts)), sorted(sq.to_vec()));
    assert_eq!(ccw_hull(&pts), sq.to_vec());
    assert_eq!(twice_area(&ccw_hull(&pts)), q("8"));
    assert!(in_hull(&pt("2", "1"), &sq));
    assert!(in_hull(&pt("0", "0"), &sq));
    assert!(!in_hull(&pt("2", "3"), &sq));
    assert!(!in_hull(&pt("-1/1000", "1"), &sq));
    assert!(full_dimensional(&pts));
    assert!(!full_dimensional(&[pt("0", "0"), pt("1", "1"), pt("3", "3"), pt("1", "1")]));
    assert!(!full_dimensional(&[pt("0", "0"), pt("0", "0"), pt("0", "0")]));
    // The supporting half-planes are the four edges; their vertices are the square.
    let hp = supporting_half_planes(&pts);
    assert_eq!(hp.len(), 4, "{hp:?}");
    assert_eq!(sorted(polygon_vertices(&hp)), sorted(sq.to_vec()));
    // Clip by x + y <= 1 (a x + b y + c >= 0 with a = b = -1, c = 1): the triangle 0, (1,0), (0,1).
    let mut cons = hp.clone();
    cons.push(HalfPlane { a: q("-1"), b: q("-1"), c: q("1") });
    assert_eq!(sorted(polygon_vertices(&cons)), sorted(vec![pt("0", "0"), pt("1", "0"), pt("0", "1")]));
    // A constant false constraint empties it; a constant true one changes nothing.
    let mut empty = hp.clone();
    empty.push(HalfPlane { a: q("0"), b: q("0"), c: q("-1") });
    assert!(polygon_vertices(&empty).is_empty());
    let mut same = hp;
    same.push(HalfPlane { a: q("0"), b: q("0"), c: q("1") });
    assert_eq!(sorted(polygon_vertices(&same)), sorted(sq.to_vec()));
}

#[test]
fn collinear_and_tiny_sets() {
    let line = [pt("0", "0"), pt("3", "3"), pt("1", "1"), pt("3", "3")];
    assert_eq!(sorted(extreme_points(&line)), vec![pt("0", "0"), pt("3", "3")]);
    assert_eq!(extreme_points(&[pt("1", "2"), pt("1", "2")]), vec![pt("1", "2")]);
    assert!(extreme_points(&[]).is_empty());
    assert_eq!(orient2(&pt("0", "0"), &pt("1", "0"), &pt("0", "1")), q("1"));
    assert!(on_segment(&pt("1/2", "1/2"), &pt("0", "0"), &pt("1", "1")));
    assert!(!on_segment(&pt("2", "2"), &pt("0", "0"), &pt("1", "1")));
}

#[test]
fn pcc_quadratic_matches_the_kernel_and_fixes_one() {
    for n in NS {
        for kappa in KAPPAS {
            for gamma in GAMMAS {
                let b = body(n, kappa, gamma);
                let mine = pcc_quadratic(&b);
                let theirs = chatter_kernel::model::pcc_quadratic(&b).expect("1 is an eigenvalue");
                assert_eq!(
                    (&mine.p, &mine.q, &mine.discriminant),
                    (&theirs.p, &theirs.q, &theirs.discriminant)
                );
                assert_eq!(mine.excludes_pcc(), theirs.excludes_pcc(), "n={n} kappa={kappa} gamma={gamma}");
            }
        }
    }
    // The two cases used in kernel::check: PCC possible for the triangle at kappa = 1/8.
    let tri = pcc_quadratic(&body(3, "1/8", "1/100"));
    assert_eq!((tri.p.to_string(), tri.q.to_string()), ("-8401/90000".into(), "1/10000".into()));
    assert!(!tri.excludes_pcc());
    assert!(pcc_quadratic(&body(4, "1/6", "1/100")).excludes_pcc());
}

#[test]
fn evaluator_categories_on_hand_made_cones() {
    let b = body(4, "1/6", "1/100");
    // Generators with v >= 0 and collinear generators stop the evaluation early.
    let above = vec![[q("0"), q("0"), q("-1")], [q("1"), q("0"), q("0")], [q("0"), q("1"), q("-1")]];
    let v = evaluate_parts(&b, Claim::EffectivelyInvariant, &above);
    assert_eq!(
        (v.failing.clone(), v.first_stage.clone()),
        (vec![Code::GeneratorNotBelow], vec![Code::GeneratorNotBelow])
    );
    let flat = lifted(&[pt("0", "0"), pt("1", "1"), pt("2", "2")]);
    assert_eq!(evaluate_parts(&b, Claim::EffectivelyInvariant, &flat).failing, vec![Code::DegenerateCone]);
    // A huge triangle: some images leave v < 0 or K, and I_0(D) is checked only when claimed.
    let big = lifted(&[pt("-100", "-100"), pt("100", "-100"), pt("0", "100")]);
    let weak = evaluate_parts(&b, Claim::EffectivelyInvariant, &big);
    assert!(!weak.accepted());
    assert!(!weak.failing.contains(&Code::InitialOutside) && weak.pcc.is_none());
    // A tiny triangle far from the post-impact velocities fails I_0(D) ⊆ K.
    let tiny = lifted(&[pt("10", "10"), pt("11", "10"), pt("10", "11")]);
    let strong = evaluate_parts(&b, Claim::CompleteChatterFromAllDown, &tiny);
    assert!(strong.failing.contains(&Code::InitialOutside), "{strong:?}");
    assert!(!strong.failing.contains(&Code::PccNotExcluded), "PCC is excluded for the square plate");
    assert!(strong.pcc.as_ref().is_some_and(Quadratic::excludes_pcc));
    // Redundant: an interior point and a later duplicate.
    let mut with_extra = lifted(&[pt("0", "0"), pt("1/2", "1/2"), pt("2", "0"), pt("0", "2")]);
    with_extra.push([q("4"), q("0"), q("-2")]);
    let v = evaluate_parts(&b, Claim::EffectivelyInvariant, &with_extra);
    assert_eq!(v.redundant, vec![1, 4]);
    assert_eq!(v.k_ccw, vec![pt("0", "0"), pt("2", "0"), pt("0", "2")]);
}
