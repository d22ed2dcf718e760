//! The float model of a regular n-gon (issue 10 §1): a differential test against the exact model
//! for n = 3, 4, 6, and identities of docs/model.md §2-4 for every n up to 64.

use crate::common::{GAMMAS, KAPPAS, NS, body, q};
use chatter::exact::QExt;
use chatter::model::FloatBody;
use chatter::model::float::{FloatPolygon, MAX_FLOAT_CONTACTS, cos_sin_turn};
use chatter::simulate::{FloatSystem, Model, Shape, regular};
use chatter_kernel::model::BodyError;
use chatter_kernel::model::linalg::{Mat3, Vec3};
use nalgebra::{Matrix3, Vector3};

/// Agreement required between the float model and the rounded exact model.
const TOL: f64 = 1e-12;

fn close(a: f64, b: f64, what: &str) {
    assert!((a - b).abs() <= TOL * (1.0 + b.abs()), "{what}: float {a} vs exact {b}");
}

fn close_vec(a: &Vector3<f64>, b: &Vec3<chatter::exact::Q>, what: &str) {
    for i in 0..3 {
        close(a[i], b[i].to_f64(), what);
    }
}

fn close_mat(a: &Matrix3<f64>, b: &Mat3<chatter::exact::Q>, what: &str) {
    for r in 0..3 {
        for c in 0..3 {
            close(a[(r, c)], b[r][c].to_f64(), what);
        }
    }
}

fn float_of(n: u64, kappa: &str, gamma: &str) -> FloatPolygon {
    FloatPolygon::new(n, q(kappa).to_f64(), q(gamma).to_f64()).expect("valid float body")
}

#[test]
fn float_model_agrees_with_the_exact_model_for_n_3_4_6() {
    for n in NS {
        for kappa in KAPPAS {
            for gamma in GAMMAS {
                let (e, f) = (body(n, kappa, gamma), float_of(n, kappa, gamma));
                let at = format!("n={n} kappa={kappa} gamma={gamma}");
                for k in 0..n as i64 {
                    close_vec(&f.contact(k), e.contact(k), &format!("f_{k} at {at}"));
                    close_vec(&f.impact_direction(k), &e.impact_direction(k), &format!("d_{k} at {at}"));
                    close_mat(&f.impact(k), &e.impact(k), &format!("I_{k} at {at}"));
                    close_vec(&f.rest_point(k, k + 1).unwrap(), &e.rest_point(k, k + 1).unwrap(), &at);
                    close(f.cos(k), e.cos(k).to_f64(), &format!("c_{k} at {at}"));
                }
                for j in 1..n as i64 {
                    close_mat(&f.step(j), &e.step(j), &format!("S_{j} at {at}"));
                    for (a, b) in f.next_contact_cone(j).iter().zip(e.next_contact_cone(j)) {
                        close_vec(a, &b, &format!("C_{j} at {at}"));
                    }
                }
                for (a, b) in f.all_down_generators().iter().zip(e.all_down_generators()) {
                    close_vec(a, &b, &format!("D at {at}"));
                }
                close(f.beta(), e.beta().to_f64(), &at);
            }
        }
    }
}

#[test]
fn float_finder_maps_agree_with_the_rounded_exact_maps() {
    for n in NS {
        let (e, f) = (body(n, "3/20", "1/20"), float_of(n, "3/20", "1/20"));
        let (a, b) = (FloatBody::from_float(&f), FloatBody::new(&e));
        assert_eq!((a.n, a.steps.len(), a.cones.len()), (b.n, b.steps.len(), b.cones.len()));
        assert!((a.impact0 - b.impact0).abs().max() <= TOL);
        for (x, y) in a.steps.iter().zip(&b.steps) {
            assert!((x - y).abs().max() <= TOL, "n={n}: {x} vs {y}");
        }
        for (x, y) in a.cones.iter().flatten().zip(b.cones.iter().flatten()) {
            assert!((x - y).abs().max() <= TOL, "n={n}: {x} vs {y}");
        }
        for (x, y) in a.all_down.iter().zip(&b.all_down) {
            assert!((x - y).abs().max() <= TOL, "n={n}: {x} vs {y}");
        }
    }
}

/// The simulator's `f64` system of the float model against the rounded exact one: covectors,
/// kicks, energy, the paper's coordinates, neighbours, the PCC Lemma (exactly equal) and frames.
#[test]
fn float_system_agrees_with_the_rounded_exact_system() {
    for n in NS {
        for (kappa, gamma) in [("1/8", "1/200"), ("3/20", "1/20"), ("1/6", "1/100"), ("2", "9/10")] {
            let exact = Model::new(Shape::Polygon(n), q(kappa), q(gamma)).unwrap().float;
            let float = regular::float_system(n, &q(kappa), &q(gamma)).unwrap();
            let at = format!("n={n} kappa={kappa} gamma={gamma}");
            let rows = |a: &[[f64; 3]], b: &[[f64; 3]], what: &str| {
                assert_eq!(a.len(), b.len(), "{what} at {at}");
                for (x, y) in a.iter().zip(b) {
                    for i in 0..3 {
                        close(x[i], y[i], &format!("{what} at {at}"));
                    }
                }
            };
            rows(&float.f, &exact.f, "f");
            rows(&float.kick, &exact.kick, "kick");
            rows(&float.gram, &exact.gram, "gram");
            rows(&float.rest_paper, &exact.rest_paper, "rest_paper");
            assert_eq!(float.centre, exact.centre);
            close(float.cos1, exact.cos1, &at);
            close(float.sin1, exact.sin1, &at);
            assert_eq!((float.pcc_possible, &float.adjacent), (exact.pcc_possible, &exact.adjacent), "{at}");
            assert_eq!(float.frames.len(), exact.frames.len());
            for (a, b) in float.frames.iter().zip(&exact.frames).filter(|(a, _)| !a.f.is_empty()) {
                assert_eq!((a.slots, &a.slot), (b.slots, &b.slot), "{at}");
                rows(&a.f, &b.f, "frame f");
                rows(&a.kick, &b.kick, "frame kick");
                rows(&a.gram, &b.gram, "frame gram");
                rows(&a.to_ours, &b.to_ours, "frame to_ours");
            }
        }
    }
}

