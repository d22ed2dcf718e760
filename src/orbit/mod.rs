//! The untrusted producer of orbit certificates (docs/orbit-certificates.md §6, issue 15): the
//! return map R_P of a pattern in `f64` on the section Σ of docs/orbit-certificates.md §2, its
//! attracting fixed point (iteration, then Newton), the Jacobian's eigenvector basis rounded to
//! rationals, and the half-width δ halved until the trusted kernel accepts. The pattern comes from
//! a simulated drop when not given. Nothing here is trusted: the kernel checks the result on both
//! backends.

pub mod band;
pub mod search;

use crate::exact::{Q, QExt};
use crate::model::float::FloatPolygon;
use crate::simulate::{Initial, Model, Options, Shape, pattern, simulate};
use chatter_kernel::certificate::{Claim, OrbitBody, OrbitCertificate, OrbitSet, Rejection};
use chatter_kernel::exact::{ParseLimits, Ring, to_canonical};
use chatter_kernel::model::Polygon;
use chatter_kernel::verify::{Backend, Verdict, agree};

/// A request for an orbit certificate.
#[derive(Clone, Debug)]
pub struct Request {
    /// Number of contacts (3 to 64).
    pub n: u64,
    /// kappa.
    pub kappa: Q,
    /// gamma.
    pub gamma: Q,
    /// The pattern's steps, or `None` to find it by simulation.
    pub pattern: Option<Vec<usize>>,
    /// Random drops simulated to find the pattern.
    pub drops: u64,
    /// The deepest subdivision the certificate may ask the kernel for (each level multiplies the
    /// worst-case number of sub-boxes by 8).
    pub max_depth: u64,
}

/// Why no certificate was produced.
#[derive(Clone, Debug, PartialEq)]
pub enum Failure {
    /// The body cannot be modelled (n, kappa, gamma).
    Body(String),
    /// No simulated drop settled into a periodic impact pattern.
    NoPattern(String),
    /// Iterating R_P from the starting points found no attracting fixed point.
    NoAttractingCycle(String),
    /// The fixed point exists but the pattern is not forced (condition 1) on any set around it.
    PatternNotStable(String),
    /// The fixed point exists but no set around it was shown invariant or contracting.
    NoContraction(String),
    /// The two backends disagree (a bug).
    Internal(String),
}

impl std::fmt::Display for Failure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Failure::Body(s) => write!(f, "body: {s}"),
            Failure::NoPattern(s) => write!(f, "no periodic impact pattern found: {s}"),
            Failure::NoAttractingCycle(s) => write!(f, "no attracting cycle found: {s}"),
            Failure::PatternNotStable(s) => write!(f, "pattern not stable over the set: {s}"),
            Failure::NoContraction(s) => write!(f, "no contraction: {s}"),
            Failure::Internal(s) => write!(f, "internal error: {s}"),
        }
    }
}

/// What the search found (floating point, for the report), with the certificate.
#[derive(Clone, Debug)]
pub struct Found {
    /// The certificate, accepted by the kernel on every backend asked.
    pub certificate: OrbitCertificate,
    /// The pattern used.
    pub pattern: Vec<usize>,
    /// The fixed point x* in `f64`.
    pub fixed_point: [f64; 3],
    /// Eigenvalues of the Jacobian of R_P (one period of the given pattern) at x* (real parts,
    /// largest modulus first; `f64`).
    pub eigenvalues: [f64; 3],
    /// The same eigenvalues as (re, im).
    pub complex_eigenvalues: [(f64, f64); 3],
    /// How many periods of the pattern the certificate's pattern repeats (R_P^k).
    pub periods: usize,
    /// ||(A^-1 J A)^k||_inf, the linear part's contraction of the box norm.
    pub box_norm: f64,
    /// The smallest relative margin of condition 1 at x*.
    pub margin: f64,
    /// alpha, beta, alpha/beta and T at x* (`f64`, for the certificate's pattern: k periods).
    pub scales: [f64; 4],
    /// δ of the accepted set.
    pub delta: f64,
    /// Sub-boxes the kernel examined with every sign shown.
    pub boxes: usize,
    /// B = T̄/(1 − ρ) as the kernel derived it ("p/q"): the impacts accumulate within B h/|v| of
    /// an impact after which the state lies in X (docs/orbit-certificates.md §4).
    pub time_to_rest_bound: Option<String>,
    /// Kernel time of the final check over all backends, seconds.
    pub kernel_seconds: f64,
}

/// The body's constants in `f64`.
#[derive(Clone, Debug)]
pub struct FloatMaps {
    n: usize,
    contacts: Vec<[f64; 3]>,
    impact0: [[f64; 3]; 3],
}

