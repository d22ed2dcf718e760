//! The untrusted producer of orbit certificates (docs/orbit-certificates.md §6, issue 15): the
//! return map R_P of a pattern in `f64` on the section Σ of docs/orbit-certificates.md §2, its
//! attracting fixed point (iteration, then Newton), the Jacobian's eigenvector basis rounded to
//! rationals, and the half-width δ halved until the trusted kernel accepts. The pattern comes from
//! a simulated drop when not given. Nothing here is trusted: the kernel checks the result on both
//! backends.

use crate::exact::{Q, QExt};
use crate::simulate::{Initial, Model, Options, Shape, pattern, simulate};
use chatter_kernel::certificate::{
    Claim, FORMAT, ORBIT_VERSION, OrbitBody, OrbitCertificate, OrbitSet, Rejection,
};
use chatter_kernel::exact::{ParseLimits, Ring, to_canonical};
use chatter_kernel::model::Polygon;
use chatter_kernel::verify::{Backend, Verdict, verify_orbit_on};

/// A request for an orbit certificate.
#[derive(Clone, Debug)]
pub struct Request {
    /// Number of contacts (3, 4 or 6).
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
    /// Eigenvalues of the Jacobian of R_P at x* (real parts; `f64`).
    pub eigenvalues: [f64; 3],
    /// alpha, beta, alpha/beta and T at x* (`f64`).
    pub scales: [f64; 4],
    /// δ of the accepted set.
    pub delta: f64,
    /// Sub-boxes the kernel examined with every sign shown.
    pub boxes: usize,
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
    /// From the exact model.
    pub fn new(body: &Polygon<Q>) -> Self {
        let n = body.n();
        let contacts = (0..n).map(|k| body.contact(k as i64).clone().map(|x| x.to_f64())).collect();
        let impact0 = body.impact(0).map(|r| r.map(|x| x.to_f64()));
        FloatMaps { n, contacts, impact0 }
    }
}

fn dot(f: &[f64; 3], x: &[f64; 3]) -> f64 {
    f[0] * x[0] + f[1] * x[1] + f[2] * x[2]
}

