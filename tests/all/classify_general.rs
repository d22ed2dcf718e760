//! `chatter classify` for general convex bodies (docs/model.md §11.11, docs/bodies.md): the
//! products of impact maps around the polygon against the paper's S_1 for regular polygons
//! (S_1^n = W P_ccw W^-1), both directions' equal spectra, affine images of the square plate,
//! the command's text and JSON, bad input, and the general catalogue in `chatter bodies`.

use crate::common::{bin, q, root};
use chatter::bodies::convex::{polygon_plate, rectangle_plate, regular_polygon, regular_polygon_exact};
use chatter::bodies::general::general_catalogue;
use chatter::certify::transport::regular_image;
use chatter::exact::{Algebraic, OrderedField, Q};
use chatter::report::schema_file_name;
use chatter::spectral::convex::{Direction, product_around, product_criterion, product_profile};
use chatter::spectral::criteria::{Family, cc_criterion, cc_profile};
use chatter::spectral::eigen::{Dominant, char_poly3};
use chatter::spectral::poly::Poly;
use chatter_kernel::model::linalg::{Mat3, identity, mat_mul};
use chatter_kernel::model::{ConvexBody, Polygon};
use serde_json::Value;
use std::process::{Command, Output};

fn chatter(args: &[&str]) -> Output {
    let d = tempfile::tempdir().unwrap();
    Command::new(bin()).args(args).current_dir(d.path()).output().expect("run chatter")
}

fn power<F: OrderedField>(m: &Mat3<F>, k: usize) -> Mat3<F> {
    (0..k).fold(identity(), |acc, _| mat_mul(&acc, m))
}

/// The coefficients of a rational polynomial as elements of Q(sqrt 3).
fn lift(p: &Poly<Q>) -> Vec<Algebraic<Q>> {
    p.coeffs().iter().map(|c| Algebraic::rational(c.clone())).collect()
}

#[test]
fn p_ccw_is_conjugate_to_s1_to_the_n_for_regular_polygons() {
    let (mut agree, mut product_only) = (0, 0);
    for n in [3usize, 4, 6] {
        for kappa in ["1/8", "1/6", "1/3", "2"] {
            for gamma in ["0", "1/100", "1/20", "3/10", "1"] {
                let (k, g) = (q(kappa), q(gamma));
                let body = regular_polygon_exact(n, &k, &g).unwrap();
                let poly = Polygon::new(n as u64, k, g).unwrap();
                let s1n = char_poly3(&power(&poly.step(1), n));
                let s_last_n = char_poly3(&power(&poly.step(n as i64 - 1), n));
                let ccw = char_poly3(&product_around(&body, Direction::CounterClockwise));
                let cw = char_poly3(&product_around(&body, Direction::Clockwise));
                let at = format!("n = {n}, kappa = {kappa}, gamma = {gamma}");
                assert_eq!(ccw.coeffs(), &lift(&s1n)[..], "P_ccw vs S_1^n at {at}");
                assert_eq!(cw.coeffs(), &lift(&s_last_n)[..], "P_cw vs S_(n-1)^n at {at}");
                // S_1 real positive dominant => so is S_1^n; the converse can fail.
                let (cc, _, dom) = cc_criterion(&poly);
                let product = product_criterion(&body, Direction::CounterClockwise);
                if dom == Dominant::Positive {
                    assert_eq!(product.dominant, Dominant::Positive, "{at}");
                }
                if cc {
                    assert!(product.holds, "S_1 criterion holds but not P_ccw's at {at}");
                    agree += 1;
                } else if product.holds {
                    // Only where every eigenvalue of S_1 has modulus 1 (gamma = 1, docs/model.md §11.11).
                    assert_eq!(gamma, "1", "the criteria differ inside (0, 1) at {at}: S_1 {dom:?}");
                    product_only += 1;
                }
            }
        }
    }
    assert!(agree > 0 && product_only > 0, "{agree} points where both hold, {product_only} only P_ccw's");
}

/// Bodies with no symmetry: the directions are different matrices with the same spectrum.
fn irregular() -> Vec<ConvexBody<Q>> {
    let g = q("1/20");
    let mut out: Vec<ConvexBody<Q>> = general_catalogue(&g).unwrap().into_iter().map(|e| e.body).collect();
    let pts =
        vec![[q("3"), q("-1")], [q("1"), q("2")], [q("-2"), q("1")], [q("-1"), q("-2")], [q("1"), q("-3")]];
    out.push(ConvexBody::new(pts, [[q("2"), q("1/3")], [q("1/3"), q("1")]], g).unwrap());
    out
}

