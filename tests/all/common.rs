//! Helpers shared by the tests.
#![allow(dead_code)]

use chatter::exact::Q;
use chatter_kernel::model::Polygon as Body;
use std::path::{Path, PathBuf};

/// A rational from canonical text (panics on bad input: test data only).
pub fn q(s: &str) -> Q {
    s.parse().unwrap_or_else(|e| panic!("bad test number {s:?}: {e}"))
}

/// The exact body of a regular n-gon.
pub fn body(n: u64, kappa: &str, gamma: &str) -> Body<Q> {
    Body::new(n, q(kappa), q(gamma)).expect("valid test body")
}

/// The `chatter` binary built for these tests.
pub fn bin() -> PathBuf {
    PathBuf::from(env!("CARGO_BIN_EXE_chatter"))
}

/// The repository root.
pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Supported polygon sizes.
pub const NS: [u64; 3] = [3, 4, 6];

/// A spread of kappa and gamma values used across tests.
pub const KAPPAS: [&str; 6] = ["1/40", "1/8", "3/20", "1/6", "1/3", "2"];
pub const GAMMAS: [&str; 6] = ["0", "1/100", "1/20", "3/10", "9/10", "1"];

/// The arguments of README.md's main job (its first command, `cargo run --release -- ...`).
pub const REPRODUCE_QUICK: [&str; 4] = ["reproduce", "--quick", "--out", "out"];

/// One run of README.md's main job, `chatter reproduce --quick --out out`, in an empty
/// directory, shared by every test that reads its output (issue 23 §4: it runs once per test
/// process, not once per test). Tests only read `dir/out`; one that runs commands there works
/// on a copy ([`copy_dir`]).
pub struct Reproduced {
    /// The directory the command ran in (it holds `out/`).
    pub dir: PathBuf,
    pub output: std::process::Output,
}

pub fn reproduce_quick() -> &'static Reproduced {
    static RUN: std::sync::OnceLock<Reproduced> = std::sync::OnceLock::new();
    RUN.get_or_init(|| {
        let tmp = PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
        // Earlier runs' folders, unless their test process still runs.
        for e in std::fs::read_dir(&tmp).into_iter().flatten().flatten() {
            let name = e.file_name().to_string_lossy().to_string();
            if let Some(pid) = name.strip_prefix("reproduce-quick-")
                && !std::path::Path::new("/proc").join(pid).exists()
            {
                let _ = std::fs::remove_dir_all(e.path());
            }
        }
        let dir = tmp.join(format!("reproduce-quick-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let output =
            std::process::Command::new(bin()).args(REPRODUCE_QUICK).current_dir(&dir).output().unwrap();
        Reproduced { dir, output }
    })
}

/// Copies a directory tree (files and directories only).
pub fn copy_dir(from: &std::path::Path, to: &std::path::Path) {
    std::fs::create_dir_all(to).unwrap();
    for e in std::fs::read_dir(from).unwrap() {
        let e = e.unwrap();
        let target = to.join(e.file_name());
        if e.file_type().unwrap().is_dir() {
            copy_dir(&e.path(), &target);
        } else {
            std::fs::copy(e.path(), target).unwrap();
        }
    }
}

/// Every file under `dir` (relative path and bytes), sorted.
pub fn files_of(dir: &Path) -> Vec<(std::path::PathBuf, Vec<u8>)> {
    let mut files = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap_or_else(|e| panic!("{}: {e}", d.display())) {
            let p = e.unwrap().path();
            if p.is_dir() {
                stack.push(p);
            } else {
                files.push((p.strip_prefix(dir).unwrap().to_path_buf(), std::fs::read(&p).unwrap()));
            }
        }
    }
    files.sort();
    files
}
