//! `chatter plot`: map panels, simulation maps and cones, in SVG and in PNG by the extension.

use crate::common::bin;
use std::path::Path;
use std::process::{Command, Output};

fn chatter(args: &[&str], dir: &Path) -> Output {
    Command::new(bin()).args(args).current_dir(dir).output().unwrap()
}

fn ok(o: &Output) {
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
}

/// Width and height of a PNG from its IHDR chunk.
fn png_size(path: &Path) -> (u32, u32) {
    let b = std::fs::read(path).unwrap();
    assert_eq!(&b[..8], b"\x89PNG\r\n\x1a\n", "{} is not a PNG", path.display());
    let be = |i: usize| u32::from_be_bytes([b[i], b[i + 1], b[i + 2], b[i + 3]]);
    (be(16), be(20))
}

#[test]
fn map_panels_and_simulation_maps_in_both_formats() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    ok(&chatter(
        &[
            "map",
            "--n",
            "3",
            "--rho",
            "0:1:12",
            "--gamma",
            "0:1:12",
            "--certify",
            "--simulate",
            "4",
            "--out",
            "m",
        ],
        p,
    ));
    ok(&chatter(&["plot", "map", "m", "-o", "map.svg"], p));
    let svg = std::fs::read_to_string(p.join("map.svg")).unwrap();
    for s in [
        "ρ = √κ",
        "\nγ\n",
        "cone finder: no cone",
        "exact: CC criterion boundary",
        "S₂S₁",
        "certified: CompleteChatterFromAllDown",
    ] {
        assert!(svg.contains(s), "map.svg lacks {s}");
    }
    // The legend stands right of the data: its texts start beyond the plotting area.
    let legend_x: u32 = svg
        .split("cone finder: effectively")
        .next()
        .unwrap()
        .rsplit("<text x=\"")
        .next()
        .unwrap()
        .split('"')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!(legend_x > 840, "legend at x = {legend_x}, inside the data");
    // --curve-lines: the exact curves computed along fewer lines are drawn with fewer points.
    ok(&chatter(&["plot", "map", "m", "--curve-lines", "24", "-o", "coarse.svg"], p));
    let coarse = std::fs::read_to_string(p.join("coarse.svg")).unwrap();
    let points = |svg: &str| svg.matches(',').count();
    assert!(coarse.contains("exact: CC criterion boundary") && points(&coarse) < points(&svg));
    for bad in ["1", "0", "2001", "x"] {
        let o = chatter(&["plot", "map", "m", "--curve-lines", bad, "-o", "bad.svg"], p);
        assert_eq!(o.status.code(), Some(2), "--curve-lines {bad}");
        assert!(String::from_utf8_lossy(&o.stderr).contains("--curve-lines"), "--curve-lines {bad}");
    }
    ok(&chatter(&["plot", "map", "m", "-o", "map.png"], p));
    assert_eq!(png_size(&p.join("map.png")), (2500, 1640), "PNG at twice the SVG size");
    ok(&chatter(&["plot", "simulations", "m", "-o", "sim.svg"], p));
    let svg = std::fs::read_to_string(p.join("sim.svg")).unwrap();
    assert!(svg.contains("level 200") && svg.contains("4 drops per point (f64 evidence"));
    // A map without simulations has no simulation map.
    ok(&chatter(&["map", "--n", "4", "--rho", "0:1:3", "--gamma", "0:1:3", "--out", "nosim"], p));
    let o = chatter(&["plot", "simulations", "nosim", "-o", "x.svg"], p);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--simulate"));
}

#[test]
fn a_certificates_cone_on_the_plane() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    ok(&chatter(&["certify", "--n", "4", "--kappa", "1/6", "--gamma", "1/100", "-o", "sq.ron"], p));
    ok(&chatter(&["plot", "cone", "sq.ron", "-o", "cone.svg"], p));
    let svg = std::fs::read_to_string(p.join("cone.svg")).unwrap();
    for s in ["K on the plane v = −1", "C₁", "C₃", "S₃(K ∩ C₃)", "p_max", "u₀ / (−v)"] {
        assert!(svg.contains(s), "cone.svg lacks {s}");
    }
    // Issue 26 §1: the two eigenvectors are told apart, and a stretched axis is said so.
    for s in ["p_max(S₁)", "p_max(S₃)", "axes not to scale: horizontal stretched"] {
        assert!(svg.contains(s), "cone.svg lacks {s}");
    }
    ok(&chatter(&["plot", "cone", "sq.ron", "-o", "cone.png"], p));
    assert_eq!(png_size(&p.join("cone.png")), (2500, 1640));
    ok(&chatter(&["certify", "--n", "2", "--kappa", "1/3", "--gamma", "1/20", "-o", "rod.ron"], p));
    std::fs::write(p.join("junk.ron"), "not a certificate").unwrap();
    for (file, out, needle) in [
        ("rod.ron", "r.svg", "rod"),
        ("junk.ron", "j.svg", "not a readable certificate"),
        ("none.ron", "n.svg", "none.ron"),
        ("sq.ron", "x.jpg", ".svg or .png"),
    ] {
        let o = chatter(&["plot", "cone", file, "-o", out], p);
        assert_eq!(o.status.code(), Some(2), "{file}");
        let e = String::from_utf8_lossy(&o.stderr);
        assert!(e.contains(needle) && !e.contains("panicked"), "{file}: {e}");
    }
}

