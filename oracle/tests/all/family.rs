//! General convex bodies (version 4) against the kernel, through the text API: the tool's family
//! certificates for random convex plates and their mutations (a cone shrunk towards one of its
//! generators, a generator lifted to v = 0, γ tripled, the claim raised, the claim lowered); the kernel's code must
//! be one the oracle's first failing rule can give. (Moved from the tool's tests/all/oracle_convex.rs.)

use crate::common::differential_ron;
use chatter::bodies::convex::polygon_plate;
use chatter::certify::convex::{ConvexRequest, certify_convex};
use chatter::exact::Q;
use chatter_oracle::arith::rational::{parse_rational, rational_text};
use chatter_oracle::read::{Encoding, Value, parse::parse, write::to_ron};

/// splitmix64.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
}

/// The tool's family certificate (RON) for the uniform plate of a random convex polygon: n
/// corners at radius 1/2 to 3/2 and jittered angles, from an integer table of (cos, sin) · 1000
/// at multiples of 2π/48 (no floating point); `None` where the tool finds no family.
fn random_certificate(rng: &mut Rng, n: usize, gamma: Q) -> Option<String> {
    const COS: [i64; 13] = [1000, 991, 966, 924, 866, 793, 707, 609, 500, 383, 259, 131, 0];
    let trig = |k: usize| -> (i64, i64) {
        let k = k % 48;
        let (q, r) = (k / 12, k % 12);
        let (c, s) = (COS[r], COS[12 - r]);
        match q {
            0 => (c, s),
            1 => (-s, c),
            2 => (-c, -s),
            _ => (s, -c),
        }
    };
    let step = 48 / n;
    let pts: Vec<[Q; 2]> = (0..n)
        .map(|k| {
            let (c, s) = trig(k * step + (rng.next() % 2) as usize);
            let r = 500 + (rng.next() % 1000) as i64;
            [Q::new(c * r, 1_000_000), Q::new(s * r, 1_000_000)]
        })
        .collect();
    let body = polygon_plate(&pts, gamma).ok()?;
    let cert = certify_convex(&ConvexRequest::new(body)).result.ok()?;
    Some(chatter::write::write_convex(&cert))
}

fn strings_of(v: &Value) -> Vec<String> {
    match v {
        Value::Tuple(xs) => {
            xs.iter().map(|x| if let Value::Str(s) = x { s.clone() } else { panic!() }).collect()
        }
        _ => panic!("a tuple"),
    }
}

fn field<'a>(v: &'a mut Value, name: &str) -> &'a mut Value {
    let Value::Named { fields: Some(fs), .. } = v else { panic!("a struct") };
    &mut fs.iter_mut().find(|(k, _)| k == name).expect("the field").1
}

/// The mutations of a version-4 text that the test tries.
fn mutations(text: &str) -> Vec<(String, String)> {
    let base = parse(text, Encoding::Ron).expect("the tool's text parses");
    let mut out = vec![];
    let Value::List(cones) = field(&mut base.clone(), "cones").clone() else { panic!("cones") };
    for i in 0..cones.len() {
        let mut m = base.clone();
        let Value::List(cone) = &mut field(&mut m, "cones").clone() else { panic!() };
        let Value::List(gens) = &mut cone[i] else { panic!() };
        let g0: Vec<_> =
            strings_of(&gens[0]).iter().map(|s| parse_rational(s, usize::MAX).unwrap()).collect();
        for g in gens.iter_mut().skip(1) {
            let x: Vec<_> = strings_of(g).iter().map(|s| parse_rational(s, usize::MAX).unwrap()).collect();
            let two = parse_rational("2", 9).unwrap();
            *g = Value::Tuple(
                x.iter().zip(&g0).map(|(a, b)| Value::Str(rational_text(&((a + b) / &two)))).collect(),
            );
        }
        *field(&mut m, "cones") = Value::List(cone.clone());
        out.push((format!("K_{i} shrunk"), to_ron(&m)));
    }
    let mut m = base.clone();
    if let Value::List(cone) = field(&mut m, "cones")
        && let Value::List(gens) = &mut cone[0]
        && let Value::Tuple(x) = &mut gens[0]
    {
        x[2] = Value::Str("0".into());
    }
    out.push(("a generator at v = 0".into(), to_ron(&m)));
    let mut m = base.clone();
    let gamma = field(field(&mut m, "body"), "gamma");
    if let Value::Str(g) = gamma {
        let tripled = parse_rational(g, usize::MAX).unwrap() * parse_rational("3", 9).unwrap();
        *gamma = Value::Str(rational_text(&tripled));
    }
    out.push(("gamma tripled".into(), to_ron(&m)));
    let mut m = base.clone();
    *field(&mut m, "claim") = Value::Named { name: "CompleteChatterFromAllDown".into(), fields: None };
    out.push(("claim raised".into(), to_ron(&m)));
    let mut m = base;
    *field(&mut m, "claim") = Value::Named { name: "EffectivelyInvariant".into(), fields: None };
    out.push(("claim lowered".into(), to_ron(&m)));
    out
}

#[test]
fn kernel_and_oracle_agree_on_random_bodies_and_mutations() {
    let mut rng = Rng(2026);
    let (mut accepted, mut rejected, mut certified) = (0, 0, 0);
    for trial in 0..10 {
        let n = 3 + trial % 4;
        let gamma = Q::new(1 + (rng.next() % 40) as i64, 1000);
        let Some(text) = random_certificate(&mut rng, n, gamma) else { continue };
        let (k, _, cmp) = differential_ron(&text);
        assert!(k.accepted && cmp.is_ok(), "trial {trial}: {cmp:?}\n{text}");
        certified += 1;
        for (what, m) in mutations(&text) {
            let (k, _, cmp) = differential_ron(&m);
            assert!(cmp.is_ok(), "trial {trial}, {what}: {cmp:?}\n{m}");
            assert!(k.accepted || what != "claim lowered", "trial {trial}: a weaker claim is refused\n{m}");
            if k.accepted { accepted += 1 } else { rejected += 1 }
        }
    }
    assert!(
        certified >= 5 && rejected >= 15 && accepted >= 1,
        "{certified} certified, {accepted} accepted, {rejected} rejected"
    );
}
