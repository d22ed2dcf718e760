//! points.csv: one row per grid point (docs/map.md lists the columns). Every field is plain text
//! without commas or quotes; empty means "not computed".

use super::grid::{Grid, Point};
use super::point::{Evaluation, SimStats};
use crate::exact::{Q, QExt};
use crate::simulate::Outcome;

/// The header of points.csv.
pub const HEADER: &str = "index,n,rho,kappa,gamma,cc_criterion,pcc_criterion,finder,certified,claim,refuted,\
sim_runs,sim_cc_evidence,sim_pcc_evidence,sim_icc_evidence,sim_undecided_evidence,sim_simultaneous_evidence,\
mean_impacts,sim_cc_proved,sim_no_icc_no_pcc_proved,sim_pcc_proved,sim_icc_proved,sim_simultaneous_proved,\
sim_undecided,sim_contradicted,\
certificate,refutation,orbit";

/// The start of a family map's header: `rho,kappa` are `family,parameter` there (the family's
/// text and the body parameter, exact); every other column is the regular map's.
pub const FAMILY_COLUMNS: &str = "index,n,family,parameter,";

/// The header of a map's points.csv: [`HEADER`], with `family,parameter` for a family map.
pub fn header(grid: &Grid) -> String {
    if grid.family.is_some() {
        HEADER.replacen("index,n,rho,kappa,", FAMILY_COLUMNS, 1)
    } else {
        HEADER.to_string()
    }
}

/// One row of points.csv.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    pub index: usize,
    pub n: u64,
    /// Exact when the grid is in rho, else sqrt(kappa) as the nearest f64.
    pub rho: String,
    pub kappa: Q,
    pub gamma: Q,
    pub cc_criterion: bool,
    pub pcc_criterion: bool,
    pub finder: String,
    pub certified: Option<bool>,
    pub claim: Option<String>,
    /// Exact refutation (with --refute, where no certificate was made).
    pub refuted: Option<bool>,
    pub sim: Option<SimStats>,
    /// The certificate's path relative to the output folder.
    pub certificate: Option<String>,
    /// The refutation's path relative to the output folder.
    pub refutation: Option<String>,
    /// The path of the orbit certificate made to prove drops CC, relative to the output folder.
    pub orbit: Option<String>,
}

/// The orbit certificate file of a point, relative to the output folder.
pub fn orbit_path(p: &Point) -> String {
    format!("orbits/x{:04}-g{:04}.ron", p.ix, p.ig)
}

/// The refutation file of a point, relative to the output folder.
pub fn refutation_path(p: &Point) -> String {
    format!("refutations/x{:04}-g{:04}.ron", p.ix, p.ig)
}

/// The certificate file of a point, relative to the output folder.
pub fn certificate_path(p: &Point) -> String {
    format!("certificates/x{:04}-g{:04}.ron", p.ix, p.ig)
}

impl Row {
    /// The row of an evaluated point.
    pub fn new(grid: &Grid, p: &Point, e: &Evaluation) -> Row {
        let rho = match (&p.rho, &grid.family) {
            (_, Some(f)) => f.text(),
            (Some(r), None) => r.to_string(),
            (None, None) => format!("{}", p.kappa.to_f64().sqrt()),
        };
        Row {
            index: p.index,
            n: grid.n,
            rho,
            kappa: p.kappa.clone(),
            gamma: p.gamma.clone(),
            cc_criterion: e.cc_criterion,
            pcc_criterion: e.pcc_criterion,
            finder: e.finder.to_string(),
            certified: e.certified.map(|c| c.is_some()),
            claim: e.certified.flatten().map(str::to_string),
            refuted: e.refuted,
            sim: e.sim.clone(),
            certificate: e.certificate.as_ref().map(|_| certificate_path(p)),
            refutation: e.refutation.as_ref().map(|_| refutation_path(p)),
            orbit: e.orbit.as_ref().map(|_| orbit_path(p)),
        }
    }

    /// Whether the simulated drops (if any) include CC or PCC as evidence.
    pub fn sim_chatter(&self) -> Option<bool> {
        self.sim.as_ref().map(|s| s.counts[Outcome::Cc.index()] + s.counts[Outcome::Pcc.index()] > 0)
    }

    /// Whether some drop was proved never to separate: proved CC, PCC, or no ICC and no PCC
    /// (a cone entry, finite accumulation time not derived); `None`: no proofs tried.
    pub fn proved_no_icc(&self) -> Option<bool> {
        let chatter = [Outcome::Cc, Outcome::Pcc, Outcome::NoIccNoPcc];
        self.sim.as_ref().and_then(|s| s.proved).map(|p| chatter.iter().any(|o| p[o.index()] > 0))
    }