#[test]
fn both_directions_have_the_same_characteristic_polynomial() {
    let mut differ = 0;
    for body in irregular() {
        let ccw = product_around(&body, Direction::CounterClockwise);
        let cw = product_around(&body, Direction::Clockwise);
        differ += usize::from(ccw != cw);
        assert_eq!(char_poly3(&ccw), char_poly3(&cw), "{:?}", body.contacts());
    }
    assert!(differ >= 2, "the two products coincide as matrices on almost every body");
}

#[test]
fn affine_images_of_the_square_plate_have_the_square_products() {
    let (zero, one) = (Q::int(0), Q::int(1));
    let maps = [
        ([q("1"), q("-1/2")], [q("1"), q("1/2")]), // the 2 x 1 rectangle
        ([q("3"), q("0")], [q("1"), q("2")]),      // a parallelogram
        ([q("1/2"), q("1/5")], [q("-1/3"), q("7/4")]),
    ];
    for gamma in ["1/1000", "1/100", "1/20", "1/5", "3/5"] {
        let g = q(gamma);
        let square = regular_polygon(4, &zero, &one, q("1/6"), g.clone()).unwrap();
        let expect = char_poly3(&product_around(&square, Direction::CounterClockwise));
        let rect = rectangle_plate(&q("2"), &q("1"), g.clone()).unwrap();
        let mut images = vec![rect];
        images.extend(maps.iter().map(|(r0, r1)| regular_image(4, r0, r1, &q("1/6"), &g).unwrap()));
        for image in images {
            for dir in Direction::BOTH {
                let got = char_poly3(&product_around(&image, dir));
                assert_eq!(got, expect, "gamma = {gamma}, {:?}, {}", image.contacts(), dir.name());
            }
        }
    }
}

/// The affine images of the square plate (kappa = 1/6) and of the equilateral plate (kappa = 1/8)
/// have the paper's S_1 threshold in gamma (docs/model.md §11.7, §11.11).
#[test]
fn plate_thresholds_are_the_regular_plates() {
    let rect = rectangle_plate(&q("2"), &q("1"), q("1/20")).unwrap();
    let pts = vec![[q("0"), q("0")], [q("4"), q("0")], [q("0"), q("3")]];
    let triangle = polygon_plate(&pts, q("1/20")).unwrap();
    for (body, n, c1, kappa) in [(rect, 4, "0", "1/6"), (triangle, 3, "-1/2", "1/8")] {
        let ours = product_profile(&body, Direction::CounterClockwise).sup_lower_bound(40).unwrap();
        let regular = cc_profile(&Family { n, c1: q(c1), kappa: q(kappa) }).sup_lower_bound(40).unwrap();
        let gap = if ours > regular { &ours - &regular } else { &regular - &ours };
        assert!(gap < q("1/1000000000000"), "n = {n}: {ours} vs {regular}");
    }
}

fn text(o: &Output) -> (String, String) {
    (String::from_utf8_lossy(&o.stdout).into_owned(), String::from_utf8_lossy(&o.stderr).into_owned())
}

#[test]
fn classify_prints_both_conjectural_directions_for_a_rectangle_and_the_phone() {
    for (args, ccw, cw) in [
        (vec!["--rectangle", "2,1"], "I_0 I_3 I_2 I_1", "I_0 I_1 I_2 I_3"),
        (vec!["--body", "phone"], "I_0 I_3 I_2 I_1", "I_0 I_1 I_2 I_3"),
        (vec!["--body", "lander"], "I_0 I_2 I_1", "I_0 I_1 I_2"),
    ] {
        let mut all = vec!["classify", "--gamma", "1/20"];
        all.extend(&args);
        let o = chatter(&all);
        let (out, err) = text(&o);
        assert_eq!(o.status.code(), Some(0), "{args:?}: {err}");
        for needle in [
            format!("conjectural CC criterion, counter-clockwise ({ccw} has a real, positive dominant"),
            format!("conjectural CC criterion, clockwise ({cw} has a real, positive dominant"),
            "PCC lemma (proved, docs/model.md §11.6), pair (0, 1)".to_string(),
            "family finder (docs/model.md §11.12): ".to_string(),
            "simulation (evidence: 20 random drops in f64, budget 2000 impacts".to_string(),
            "certificate: ".to_string(),
        ] {
            assert!(out.contains(&needle), "{args:?}: missing {needle:?} in\n{out}");
        }
        let criteria: Vec<&str> = out.lines().filter(|l| l.contains("criterion")).collect();
        assert_eq!(criteria.len(), 2, "{out}");
        assert!(criteria.iter().all(|l| l.starts_with("conjectural")), "{out}");
    }
}

