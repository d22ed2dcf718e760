//! Figures (SVG or PNG, chosen by the file extension): the paper's map panels and simulation
//! maps ([`map`]), an effectively invariant cone on the plane v = -1 ([`cone`]) and a simulated
//! drop ([`trajectory`]). Every figure is drawn once, as SVG (plotters); PNG is that SVG
//! rasterised by resvg (pure Rust), so both formats show the same picture. Text is set in DejaVu
//! Sans (Greek included), read at run time from `CHATTER_FONT` or the usual system paths
//! (Debian's fonts-dejavu-core), see docs/figures.md.

pub mod basin;
pub mod basin_map;
pub mod cone;
pub mod contour;
pub mod cover;
pub mod label;
pub mod map;
pub mod simulations;
pub mod trajectory;

use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;
use std::sync::{Arc, OnceLock};

/// Where the font is looked for, after `CHATTER_FONT`.
pub const FONT_PATHS: [&str; 4] = [
    "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
    "/usr/share/fonts/TTF/DejaVuSans.ttf",
    "/usr/share/fonts/dejavu/DejaVuSans.ttf",
    "/usr/share/fonts/dejavu-sans-fonts/DejaVuSans.ttf",
];

/// The family every figure names (SVG viewers fall back to their own sans-serif font; PNG uses
/// DejaVu Sans).
pub const FONT: &str = "DejaVu Sans, sans-serif";

/// Columns (and rows) of a map along which `chatter plot` computes the exact curves by default
/// (`--curve-lines`).
pub const CURVE_LINES: u32 = 200;

/// PNG pixels per SVG unit (print resolution).
pub const PNG_SCALE: f32 = 2.0;

/// The font database for rasterising: DejaVu Sans read once; the error says how to provide it.
pub fn fonts() -> Result<Arc<resvg::usvg::fontdb::Database>, String> {
    static DB: OnceLock<Result<Arc<resvg::usvg::fontdb::Database>, String>> = OnceLock::new();
    DB.get_or_init(|| {
        let candidates: Vec<String> =
            std::env::var("CHATTER_FONT").into_iter().chain(FONT_PATHS.iter().map(|s| s.to_string())).collect();
        let bytes = candidates.iter().find_map(|p| std::fs::read(p).ok()).ok_or_else(|| {
            format!(
                "PNG figures need the TrueType font DejaVu Sans: install it (Debian: apt-get install fonts-dejavu-core) or set CHATTER_FONT to a .ttf file, or write .svg; looked in {}",
                candidates.join(", ")
            )
        })?;
        let mut db = resvg::usvg::fontdb::Database::new();
        db.load_font_data(bytes);
        let family = db.faces().next().and_then(|f| f.families.first().map(|(name, _)| name.clone()));
        let family = family.ok_or("the font file (CHATTER_FONT?) holds no usable TrueType face")?;
        db.set_sans_serif_family(family.clone());
        db.set_serif_family(family);
        Ok(Arc::new(db))
    })
    .clone()
}

/// The image formats.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    Svg,
    Png,
}

impl Format {
    /// The format named by a file's extension.
    pub fn of(path: &Path) -> Result<Format, String> {
        match path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase).as_deref() {
            Some("svg") => Ok(Format::Svg),
            Some("png") => Ok(Format::Png),
            _ => Err(format!("{}: the file name must end in .svg or .png (the format)", path.display())),
        }
    }
}

/// A figure that can draw itself on any plotters backend.
pub trait Figure {
    /// Size in SVG units (PNG pixels / [`PNG_SCALE`]).
    fn size(&self) -> (u32, u32);
    /// Draws the figure.
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), String>;
}

/// A tick label as plotters prints an f64 axis, but never "-0.0": a tick a rounding error away
/// from zero (|v| below 1e-12) is labelled as zero.
pub fn tick(v: &f64) -> String {
    use plotters::coord::ranged1d::ValueFormatter;
    let v = if v.abs() < 1e-12 { 0.0 } else { *v };
    plotters::coord::types::RangedCoordf64::format(&v)
}

/// Turns any plotters error into the figures' error type.
pub fn err(e: impl std::fmt::Display) -> String {
    format!("plot: {e}")
}

/// Renders a figure as an SVG document in memory.
pub fn svg_string(fig: &impl Figure) -> Result<String, String> {
    let mut out = String::new();
    {
        let root = SVGBackend::with_string(&mut out, fig.size()).into_drawing_area();
        fig.draw(&root)?;
        root.present().map_err(err)?;
    }
    Ok(out)
}

/// Rasterises an SVG document to PNG bytes at [`PNG_SCALE`].
pub fn png_bytes(svg: &str) -> Result<Vec<u8>, String> {
    use resvg::{tiny_skia, usvg};
    let opts = usvg::Options { fontdb: fonts()?, font_family: "DejaVu Sans".into(), ..Default::default() };
    let tree = usvg::Tree::from_str(svg, &opts).map_err(|e| format!("rasterising the figure: {e}"))?;
    let size = tree.size().to_int_size().scale_by(PNG_SCALE).ok_or("figure too large to rasterise")?;
    let mut pixmap =
        tiny_skia::Pixmap::new(size.width(), size.height()).ok_or("figure too large to rasterise")?;
    pixmap.fill(tiny_skia::Color::WHITE);
    resvg::render(&tree, tiny_skia::Transform::from_scale(PNG_SCALE, PNG_SCALE), &mut pixmap.as_mut());
    pixmap.encode_png().map_err(|e| format!("encoding PNG: {e}"))
}