impl FloatMaps {
    /// From the exact model (n = 3, 4, 6).
    pub fn new(body: &Polygon<Q>) -> Self {
        let n = body.n();
        let contacts = (0..n).map(|k| body.contact(k as i64).clone().map(|x| x.to_f64())).collect();
        let impact0 = body.impact(0).map(|r| r.map(|x| x.to_f64()));
        FloatMaps { n, contacts, impact0 }
    }

    /// From the float model of any regular n-gon (docs/model.md §2-3).
    pub fn of_float(body: &FloatPolygon) -> Self {
        let n = body.n();
        let contacts = (0..n)
            .map(|k| {
                let f = body.contact(k as i64);
                [f[0], f[1], f[2]]
            })
            .collect();
        let i0 = body.impact(0);
        let impact0 = std::array::from_fn(|r| std::array::from_fn(|c| i0[(r, c)]));
        FloatMaps { n, contacts, impact0 }
    }

    /// The body (n, κ, γ): from the exact model where cos 2π/n is rational (n = 3, 4, 6), else
    /// from the float model.
    pub fn of(n: u64, kappa: &Q, gamma: &Q) -> Result<Self, String> {
        if let Ok(body) = Polygon::new(n, kappa.clone(), gamma.clone()) {
            return Ok(FloatMaps::new(&body));
        }
        let body = FloatPolygon::new(n, kappa.to_f64(), gamma.to_f64()).map_err(|e| e.to_string())?;
        Ok(FloatMaps::of_float(&body))
    }
}

fn dot(f: &[f64; 3], x: &[f64; 3]) -> f64 {
    f[0] * x[0] + f[1] * x[1] + f[2] * x[2]
}

/// One period of R_P in `f64`: (R_P(x), alpha, beta, T) and the smallest relative margin of
/// condition 1 met; `None` if some quantity of conditions 1-2 is not positive.
pub fn float_return(maps: &FloatMaps, pattern: &[usize], x: &[f64; 3]) -> Option<([f64; 3], [f64; 3], f64)> {
    float_period(maps, pattern, x, true)
}

/// One period of R_P in `f64` as an algebraic map: with `strict`, `None` as soon as a quantity of
/// conditions 1-2 is not positive ([`float_return`]); without, the map is followed wherever its
/// divisors are non-zero and the margin of condition 1 (negative where a competitor lands first,
/// or the target moves up) is returned, for Newton's method and diagnostics.
pub fn float_period(
    maps: &FloatMaps,
    pattern: &[usize],
    x: &[f64; 3],
    strict: bool,
) -> Option<([f64; 3], [f64; 3], f64)> {
    let mut q = [0.0, x[0], 1.0];
    let mut p = [x[1], x[2], -1.0];
    let (mut time, mut margin) = (0.0, f64::INFINITY);
    for &j in pattern {
        let hj = dot(&maps.contacts[j], &q);
        let uj = dot(&maps.contacts[j], &p);
        if uj == 0.0 || (strict && (uj >= 0.0 || hj <= 0.0)) {
            return None;
        }
        if uj >= 0.0 || hj <= 0.0 {
            margin = margin.min(-1.0);
        }
        for k in (0..maps.n).filter(|&k| k != j) {
            let g = dot(&maps.contacts[k], &q) * -uj + hj * dot(&maps.contacts[k], &p);
            if strict && g <= 0.0 {
                return None;
            }
            margin = margin.min(g / (hj * -uj).abs());
        }
        let t = hj / -uj;
        time += t;
        let moved = [q[0] + t * p[0], q[1] + t * p[1], q[2] + t * p[2]];
        let next = &maps.contacts[(j + 1) % maps.n];
        q = [0.0, dot(next, &moved), moved[2]];
        let r = [uj, dot(next, &p), p[2]];
        p = [dot(&maps.impact0[0], &r), dot(&maps.impact0[1], &r), dot(&maps.impact0[2], &r)];
    }
    let (alpha, beta) = (q[2], -p[2]);
    if (strict && (alpha <= 0.0 || beta <= 0.0)) || alpha == 0.0 || beta == 0.0 {
        return None;
    }
    let y = [q[1] / alpha, p[0] / beta, p[1] / beta];
    if !y.iter().all(|v| v.is_finite()) {
        return None;
    }
    Some((y, [alpha, beta, time], margin))
}

/// The Jacobian of R_P at x by central differences (of the strict map: `None` if a neighbour
/// breaks the pattern).
pub fn jacobian(maps: &FloatMaps, pattern: &[usize], x: &[f64; 3]) -> Option<[[f64; 3]; 3]> {
    jacobian_of(maps, pattern, x, true)
}

