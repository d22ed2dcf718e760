//! The parameter plane of the paper's maps (figures "sajatertekek" and "simulations"): a grid of
//! cell centres over (rho = sqrt(kappa), gamma) or (kappa, gamma), and its split into shards.

use crate::exact::{Q, parse_user_number};
use serde::{Deserialize, Serialize};
use std::path::Path;

/// Largest number of steps on one axis.
pub const MAX_STEPS: u32 = 10_000;

/// The horizontal variable of a map.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "lowercase")]
pub enum Variable {
    /// rho = sqrt(kappa), the paper's horizontal axis; kappa = rho^2 is exact.
    Rho,
    /// kappa itself.
    Kappa,
    /// The parameter of a body family (`map --family`, docs/map.md "Body families").
    Parameter,
}

/// One axis `a:b:STEPS`: the centres of STEPS equal cells of [a, b],
/// a + (i + 1/2)(b - a)/STEPS for i = 0..STEPS-1 (so (0, 1) never touches 0 or 1).
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize, schemars::JsonSchema)]
pub struct Axis {
    /// Canonical `p/q`.
    #[schemars(with = "String")]
    pub lo: Q,
    /// Canonical `p/q`.
    #[schemars(with = "String")]
    pub hi: Q,
    pub steps: u32,
}

impl Axis {
    /// Reads `a:b:STEPS` (numbers exact, as everywhere: 0.1 is 1/10).
    pub fn parse(text: &str) -> Result<Axis, String> {
        let parts: Vec<&str> = text.split(':').collect();
        let [a, b, s] = parts.as_slice() else {
            return Err(format!("{text:?} is not of the form a:b:STEPS (e.g. 0:1:100)"));
        };
        let lo = parse_user_number(a)?;
        let hi = parse_user_number(b)?;
        let steps: u32 = s.trim().parse().map_err(|_| format!("STEPS {s:?} is not a positive integer"))?;
        if steps == 0 || steps > MAX_STEPS {
            return Err(format!("STEPS must be between 1 and {MAX_STEPS}"));
        }
        if lo >= hi {
            return Err(format!("the interval {lo}:{hi} is empty (a must be below b)"));
        }
        Ok(Axis { lo, hi, steps })
    }

    /// The centre of cell i.
    pub fn value(&self, i: u32) -> Q {
        let width = &self.hi - &self.lo;
        &self.lo + &(width * Q::new(2 * i as i64 + 1, 2 * self.steps as i64))
    }

    /// `a:b:STEPS` in canonical numbers.
    pub fn text(&self) -> String {
        format!("{}:{}:{}", self.lo, self.hi, self.steps)
    }
}

/// A map's grid: the body (regular n-gon, or a body family with n contacts), the horizontal
/// axis and the gamma axis.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize, schemars::JsonSchema)]
pub struct Grid {
    pub n: u64,
    pub variable: Variable,
    pub x: Axis,
    pub gamma: Axis,
    /// The body family whose parameter is the horizontal axis (variable `parameter`); absent for
    /// the regular n-gon's maps.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub family: Option<super::family::BodyFamily>,
}

/// One grid point, with exact parameters.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Point {
    /// index = ix * (gamma steps) + ig: the row of points.csv.
    pub index: usize,
    pub ix: u32,
    pub ig: u32,
    /// rho when it is the grid's variable (exact); else sqrt(kappa) is printed as a decimal.
    pub rho: Option<Q>,
    /// kappa; on a family's grid, the body parameter.
    pub kappa: Q,
    pub gamma: Q,
}

impl Grid {
    /// Number of points.
    pub fn len(&self) -> usize {
        self.x.steps as usize * self.gamma.steps as usize
    }

    /// Whether the grid has no point (never, for a parsed grid).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The point of row `index`.
    pub fn point(&self, index: usize) -> Point {
        let per = self.gamma.steps as usize;
        let (ix, ig) = ((index / per) as u32, (index % per) as u32);
        let x = self.x.value(ix);
        let gamma = self.gamma.value(ig);
        match self.variable {
            Variable::Rho => Point { index, ix, ig, kappa: &x * &x, rho: Some(x), gamma },
            Variable::Kappa | Variable::Parameter => Point { index, ix, ig, rho: None, kappa: x, gamma },
        }
    }

