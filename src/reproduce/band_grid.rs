//! The n = 3 band across κ (issue 15 §3, docs/orbit-certificates.md §7): orbit certificates above
//! the CC threshold γ*(κ), beside the exact S₁ and S₁²S₂² criteria and random drops, the drops
//! at 1.02 γ* for n = 4, 5, 6, and the pentagon's band point (issue 22 §2), certified in
//! Q(cos 2π/5).

use super::items::{Context, orbit_certificate};
use super::{Item, Report, Table, Verdict};
use crate::bodies::cosine;
use crate::exact::{Q, QExt};
use crate::orbit::band::{OrbitVerdict, Row, band_rows, cc_threshold, drops, gamma_at};
use crate::spectral::criteria::pcc_criterion;
use crate::spectral::pcc_sign::pair_signs;
use chatter_kernel::model::Polygon;

/// The κ grid and the ratios γ/γ* of a run.
fn grid(quick: bool) -> (Vec<Q>, Vec<f64>, u64) {
    let k = |a: i64, b: i64| Q::new(a, b);
    if quick {
        (vec![k(1, 20), k(1, 8), k(3, 10)], vec![1.02, 1.2], 4)
    } else {
        let kappas =
            vec![k(1, 20), k(1, 10), k(1, 8), k(3, 20), k(1, 5), k(1, 4), k(3, 10), k(7, 20), k(2, 5)];
        (kappas, vec![1.02, 1.05, 1.1, 1.2], 10)
    }
}

/// One table row: κ, γ*, γ, the producer, the two exact criteria, the drops.
fn table_row(r: &Row) -> Vec<String> {
    let yes = |b: bool| if b { "holds" } else { "fails" }.to_string();
    vec![
        r.kappa.to_string(),
        format!("{:.6}", r.gamma_star.0.to_f64()),
        format!("{} ({:.6}, r = {})", r.gamma, r.gamma.to_f64(), r.ratio),
        match &r.orbit {
            OrbitVerdict::Certified { .. } => format!("certified ({})", r.orbit.letter()),
            OrbitVerdict::Failed { kind, .. } => format!("not certified: {kind}"),
        },
        yes(r.cc),
        yes(r.cycle),
        r.drops.text(),
    ]
}

/// Drops just above γ* for n = 4, 5, 6: "n = 4, κ = 1/6, γ = …: ICC 4/4".
fn other_n(runs: u64) -> Vec<String> {
    let mut lines = Vec::new();
    for (n, a, b) in [(4u64, 1, 6), (5, 1, 10), (6, 1, 20)] {
        let kappa = Q::new(a, b);
        let Some(th) = cc_threshold(n, &kappa, 40) else { continue };
        let gamma = gamma_at(&th, 1.02, 100_000);
        let d = drops(n, &kappa, &gamma, runs, 600);
        lines.push(format!(
            "n = {n}, κ = {kappa}, γ = {gamma} (1.02 γ*, γ* ≈ {:.6}): drops {}",
            th.0.to_f64(),
            d.text()
        ));
    }
    lines
}

/// Drops simulated at the pentagon's band point (its cycle holds a few percent of them).
const PENTAGON_DROPS: u64 = 300;

/// The pentagon's band point (n = 5, κ = 961/25600, γ = 61/160; issue 22): S₁'s criterion decided
/// exactly in Q(cos 2π/5), the drops' patterns, and an orbit certificate written and re-verified.
/// The line, and whether it refutes Conjecture 1 (i) ⇒ (iii).
fn pentagon(ctx: &Context) -> Result<(String, bool), String> {
    use crate::exact::QField;
    use crate::spectral::number_field::Nf;
    let (kappa, gamma) = (Q::new(961, 25600), Q::new(61, 160));
    let body = Polygon::with_cosine(5, cosine(5), Nf::from_q(&kappa), Nf::from_q(&gamma))
        .map_err(|e| e.to_string())?;
    let holds = crate::spectral::criteria::cc_criterion(&body).0;
    let ([cc, pcc, icc, other], cycles) =
        crate::orbit::search::settle(5, &kappa, &gamma, PENTAGON_DROPS, 2000);
    let shares: Vec<String> = cycles
        .iter()
        .map(|(p, k)| format!("{} ({k}/{PENTAGON_DROPS})", crate::orbit::band::steps_text(p)))
        .collect();
    let head = format!(
        "pentagon, κ = 961/25600, γ = 61/160: S₁'s criterion {} (exact, in Q(cos 2π/5)); {PENTAGON_DROPS} drops (f64 evidence, 2000 impacts): CC {cc}, PCC {pcc}, ICC {icc}, other {other}; cycles of the CC drops: {}",
        if holds { "holds" } else { "fails" },
        if shares.is_empty() { "none".to_string() } else { shares.join(", ") }
    );
    let name = "orbit-n5-kappa961_25600-gamma61_160";
    Ok(match orbit_certificate(ctx, name, (5, &kappa, &gamma), Some(vec![1, 1, 2, 4, 4, 3]))? {
        Ok((rel, found, boxes)) => (
            format!(
                "{head}; the orbit certificate `{rel}` (pattern {}, {boxes} sub-boxes, constants of Q(cos 2π/5) enclosed by rationals) is accepted by the kernel on both backends: CC is proved from a set of states{}",
                crate::orbit::band::steps_text(&found.pattern),
                if holds { "" } else { ", so Conjecture 1 (i) ⇒ (iii) fails for n = 5 too" }
            ),
            !holds,
        ),
        Err(why) => (format!("{head}; no orbit certificate: {why}"), false),
    })
}