fn jacobian_of(maps: &FloatMaps, pattern: &[usize], x: &[f64; 3], strict: bool) -> Option<[[f64; 3]; 3]> {
    let mut j = [[0.0; 3]; 3];
    for k in 0..3 {
        let h = 1e-7 * x[k].abs().max(1.0);
        let (mut xp, mut xm) = (*x, *x);
        xp[k] += h;
        xm[k] -= h;
        let (fp, fm) =
            (float_period(maps, pattern, &xp, strict)?.0, float_period(maps, pattern, &xm, strict)?.0);
        for i in 0..3 {
            j[i][k] = (fp[i] - fm[i]) / (2.0 * h);
        }
    }
    Some(j)
}

fn solve3(m: &[[f64; 3]; 3], b: &[f64; 3]) -> Option<[f64; 3]> {
    let det = |m: &[[f64; 3]; 3]| {
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    };
    let d = det(m);
    if d.abs() < 1e-300 {
        return None;
    }
    let mut out = [0.0; 3];
    for (k, o) in out.iter_mut().enumerate() {
        let mut mk = *m;
        for i in 0..3 {
            mk[i][k] = b[i];
        }
        *o = det(&mk) / d;
    }
    Some(out)
}

/// An attracting fixed point of R_P: iteration from a grid of starting points, then Newton.
pub fn fixed_point(maps: &FloatMaps, pattern: &[usize]) -> Option<[f64; 3]> {
    let starts = [0.25, 0.5, 1.0, 2.0];
    let vel = [0.01, 0.1, 0.5, 1.0];
    let cs = [-4.0, -2.0, -1.0, -0.5, 0.0, 0.5, 1.0];
    for &a in &starts {
        for &b in &vel {
            for &c in &cs {
                let mut x = [a, b, c];
                let mut ok = true;
                for _ in 0..2000 {
                    match float_return(maps, pattern, &x) {
                        Some((y, _, _)) if y.iter().all(|v| v.is_finite() && v.abs() < 1e6) => x = y,
                        _ => {
                            ok = false;
                            break;
                        }
                    }
                }
                if !ok {
                    continue;
                }
                // Newton on R(x) - x = 0.
                for _ in 0..20 {
                    let (y, _, _) = float_return(maps, pattern, &x)?;
                    let j = jacobian(maps, pattern, &x)?;
                    let m: [[f64; 3]; 3] = std::array::from_fn(|i| {
                        std::array::from_fn(|k| j[i][k] - if i == k { 1.0 } else { 0.0 })
                    });
                    let r = [x[0] - y[0], x[1] - y[1], x[2] - y[2]];
                    let Some(dx) = solve3(&m, &r) else { break };
                    x = [x[0] + dx[0], x[1] + dx[1], x[2] + dx[2]];
                }
                let (y, _, _) = float_return(maps, pattern, &x)?;
                let res = (0..3).map(|i| (y[i] - x[i]).abs()).fold(0.0, f64::max);
                if res < 1e-12 {
                    return Some(x);
                }
            }
        }
    }
    None
}

/// (trace, sum of principal 2x2 minors, determinant): det(λI - j) = λ³ - t λ² + s λ - d.
fn char_coefficients(j: &[[f64; 3]; 3]) -> (f64, f64, f64) {
    let t = j[0][0] + j[1][1] + j[2][2];
    let s = j[0][0] * j[1][1] - j[0][1] * j[1][0] + j[0][0] * j[2][2] - j[0][2] * j[2][0] + j[1][1] * j[2][2]
        - j[1][2] * j[2][1];
    let d = j[0][0] * (j[1][1] * j[2][2] - j[1][2] * j[2][1])
        - j[0][1] * (j[1][0] * j[2][2] - j[1][2] * j[2][0])
        + j[0][2] * (j[1][0] * j[2][1] - j[1][1] * j[2][0]);
    (t, s, d)
}

