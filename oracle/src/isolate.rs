//! Every content rule of a file's claim evaluated on its own (R1, then R2, R3 and R4 each
//! regardless of the others, and the rod's T1; K1, then K2, K3, K4), for tests that a corpus
//! file breaks exactly one rule (docs/kernel-soundness.md §5). Files that fail before the content
//! rules give the codes of their first failing rule.

use crate::claim::Claim;
use crate::kinds::cone::{Parts, bound, claim, prepare, read};
use crate::kinds::limits::Limits;
use crate::read::header::{Reader, header};
use crate::read::parse::parse;
use crate::read::{Encoding, Value};
use crate::regular::boxes::{Gens, box_failures};
use crate::regular::pcc::pcc_quadratic;
use crate::regular::rest::time_to_rest;
use crate::regular::{rod, rules};
use crate::verdict::Checked;

/// The codes of the failing rules, each once, in the order R1 (alone if it fails), R2, R3, R4.
pub fn every_failure(text: &str, encoding: Encoding) -> Vec<&'static str> {
    let judged = crate::judge(text, encoding);
    let Ok(value) = parse(text, encoding) else { return judged.codes().to_vec() };
    match header(&value) {
        Ok(Reader::Cone(_)) => cone_failures(&value).unwrap_or_else(|f| f.codes),
        Ok(Reader::Family) => crate::kinds::family::every_failure(&value).unwrap_or_else(|f| f.codes),
        Ok(Reader::Basin) => crate::kinds::basin::every_failure(&value).unwrap_or_else(|f| f.codes),
        _ => judged.codes().to_vec(),
    }
}

fn collect(out: &mut Vec<&'static str>, r: Checked<impl Sized>) {
    if let Err(f) = r {
        for c in f.codes {
            if !out.contains(&c) {
                out.push(c);
            }
        }
    }
}

fn cone_failures(value: &Value) -> Checked<Vec<&'static str>> {
    let f = read(value)?;
    let (parts, _) = prepare(&f, &Limits::default())?;
    let drops = claim(&f) >= Claim::CcOrPccFromAllDown;
    let cc = claim(&f) >= Claim::CompleteChatterFromAllDown;
    let mut out = vec![];
    match parts {
        Parts::Point(b, gens) => {
            let k = rules::cone_polygon(&gens)?;
            collect(&mut out, rules::invariance(&b, &k));
            if drops {
                collect(&mut out, rules::all_down(&b, &k));
            }
            if cc && !pcc_quadratic(&b).excludes_pcc() {
                out.push("pcc-not-excluded");
            }
        }
        Parts::Rod(r, gens) => {
            let k = rod::interval(&gens)?;
            collect(&mut out, rod::invariance(&r, &k));
            if drops {
                collect(&mut out, rod::all_down(&r, &k));
            }
            if let Some(b) = bound(&f) {
                collect(&mut out, time_to_rest(&r, claim(&f), b, &Limits::default()));
            }
        }
        Parts::Box(2, k, g, _, gens) => out = box_failures(2, &k, &g, claim(&f), &Gens::Rod(&gens))?,
        Parts::Box(n, k, g, gens, _) => out = box_failures(n, &k, &g, claim(&f), &Gens::Polygon(&gens))?,
    }
    Ok(out)
}
