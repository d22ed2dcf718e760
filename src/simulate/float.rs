//! The `f64` engine with renormalisation (docs/model.md §10).
//!
//! The dynamics are homogeneous: scaling q by a and p by b maps trajectories to trajectories
//! with times scaled by a/b. After every impact q and p are each divided by the power of two
//! that brings their largest component into [1, 2) (exact: only exponents change), and the
//! exponents are carried as integers, so the physical state is q·2^eq, p·2^ep and a normalised
//! interval τ is the physical interval τ·2^(eq-ep). Nothing underflows, however many impacts,
//! and no `ln` is taken in the loop.
//!
//! The state is kept in the coordinates of a [`Frame`]: the heights and normal velocities of
//! the last three distinct contacts to land. A change of frame copies two coordinates and sets
//! the new contact's to h = 0, u = -γ u⁻, exactly, so the heights and velocities of chattering
//! contacts keep full relative precision next to the rest of the state (see [`Frame`]).

use super::drop::Start;
use super::engine::{Engine, Step};
use super::snapshot::{Scaled, Snapshot, pow2};
use super::system::{FloatSystem, Frame, Shape, TABLE_CONTACTS, frame_index};

/// Relative difference below which two `f64` impact times count as a tie.
pub const NEAR_TIE: f64 = 1e-12;

const NONE: usize = usize::MAX;

/// Exponent of a finite non-zero x: x in [2^e, 2^(e+1)).
#[inline]
fn exponent(x: f64) -> i64 {
    let b = ((x.to_bits() >> 52) & 0x7ff) as i64;
    if b == 0 {
        // Subnormal: rescale first (never on the hot path).
        exponent(x * pow2(64)) - 64
    } else {
        b - 1023
    }
}

/// Divides v by the power of two that puts its largest |component| in [1, 2); returns it.
/// (The largest |component| is found on the bit patterns: for finite floats, |x| orders like
/// its bits with the sign cleared.)
#[inline(always)]
fn renormalise(v: &mut [f64; 3]) -> i64 {
    const ABS: u64 = !(1u64 << 63);
    let m = (v[0].to_bits() & ABS).max(v[1].to_bits() & ABS).max(v[2].to_bits() & ABS);
    let b = (m >> 52) as i64; // biased exponent of the largest component
    if b == 1023 {
        return 0;
    }
    if b == 0 || b >= 2046 {
        return renormalise_rare(v, m);
    }
    let e = b - 1023; // in [-1022, 1022], so 2^-e is a normal float
    let s = f64::from_bits(((1023 - e) as u64) << 52);
    v[0] *= s;
    v[1] *= s;
    v[2] *= s;
    e
}

/// Zero, subnormal or non-finite largest component.
#[cold]
fn renormalise_rare(v: &mut [f64; 3], m: u64) -> i64 {
    if m == 0 || (m >> 52) == 0x7ff {
        return 0;
    }
    let e = exponent(f64::from_bits(m));
    renormalise_slow(v, e)
}

#[cold]
fn renormalise_slow(v: &mut [f64; 3], e: i64) -> i64 {
    for x in v.iter_mut() {
        *x = *x * pow2(-e / 2) * pow2(-e - (-e / 2));
    }
    e
}

#[inline(always)]
fn dot(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The `f64` event-driven simulation of one drop.
#[derive(Clone, Debug)]
pub struct FloatEngine<'a> {
    sys: &'a FloatSystem,
    /// q and p in the coordinates of `frame`, normalised.
    q: [f64; 3],
    p: [f64; 3],
    eq: i64,
    ep: i64,
    /// Index of the frame in `sys.frames` (bodies with a table of frames).
    frame: usize,
    /// The frame itself, for bodies without a table (n > 6), recomputed on a change of frame.
    own: Option<Box<Frame>>,
    /// Slots from the least to the most recently landed contact.
    order: [u8; 3],
    last: usize,
    time: f64,
}

