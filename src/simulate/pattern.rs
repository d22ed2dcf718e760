//! The impact sequence in words: the transient and the periodic pattern it settles into,
//! named by the step maps S_j of docs/model.md §3 (S_1 repeated is the paper's regular pattern
//! "an impact at a vertex is followed by an impact at its immediate neighbour").

use super::system::Shape;
use super::text::singular;

/// Longest period looked for.
pub const MAX_PERIOD: usize = 12;

/// A periodic tail of an impact sequence.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Pattern {
    /// Impacts before the periodic tail.
    pub transient: usize,
    /// One period, as it first appears in the tail.
    pub cycle: Vec<u8>,
    /// Length of the periodic tail (at least three periods).
    pub tail: usize,
}

/// How the settled pattern moves around the polygon.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Kind {
    /// The rod's two ends alternate.
    RodEnds,
    /// Two neighbours alternate (PCC-like).
    AdjacentPair,
    /// Two non-neighbours alternate (rod-like, e.g. a square on a diagonal).
    DistantPair,
    /// Every impact is followed by its neighbour j places on (S_j repeated; 1 is
    /// counter-clockwise, n-1 clockwise).
    Rotation(usize),
    /// Other cycles, with their steps j (S_j) listed.
    Steps(Vec<usize>),
}

/// The steps j (next contact = previous + j mod n) around a cycle.
pub fn steps(cycle: &[u8], n: usize) -> Vec<usize> {
    (0..cycle.len()).map(|i| (cycle[(i + 1) % cycle.len()] as usize + n - cycle[i] as usize) % n).collect()
}

/// The smallest period whose tail covers at least three periods, if any.
pub fn find(seq: &[u8]) -> Option<Pattern> {
    let len = seq.len();
    (1..=MAX_PERIOD.min(len / 3)).find_map(|p| {
        let mut start = len - p;
        while start > 0 && seq[start - 1] == seq[start - 1 + p] {
            start -= 1;
        }
        let tail = len - start;
        (tail >= 3 * p).then(|| Pattern { transient: start, cycle: seq[start..start + p].to_vec(), tail })
    })
}

impl Pattern {
    /// What kind of motion the cycle is on a body of this shape.
    pub fn kind(&self, shape: Shape) -> Kind {
        let (c, n) = (&self.cycle, shape.n());
        if c.len() == 2 {
            let (a, b) = (c[0] as usize, c[1] as usize);
            return match shape {
                Shape::Rod => Kind::RodEnds,
                Shape::Polygon(_) | Shape::Convex(_) if (a + 1) % n == b || (b + 1) % n == a => {
                    Kind::AdjacentPair
                }
                Shape::Polygon(_) | Shape::Convex(_) => Kind::DistantPair,
            };
        }
        let s = steps(c, n);
        if s.iter().all(|&j| j == s[0]) { Kind::Rotation(s[0]) } else { Kind::Steps(s) }
    }
}

fn list(xs: &[u8]) -> String {
    xs.iter().map(ToString::to_string).collect::<Vec<_>>().join(",")
}

/// A one-line summary: transient, then the settled pattern, e.g. "2,0 (2 impacts), then cycles
/// 1→2→0 (S_1 repeated: ...)" or "..., then 0,1,0,1 (adjacent pair: PCC-like)".
pub fn summary_for(seq: &[u8], shape: Shape) -> String {
    singular(summary_raw(seq, shape))
}

fn summary_raw(seq: &[u8], shape: Shape) -> String {
    const SHOW: usize = 12;
    if seq.is_empty() {
        return "no impacts".into();
    }
    let Some(pat) = find(seq) else {
        let head = if seq.len() <= 2 * SHOW {
            list(seq)
        } else {
            format!("{},…,{}", list(&seq[..SHOW]), list(&seq[seq.len() - SHOW..]))
        };
        return format!("{head} ({} impacts, no settled pattern)", seq.len());
    };
    let n = shape.n();
    let settled = match pat.kind(shape) {
        Kind::RodEnds => format!("{0},{1},{0},{1} (the two ends alternate)", pat.cycle[0], pat.cycle[1]),
        Kind::AdjacentPair => {
            format!("{0},{1},{0},{1} (adjacent pair: PCC-like)", pat.cycle[0], pat.cycle[1])
        }
        Kind::DistantPair => {
            format!("{0},{1},{0},{1} (non-adjacent pair: rod-like)", pat.cycle[0], pat.cycle[1])
        }
        Kind::Rotation(j) => {
            let arrows = pat.cycle.iter().map(ToString::to_string).collect::<Vec<_>>().join("→");
            let dir = if j == 1 {
                "each impact followed by its counter-clockwise neighbour".to_string()
            } else if j == n - 1 {
                "each impact followed by its clockwise neighbour".to_string()
            } else {
                format!("each impact followed by the contact {j} places on")
            };
            format!("cycles {arrows} (S_{j} repeated: {dir})")
        }
        Kind::Steps(s) => {
            let maps = s.iter().map(|j| format!("S_{j}")).collect::<Vec<_>>().join(" ");
            format!("cycles {} (steps {maps})", list(&pat.cycle))
        }
    };
    let repeats = format!("{} impacts", pat.tail);
    if pat.transient == 0 {
        format!("{settled} from the first impact ({repeats})")
    } else {
        let t = &seq[..pat.transient];
        let head = if t.len() <= SHOW { list(t) } else { format!("{},…", list(&t[..SHOW])) };
        format!("{head} ({} impacts), then {settled} ({repeats})", pat.transient)
    }
}
