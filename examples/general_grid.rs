//! Issue 13 §4: the family finder's success rate against the simulation on a grid of gamma, for
//! the rectangle plates of aspect 1, 2, 4, the phone box 150 x 75 x 8 and the named bodies.
//! `cargo run --release --features research --example general_grid [POINTS]` (default 40 points, gamma = k/200).

use chatter::bodies::convex::{rectangle_plate, uniform_box};
use chatter::bodies::general::general_catalogue;
use chatter::exact::Q;
use chatter::sweep::general::{Agreement, finder_vs_simulation};
use chatter_kernel::model::ConvexBody;

fn q(n: i64, d: i64) -> Q {
    Q::new(n, d)
}

fn main() {
    let points: i64 = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(40);
    let gammas: Vec<Q> = (1..=points).map(|k| q(k, 200)).collect();
    let g = q(1, 100);
    let mut bodies: Vec<(String, ConvexBody<Q>)> = vec![
        ("rectangle 1 x 1".into(), rectangle_plate(&q(1, 1), &q(1, 1), g.clone()).unwrap()),
        ("rectangle 2 x 1".into(), rectangle_plate(&q(2, 1), &q(1, 1), g.clone()).unwrap()),
        ("rectangle 4 x 1".into(), rectangle_plate(&q(4, 1), &q(1, 1), g.clone()).unwrap()),
        ("box 150 x 75 x 8".into(), uniform_box(&q(150, 1), &q(75, 1), &q(8, 1), g.clone()).unwrap()),
    ];
    for e in general_catalogue(&g).unwrap().into_iter().skip(1) {
        bodies.push((e.name.to_string(), e.body));
    }
    println!("gamma = k/200, k = 1..={points}; 20 f64 drops per point, budget 20000 impacts");
    println!(
        "body              points  all-CC  certified  cert&all-CC  success  contradictions  median ms (all / certified)"
    );
    for (name, body) in bodies {
        let grid = finder_vs_simulation(&body, &gammas, 20, 20_000);
        let a = Agreement::of(&grid);
        let median = |only_certified: bool| {
            let mut t: Vec<f64> = grid
                .iter()
                .filter(|p| !only_certified || p.certified.is_some())
                .map(|p| p.time.as_secs_f64() * 1e3)
                .collect();
            t.sort_by(f64::total_cmp);
            t.get(t.len() / 2).copied().unwrap_or(f64::NAN)
        };
        println!(
            "{name:<17} {:>6} {:>7} {:>10} {:>12} {:>7.1}% {:>15} {:>10.2} / {:.2}",
            a.points,
            a.all_cc,
            a.certified,
            a.certified_and_all_cc,
            100.0 * a.success_rate(),
            a.contradictions,
            median(false),
            median(true)
        );
    }
}