#[inline(always)]
fn mat_vec(m: &[[f64; 3]; 3], x: &[f64; 3]) -> [f64; 3] {
    [dot(&m[0], x), dot(&m[1], x), dot(&m[2], x)]
}

impl<'a> FloatEngine<'a> {
    /// Starts from a state in our coordinates, in the frame of contacts 0, 1, 2.
    pub fn new(sys: &'a FloatSystem, start: &Start<f64>) -> FloatEngine<'a> {
        let frame = if sys.shape == Shape::Rod { 0 } else { frame_index([0, 1, 2]) };
        let own = sys.frames.is_empty().then(|| Box::new(Frame::from_float(sys, [0, 1, 2])));
        let a = own.as_deref().unwrap_or_else(|| &sys.frames[frame]).from_ours;
        let (mut q, mut p) = (mat_vec(&a, &start.q), mat_vec(&a, &start.p));
        let eq = renormalise(&mut q);
        let ep = renormalise(&mut p);
        FloatEngine { sys, q, p, eq, ep, frame, own, order: [0, 1, 2], last: NONE, time: 0.0 }
    }

    /// The current frame.
    #[inline(always)]
    fn fr(&self) -> &Frame {
        match &self.own {
            Some(fr) => fr,
            None => &self.sys.frames[self.frame],
        }
    }

    /// The current frame: its own (`OWN`, n > 6) or from the table.
    #[inline(always)]
    fn frame_of<const OWN: bool>(&self) -> &Frame {
        let sys = self.sys;
        match &self.own {
            Some(fr) if OWN => fr,
            _ => &sys.frames[self.frame],
        }
    }

    /// Moves to the frame of the contacts `slots`: computed (`OWN`, n > 6) or from the table.
    #[inline(always)]
    fn change_frame<const OWN: bool>(&mut self, slots: [usize; 3]) {
        match &mut self.own {
            Some(fr) if OWN => fr.refill(self.sys, slots),
            _ => self.frame = frame_index(slots),
        }
    }

    /// Kinetic energy as m · 2^e (exact scaling: T(p·2^ep) = T(p)·4^ep).
    pub fn energy(&self) -> Scaled {
        Scaled { m: 0.5 * dot(&self.p, &mat_vec(&self.fr().gram, &self.p)), e: 2 * self.ep }
    }

    /// The normalised state in our coordinates (q, eq, p, ep).
    pub fn raw(&self) -> ([f64; 3], i64, [f64; 3], i64) {
        let b = &self.fr().to_ours;
        (mat_vec(b, &self.q), self.eq, mat_vec(b, &self.p), self.ep)
    }

    /// The contacts whose heights are the current coordinates.
    pub fn frame_contacts(&self) -> [usize; 3] {
        self.fr().slots
    }

    /// Runs up to `budget` impacts without any bookkeeping; returns the number of impacts done.
    /// (The hot loop on its own, for benchmarks.)
    pub fn run_bare(&mut self, budget: usize) -> usize {
        for i in 0..budget {
            match self.step() {
                Step::Impact { .. } => {}
                _ => return i,
            }
        }
        budget
    }

    #[cold]
    fn tie(&self, best: usize, t: f64) -> Step {
        let mut contacts: Vec<usize> = (0..self.sys.n)
            .filter(|&k| {
                let f = &self.fr().f[k];
                let u = dot(f, &self.p);
                k != self.last && u < 0.0 && {
                    let tk = dot(f, &self.q).max(0.0) / -u;
                    tk <= t + t * NEAR_TIE
                }
            })
            .collect();
        if !contacts.contains(&best) {
            contacts.push(best);
        }
        contacts.sort_unstable();
        Step::Tie { contacts, dt: Scaled { m: t, e: self.eq - self.ep }, exact: false }
    }
}

impl FloatEngine<'_> {
    /// One event for a body with its own frame (n > 6), kept out of line.
    #[inline(never)]
    fn step_dynamic(&mut self, n: usize) -> Step {
        self.step_n::<true>(n)
    }