/// Writes a figure to `path`, SVG or PNG by the extension.
pub fn save(fig: &impl Figure, path: &Path) -> Result<(), String> {
    let format = Format::of(path)?;
    let svg = svg_string(fig)?;
    let bytes = match format {
        Format::Svg => svg.into_bytes(),
        Format::Png => png_bytes(&svg)?,
    };
    std::fs::write(path, bytes).map_err(|e| format!("cannot write {}: {e}", path.display()))
}

/// The sample drawn beside a legend entry.
#[derive(Clone, Copy, Debug)]
pub enum Sample {
    /// A filled square (a background colour), outlined.
    Fill(RGBColor),
    /// A line of this width.
    Line(RGBColor, u32),
    /// A dashed line.
    Dashed(RGBColor, u32),
    /// A dot.
    Dot(RGBColor),
    /// A star (a marked vector).
    Star(RGBColor),
    /// An outlined square (a second kind of marked vector).
    Square(RGBColor),
    /// A hatched square (a region that may overlap others).
    Hatch(RGBColor),
    /// No sample: a note.
    Note,
}

/// One legend line.
#[derive(Clone, Debug)]
pub struct Entry {
    pub sample: Sample,
    pub text: String,
}

impl Entry {
    pub fn new(sample: Sample, text: impl Into<String>) -> Entry {
        Entry { sample, text: text.into() }
    }
}

/// Font sizes (pixels) shared by every figure.
pub const TITLE: u32 = 24;
pub const LABEL: u32 = 22;
pub const TICKS: u32 = 17;
pub const LEGEND: u32 = 17;

/// Draws a legend in its own area (outside the data), one entry per line, long texts wrapped.
pub fn legend<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, entries: &[Entry]) -> Result<(), String> {
    let style = TextStyle::from((FONT, LEGEND).into_font()).color(&BLACK);
    let (w, _) = area.dim_in_pixel();
    let chars = ((w as i32 - 60) / (LEGEND as i32 / 2 + 1)).max(10) as usize;
    let mut y = 10i32;
    for e in entries {
        let (x0, yc) = (8i32, y + LEGEND as i32 / 2 + 1);
        match e.sample {
            Sample::Fill(c) => {
                area.draw(&Rectangle::new([(x0, yc - 8), (x0 + 30, yc + 8)], c.filled())).map_err(err)?;
                area.draw(&Rectangle::new([(x0, yc - 8), (x0 + 30, yc + 8)], BLACK.stroke_width(1)))
                    .map_err(err)?;
            }
            Sample::Line(c, wd) => area
                .draw(&PathElement::new(vec![(x0, yc), (x0 + 30, yc)], c.stroke_width(wd)))
                .map_err(err)?,
            Sample::Dashed(c, wd) => {
                for k in 0..3 {
                    let a = x0 + 12 * k;
                    area.draw(&PathElement::new(vec![(a, yc), (a + 7, yc)], c.stroke_width(wd)))
                        .map_err(err)?;
                }
            }
            Sample::Dot(c) => area.draw(&Circle::new((x0 + 15, yc), 4, c.filled())).map_err(err)?,
            Sample::Star(c) => area.draw(&Cross::new((x0 + 15, yc), 7, c.stroke_width(3))).map_err(err)?,
            Sample::Square(c) => area
                .draw(&Rectangle::new([(x0 + 9, yc - 6), (x0 + 21, yc + 6)], c.stroke_width(3)))
                .map_err(err)?,
            Sample::Hatch(c) => {
                for k in 0..4 {
                    let a = x0 + 8 * k;
                    let line = vec![(a, yc + 8), (a + 8, yc - 8)];
                    area.draw(&PathElement::new(line, c.stroke_width(1))).map_err(err)?;
                }
                area.draw(&Rectangle::new([(x0, yc - 8), (x0 + 30, yc + 8)], c.stroke_width(1)))
                    .map_err(err)?;
            }
            Sample::Note => {}
        }
        for (i, line) in wrap(&e.text, chars).iter().enumerate() {
            area.draw(&Text::new(line.clone(), (x0 + 40, y + i as i32 * (LEGEND as i32 + 4)), style.clone()))
                .map_err(err)?;
        }
        y += (wrap(&e.text, chars).len() as i32) * (LEGEND as i32 + 4) + 10;
    }
    Ok(())
}

/// Splits text into lines of at most `width` characters at spaces.
pub fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    for word in text.split_whitespace() {
        match lines.last_mut() {
            Some(l) if l.chars().count() + 1 + word.chars().count() <= width => {
                l.push(' ');
                l.push_str(word);
            }
            _ => lines.push(word.to_string()),
        }
    }
    if lines.is_empty() {
        lines.push(String::new());
    }
    lines
}
