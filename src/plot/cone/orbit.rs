//! An orbit certificate (version 5) on the velocity plane: the set X of the section
//! Σ = {q = (0, a, 1), p = (b, c, −1)} projected along a onto (b, c) = (u₀/(−v), u₁/(−v)), the
//! projection of its image under the return map R_P (which the kernel proves lies in X), and the
//! centre x* of X.

use super::{ConeFigure, Mark, Marker, Panel, Region, colour, window};
use crate::exact::{Q, QExt};
use crate::finder::geometry::{P2, hull};
use crate::orbit::{FloatMaps, float_return};
use crate::plot::map::body_name;
use chatter_kernel::certificate::{Encoding, OrbitBody, OrbitSet, read_orbit};

fn q(text: &str) -> Result<Q, String> {
    text.parse::<Q>().map_err(|e| format!("{text:?}: {e}"))
}

fn triple(t: &(String, String, String)) -> Result<[f64; 3], String> {
    Ok([q(&t.0)?.to_f64(), q(&t.1)?.to_f64(), q(&t.2)?.to_f64()])
}

/// Points of X on a 5 x 5 x 5 lattice (corners included) and its centre.
fn lattice(set: &OrbitSet) -> Result<(Vec<[f64; 3]>, [f64; 3]), String> {
    let steps = [-1.0, -0.5, 0.0, 0.5, 1.0];
    let mut pts = Vec::new();
    let centre = match set {
        OrbitSet::Parallelepiped { centre, axes, delta } => {
            let (c, d) = (triple(centre)?, q(delta)?.to_f64());
            let a = [triple(&axes.0)?, triple(&axes.1)?, triple(&axes.2)?];
            for s0 in steps {
                for s1 in steps {
                    for s2 in steps {
                        pts.push(std::array::from_fn(|r| {
                            c[r] + d * (s0 * a[0][r] + s1 * a[1][r] + s2 * a[2][r])
                        }));
                    }
                }
            }
            c
        }
        OrbitSet::Box { lo, hi } => {
            let (lo, hi) = (triple(lo)?, triple(hi)?);
            let at = |r: usize, t: f64| lo[r] + (hi[r] - lo[r]) * (t + 1.0) / 2.0;
            for s0 in steps {
                for s1 in steps {
                    for s2 in steps {
                        pts.push([at(0, s0), at(1, s1), at(2, s2)]);
                    }
                }
            }
            std::array::from_fn(|r| (lo[r] + hi[r]) / 2.0)
        }
    };
    Ok((pts, centre))
}

fn velocity(x: &[f64; 3]) -> P2 {
    P2::new(x[1], x[2])
}

/// The figure of a version-5 certificate.
pub fn figure(text: &str, encoding: Encoding) -> Result<ConeFigure, String> {
    let cert =
        read_orbit(text, encoding).map_err(|r| format!("not a readable certificate: {}", r.message()))?;
    let OrbitBody::RegularPolygon { n, kappa, gamma } = &cert.body;
    let maps = FloatMaps::of(*n, &q(kappa)?, &q(gamma)?)?;
    let pattern: Vec<usize> = cert.pattern.iter().map(|&j| j as usize).collect();
    let (pts, centre) = lattice(&cert.set)?;
    let x = hull(&pts.iter().map(velocity).collect::<Vec<_>>(), 0.0);
    let images: Vec<P2> =
        pts.iter().filter_map(|p| float_return(&maps, &pattern, p)).map(|(y, ..)| velocity(&y)).collect();
    let image = Region {
        name: String::new(),
        colour: colour(1),
        polygon: hull(&images, 0.0),
        legend: "R_P(X), projected: X after one period of the pattern; must lie in X".into(),
    };
    let all: Vec<P2> = x.iter().chain(&image.polygon).copied().collect();
    let (lo, hi, stretch) = window::fit(&all, window::pixels(1));
    let pat = cert.pattern.iter().map(u64::to_string).collect::<Vec<_>>().join(",");
    let mark = Mark {
        label: "x*".into(),
        at: velocity(&centre),
        marker: Marker::Dot,
        legend: "x*: the centre of X, near the attracting cycle".into(),
    };
    let panel = Panel {
        title: String::new(),
        k: x,
        k_legend: "X, projected along a: the set of post-impact states the certificate covers".into(),
        regions: Vec::new(),
        images: vec![image],
        seeds: Vec::new(),
        seeds_legend: String::new(),
        marks: vec![mark],
        window: (lo, hi),
        stretch,
    };
    let title = format!(
        "n = {n} ({}), κ = {kappa}, γ = {gamma}: orbit certificate, pattern {pat}, the set X on the velocity plane",
        body_name(*n)
    );
    let notes = vec![
        "states right after an impact at contact 0: q = (0, a, 1), p = (b, c, −1) (docs/orbit-certificates.md §2); a, the height of contact 1, is not shown".into(),
    ];
    Ok(ConeFigure {
        title,
        axes: ("b = u₀ / (−v)".into(), "c = u₁ / (−v)".into()),
        panels: vec![panel],
        notes,
    })
}