    /// Checks that every point is a body: kappa > 0 (a family's body at every parameter) and
    /// 0 <= gamma <= 1.
    pub fn validate(&self) -> Result<(), String> {
        for a in [&self.x, &self.gamma] {
            if a.steps == 0 || a.steps > MAX_STEPS || a.lo >= a.hi {
                return Err(format!(
                    "the axis {} is not a:b:STEPS with a < b and 1 to {MAX_STEPS} steps",
                    a.text()
                ));
            }
        }
        if let Some(f) = &self.family {
            return self.validate_family(f);
        }
        if !(3..=6).contains(&self.n) {
            return Err(format!(
                "--n: {0} is not supported by maps, which cover n = 3, 4, 5 and 6 (the paper's triangle, square and pentagon, and the hexagon); for n = {0} take single points (`chatter classify --n {0} ...`, `chatter simulate --n {0} ...`); the rod's (n = 2) CC region is Goyal's closed formula (`chatter bodies`)",
                self.n
            ));
        }
        let zero = Q::int(0);
        if self.x.lo < zero {
            let name = if self.variable == Variable::Rho { "--rho" } else { "--kappa" };
            return Err(format!(
                "{name}: an axis from {} is not accepted: it must start at 0 or above (cell centres are then > 0)",
                self.x.lo
            ));
        }
        if self.gamma.lo < zero || self.gamma.hi > Q::int(1) {
            return Err(format!(
                "--gamma: the axis from {} to {} is not accepted: it must lie in [0, 1]",
                self.gamma.lo, self.gamma.hi
            ));
        }
        Ok(())
    }
}

impl Grid {
    /// A family's grid: the body at every parameter of the axis, gamma within [0, 1].
    fn validate_family(&self, f: &super::family::BodyFamily) -> Result<(), String> {
        if self.gamma.lo < Q::int(0) || self.gamma.hi > Q::int(1) {
            return Err(format!(
                "--gamma: the axis from {} to {} is not accepted: it must lie in [0, 1]",
                self.gamma.lo, self.gamma.hi
            ));
        }
        for i in 0..self.x.steps {
            let (body, _) = f.body(&self.x.value(i), &Q::new(1, 2)).map_err(|e| format!("--family: {e}"))?;
            if body.n() as u64 != self.n {
                return Err(format!("--family: {} contacts, not {}", body.n(), self.n));
            }
        }
        Ok(())
    }
}

/// Part K of N of a sweep (K = 0..N-1): the points whose index is K modulo N, so that every
/// shard gets a share of the slow points near the thresholds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Shard {
    pub index: u32,
    pub count: u32,
}

impl Shard {
    /// The whole grid.
    pub const ALL: Shard = Shard { index: 0, count: 1 };

    /// Checks that `shards` (each with the folder it was read from) are shards 0..N-1 of one
    /// `count` = N, each exactly once (a shard file naming K >= N is refused, never indexed; the
    /// work is bounded by the number of shards given, whatever N a file names).
    pub fn check_cover<'a>(
        count: u32,
        shards: impl IntoIterator<Item = (Shard, &'a Path)>,
    ) -> Result<(), String> {
        let mut seen = std::collections::BTreeSet::new();
        for (s, dir) in shards {
            if s.count != count || s.index >= count {
                return Err(format!(
                    "{} is not one of the {count} shards (shard {}/{})",
                    dir.display(),
                    s.index,
                    s.count
                ));
            }
            if !seen.insert(s.index) {
                return Err(format!("shard {}/{count} given twice ({})", s.index, dir.display()));
            }
        }
        match (0..count).find(|k| !seen.contains(k)) {
            Some(k) => Err(format!("shard {k}/{count} is missing")),
            None => Ok(()),
        }
    }

    /// Reads `K/N` (0 <= K < N).
    pub fn parse(text: &str) -> Result<Shard, String> {
        let (k, n) = text.split_once('/').ok_or_else(|| format!("{text:?} is not K/N or auto"))?;
        let k: u32 = k.trim().parse().map_err(|_| format!("K in {text:?} is not a non-negative integer"))?;
        let n: u32 = n.trim().parse().map_err(|_| format!("N in {text:?} is not a positive integer"))?;
        if n == 0 || k >= n {
            return Err(format!("shard {k}/{n}: K must satisfy 0 <= K < N"));
        }
        Ok(Shard { index: k, count: n })
    }

