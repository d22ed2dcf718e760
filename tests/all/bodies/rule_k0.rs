//! Rule K0 (issue 25 §1, docs/certificate-format.md §13): a family certificate may record the
//! body's full inertia tensor, and the kernel accepts it only when the planar J is its J_eff.
//! The tensors here are built around the corpus lander's J, so that every other rule holds;
//! J_eff is recomputed independently as the inverse of the upper-left 2×2 block of I⁻¹
//! (docs/model.md Proposition 11.0), never with the kernel's Schur complement.

use crate::common::{bin, root};
use chatter::exact::Q;
use chatter_kernel::exact::ParseLimits;
use chatter_kernel::reject::Code;
use chatter_kernel::syntax::family::{ConvexBodyText, ConvexCertificate};
use chatter_kernel::syntax::{Encoding, read};
use chatter_kernel::verify::{BOTH, Verdict, verify_convex_on};

const LANDER: &str = "certificates/valid/convex-lander-gamma1_20-inertia-tensor.ron";

fn lander() -> ConvexCertificate {
    read(&std::fs::read_to_string(root().join(LANDER)).unwrap(), Encoding::Ron).unwrap()
}

fn q(s: &str) -> Q {
    s.parse().unwrap()
}

/// The certificate's J as rationals (Jxx, Jxy, Jyy).
fn planar(c: &ConvexCertificate) -> [Q; 3] {
    let ConvexBodyText::ConvexPolygon { inertia, .. } = &c.body;
    [q(&inertia.0), q(&inertia.1), q(&inertia.2)]
}

fn with_tensor(c: &ConvexCertificate, t: &[Q; 6]) -> ConvexCertificate {
    let mut c = c.clone();
    let ConvexBodyText::ConvexPolygon { inertia_tensor, .. } = &mut c.body;
    let s = t.clone().map(|x| x.to_string());
    *inertia_tensor =
        Some((s[0].clone(), s[1].clone(), s[2].clone(), s[3].clone(), s[4].clone(), s[5].clone()));
    c
}

/// J_eff as the inverse of the upper-left 2×2 block of I⁻¹ (adjugates, exact).
fn j_eff_by_inversion(t: &[Q; 6]) -> [Q; 3] {
    let [xx, xy, xz, yy, yz, zz] = t.clone();
    let m = [[xx, xy.clone(), xz.clone()], [xy, yy, yz.clone()], [xz, yz, zz]];
    let cof = |r: usize, c: usize| {
        let (r1, r2, c1, c2) = ((r + 1) % 3, (r + 2) % 3, (c + 1) % 3, (c + 2) % 3);
        &(&m[r1][c1] * &m[r2][c2]) - &(&m[r1][c2] * &m[r2][c1])
    };
    let det = (0..3).fold(Q::int(0), |s, c| &s + &(&m[0][c] * &cof(0, c)));
    // (I⁻¹)_{rc} = cof(c, r) / det; the block's inverse is adj(block) / det(block).
    let inv = |r: usize, c: usize| &cof(c, r) / &det;
    let (a, b, d) = (inv(0, 0), inv(0, 1), inv(1, 1));
    let det2 = &(&a * &d) - &(&b * &b);
    [&d / &det2, &(-&b) / &det2, &a / &det2]
}

fn code(c: &ConvexCertificate) -> Option<Code> {
    match verify_convex_on(c, ParseLimits::default(), &BOTH) {
        Verdict::Accepted(_) => None,
        Verdict::Rejected(r) => Some(r.code),
        Verdict::Disagree(s) => panic!("the backends disagree: {s}"),
    }
}

