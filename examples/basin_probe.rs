//! Diagnostics for basin certificates (evidence only): the `f64` walk of one drop of the paper's
//! box, printed impact by impact with its distance to the orbit certificate's X.
//! `cargo run --release --features research --example basin_probe -- FILE R1 R2 R3 R4 R5 [IMPACTS]`.

use chatter::basin::float::Walker;
use chatter_kernel::exact::ParseLimits;
use chatter_kernel::rules::basin::read;
use chatter_kernel::syntax::{Encoding, read as read_file};
use malachite::rational::Rational;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let (Some(path), true) = (args.get(1), args.len() >= 7) else {
        return eprintln!("usage: FILE R1 R2 R3 R4 R5 [IMPACTS [HALF-WIDTH]]");
    };
    let text = std::fs::read_to_string(path).unwrap_or_default();
    let cert = match read_file(&text, Encoding::Ron) {
        Ok(c) => c,
        Err(e) => return eprintln!("{e}"),
    };
    let (maps, orbit, _, _) = match read::<Rational>(&cert, ParseLimits::default()) {
        Ok(x) => x,
        Err(e) => return eprintln!("{e}"),
    };
    let r: Vec<f64> = args[2..7].iter().map(|s| s.parse().unwrap_or(0.05)).collect();
    let y = [r[0], r[1], r[2], r[3], 1.0 + r[4]];
    let impacts = args.get(7).and_then(|s| s.parse().ok()).unwrap_or(200);
    let mut w = Walker::new(&maps, orbit.as_ref(), 400);
    w.entry = std::env::var("ENTRY").ok().and_then(|s| s.parse().ok()).unwrap_or(0.5);
    w.cut_within = std::env::var("WITHIN").ok().and_then(|s| s.parse().ok()).unwrap_or(f64::INFINITY);
    w.cut_every = std::env::var("CUT").ok().and_then(|s| s.parse().ok()).unwrap_or(4);
    for (i, (k, v, x)) in w.trace(&y, impacts).into_iter().enumerate() {
        let d = x.map_or(f64::NAN, |x| x.iter().fold(0.0f64, |m, a| m.max(a.abs())));
        println!("{i:4} contact/step {k} v {v:+.3e} |y|/delta {d:.3e}");
    }
    let plan = w.plan(&y);
    println!("plan: {:?}", plan.as_ref().map(|p| (p.first, p.steps.len(), p.cc)));
    if let (Some(plan), Some(width)) = (plan, args.get(8).and_then(|s| s.parse::<f64>().ok())) {
        kernel_on(maps, orbit, y, width, &plan);
    }
}

/// The kernel's rule B4 on the cube of half-width `w` around y with the walk's plan.
pub fn kernel_on(
    maps: chatter_kernel::orbit::Maps<chatter_kernel::orbit::Iv<Rational>>,
    orbit: Option<chatter_kernel::orbit::Orbit<Rational>>,
    y: [f64; 5],
    w: f64,
    plan: &chatter::basin::float::Plan,
) {
    use chatter::exact::{Q, QExt};
    let ctx = chatter_kernel::rules::basin::Context::new(maps, orbit);
    let q = |x: f64| Q::from_f64_exact(x).map(|q| q.as_rational().clone()).unwrap_or_default();
    let lo = y.map(|v| q(v - w));
    let hi = y.map(|v| q(v + w));
    let t = std::time::Instant::now();
    let prefix = chatter_kernel::rules::basin::Prefix {
        first: plan.first,
        steps: &plan.steps,
        cuts: &plan.cuts,
        end: if plan.cc {
            chatter_kernel::rules::basin::End::Cc
        } else {
            chatter_kernel::rules::basin::End::Icc
        },
    };
    let r = ctx.leaf(&lo, &hi, &prefix);
    println!(
        "kernel, half-width {w:e}: {:?} in {:.3} s",
        r.map(|b| b.map(|b| Q::from_rational(b).to_f64())),
        t.elapsed().as_secs_f64()
    );
}