/// One period of R_P in `f64`: (R_P(x), alpha, beta, T) and the smallest relative margin of
/// condition 1 met; `None` if some quantity of conditions 1-2 is not positive.
pub fn float_return(maps: &FloatMaps, pattern: &[usize], x: &[f64; 3]) -> Option<([f64; 3], [f64; 3], f64)> {
    let mut q = [0.0, x[0], 1.0];
    let mut p = [x[1], x[2], -1.0];
    let (mut time, mut margin) = (0.0, f64::INFINITY);
    for &j in pattern {
        let hj = dot(&maps.contacts[j], &q);
        let uj = dot(&maps.contacts[j], &p);
        if uj >= 0.0 || hj <= 0.0 {
            return None;
        }
        for k in (0..maps.n).filter(|&k| k != j) {
            let g = dot(&maps.contacts[k], &q) * -uj + hj * dot(&maps.contacts[k], &p);
            if g <= 0.0 {
                return None;
            }
            margin = margin.min(g / (hj * -uj));
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
    if alpha <= 0.0 || beta <= 0.0 {
        return None;
    }
    Some(([q[1] / alpha, p[0] / beta, p[1] / beta], [alpha, beta, time], margin))
}

fn jacobian(maps: &FloatMaps, pattern: &[usize], x: &[f64; 3]) -> Option<[[f64; 3]; 3]> {
    let mut j = [[0.0; 3]; 3];
    for k in 0..3 {
        let h = 1e-7 * x[k].abs().max(1.0);
        let (mut xp, mut xm) = (*x, *x);
        xp[k] += h;
        xm[k] -= h;
        let (fp, fm) = (float_return(maps, pattern, &xp)?.0, float_return(maps, pattern, &xm)?.0);
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

/// Real eigenvalues and eigenvectors of a 3x3 matrix (`None` if some eigenvalue is not real).
pub fn real_eigen(j: &[[f64; 3]; 3]) -> Option<([f64; 3], [[f64; 3]; 3])> {
    // Characteristic polynomial λ³ - t λ² + s λ - d.
    let t = j[0][0] + j[1][1] + j[2][2];
    let s = j[0][0] * j[1][1] - j[0][1] * j[1][0] + j[0][0] * j[2][2] - j[0][2] * j[2][0] + j[1][1] * j[2][2]
        - j[1][2] * j[2][1];
    let d = j[0][0] * (j[1][1] * j[2][2] - j[1][2] * j[2][1])
        - j[0][1] * (j[1][0] * j[2][2] - j[1][2] * j[2][0])
        + j[0][2] * (j[1][0] * j[2][1] - j[1][1] * j[2][0]);
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
    let model = Model::new(Shape::Polygon(req.n), req.kappa.clone(), req.gamma.clone())
        .map_err(|e| Failure::Body(e.to_string()))?;
    let mut seen = Vec::new();
    for seed in 1..=req.drops.max(1) {
        let run = simulate(
            &model,
            &Initial::RandomDrop { seed },
            crate::simulate::Arithmetic::Float,
            &Options::new(600),
        );
        if let Some(p) = pattern::find(&run.sequence) {
            return Ok(pattern::steps(&p.cycle, req.n as usize));
        }
        seen.push(run.outcome.name());
    }
    Err(Failure::NoPattern(format!("{} drops simulated, outcomes {}", seen.len(), seen.join(", "))))
}

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
        format: FORMAT.into(),
        version: ORBIT_VERSION,
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

/// Produces an orbit certificate: pattern, fixed point, basis, bounds, then δ = 2^-4, 2^-5, ...
/// (each with subdivision 0 to `max_depth`) until the kernel (first backend) accepts; the accepted file is re-checked on every backend.
pub fn certify_orbit(req: &Request, backends: &[Backend]) -> Result<Found, Failure> {
    let body = Polygon::new(req.n, req.kappa.clone(), req.gamma.clone())
        .map_err(|e| Failure::Body(e.to_string()))?;
    let maps = FloatMaps::new(&body);
    let given = match &req.pattern {
        Some(p) => {
            if p.is_empty() || p.iter().any(|&j| j == 0 || j >= req.n as usize) {
                return Err(Failure::Body(format!("pattern steps must lie in 1..{}", req.n - 1)));
            }
            p.clone()
        }
        None => find_pattern(req)?,
    };
    let mut last = Failure::NoAttractingCycle(format!(
        "iterating R_P for the pattern {:?} (every phase) from a grid of starting points did not converge",
        given
    ));
    for pattern in rotations(&given) {
        let Some(x) = fixed_point(&maps, &pattern) else { continue };
        let Some(j) = jacobian(&maps, &pattern, &x) else { continue };
        let Some((eig, vecs)) = real_eigen(&j) else {
            last = Failure::NoContraction(format!(
                "the fixed point {x:?} of R_P for {pattern:?} has complex eigenvalues (not handled by this producer)"
            ));
            continue;
        };
        if eig.iter().any(|l| l.abs() >= 1.0) {
            last = Failure::NoAttractingCycle(format!(
                "the fixed point {x:?} of R_P for {pattern:?} is not attracting: eigenvalues {eig:?}"
            ));
            continue;
        }
        let Some((_, [alpha, beta, time], _)) = float_return(&maps, &pattern, &x) else { continue };
        let ratio = alpha / beta;
        if alpha >= 1.0 || beta >= 1.0 || ratio >= 1.0 {
            last = Failure::NoContraction(format!(
                "at the fixed point alpha = {alpha}, beta = {beta}, alpha/beta = {ratio}: not all below 1"
            ));
            continue;
        }
        let rho = above(ratio + (1.0 - ratio) / 10.0).min(Q::new(999, 1000));
        let lambda = above(alpha.max(beta) + (1.0 - alpha.max(beta)) / 10.0).min(Q::new(999, 1000));
        let period = above(time * 1.1);
        // The axes are the eigenvectors: the columns of A.
        let mut delta = Q::new(1, 16);
        let limits = ParseLimits::default();
        for attempt in 0..24 * (req.max_depth + 1) {
            let depth = attempt % (req.max_depth + 1);
            if attempt > 0 && depth == 0 {
                delta = delta.times(&Q::new(1, 2));
            }
            let cert = certificate(req, &pattern, &x, &vecs, &delta, depth, [&rho, &lambda, &period]);
            match verify_orbit_on(&cert, limits, &backends[..1]) {
                Verdict::Accepted(_) => {
                    let start = std::time::Instant::now();
                    let verdict = verify_orbit_on(&cert, limits, backends);
                    let kernel_seconds = start.elapsed().as_secs_f64();
                    return match verdict {
                        Verdict::Accepted(a) => Ok(Found {
                            certificate: cert,
                            pattern,
                            fixed_point: x,
                            eigenvalues: eig,
                            scales: [alpha, beta, ratio, time],
                            delta: delta.to_f64(),
                            boxes: a.orbit_boxes.unwrap_or(0),
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