/// Tensors I = [[J + b bᵀ/c, b], [bᵀ, c]] for many b and c > 0 have J_eff = J (checked by
/// inversion): the kernel accepts each; moving any one entry by 1/1000 (with b ≠ 0) changes
/// J_eff, and the kernel rejects it with `inertia-not-derived`, the rest of the file unchanged.
#[test]
fn the_kernel_accepts_exactly_the_tensors_whose_j_eff_is_the_certificates_j() {
    let base = lander();
    let [jxx, jxy, jyy] = planar(&base);
    let mut accepted = 0;
    for (bx, by, c) in
        [("4/375", "0", "7/5"), ("-1/7", "1/9", "2"), ("1/3", "-2/5", "11/10"), ("0", "1/50", "1/2")]
    {
        let (bx, by, c) = (q(bx), q(by), q(c));
        let t = [
            &jxx + &(&(&bx * &bx) / &c),
            &jxy + &(&(&bx * &by) / &c),
            bx.clone(),
            &jyy + &(&(&by * &by) / &c),
            by.clone(),
            c.clone(),
        ];
        assert_eq!(j_eff_by_inversion(&t), [jxx.clone(), jxy.clone(), jyy.clone()], "the test's own tensor");
        assert_eq!(code(&with_tensor(&base, &t)), None, "{t:?}");
        accepted += 1;
        for k in 0..6 {
            let mut moved = t.clone();
            moved[k] = &moved[k] + &Q::new(1, 1000);
            let unchanged = j_eff_by_inversion(&moved) == [jxx.clone(), jxy.clone(), jyy.clone()];
            let expected = if unchanged { None } else { Some(Code::InertiaNotDerived) };
            assert_eq!(code(&with_tensor(&base, &moved)), expected, "entry {k} moved: {moved:?}");
        }
    }
    assert_eq!(accepted, 4);
}

/// Izz <= 0 is refused before any entry is compared (no rigid body has such a tensor), and a
/// certificate without a tensor is unaffected by rule K0.
#[test]
fn a_tensor_with_izz_not_positive_is_refused_and_no_tensor_means_no_rule_k0() {
    let base = lander();
    let [jxx, jxy, jyy] = planar(&base);
    for izz in ["0", "-1"] {
        let t = [jxx.clone(), jxy.clone(), Q::int(0), jyy.clone(), Q::int(0), q(izz)];
        assert_eq!(code(&with_tensor(&base, &t)), Some(Code::InertiaNotDerived), "Izz = {izz}");
    }
    let mut bare = base.clone();
    let ConvexBodyText::ConvexPolygon { inertia_tensor, .. } = &mut bare.body;
    *inertia_tensor = None;
    assert_eq!(code(&bare), None);
}

/// `chatter certify --body lander` records the catalogue's tensor, `verify` names rule K0 in text
/// and JSON, and the JSON twin keeps the tensor (RON -> JSON -> RON is byte-identical).
#[test]
fn certify_records_the_tensor_and_verify_and_convert_keep_it() {
    let d = tempfile::tempdir().unwrap();
    let ron = d.path().join("lander.ron");
    let run = |args: &[&str]| std::process::Command::new(bin()).args(args).output().unwrap();
    let o = run(&["certify", "--body", "lander", "--gamma", "1/20", "-o", ron.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stdout).contains("J is its J_eff (rule K0)"));
    let written = std::fs::read_to_string(&ron).unwrap();
    assert_eq!(
        written,
        std::fs::read_to_string(root().join(LANDER)).unwrap(),
        "the corpus file is certify's"
    );
    let tensor = chatter::bodies::general::general_catalogue(&Q::new(1, 20))
        .unwrap()
        .into_iter()
        .find(|e| e.name == "lander")
        .unwrap()
        .tensor
        .urdf();
    let cert: ConvexCertificate = read(&written, Encoding::Ron).unwrap();
    let ConvexBodyText::ConvexPolygon { inertia_tensor: Some(t), .. } = &cert.body else {
        panic!("no tensor")
    };
    assert_eq!([&t.0, &t.1, &t.2, &t.3, &t.4, &t.5].map(|s| q(s)), tensor);
    let v = run(&["verify", "--json", ron.to_str().unwrap()]);
    let json: serde_json::Value = serde_json::from_slice(&v.stdout).unwrap();
    assert_eq!(json["files"][0]["inertia_tensor"][2], "4/375");
    let text = run(&["verify", ron.to_str().unwrap()]);
    assert!(String::from_utf8_lossy(&text.stdout).contains("J is J_eff of the recorded inertia tensor"));
    let json_twin = d.path().join("lander.json");
    let c = run(&["convert", "--to", "json", ron.to_str().unwrap()]);
    std::fs::write(&json_twin, &c.stdout).unwrap();
    let back = run(&["convert", "--to", "ron", json_twin.to_str().unwrap()]);
    assert_eq!(String::from_utf8_lossy(&back.stdout), written);
}
