use crate::common::q;
use chatter::bodies;
use chatter::sweep::curves::{column, curves, row};
use chatter::sweep::grid::Variable;

#[test]
fn column_crossings_are_the_catalogue_thresholds() {
    // The square plate: the CC criterion's crossing at kappa = 1/6 is the body's CC threshold.
    let c = column(4, &q("1/6"));
    let e = bodies::user(4, &q("1/6")).unwrap();
    let (cc, pcc) = bodies::thresholds(&e, 12);
    assert_eq!(c.cc.len(), 1);
    assert!((c.cc[0].at - cc.midpoint.unwrap()).abs() < 1e-10, "{:?} vs {:?}", c.cc, cc.midpoint);
    assert!((c.pcc[0].at - pcc.unwrap().midpoint.unwrap()).abs() < 1e-10);
    assert!(c.cc.iter().all(|x| c.kind.iter().any(|k| k.at == x.at)), "CC changes are kind changes");
}

#[test]
fn no_false_crossing_from_samples_at_the_ends_or_on_exact_roots() {
    // At rho = 0.14 S_1's dominant eigenvalue is never complex for gamma in (0, 1) (it is at
    // gamma = 1 itself, which a sample at 1 used to report as a threshold).
    let c = column(3, &q("49/2500"));
    assert!(c.kind.iter().all(|x| !x.tag.starts_with("complex")), "{:?}", c.kind);
    // Along gamma = 1/20 the dominant eigenvalue becomes complex exactly at kappa = 1/2 (where
    // kappa + cos(2 pi/3) = 0), a rational root that a sample used to land on.
    let r = row(3, &q("1/20"), &q("1"));
    let complex: Vec<f64> = r.kind.iter().filter(|x| x.tag.starts_with("complex")).map(|x| x.at).collect();
    assert_eq!(complex, vec![0.5], "{:?}", r.kind);
}

#[test]
fn curves_link_columns_and_rows() {
    let c = curves(3, Variable::Rho, (&q("0"), &q("1")), (&q("0"), &q("1")), 24);
    assert!(!c.cc.is_empty() && !c.kind.is_empty() && !c.pcc.is_empty());
    // The CC boundary passes through (sqrt(1/8), (7 - 3 sqrt 5)/2).
    let (x, g) = ((1.0f64 / 8.0).sqrt(), (7.0 - 3.0 * 5f64.sqrt()) / 2.0);
    let near = c.cc.iter().flatten().any(|p| (p.0 - x).abs() < 0.03 && (p.1 - g).abs() < 0.03);
    assert!(near, "no CC curve point near the triangle plate's threshold");
    // The vertical boundary at kappa = 1/2 (rho = 0.7071...) comes from the rows.
    let vertical = c.kind.iter().any(|l| l.len() > 5 && l.iter().all(|p| (p.0 - 0.5f64.sqrt()).abs() < 1e-9));
    assert!(vertical);
}