    /// K and N from a SLURM job array, counting as SLURM does: task IDs run from
    /// SLURM_ARRAY_TASK_MIN to SLURM_ARRAY_TASK_MAX in steps of SLURM_ARRAY_TASK_STEP,
    /// SLURM_ARRAY_TASK_COUNT of them (`--array=0-9`, `--array=1-10` and `--array=0-18:2` all give
    /// shards 0..9 of 10; a `%` limit changes none of these variables).
    ///
    /// The variables must describe such a range, and the task ID must be on it: otherwise every
    /// task of the array is refused with a message naming the variables and their values. A list
    /// with gaps such as `--array=1,5,9` is the common case: SLURM reports MIN=1, MAX=9, STEP=1 and
    /// COUNT=3, and 9 IDs from 1 to 9 are not 3 tasks. SLURM always sets all five variables; for a
    /// hand-made environment MIN defaults to 0, STEP to 1 and MAX to MIN + (COUNT - 1) STEP.
    pub fn from_slurm(var: impl Fn(&str) -> Option<String>) -> Result<Shard, String> {
        let get = |name: &str| -> Result<Option<u64>, String> {
            var(name)
                .map(|v| v.trim().parse().map_err(|_| format!("{name}={v:?} is not a non-negative integer")))
                .transpose()
        };
        let required = |name: &str| -> Result<u64, String> {
            get(name)?.ok_or_else(|| {
                format!(
                    "--shard auto needs a SLURM job array ({name} is not set; submit with sbatch --array)"
                )
            })
        };
        let id = required("SLURM_ARRAY_TASK_ID")?;
        let count = required("SLURM_ARRAY_TASK_COUNT")?;
        let min = get("SLURM_ARRAY_TASK_MIN")?.unwrap_or(0);
        let step = get("SLURM_ARRAY_TASK_STEP")?.unwrap_or(1);
        let use_range = "submit a range (--array=0-31, --array=1-32 or --array=0-62:2, with any % limit) or use --shard K/N";
        if count == 0 || count > u32::MAX as u64 {
            return Err(format!(
                "SLURM_ARRAY_TASK_COUNT={count} is not a number of tasks (1 to {})",
                u32::MAX
            ));
        }
        if step == 0 {
            return Err(format!(
                "SLURM_ARRAY_TASK_STEP={step}: the task IDs of an array are at least 1 apart"
            ));
        }
        let max = match get("SLURM_ARRAY_TASK_MAX")? {
            Some(max) => max,
            None => (count - 1).checked_mul(step).and_then(|d| d.checked_add(min)).ok_or_else(|| {
                format!("SLURM_ARRAY_TASK_MIN={min} + (SLURM_ARRAY_TASK_COUNT={count} - 1) x SLURM_ARRAY_TASK_STEP={step} overflows")
            })?,
        };
        // The array itself: MIN, MIN + STEP, ..., MAX must be COUNT IDs.
        if min > max {
            return Err(format!(
                "SLURM_ARRAY_TASK_MIN={min} is above SLURM_ARRAY_TASK_MAX={max}: not a job array; {use_range}"
            ));
        }
        if (max - min) % step != 0 {
            return Err(format!(
                "SLURM_ARRAY_TASK_STEP={step} does not divide SLURM_ARRAY_TASK_MAX - SLURM_ARRAY_TASK_MIN = {max} - {min}: the task IDs do not form a range; {use_range}"
            ));
        }
        let ids = (max - min) / step + 1;
        if ids != count {
            return Err(format!(
                "SLURM_ARRAY_TASK_COUNT={count} but SLURM_ARRAY_TASK_MIN={min} to SLURM_ARRAY_TASK_MAX={max} in steps of SLURM_ARRAY_TASK_STEP={step} are {ids} IDs: the array has gaps (a list such as --array=1,5,9), so its tasks are not shards 0..{} of {count}; {use_range}",
                count - 1
            ));
        }
        // This task in it.
        if id < min || id > max {
            return Err(format!(
                "SLURM_ARRAY_TASK_ID={id} is outside SLURM_ARRAY_TASK_MIN={min}..SLURM_ARRAY_TASK_MAX={max}"
            ));
        }
        if (id - min) % step != 0 {
            return Err(format!(
                "SLURM_ARRAY_TASK_ID={id} is not SLURM_ARRAY_TASK_MIN={min} plus a multiple of SLURM_ARRAY_TASK_STEP={step}"
            ));
        }
        Ok(Shard { index: ((id - min) / step) as u32, count: count as u32 })
    }

    /// The indices of this shard's points, in order.
    pub fn indices(self, len: usize) -> impl Iterator<Item = usize> {
        (self.index as usize..len).step_by(self.count as usize)
    }
}