/// The square (κ = 1/6) at γ = 1/500, where the PCC criterion holds: what drops do.
fn square_pcc(runs: u64) -> Result<String, String> {
    let (kappa, gamma) = (Q::new(1, 6), Q::new(1, 500));
    let body = Polygon::new(4, kappa.clone(), gamma.clone()).map_err(|e| e.to_string())?;
    let (holds, _) = pcc_criterion(&body);
    let d = drops(4, &kappa, &gamma, runs, 2000);
    let signs = pair_signs(&body)?;
    let alternation = match signs.signs {
        Some(_) if signs.blocks_alternation() => "both eigenvectors of S₃S₁ other than that of the eigenvalue 1 have u₀u₁ > 0 (decided exactly in Q(√D)), so by the argument of docs/orbit-certificates.md §7.4 (not machine-checked) the alternation 0, 1, 0, … cannot go on for ever".to_string(),
        Some(s) => format!("the signs of u₀u₁ on the eigenvectors of S₃S₁ other than that of the eigenvalue 1 are {s:?} (exact)"),
        None => "S₃S₁ has no two distinct real eigenvalues besides 1".to_string(),
    };
    Ok(format!(
        "square, κ = 1/6, γ = 1/500: the PCC criterion (Conjecture 2) {} (exact); drops {}; {alternation}; no PCC orbit certificate (the format cannot express PCC)",
        if holds { "holds" } else { "fails" },
        d.text()
    ))
}

/// The report item: Conjecture 1 against certificates across κ, and the candidate criterion.
pub fn band_grid(ctx: &Context, r: &mut Report) -> Result<(), String> {
    let (kappas, ratios, runs) = grid(ctx.plan.quick);
    let rows = band_rows(&kappas, &ratios, runs);
    let certified = rows.iter().filter(|r| r.orbit.certified()).count();
    let refuting = rows.iter().filter(|r| r.orbit.certified() && !r.cc).count();
    let matched = rows.iter().filter(|r| r.orbit.certified() == r.cycle).count();
    let all_cc = rows.iter().filter(|r| r.drops.cc == r.drops.runs).count();
    r.tables.push(Table {
        title: "The n = 3 band: orbit certificates (pattern 2,2,1,1) above γ*(κ) against the exact criteria"
            .into(),
        header: ["κ", "γ*", "γ", "orbit certificate", "S₁ criterion", "S₁²S₂² criterion", "drops"]
            .map(String::from)
            .to_vec(),
        rows: rows.iter().map(table_row).collect(),
    });
    let mut evidence = vec![
        format!(
            "{} points above γ* ({} κ × {} ratios γ/γ*), {runs} random drops each: {certified} certified (accepted by the kernel on both backends), {refuting} of them where S₁'s criterion fails (decided exactly); drops all CC at {all_cc} points",
            rows.len(),
            kappas.len(),
            ratios.len()
        ),
        format!(
            "candidate criterion S₁²S₂² (real positive dominant eigenvalue, decided exactly) holds exactly where a certificate was made at {matched} of {} points",
            rows.len()
        ),
    ];
    evidence.extend(other_n(runs));
    let (pentagon_line, pentagon_refutes) = pentagon(ctx)?;
    evidence.push(pentagon_line);
    evidence.push(square_pcc(runs)?);
    evidence.push("the full grid (9 κ × 10 ratios), the exact edges γ_c and the n = 4, 5, 6 search: `cargo run --release --features research --example orbit_band -- band 10` (also `cycle`, `edge 10`, `search 4 10`, `pcc`), docs/orbit-certificates.md §7".into());
    let mut refuted: Vec<String> =
        rows.iter().filter(|r| r.orbit.certified() && !r.cc).map(|r| r.kappa.to_string()).collect();
    refuted.dedup();
    let n5 = if pentagon_refutes {
        "; and for the pentagon at κ = 961/25600, γ = 61/160 (certified in Q(cos 2π/5))"
    } else {
        ""
    };
    let ours = if refuted.is_empty() {
        format!("no orbit certificate at the {} points above the CC threshold", rows.len())
    } else {
        format!(
            "orbit certificates at {refuting} of {} points above the CC threshold refute Conjecture 1 (i) ⇒ (iii) for the triangle at κ ∈ {{{}}}{n5}; the S₁²S₂² criterion matched certificate existence at {matched} of {} points",
            rows.len(),
            refuted.join(", "),
            rows.len()
        )
    };
    r.items.push(Item {
        title: "The n = 3 band across κ: orbit certificates and the S₁²S₂² criterion".into(),
        paper: "Conjecture 1: (i) CC possible ⇔ (iii) S₁ has a real positive dominant eigenvalue; Conjecture 2 (n ≥ 4): PCC possible ⇔ the PCC criterion.".into(),
        ours,
        verdict: Verdict::of(refuting == 0 && !pentagon_refutes),
        evidence,
        commands: vec![
            "chatter certify-orbit --n 3 --kappa 3/10 --gamma 0.02536 --pattern 2,2,1,1 -o orbit-3_10.ron && chatter verify orbit-3_10.ron".into(),
            "chatter classify --n 4 --kappa 1/6 --gamma 1/500".into(),
            "chatter certify-orbit --n 5 --kappa 961/25600 --gamma 61/160 --pattern 1,1,2,4,4,3 -o pentagon.ron && chatter verify pentagon.ron".into(),
        ],
        figures: Vec::new(),
    });
    Ok(())
}