/// A tick a rounding error away from zero is labelled as zero, never "-0.0" (seen on the
/// lander's cone figure, whose panels K_1 and K_2 have a tick at ω_y ≈ -1e-17).
#[test]
fn cone_figures_label_no_tick_negative_zero() {
    let d = tempfile::tempdir().unwrap();
    let lander = crate::common::root().join("certificates/valid/convex-lander-gamma1_20-inertia-tensor.ron");
    ok(&chatter(&["plot", "cone", lander.to_str().unwrap(), "-o", "lander.svg"], d.path()));
    let svg = std::fs::read_to_string(d.path().join("lander.svg")).unwrap();
    let ticks: Vec<&str> =
        svg.split("<text").filter_map(|t| t.split('>').nth(1)?.split('<').next()).map(str::trim).collect();
    let zeros = ticks
        .iter()
        .filter(|t| t.trim_start_matches('-').trim_matches(['0', '.']).is_empty() && !t.is_empty());
    let zeros: Vec<&&str> = zeros.collect();
    assert!(!zeros.is_empty(), "the figure labels a zero tick somewhere");
    assert!(zeros.iter().all(|t| !t.starts_with('-')), "negative zero among the ticks: {zeros:?}");
}

/// A family certificate over an interval of γ: the title names the interval; each image region is
/// the hull of the images at both ends (which holds every γ between), and I_i(D) is marked at both.
#[test]
fn the_cone_figure_of_an_interval_family_says_where_its_images_are_drawn() {
    let d = tempfile::tempdir().unwrap();
    let file =
        crate::common::root().join("certificates/valid/convex-lander-gamma1_20-117_2000-inertia-tensor.ron");
    ok(&chatter(&["plot", "cone", file.to_str().unwrap(), "-o", "i.svg"], d.path()));
    let svg = std::fs::read_to_string(d.path().join("i.svg")).unwrap();
    assert!(svg.contains("every γ ∈ [1/20, 117/2000]: the cones"), "the title");
    assert!(
        svg.contains("images and I_i(D) at both ends of the") && svg.contains("interval of γ"),
        "the note"
    );

    let point = crate::common::root().join("certificates/valid/convex-lander-gamma1_20-inertia-tensor.ron");
    ok(&chatter(&["plot", "cone", point.to_str().unwrap(), "-o", "p.svg"], d.path()));
    let svg = std::fs::read_to_string(d.path().join("p.svg")).unwrap();
    assert!(svg.contains("γ = 1/20:") && !svg.contains("both ends"), "a single γ is named as before");
    // The figure's data: I_i(D) at both ends (3 + 3 per panel), and each image region holds the
    // images of the pieces' vertices at every γ between the ends (affine in γ: their hull).
    use chatter::finder::geometry::outside_distance;
    use chatter::plot::cone::convex::figure;
    use chatter_kernel::certificate::Encoding;
    let f = figure(&std::fs::read_to_string(&file).unwrap(), Encoding::Ron).unwrap();
    let one = figure(&std::fs::read_to_string(&point).unwrap(), Encoding::Ron).unwrap();
    for (a, b) in f.panels.iter().zip(&one.panels) {
        assert_eq!((a.seeds.len(), b.seeds.len()), (6, 3), "{}", a.title);
    }
    let text = std::fs::read_to_string(&file).unwrap();
    let mid = text.replacen("[\"1/20\", \"117/2000\"]", "\"217/4000\"", 1).replacen(
        "version: 2,",
        "version: 1,",
        1,
    );
    let mid = figure(&mid, Encoding::Ron).unwrap();
    for (a, m) in f.panels.iter().zip(&mid.panels) {
        for (r, s) in a.images.iter().zip(&m.images) {
            let out = s.polygon.iter().map(|q| outside_distance(&r.polygon, q)).fold(0.0, f64::max);
            assert!(
                out < 1e-9,
                "{}: an image at the interval's middle is drawn outside the region by {out}",
                a.title
            );
        }
    }
}

#[test]
fn issue12_refuted_points_are_marked_on_the_map() {
    let d = tempfile::tempdir().unwrap();
    let dir = d.path();
    ok(&chatter(
        &["map", "--n", "4", "--rho", "0:1:8", "--gamma", "0:0.3:8", "--certify", "--refute", "--out", "m"],
        dir,
    ));
    ok(&chatter(&["plot", "map", "m", "-o", "m.svg"], dir));
    let svg = std::fs::read_to_string(dir.join("m.svg")).unwrap();
    assert!(svg.contains("refuted: an exact refutation"), "the legend names refuted points");
    let refuted = std::fs::read_to_string(dir.join("m/points.csv")).unwrap().matches(",true,").count();
    assert!(refuted > 0);
    // Without --refute, no mark and no legend entry.
    ok(&chatter(&["map", "--n", "4", "--rho", "0:1:8", "--gamma", "0:0.3:8", "--out", "n"], dir));
    ok(&chatter(&["plot", "map", "n", "-o", "n.svg"], dir));
    assert!(!std::fs::read_to_string(dir.join("n.svg")).unwrap().contains("refuted:"));
}