    /// The CSV line (without newline).
    pub fn to_csv(&self) -> String {
        let b = |x: Option<bool>| x.map(|v| v.to_string()).unwrap_or_default();
        let s = self.sim.as_ref();
        let count = |o: Outcome| s.map(|s| s.counts[o.index()].to_string()).unwrap_or_default();
        let proved =
            |o: Outcome| s.and_then(|s| s.proved).map(|p| p[o.index()].to_string()).unwrap_or_default();
        let contradicted = s.filter(|s| s.proved.is_some()).map(|s| s.contradicted.to_string());
        [
            self.index.to_string(),
            self.n.to_string(),
            self.rho.clone(),
            self.kappa.to_string(),
            self.gamma.to_string(),
            self.cc_criterion.to_string(),
            self.pcc_criterion.to_string(),
            self.finder.clone(),
            b(self.certified),
            self.claim.clone().unwrap_or_default(),
            b(self.refuted),
            s.map(|s| s.runs.to_string()).unwrap_or_default(),
            count(Outcome::Cc),
            count(Outcome::Pcc),
            count(Outcome::Icc),
            count(Outcome::Undecided),
            count(Outcome::Simultaneous),
            s.map(|s| format!("{}", s.mean_impacts())).unwrap_or_default(),
            proved(Outcome::Cc),
            proved(Outcome::NoIccNoPcc),
            proved(Outcome::Pcc),
            proved(Outcome::Icc),
            proved(Outcome::Simultaneous),
            proved(Outcome::Undecided),
            contradicted.unwrap_or_default(),
            self.certificate.clone().unwrap_or_default(),
            self.refutation.clone().unwrap_or_default(),
            self.orbit.clone().unwrap_or_default(),
        ]
        .join(",")
    }

    /// Reads a line written by [`Row::to_csv`].
    pub fn from_csv(line: &str) -> Result<Row, String> {
        let f: Vec<&str> = line.split(',').collect();
        let columns = HEADER.split(',').count();
        if f.len() != columns {
            return Err(format!("expected {columns} fields, found {}", f.len()));
        }
        let opt = |s: &str| (!s.is_empty()).then(|| s.to_string());
        let boolean = |s: &str| s.parse::<bool>().map_err(|_| format!("{s:?} is not true/false"));
        let optb = |s: &str| if s.is_empty() { Ok(None) } else { boolean(s).map(Some) };
        let int = |s: &str| s.parse::<u64>().map_err(|_| format!("{s:?} is not a count"));
        let q = |s: &str| s.parse::<Q>().map_err(|e| format!("{s:?}: {e}"));
        let sim = if f[11].is_empty() {
            None
        } else {
            let runs = int(f[11])?;
            // The f64 evidence is never no-ICC-no-PCC (no column).
            let counts = [int(f[12])?, int(f[13])?, int(f[14])?, int(f[15])?, int(f[16])?, 0];
            let mean: f64 = f[17].parse().map_err(|_| format!("{:?} is not a number", f[17]))?;
            let proved = if f[18].is_empty() {
                None
            } else {
                // Columns: CC, no-ICC-no-PCC, PCC, ICC, simultaneous, undecided.
                let [cc, none, pcc, icc, sim, und] =
                    [int(f[18])?, int(f[19])?, int(f[20])?, int(f[21])?, int(f[22])?, int(f[23])?];
                let mut p = [0; Outcome::COUNT];
                for (o, k) in [
                    (Outcome::Cc, cc),
                    (Outcome::NoIccNoPcc, none),
                    (Outcome::Pcc, pcc),
                    (Outcome::Icc, icc),
                    (Outcome::Simultaneous, sim),
                    (Outcome::Undecided, und),
                ] {
                    p[o.index()] = k;
                }
                Some(p)
            };
            let contradicted = if f[24].is_empty() { 0 } else { int(f[24])? };
            Some(SimStats {
                runs,
                counts,
                proved,
                contradicted,
                impacts: (mean * runs as f64).round() as u64,
            })
        };
        Ok(Row {
            index: int(f[0])? as usize,
            n: int(f[1])?,
            rho: f[2].to_string(),
            kappa: q(f[3])?,
            gamma: q(f[4])?,
            cc_criterion: boolean(f[5])?,
            pcc_criterion: boolean(f[6])?,
            finder: f[7].to_string(),
            certified: optb(f[8])?,
            claim: opt(f[9]),
            refuted: optb(f[10])?,
            sim,
            certificate: opt(f[25]),
            refutation: opt(f[26]),
            orbit: opt(f[27]),
        })
    }
}

/// The whole file: the grid's header and rows in index order.
pub fn csv(grid: &Grid, rows: &[Row]) -> String {
    let mut out = header(grid);
    out.push('\n');
    for r in rows {
        out.push_str(&r.to_csv());
        out.push('\n');
    }
    out
}

/// Reads points.csv (the header must be a regular or a family map's).
pub fn parse_csv(text: &str) -> Result<Vec<Row>, String> {
    let mut lines = text.lines();
    let family = HEADER.replacen("index,n,rho,kappa,", FAMILY_COLUMNS, 1);
    if !matches!(lines.next(), Some(h) if h == HEADER || h == family) {
        return Err("not a points.csv of this version of chatter (header differs)".into());
    }
    lines.enumerate().map(|(i, l)| Row::from_csv(l).map_err(|e| format!("line {}: {e}", i + 2))).collect()
}
