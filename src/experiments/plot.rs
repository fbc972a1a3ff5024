//! SVG line and scatter charts (plotters, SVG backend only).
//!
//! Logarithmic axes are drawn as linear axes over log2 (x) or log10 (y) of the values,
//! with tick labels showing the values, so one code path serves every chart.

use plotters::prelude::*;
use std::io;
use std::path::Path;

/// One named curve.
#[derive(Clone, Debug)]
pub struct Series {
    pub name: String,
    pub points: Vec<(f64, f64)>,
}

impl Series {
    pub fn new(name: impl Into<String>, points: Vec<(f64, f64)>) -> Series {
        Series {
            name: name.into(),
            points,
        }
    }
}

/// How a chart looks.
#[derive(Clone, Debug)]
pub struct Chart<'a> {
    pub title: &'a str,
    pub x_label: &'a str,
    pub y_label: &'a str,
    /// x values are powers of two: the axis is log2 x, labelled 2^k.
    pub log2_x: bool,
    /// y on a log10 axis.
    pub log_y: bool,
    /// Points only (a scatter plot), each series named in a legend beside the points
    /// (names written at the points would overlap where points crowd).
    pub scatter: bool,
}

/// Twenty distinct colours (the ten of the common "category 10" palette, then ten of
/// other hues and lightness), so that charts of up to twenty series repeat none.
const COLORS: [RGBColor; 20] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(23, 190, 207),
    RGBColor(0, 0, 0),
    RGBColor(118, 29, 110),
    RGBColor(0, 90, 50),
    RGBColor(160, 100, 0),
    RGBColor(0, 60, 130),
    RGBColor(255, 70, 160),
    RGBColor(90, 200, 100),
    RGBColor(120, 120, 255),
    RGBColor(170, 0, 0),
    RGBColor(90, 90, 40),
];

fn err(e: impl std::fmt::Display) -> io::Error {
    io::Error::other(e.to_string())
}

/// A short number: 3 significant digits, SI suffix for large values, trailing zeros
/// dropped (`316k`, `1.5M`, `0.00123`, `12.5`).
fn short(v: f64) -> String {
    let a = v.abs();
    if a == 0.0 || !a.is_finite() {
        return if a == 0.0 { "0".into() } else { format!("{v}") };
    }
    let (scaled, suffix) = if a >= 1e9 {
        (v / 1e9, "G")
    } else if a >= 1e6 {
        (v / 1e6, "M")
    } else if a >= 1e3 {
        (v / 1e3, "k")
    } else {
        (v, "")
    };
    let magnitude = scaled.abs().log10().floor() as i32;
    let decimals = (2 - magnitude).max(0) as usize;
    let mut text = format!("{scaled:.decimals$}");
    if text.contains('.') {
        text = text.trim_end_matches('0').trim_end_matches('.').to_string();
    }
    text + suffix
}

/// The label of a tick at `exponent` on a log axis: the power itself when the tick sits
/// on a whole exponent, nothing between (ticks between decades would read `316k`).
fn log_tick(exponent: f64, power: impl Fn(i32) -> String) -> String {
    let k = exponent.round();
    if (exponent - k).abs() < 1e-6 {
        power(k as i32)
    } else {
        String::new()
    }
}