/// Real eigenvalues and eigenvectors of a 3x3 matrix (`None` if some eigenvalue is not real).
pub fn real_eigen(j: &[[f64; 3]; 3]) -> Option<([f64; 3], [[f64; 3]; 3])> {
    // Characteristic polynomial λ³ - t λ² + s λ - d.
    let (t, s, d) = char_coefficients(j);
    // Depressed cubic: λ = y + t/3.
    let p = s - t * t / 3.0;
    let q = -2.0 * t * t * t / 27.0 + t * s / 3.0 - d;
    // y³ + p y + q = 0 has three real roots iff p < 0 and 4p³ + 27 q² <= 0.
    if p >= 0.0 || 4.0 * p * p * p + 27.0 * q * q > 0.0 {
        return None;
    }
    let r = (-p / 3.0).sqrt();
    let phi = (3.0 * q / (2.0 * p * r)).clamp(-1.0, 1.0).acos() / 3.0;
    let mut ls: [f64; 3] = std::array::from_fn(|k| {
        2.0 * r * (phi - 2.0 * std::f64::consts::PI * k as f64 / 3.0).cos() + t / 3.0
    });
    ls.sort_by(|a, b| b.abs().total_cmp(&a.abs()));
    let mut vecs = [[0.0; 3]; 3];
    for (k, &l) in ls.iter().enumerate() {
        let m: [[f64; 3]; 3] =
            std::array::from_fn(|i| std::array::from_fn(|c| j[i][c] - if i == c { l } else { 0.0 }));
        let cross = |a: &[f64; 3], b: &[f64; 3]| {
            [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
        };
        let cands = [cross(&m[0], &m[1]), cross(&m[0], &m[2]), cross(&m[1], &m[2])];
        let v = cands.into_iter().max_by(|a, b| dot(a, a).total_cmp(&dot(b, b)))?;
        let norm = v.iter().fold(0.0_f64, |acc, x| acc.max(x.abs()));
        if norm == 0.0 || !norm.is_finite() {
            return None;
        }
        vecs[k] = v.map(|x| x / norm);
    }
    Some((ls, vecs))
}

/// A rational close to x: a dyadic with `bits` bits after the point.
fn rational(x: f64, bits: u64) -> Q {
    Q::from_f64_exact(x).unwrap_or_else(|| Q::int(0)).floor_dyadic(bits)
}

/// A short rational >= x: the next multiple of 1/1000.
fn above(x: f64) -> Q {
    let k = (x * 1000.0).ceil() as i64 + 1;
    Q::new(k, 1000)
}

/// Finds the pattern a random drop settles into: the steps of the periodic tail, rotated so
/// that the longest run of the largest step comes first (a canonical phase; the producer tries
/// every phase anyway).
pub fn find_pattern(req: &Request) -> Result<Vec<usize>, Failure> {
    let (cc, any, seen) = scan_drops(req)?;
    if let Some(p) = cc.or(any) {
        return Ok(p);
    }
    let counts: Vec<String> = seen.iter().map(|(k, v)| format!("{k} {v}")).collect();
    Err(Failure::NoPattern(format!(
        "{} drops simulated, outcomes {} (seeds 1..{}, {PATTERN_IMPACTS} impacts each)",
        req.drops.max(1),
        counts.join(", "),
        req.drops.max(1)
    )))
}

/// The pattern of the first of the request's drops that ends in CC (`f64` evidence) and settles
/// into a periodic pattern; `None` if none does (patterns of ICC transients do not count).
pub fn find_cc_pattern(req: &Request) -> Option<Vec<usize>> {
    scan_drops(req).ok()?.0
}

/// The drops of [`find_pattern`]: the first CC drop's pattern, the first pattern of any drop,
/// and the outcome counts up to the first CC pattern.
type Scan = (Option<Vec<usize>>, Option<Vec<usize>>, std::collections::BTreeMap<&'static str, usize>);

fn scan_drops(req: &Request) -> Result<Scan, Failure> {
    let model = Model::new(Shape::Polygon(req.n), req.kappa.clone(), req.gamma.clone())
        .map_err(|e| Failure::Body(e.to_string()))?;
    let (mut any, mut seen) = (None, std::collections::BTreeMap::new());
    for seed in 1..=req.drops.max(1) {
        let options = Options::new(PATTERN_IMPACTS);
        let run =
            simulate(&model, &Initial::RandomDrop { seed }, crate::simulate::Arithmetic::Float, &options);
        let steps = pattern::find(&run.sequence).map(|p| pattern::steps(&p.cycle, req.n as usize));
        if run.outcome == crate::simulate::Outcome::Cc && steps.is_some() {
            return Ok((steps, any, seen));
        }
        any = any.or(steps);
        *seen.entry(run.outcome.name()).or_default() += 1;
    }
    Ok((None, any, seen))
}

/// The impact budget of each drop [`find_pattern`] simulates.
pub const PATTERN_IMPACTS: usize = 600;

fn certificate(
    req: &Request,
    pattern: &[usize],
    x: &[f64; 3],
    axes: &[[f64; 3]; 3],
    delta: &Q,
    depth: u64,
    bounds: [&Q; 3],
) -> OrbitCertificate {
    let t = |v: &[f64; 3]| {
        (
            to_canonical(&rational(v[0], 48)),
            to_canonical(&rational(v[1], 48)),
            to_canonical(&rational(v[2], 48)),
        )
    };
    OrbitCertificate {
        format: chatter_kernel::syntax::orbit::FORMAT.into(),
        version: chatter_kernel::syntax::orbit::VERSION,
        body: OrbitBody::RegularPolygon {
            n: req.n,
            kappa: to_canonical(&req.kappa),
            gamma: to_canonical(&req.gamma),
        },
        claim: Claim::CompleteChatterFromSet,
        pattern: pattern.iter().map(|&j| j as u64).collect(),
        set: OrbitSet::Parallelepiped {
            centre: t(x),
            axes: (t(&axes[0]), t(&axes[1]), t(&axes[2])),
            delta: to_canonical(delta),
        },
        subdivision: depth,
        rho: to_canonical(bounds[0]),
        lambda: to_canonical(bounds[1]),
        period: to_canonical(bounds[2]),
        producer: format!("chatter {} certify-orbit", env!("CARGO_PKG_VERSION")),
    }
}

/// The rotations of a pattern (each phase of the cycle), the given one first.
fn rotations(p: &[usize]) -> Vec<Vec<usize>> {
    let mut out: Vec<Vec<usize>> = Vec::new();
    for r in 0..p.len() {
        let v: Vec<usize> = p[r..].iter().chain(&p[..r]).copied().collect();
        if !out.contains(&v) {
            out.push(v);
        }
    }
    out
}

/// Newton's method on R_P(x) = x for the algebraic map (conditions not checked), from `x0`;
/// `Some` if it converges (residual below 1e-12 relative to |x|).
pub fn newton(maps: &FloatMaps, pattern: &[usize], x0: &[f64; 3]) -> Option<[f64; 3]> {
    let mut x = *x0;
    for _ in 0..60 {
        let (y, _, _) = float_period(maps, pattern, &x, false)?;
        let res = (0..3).map(|i| (y[i] - x[i]).abs()).fold(0.0, f64::max);
        let scale = x.iter().fold(1.0_f64, |a, v| a.max(v.abs()));
        if res < 1e-12 * scale {
            return Some(x);
        }
        let j = jacobian_of(maps, pattern, &x, false)?;
        let m: [[f64; 3]; 3] =
            std::array::from_fn(|i| std::array::from_fn(|k| j[i][k] - if i == k { 1.0 } else { 0.0 }));
        let r = [x[0] - y[0], x[1] - y[1], x[2] - y[2]];
        let mut dx = solve3(&m, &r)?;
        // Damped: never move by more than the current scale at once.
        let size = dx.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
        if size > scale {
            dx = dx.map(|v| v * scale / size);
        }
        x = [x[0] + dx[0], x[1] + dx[1], x[2] + dx[2]];
        if !x.iter().all(|v| v.is_finite() && v.abs() < 1e8) {
            return None;
        }
    }
    None
}

/// A complex number (re, im).
type C = (f64, f64);

fn cmul(a: C, b: C) -> C {
    (a.0 * b.0 - a.1 * b.1, a.0 * b.1 + a.1 * b.0)
}

fn csub(a: C, b: C) -> C {
    (a.0 - b.0, a.1 - b.1)
}

/// The three eigenvalues of a 3x3 matrix as complex numbers, by modulus, largest first.
pub fn eigenvalues(j: &[[f64; 3]; 3]) -> [C; 3] {
    let (t, s, d) = char_coefficients(j);
    let f = |l: f64| ((l - t) * l + s) * l - d;
    let df = |l: f64| (3.0 * l - 2.0 * t) * l + s;
    // A real root: bracket by sign change, bisect, then Newton.
    let bound = 1.0 + t.abs().max(s.abs()).max(d.abs());
    let (mut lo, mut hi) = (-bound, bound);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if (f(mid) < 0.0) == (f(lo) < 0.0) { lo = mid } else { hi = mid }
    }
    let mut r = 0.5 * (lo + hi);
    for _ in 0..3 {
        let dr = df(r);
        if dr != 0.0 {
            r -= f(r) / dr;
        }
    }
    // Deflate: l^3 - t l^2 + s l - d = (l - r)(l^2 + b l + c).
    let b = r - t;
    let c = s + r * b;
    let disc = b * b - 4.0 * c;
    let mut out: [C; 3] = if disc >= 0.0 {
        let sq = disc.sqrt();
        [(r, 0.0), ((-b + sq) / 2.0, 0.0), ((-b - sq) / 2.0, 0.0)]
    } else {
        let im = (-disc).sqrt() / 2.0;
        [(r, 0.0), (-b / 2.0, im), (-b / 2.0, -im)]
    };
    out.sort_by(|x, y| (y.0.hypot(y.1)).total_cmp(&x.0.hypot(x.1)));
    out
}

/// A (complex) eigenvector of `j` for the eigenvalue `mu`: the largest cross product of two rows
/// of J - mu I.
pub fn eigenvector(j: &[[f64; 3]; 3], mu: C) -> [C; 3] {
    let m: [[C; 3]; 3] = std::array::from_fn(|i| {
        std::array::from_fn(|k| if i == k { csub((j[i][k], 0.0), mu) } else { (j[i][k], 0.0) })
    });
    let cross = |a: &[C; 3], b: &[C; 3]| -> [C; 3] {
        [
            csub(cmul(a[1], b[2]), cmul(a[2], b[1])),
            csub(cmul(a[2], b[0]), cmul(a[0], b[2])),
            csub(cmul(a[0], b[1]), cmul(a[1], b[0])),
        ]
    };
    let norm = |v: &[C; 3]| v.iter().map(|z| z.0 * z.0 + z.1 * z.1).sum::<f64>();
    [cross(&m[0], &m[1]), cross(&m[0], &m[2]), cross(&m[1], &m[2])]
        .into_iter()
        .max_by(|a, b| norm(a).total_cmp(&norm(b)))
        .expect("three candidates")
}

/// The axes of the set X (the columns of A) and the number of periods k: eigenvectors when the
/// spectrum is real, (Re v, Im v, w) for a complex pair with eigenvector v and real eigenvector w
/// (a real block form); k is the smallest number of periods (at most `max_k`) for which the linear
/// part contracts the box norm, ||(A^-1 J A)^k||_inf <= 0.9. `None` if the axes are singular or
/// no such k exists.
pub fn axes_and_periods(j: &[[f64; 3]; 3], max_k: usize) -> Option<([[f64; 3]; 3], usize, f64)> {
    let eig = eigenvalues(j);
    let normalise = |v: [f64; 3]| -> Option<[f64; 3]> {
        let n = v.iter().fold(0.0_f64, |a, x| a.max(x.abs()));
        (n > 0.0 && n.is_finite()).then(|| v.map(|x| x / n))
    };
    let axes: [[f64; 3]; 3] = if eig.iter().all(|z| z.1 == 0.0) {
        let mut axes = [[0.0; 3]; 3];
        for (k, z) in eig.iter().enumerate() {
            axes[k] = normalise(eigenvector(j, *z).map(|c| c.0))?;
        }
        axes
    } else {
        let (pair, real) = if eig[0].1 != 0.0 { (eig[0], eig[2]) } else { (eig[1], eig[0]) };
        let v = eigenvector(j, pair);
        // Scale v so that its largest component is real (a well-conditioned real/imaginary split).
        let big = *v.iter().max_by(|a, b| a.0.hypot(a.1).total_cmp(&b.0.hypot(b.1)))?;
        let inv = {
            let m = big.0 * big.0 + big.1 * big.1;
            (big.0 / m, -big.1 / m)
        };
        let v = v.map(|z| cmul(z, inv));
        [
            normalise(v.map(|z| z.0))?,
            normalise(v.map(|z| z.1))?,
            normalise(eigenvector(j, real).map(|c| c.0))?,
        ]
    };
    // M = A^-1 J A, column by column.
    let a: [[f64; 3]; 3] = std::array::from_fn(|r| std::array::from_fn(|c| axes[c][r]));
    let mut m = [[0.0; 3]; 3];
    for c in 0..3 {
        let col: [f64; 3] = std::array::from_fn(|r| (0..3).map(|i| j[r][i] * axes[c][i]).sum());
        let x = solve3(&a, &col)?;
        for r in 0..3 {
            m[r][c] = x[r];
        }
    }
    let mut power = m;
    for k in 1..=max_k {
        let norm = power.iter().map(|row| row.iter().map(|x| x.abs()).sum::<f64>()).fold(0.0, f64::max);
        if norm <= 0.9 {
            return Some((axes, k, norm));
        }
        power = std::array::from_fn(|r| std::array::from_fn(|c| (0..3).map(|i| power[r][i] * m[i][c]).sum()));
    }
    None
}

/// The fixed point of R_P found and what it is like (floating point, untrusted).
#[derive(Clone, Debug)]
pub struct FixedPoint {
    /// The phase of the pattern.
    pub pattern: Vec<usize>,
    /// x* (residual below 1e-12).
    pub x: [f64; 3],
    /// Eigenvalues of the Jacobian of R_P at x*, as (re, im), largest modulus first.
    pub eigenvalues: [(f64, f64); 3],
    /// The smallest relative margin of condition 1 at x* (negative: the pattern is not forced).
    pub margin: f64,
    /// alpha, beta, T at x*.
    pub scales: [f64; 3],
}

impl FixedPoint {
    /// The largest modulus of an eigenvalue.
    pub fn radius(&self) -> f64 {
        self.eigenvalues.iter().map(|z| z.0.hypot(z.1)).fold(0.0, f64::max)
    }

    /// Whether x* is a candidate for a certificate: pattern forced, attracting, all scales < 1.
    pub fn usable(&self) -> bool {
        self.margin > 0.0
            && self.radius() < 1.0
            && self.scales[0] < 1.0
            && self.scales[1] < 1.0
            && self.scales[0] < self.scales[1]
    }

    /// The eigenvalues as text.
    pub fn eigen_text(&self) -> String {
        let e: Vec<String> = self
            .eigenvalues
            .iter()
            .map(|z| if z.1 == 0.0 { format!("{:.5}", z.0) } else { format!("{:.5}{:+.5}i", z.0, z.1) })
            .collect();
        format!("({})", e.join(", "))
    }
}

fn fixed_point_info(maps: &FloatMaps, pattern: &[usize], x: [f64; 3]) -> Option<FixedPoint> {
    let (_, [alpha, beta, time], margin) = float_period(maps, pattern, &x, false)?;
    let j = jacobian_of(maps, pattern, &x, false)?;
    Some(FixedPoint {
        pattern: pattern.to_vec(),
        x,
        eigenvalues: eigenvalues(&j),
        margin,
        scales: [alpha, beta, time],
    })
}

/// Every fixed point of R_P found for the phases of `given`: by iterating the strict map from a
/// grid (attracting ones), by Newton's method on the algebraic map from `hints` and from the same
/// grid (any); duplicates removed, usable ones first.
pub fn fixed_points(maps: &FloatMaps, given: &[usize], hints: &[[f64; 3]]) -> Vec<FixedPoint> {
    let mut out: Vec<FixedPoint> = Vec::new();
    let push = |f: FixedPoint, out: &mut Vec<FixedPoint>| {
        let same = |g: &FixedPoint| {
            g.pattern == f.pattern && (0..3).all(|i| (g.x[i] - f.x[i]).abs() < 1e-7 * (1.0 + f.x[i].abs()))
        };
        if !out.iter().any(same) {
            out.push(f);
        }
    };
    for pattern in rotations(given) {
        for h in hints {
            if let Some(f) = newton(maps, &pattern, h).and_then(|x| fixed_point_info(maps, &pattern, x)) {
                push(f, &mut out);
            }
        }
        if let Some(f) = fixed_point(maps, &pattern).and_then(|x| fixed_point_info(maps, &pattern, x)) {
            push(f, &mut out);
        }
        if out.iter().any(FixedPoint::usable) {
            continue;
        }
        for a in [0.25, 1.0, 2.0] {
            for b in [0.1, 1.0] {
                for c in [-2.0, -0.5, 0.5] {
                    if let Some(f) =
                        newton(maps, &pattern, &[a, b, c]).and_then(|x| fixed_point_info(maps, &pattern, x))
                    {
                        push(f, &mut out);
                    }
                }
            }
        }
    }
    out.sort_by_key(|f| !f.usable());
    out
}

/// Produces an orbit certificate: pattern, fixed point, basis, bounds, then δ = 2^-4, 2^-5, ...
/// (each with subdivision 0 to `max_depth`) until the kernel (first backend) accepts; the
/// accepted file is re-checked on every backend.
pub fn certify_orbit(req: &Request, backends: &[Backend]) -> Result<Found, Failure> {
    certify_orbit_from(req, backends, &[])
}

/// [`certify_orbit`] with starting points for Newton's method (e.g. the fixed point at a nearby
/// gamma, for continuation along a sweep).
///
/// Every fixed point of every phase is tried, usable ones first (condition 1 holds at x* with a
/// margin, every eigenvalue of the Jacobian inside the unit circle, alpha, beta, alpha/beta < 1).
/// The axes of X are the Jacobian's eigenvectors, or the real and imaginary parts of a complex
/// eigenvector and the real one; when the linear part does not contract the box norm in one
/// period, the pattern is repeated k times (R_P^k has the same fixed point; at most 64 steps).
pub fn certify_orbit_from(req: &Request, backends: &[Backend], hints: &[[f64; 3]]) -> Result<Found, Failure> {
    certify_orbit_within(req, backends, hints, MAX_HALVINGS)
}

/// How many times [`certify_orbit_from`] halves δ from 2^-4 per fixed point (down to 2^-27).
pub const MAX_HALVINGS: u64 = 24;

/// [`certify_orbit_from`] with δ halved at most `halvings` times per fixed point: a bounded
/// attempt (e.g. for the proofs of a sweep's drops), at the price of missing certificates that
/// need a smaller set.
pub fn certify_orbit_within(
    req: &Request,
    backends: &[Backend],
    hints: &[[f64; 3]],
    halvings: u64,
) -> Result<Found, Failure> {
    let maps = FloatMaps::of(req.n, &req.kappa, &req.gamma).map_err(Failure::Body)?;
    let given = match &req.pattern {
        Some(p) => {
            if p.is_empty() || p.iter().any(|&j| j == 0 || j >= req.n as usize) {
                return Err(Failure::Body(format!("pattern steps must lie in 1..{}", req.n - 1)));
            }
            p.clone()
        }
        None => find_pattern(req)?,
    };
    let points = fixed_points(&maps, &given, hints);
    let Some(first) = points.first() else {
        return Err(Failure::NoAttractingCycle(format!(
            "no fixed point of R_P for the pattern {given:?} (any phase) found by iteration or Newton's method"
        )));
    };
    if !first.usable() {
        let f = first;
        let what = if f.margin <= 0.0 {
            return Err(Failure::PatternNotStable(format!(
                "the fixed point {:?} of R_P for {:?} (eigenvalues {}) breaks the pattern: condition 1's margin there is {:.3e} (a competing contact lands first or the target moves up)",
                f.x,
                f.pattern,
                f.eigen_text(),
                f.margin
            )));
        } else if f.radius() >= 1.0 {
            format!("is not attracting: eigenvalues {} (largest modulus {:.5})", f.eigen_text(), f.radius())
        } else {
            format!(
                "has alpha = {:.5}, beta = {:.5}: not both below 1 with alpha < beta",
                f.scales[0], f.scales[1]
            )
        };
        return Err(Failure::NoAttractingCycle(format!(
            "the fixed point {:?} of R_P for {:?} (condition 1 holds there, margin {:.3e}) {what}",
            f.x, f.pattern, f.margin
        )));
    }
    let mut last = Failure::NoContraction("no usable fixed point".into());
    for f in points.iter().filter(|f| f.usable()) {
        let Some(j) = jacobian_of(&maps, &f.pattern, &f.x, false) else { continue };
        let max_k = (64 / f.pattern.len()).clamp(1, 16);
        let Some((axes, k, norm)) = axes_and_periods(&j, max_k) else {
            last = Failure::NoContraction(format!(
                "the fixed point {:?} of R_P for {:?} (eigenvalues {}) has no basis in which up to {max_k} periods contract the box norm",
                f.x,
                f.pattern,
                f.eigen_text()
            ));
            continue;
        };
        let pattern: Vec<usize> = f.pattern.iter().copied().cycle().take(k * f.pattern.len()).collect();
        let Some((_, [alpha, beta, time], _)) = float_return(&maps, &pattern, &f.x) else { continue };
        let ratio = alpha / beta;
        let rho = above(ratio + (1.0 - ratio) / 10.0).min(Q::new(999, 1000));
        let lambda = above(alpha.max(beta) + (1.0 - alpha.max(beta)) / 10.0).min(Q::new(999, 1000));
        let period = above(time * 1.1);
        let mut delta = Q::new(1, 16);
        let limits = ParseLimits::default();
        for attempt in 0..halvings.min(MAX_HALVINGS) * (req.max_depth + 1) {
            let depth = attempt % (req.max_depth + 1);
            if attempt > 0 && depth == 0 {
                delta = delta.times(&Q::new(1, 2));
            }
            let cert = certificate(req, &pattern, &f.x, &axes, &delta, depth, [&rho, &lambda, &period]);
            let start = std::time::Instant::now();
            let Some((main, others)) = backends.split_first() else {
                return Err(Failure::Internal("no backend to check the certificate".into()));
            };
            let on_main = (main.kinds.orbit)(&cert, limits);
            match agree([(main.name, on_main.clone())]) {
                Verdict::Accepted(_) => {
                    // The other backends are compared with the first one's result: it is not run twice.
                    let rest = others.iter().map(|b| (b.name, (b.kinds.orbit)(&cert, limits)));
                    let verdict = agree(std::iter::once((main.name, on_main)).chain(rest));
                    let kernel_seconds = start.elapsed().as_secs_f64();
                    return match verdict {
                        Verdict::Accepted(a) => Ok(Found {
                            certificate: cert,
                            pattern,
                            fixed_point: f.x,
                            eigenvalues: f.eigenvalues.map(|z| z.0),
                            complex_eigenvalues: f.eigenvalues,
                            periods: k,
                            box_norm: norm,
                            margin: f.margin,
                            scales: [alpha, beta, ratio, time],
                            delta: delta.to_f64(),
                            boxes: a.orbit_boxes.unwrap_or(0),
                            time_to_rest_bound: a.time_to_rest_bound.clone(),
                            kernel_seconds,
                        }),
                        Verdict::Rejected(r) => {
                            Err(Failure::Internal(format!("first backend accepts, all reject: {r}")))
                        }
                        Verdict::Disagree(s) => Err(Failure::Internal(s)),
                    };
                }
                Verdict::Rejected(r) => last = reason(&r),
                Verdict::Disagree(s) => return Err(Failure::Internal(s)),
            }
        }
    }
    Err(last)
}

fn reason(r: &Rejection) -> Failure {
    use chatter_kernel::certificate::Code;
    match r.code {
        Code::PatternNotForced => Failure::PatternNotStable(r.to_string()),
        _ => Failure::NoContraction(r.to_string()),
    }
}