    /// One event for a body with n contacts (inlined with a constant n for small bodies, so
    /// that the contact loop unrolls), with the engine's own frame (`OWN`) or the table's.
    ///
    /// Times are compared as fractions h/w (w = -u > 0) by cross-multiplication; the one division
    /// is for the winner. (+∞ is 1/0.)
    #[inline(always)]
    fn step_n<const OWN: bool>(&mut self, n: usize) -> Step {
        let fr = self.frame_of::<OWN>();
        let (mut q, mut p) = (self.q, self.p);
        let (mut best, mut bh, mut bw) = (NONE, 1.0, 0.0);
        let (mut sh, mut sw) = (1.0, 0.0);
        let covectors = if n <= TABLE_CONTACTS { &fr.inline_f[..n] } else { &fr.f[..n] };
        for (k, f) in covectors.iter().enumerate() {
            let u = dot(f, &p);
            if u < 0.0 && k != self.last {
                let (h, w) = (dot(f, &q).max(0.0), -u);
                if h * bw < bh * w {
                    (sh, sw) = (bh, bw);
                    (best, bh, bw) = (k, h, w);
                } else if h * sw < sh * w {
                    (sh, sw) = (h, w);
                }
            }
        }
        if best == NONE {
            return if p.iter().all(|x| x.is_finite()) { Step::NoApproach } else { Step::Breakdown };
        }
        let bt = bh / bw;
        if sh <= (bt + bt * NEAR_TIE) * sw {
            return self.tie(best, bt);
        }
        if !bt.is_finite() {
            return Step::Breakdown;
        }
        let (kick, best_slot) = if n <= TABLE_CONTACTS {
            (fr.inline_kick[best], fr.inline_slot[best] as usize)
        } else {
            (fr.kick[best], fr.slot[best] as usize)
        };
        let slots = fr.slots;
        let bu = -bw;
        let dt = Scaled { m: bt, e: self.eq - self.ep };
        self.time += bt * pow2(dt.e);
        for i in 0..3 {
            q[i] += bt * p[i];
            p[i] -= bu * kick[i];
        }
        // The landing contact's coordinates: h = 0, u = -γ u⁻ (a new slot replaces the oldest).
        let mut slot = best_slot;
        if slot >= 3 {
            slot = self.order[0] as usize;
            let mut slots = slots;
            slots[slot] = best;
            self.change_frame::<OWN>(slots);
        }
        q[slot] = 0.0;
        p[slot] = -self.sys.gamma * bu;
        if self.order[2] as usize != slot {
            let o = self.order;
            self.order = if o[0] as usize == slot { [o[1], o[2], o[0]] } else { [o[0], o[2], o[1]] };
        }
        self.eq += renormalise(&mut q);
        self.ep += renormalise(&mut p);
        self.q = q;
        self.p = p;
        self.last = best;
        Step::Impact { contact: best, dt }
    }
}

impl Engine for FloatEngine<'_> {
    #[inline]
    fn step(&mut self) -> Step {
        match (self.sys.n, self.own.is_some()) {
            (2, _) => self.step_n::<false>(2),
            (3, _) => self.step_n::<false>(3),
            (4, _) => self.step_n::<false>(4),
            (n, false) => self.step_n::<false>(n),
            (n, true) => self.step_dynamic(n),
        }
    }

    fn v_positive(&self) -> bool {
        dot(&self.fr().centre, &self.p) > 0.0
    }

    fn at_rest(&self) -> bool {
        self.p.iter().all(|&x| x == 0.0)
    }

    fn time(&self) -> f64 {
        self.time
    }

    fn snapshot(&self) -> Snapshot {
        let (mut q, eq, mut p, ep) = self.raw();
        let q_exp = eq + renormalise(&mut q);
        let p_exp = ep + renormalise(&mut p);
        Snapshot { q, q_exp, p, p_exp, energy: self.energy() }
    }

    fn is_exact(&self) -> bool {
        false
    }
}