/// Draws `series` into the SVG file `path` (640×400).
///
/// # Errors
/// When the file cannot be written.
pub fn draw(path: &Path, chart: &Chart<'_>, series: &[Series]) -> io::Result<()> {
    let fx = |x: f64| if chart.log2_x { x.log2() } else { x };
    let fy = |y: f64| if chart.log_y { y.log10() } else { y };
    let pts: Vec<Vec<(f64, f64)>> = series
        .iter()
        .map(|s| {
            s.points
                .iter()
                .map(|&(x, y)| (fx(x), fy(y)))
                .filter(|(x, y)| x.is_finite() && y.is_finite())
                .collect()
        })
        .collect();
    let all = pts.iter().flatten();
    let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for &(x, y) in all {
        (x0, x1, y0, y1) = (x0.min(x), x1.max(x), y0.min(y), y1.max(y));
    }
    if x0 > x1 {
        (x0, x1, y0, y1) = (0.0, 1.0, 0.0, 1.0);
    }
    let pad_x = ((x1 - x0) * 0.05).max(0.5);
    let pad_y = ((y1 - y0) * 0.08).max(if chart.log_y { 0.1 } else { y1.abs() * 0.05 + 1e-9 });
    let (y0, y1) = if !chart.log_y && y0 >= 0.0 {
        (0.0, y1 + pad_y)
    } else {
        (y0 - pad_y, y1 + pad_y)
    };
    let (x0, x1) = (
        x0 - pad_x,
        x1 + if chart.scatter {
            (x1 - x0) * 0.6 + pad_x
        } else {
            pad_x
        },
    );

    let root = SVGBackend::new(path, (640, 400)).into_drawing_area();
    root.fill(&WHITE).map_err(err)?;
    let mut c = ChartBuilder::on(&root)
        .caption(chart.title, ("sans-serif", 17))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(err)?;
    let x_fmt = |x: &f64| {
        if chart.log2_x {
            log_tick(*x, |k| format!("2^{k}"))
        } else {
            short(*x)
        }
    };
    let y_fmt = |y: &f64| {
        if chart.log_y {
            log_tick(*y, |k| short(10f64.powi(k)))
        } else {
            short(*y)
        }
    };
    // On log axes, about one tick per whole exponent, so that most ticks sit on one.
    let whole = |lo: f64, hi: f64| ((hi - lo).floor() as usize + 1).clamp(2, 12);
    let x_ticks = if chart.log2_x { whole(x0, x1) } else { 10 };
    let y_ticks = if chart.log_y { whole(y0, y1) } else { 10 };
    c.configure_mesh()
        .x_labels(x_ticks)
        .y_labels(y_ticks)
        .x_desc(chart.x_label)
        .y_desc(chart.y_label)
        .x_label_formatter(&x_fmt)
        .y_label_formatter(&y_fmt)
        .light_line_style(WHITE.mix(0.0))
        .draw()
        .map_err(err)?;
    for (i, (s, p)) in series.iter().zip(&pts).enumerate() {
        let color = COLORS[i % COLORS.len()];
        if chart.scatter {
            c.draw_series(p.iter().map(|&xy| Circle::new(xy, 4, color.filled())))
                .map_err(err)?
                .label(&s.name)
                .legend(move |(x, y)| Circle::new((x + 8, y), 4, color.filled()));
        } else {
            c.draw_series(LineSeries::new(p.iter().copied(), color.stroke_width(2)))
                .map_err(err)?
                .label(&s.name)
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], color.stroke_width(2)));
            c.draw_series(p.iter().map(|&xy| Circle::new(xy, 2, color.filled())))
                .map_err(err)?;
        }
    }
    // Line charts: the legend at the upper left; scatter charts: in the room kept free
    // on the right.
    c.configure_series_labels()
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK.mix(0.3))
        .position(if chart.scatter {
            SeriesLabelPosition::UpperRight
        } else {
            SeriesLabelPosition::UpperLeft
        })
        .draw()
        .map_err(err)?;
    root.present().map_err(err)
}

#[cfg(test)]
mod tests {
    use super::{COLORS, Chart, Series, draw, log_tick, short};

    #[test]
    fn scatter_names_every_series_once_in_a_legend_in_its_own_colour() {
        let mut distinct: Vec<_> = COLORS.iter().map(|c| (c.0, c.1, c.2)).collect();
        distinct.sort_unstable();
        distinct.dedup();
        assert_eq!(distinct.len(), COLORS.len(), "a colour repeats");
        // Twelve series, several at the same point (where names written at the points
        // would overlap).
        let series: Vec<Series> = (0..12)
            .map(|i| Series::new(format!("series-{i}"), vec![(f64::from(i % 3), 100.0)]))
            .collect();
        let path = std::env::temp_dir().join(format!("polysect-scatter-{}.svg", std::process::id()));
        let chart = Chart {
            title: "t",
            x_label: "x",
            y_label: "y",
            log2_x: false,
            log_y: true,
            scatter: true,
        };
        draw(&path, &chart, &series).unwrap();
        let svg = std::fs::read_to_string(&path).unwrap();
        let _ = std::fs::remove_file(&path);
        for s in &series {
            assert_eq!(
                svg.matches(&format!("\n{}\n</text>", s.name)).count(),
                1,
                "{}: {svg}",
                s.name
            );
        }
        for c in &COLORS[..12] {
            let hex = format!("#{:02X}{:02X}{:02X}", c.0, c.1, c.2);
            assert!(svg.to_uppercase().contains(&hex), "colour {hex} unused");
        }
    }

    #[test]
    fn tick_labels_are_short_and_round() {
        assert_eq!(short(316_227.766), "316k");
        assert_eq!(short(1_500_000.0), "1.5M");
        assert_eq!(short(1000.0), "1k");
        assert_eq!(short(12.5), "12.5");
        assert_eq!(short(0.001234), "0.00123");
        assert_eq!(short(-2.0), "-2");
        assert_eq!(log_tick(5.0, |k| short(10f64.powi(k))), "100k");
        assert_eq!(log_tick(5.5, |k| short(10f64.powi(k))), "");
        assert_eq!(log_tick(12.0000001, |k| format!("2^{k}")), "2^12");
    }
}