#[test]
fn the_pcc_lemma_in_the_number_field_agrees_with_the_rationals() {
    for n in NS {
        for kappa in KAPPAS {
            for gamma in GAMMAS {
                let m = Model::new(Shape::Polygon(n), q(kappa), q(gamma)).unwrap();
                let field = regular::pcc_possible(n, &q(kappa), &q(gamma));
                assert_eq!(field, m.system().pcc_possible(), "n={n} kappa={kappa} gamma={gamma}");
            }
        }
    }
    // For n >= 5, c_1 = cos 2π/n > 0, so E = β(κ + c_1) > 0: an impact lifts the neighbours.
    assert!(!regular::pcc_possible(5, &q("1/20"), &q("1/100")));
    assert!(!regular::pcc_possible(8, &q("1/20"), &q("1/100")));
}

#[test]
fn identities_hold_for_every_n() {
    for n in 3..=MAX_FLOAT_CONTACTS {
        let (kappa, gamma) = (0.15, 0.3);
        let f = FloatPolygon::new(n, kappa, gamma).unwrap();
        for k in 0..n as i64 {
            // u_k+ = -γ u_k- (docs/model.md §3): f_k·kick_k = 1 + γ.
            close(f.contact(k).dot(&f.kick(k)), 1.0 + gamma, &format!("n={n} k={k}"));
            // h_k vanishes at the rest points of its two edges (docs/model.md §4).
            for m in [f.rest_point(k - 1, k).unwrap(), f.rest_point(k, k + 1).unwrap()] {
                assert!(f.contact(k).dot(&m).abs() < 1e-11, "n={n} k={k}");
            }
        }
        // det I_0 = -γ and det R_j = 1 (docs/model.md §3).
        close(f.impact(0).determinant(), -gamma, &format!("n={n}"));
        for j in 1..n as i64 {
            assert!((f.relabel(j).determinant() - 1.0).abs() < 1e-9, "n={n} j={j}");
            // The four generators of the paper's Lemma lie in C_j.
            let m = |k: i64| f.rest_point(k, k + 1).unwrap();
            let gens = [m(j - 1) - m(-1), -m(-1), -m(0), m(j) - m(0)];
            for l in f.next_contact_cone(j) {
                for g in &gens {
                    assert!(l.dot(g) >= -1e-9, "n={n} j={j}: {l} . {g}");
                }
            }
        }
        // S_1 and S_{n-1} are conjugate (mirror symmetry): equal traces and determinants.
        let (s1, sl) = (f.step(1), f.step(n as i64 - 1));
        assert!((s1.trace() - sl.trace()).abs() < 1e-9 && (s1.determinant() - sl.determinant()).abs() < 1e-9);
    }
}

#[test]
fn quarter_turns_are_exact_and_bad_bodies_are_refused() {
    assert_eq!(cos_sin_turn(1, 4), (0.0, 1.0));
    assert_eq!(cos_sin_turn(2, 4), (-1.0, 0.0));
    assert_eq!(cos_sin_turn(-1, 8), (cos_sin_turn(7, 8).0, cos_sin_turn(7, 8).1));
    assert_eq!(cos_sin_turn(3, 12).0, 0.0);
    for n in [0, 1, 2, MAX_FLOAT_CONTACTS + 1] {
        assert_eq!(FloatPolygon::new(n, 0.1, 0.1).unwrap_err(), BodyError::UnsupportedN(n));
    }
    assert_eq!(FloatPolygon::new(5, 0.0, 0.1).unwrap_err(), BodyError::KappaNotPositive);
    assert_eq!(FloatPolygon::new(5, f64::NAN, 0.1).unwrap_err(), BodyError::KappaNotPositive);
    assert_eq!(FloatPolygon::new(5, 0.1, 1.5).unwrap_err(), BodyError::GammaOutOfRange);
    let bad =
        |n: u64, kappa: &str, gamma: &str| Model::new(Shape::Polygon(n), q(kappa), q(gamma)).unwrap_err();
    assert_eq!(bad(65, "1/6", "1/100"), BodyError::UnsupportedN(65));
    assert_eq!(bad(7, "-1/6", "1/100"), BodyError::KappaNotPositive);
    assert_eq!(bad(7, "1/6", "-1/100"), BodyError::GammaOutOfRange);
    let _: FloatSystem = regular::float_system(64, &q("1/6"), &q("1/100")).unwrap();
}