/// The committed schema of a document validates it.
fn assert_valid(doc: &Value) {
    let name = doc["schema"].as_str().unwrap();
    let path = root().join("docs/schema").join(schema_file_name(name));
    let schema: Value = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    let v = jsonschema::validator_for(&schema).unwrap();
    let errors: Vec<String> = v.iter_errors(doc).map(|e| e.to_string()).collect();
    assert!(errors.is_empty(), "{errors:#?}");
}

fn json(args: &[&str]) -> Value {
    let o = chatter(args);
    assert_eq!(o.status.code(), Some(0), "{args:?}: {}", text(&o).1);
    serde_json::from_slice(&o.stdout).unwrap()
}

#[test]
fn classify_json_of_a_rectangle_is_valid_and_matches_the_square() {
    for gamma in ["1/100", "1/20"] {
        let v = json(&["classify", "--rectangle", "2,1", "--gamma", gamma, "--json"]);
        assert_valid(&v);
        let g = &v["general_body"];
        for (dir, matrix) in [("counter_clockwise", "I_0 I_3 I_2 I_1"), ("clockwise", "I_0 I_1 I_2 I_3")] {
            assert_eq!(g[dir]["status"], "conjectural", "{v}");
            assert_eq!(g[dir]["criterion"]["matrix"], matrix);
        }
        assert_eq!(g["pairs"].as_array().unwrap().len(), 4);
        // The family finder ran; below the square's largest certified gamma (0.0295) it found a
        // family, above it it did not.
        let found = gamma == "1/100";
        assert_eq!(g["finder"]["outcome"] == "found", found, "gamma = {gamma}: {v}");
        assert!(g["finder"]["iterations"].as_u64().unwrap() >= 1);
        assert_eq!(g["body"]["contacts"][0][0]["exact"], "1");
        // The rectangle is an affine image of the square plate (kappa = 1/6): same verdict.
        let square = json(&["classify", "--n", "4", "--kappa", "1/6", "--gamma", gamma, "--json"]);
        assert!(square.get("general_body").is_none(), "regular JSON gained a field");
        assert_eq!(v["cc"]["holds"], square["cc"]["holds"], "gamma = {gamma}");
        assert_eq!(v["cc_threshold"]["decimal"], square["cc_threshold"]["decimal"]);
        let excluded = g["pairs"].as_array().unwrap().iter().all(|p| p["excluded"] == true);
        assert_eq!(Some(excluded), square["pcc"]["holds"].as_bool().map(|all_real| !all_real));
    }
}

#[test]
fn classify_rejects_bad_general_bodies_naming_the_flag() {
    for (args, flag) in [
        (vec!["--rectangle", "2,-1"], "--rectangle"),
        (vec!["--polygon", "0,0 4,0 0,3"], "--polygon"),
        (vec!["--rectangle", "2,1", "--velocity", "1,2"], "--velocity"),
        (vec!["--rectangle", "2,1", "--gamma", "2"], "--gamma"),
        (vec!["--rectangle", "2,1", "--n", "3"], "--n"),
    ] {
        let mut all = vec!["classify"];
        all.extend(&args);
        let o = chatter(&all);
        let (out, err) = text(&o);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {out}{err}");
        assert!(err.contains(flag), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{err}");
    }
}

#[test]
fn bodies_lists_the_general_catalogue() {
    let names = [("phone", 4), ("brick", 4), ("table", 4), ("lander", 3)];
    let o = chatter(&["bodies"]);
    let (out, err) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{err}");
    for (name, n) in names {
        let head = format!("{name} (general body, {n} contacts; gamma is not a property of the body)");
        assert!(out.contains(&head), "missing {head:?}");
    }
    let v = json(&["bodies", "--json"]);
    assert_valid(&v);
    let general = v["general"].as_array().unwrap();
    let got: Vec<(&str, usize)> =
        general.iter().map(|b| (b["name"].as_str().unwrap(), b["n"].as_u64().unwrap() as usize)).collect();
    assert_eq!(got, names);
    for b in general {
        assert_eq!(b["contacts"].as_array().unwrap().len() as u64, b["n"].as_u64().unwrap());
        assert!(b.get("gamma").is_none());
    }
    let only = json(&["bodies", "--only", "--plate", "4", "--json"]);
    assert!(only["general"].as_array().unwrap().is_empty());
}
