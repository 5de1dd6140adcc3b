//! The bench chart: frame time (log scale) against error, one dot per variant, the Pareto front
//! drawn through the dots nothing beats. Numbered like the summary table, with a legend of the
//! numbers' variants beside the plot, in the contact sheet's 5×7 bitmap font.

use super::Summary;
use super::label_placement::place_labels;
use super::pareto::pareto_front;
use super::variants::VariantKind;
use crate::label_font::{GLYPH_HEIGHT, text_pixels, text_width};
use crate::raster::Framebuffer;
use crate::texture::srgb_to_linear;
use glam::Vec3;
use tiny_skia::{Color, FillRule, Paint, PathBuilder, Pixmap, Rect, Stroke, Transform};

/// Which error the vertical axis shows (up is better for both).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ChartMetric {
    /// Mean PSNR over the scenes, dB.
    Psnr,
    /// Mean normal angle error over the scenes, degrees (axis drawn inverted).
    NormalDegrees,
}

/// The plot's square of the image; the legend is to its right.
const PLOT_WIDTH: u32 = 800;
const LEGEND_WIDTH: u32 = 340;
const WIDTH: u32 = PLOT_WIDTH + LEGEND_WIDTH;
const HEIGHT: u32 = 500;
const MARGIN: f32 = 60.0;
const GLYPH_SCALE: u32 = 2;

/// The chart, WIDTH × HEIGHT, as a framebuffer for the PNG writer (its 8-bit sRGB pixels decoded
/// to linear light, which the writer encodes back to the same bytes).
pub fn draw_chart(summaries: &[Summary], metric: ChartMetric) -> Framebuffer {
    let mut pixmap = Pixmap::new(WIDTH, HEIGHT).expect("non-zero chart size");
    pixmap.fill(Color::WHITE);
    let points: Vec<(f64, f64)> = summaries
        .iter()
        .map(|s| (s.total_median_ms.max(1e-3).log10(), error_of(s, metric)))
        .collect();
    let axes = Axes::fit(&points);
    axes.draw(&mut pixmap);
    draw_units(&mut pixmap, metric);
    let front = pareto_front(&points);
    draw_front(
        &mut pixmap,
        &axes,
        &front.iter().map(|&i| points[i]).collect::<Vec<_>>(),
    );
    for (i, (&point, summary)) in points.iter().zip(summaries).enumerate() {
        let on_front = front.contains(&i);
        draw_point(&mut pixmap, &axes, point, summary.variant.kind, on_front);
    }
    let anchors: Vec<(f32, f32)> = points.iter().map(|&p| axes.to_pixel(p)).collect();
    let sizes: Vec<(f32, f32)> = (1..=points.len())
        .map(|n| {
            let width = text_width(&n.to_string(), GLYPH_SCALE) as f32;
            (width, (GLYPH_HEIGHT * GLYPH_SCALE) as f32)
        })
        .collect();
    for (i, (x, y)) in place_labels(&anchors, &sizes).into_iter().enumerate() {
        draw_number(&mut pixmap, x, y, i as u32 + 1, [40, 40, 40]);
    }
    draw_legend(&mut pixmap, summaries, &front);
    to_framebuffer(&pixmap)
}

/// The opaque pixmap (so premultiplied equals straight alpha) in linear light.
fn to_framebuffer(pixmap: &Pixmap) -> Framebuffer {
    let decode = |c: u8| srgb_to_linear(c as f32 / 255.0);
    let color: Vec<Vec3> = pixmap
        .data()
        .chunks_exact(4)
        .map(|p| Vec3::new(decode(p[0]), decode(p[1]), decode(p[2])))
        .collect();
    let depth = vec![0.0; color.len()];
    Framebuffer::from_parts(pixmap.width(), pixmap.height(), color, depth)
}

/// "1 draft", "2 interactive", … beside the plot, in the dots' colours; `*` marks the front.
/// Rows shrink to fit when there are many variants.
fn draw_legend(pixmap: &mut Pixmap, summaries: &[Summary], front: &[usize]) {
    let rows = summaries.len().max(1) as f32;
    let row_height = ((HEIGHT as f32 - 2.0 * MARGIN) / rows).min(20.0);
    let scale = if row_height >= 18.0 { GLYPH_SCALE } else { 1 };
    for (i, summary) in summaries.iter().enumerate() {
        let mark = if front.contains(&i) { "*" } else { "" };
        let text = format!("{:>2}{mark} {}", i + 1, summary.variant.name);
        let rgb = match summary.variant.kind {
            VariantKind::Preset => [30, 90, 200],
            VariantKind::Knob => [40, 40, 40],
        };
        let y = MARGIN + i as f32 * row_height;
        draw_text_scaled(pixmap, PLOT_WIDTH as f32 + 8.0, y, &text, rgb, scale);
    }
}

/// "ms" under the time axis, "dB" or "deg" over the error axis.
fn draw_units(pixmap: &mut Pixmap, metric: ChartMetric) {
    let (w, h) = (PLOT_WIDTH as f32, HEIGHT as f32);
    draw_text(
        pixmap,
        w - MARGIN - 16.0,
        h - MARGIN + 30.0,
        "ms",
        [0, 0, 0],
    );
    let unit = match metric {
        ChartMetric::Psnr => "dB",
        ChartMetric::NormalDegrees => "deg",
    };
    draw_text(pixmap, 8.0, MARGIN - 24.0, unit, [0, 0, 0]);
}

/// The error to minimise: −PSNR, or the normal error.
fn error_of(summary: &Summary, metric: ChartMetric) -> f64 {
    match metric {
        ChartMetric::Psnr => -summary.mean_psnr_db,
        ChartMetric::NormalDegrees => summary.mean_normal_degrees,
    }
}

/// Data ranges and the plot rectangle: x is log10(ms), y the error (worse is lower on screen).
struct Axes {
    x: (f64, f64),
    y: (f64, f64),
}

impl Axes {
    fn fit(points: &[(f64, f64)]) -> Axes {
        let finite = points.iter().filter(|p| p.0.is_finite() && p.1.is_finite());
        let (mut x, mut y) = ((f64::MAX, f64::MIN), (f64::MAX, f64::MIN));
        for p in finite {
            x = (x.0.min(p.0), x.1.max(p.0));
            y = (y.0.min(p.1), y.1.max(p.1));
        }
        let pad = |(lo, hi): (f64, f64), min_span: f64| {
            if lo > hi {
                return (0.0, 1.0);
            }
            let span = (hi - lo).max(min_span);
            (lo - span * 0.08, lo + span * 1.08)
        };
        Axes {
            x: pad(x, 0.3),
            y: pad(y, 1.0),
        }
    }

    fn to_pixel(&self, (x, y): (f64, f64)) -> (f32, f32) {
        let fx = (x - self.x.0) / (self.x.1 - self.x.0);
        let fy = (y - self.y.0) / (self.y.1 - self.y.0);
        let plot_w = PLOT_WIDTH as f32 - 2.0 * MARGIN;
        let plot_h = HEIGHT as f32 - 2.0 * MARGIN;
        (
            MARGIN + fx as f32 * plot_w,
            // Lower error is better and drawn higher.
            MARGIN + fy as f32 * plot_h,
        )
    }

    /// The frame, and ticks with numbers: each power of ten of milliseconds (and 2×, 5×), and
    /// round error values.
    fn draw(&self, pixmap: &mut Pixmap) {
        let grey = paint([200, 200, 200]);
        let black = paint([0, 0, 0]);
        let (w, h) = (PLOT_WIDTH as f32, HEIGHT as f32);
        let frame = Rect::from_ltrb(MARGIN, MARGIN, w - MARGIN, h - MARGIN).expect("valid");
        let path = PathBuilder::from_rect(frame);
        pixmap.stroke_path(&path, &black, &stroke(1.5), Transform::identity(), None);
        for decade in (self.x.0.floor() as i32)..=(self.x.1.ceil() as i32) {
            for factor in [1.0, 2.0, 5.0] {
                let ms = factor * 10f64.powi(decade);
                let x = ms.log10();
                if x < self.x.0 || x > self.x.1 {
                    continue;
                }
                let (px, _) = self.to_pixel((x, self.y.0));
                line(pixmap, (px, MARGIN), (px, h - MARGIN), &grey, 1.0);
                if ms >= 1.0 {
                    draw_number(pixmap, px - 4.0, h - MARGIN + 8.0, ms as u32, [0, 0, 0]);
                }
            }
        }
        let step = nice_step(self.y.1 - self.y.0);
        let mut value = (self.y.0 / step).ceil() * step;
        while value <= self.y.1 {
            let (_, py) = self.to_pixel((self.x.0, value));
            line(pixmap, (MARGIN, py), (w - MARGIN, py), &grey, 1.0);
            if step >= 1.0 {
                draw_number(
                    pixmap,
                    8.0,
                    py - (GLYPH_HEIGHT * GLYPH_SCALE) as f32 / 2.0,
                    value.abs().round() as u32,
                    [0, 0, 0],
                );
            }
            value += step;
        }
    }
}

/// A round tick step giving about five ticks.
fn nice_step(span: f64) -> f64 {
    let raw = (span / 5.0).max(1e-9);
    let magnitude = 10f64.powf(raw.log10().floor());
    [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|f| f * magnitude)
        .find(|&s| s >= raw)
        .unwrap_or(10.0 * magnitude)
}

fn draw_front(pixmap: &mut Pixmap, axes: &Axes, front: &[(f64, f64)]) {
    let mut builder = PathBuilder::new();
    for (k, &p) in front.iter().enumerate() {
        let (x, y) = axes.to_pixel(p);
        if k == 0 {
            builder.move_to(x, y);
        } else {
            builder.line_to(x, y);
        }
    }
    if let Some(path) = builder.finish() {
        let paint = paint(FRONT_RED);
        pixmap.stroke_path(&path, &paint, &stroke(2.5), Transform::identity(), None);
    }
}

/// The colour of the Pareto front: its line, and a ring around each of its dots (so a front of
/// one dot, one variant both fastest and most accurate, still shows).
const FRONT_RED: [u8; 3] = [220, 60, 40];

fn draw_point(pixmap: &mut Pixmap, axes: &Axes, p: (f64, f64), kind: VariantKind, front: bool) {
    let (x, y) = axes.to_pixel(p);
    let color = match kind {
        VariantKind::Preset => [30, 90, 200],
        VariantKind::Knob => [90, 90, 90],
    };
    let radius = if front { 6.0 } else { 4.5 };
    if let Some(circle) = PathBuilder::from_circle(x, y, radius) {
        pixmap.fill_path(
            &circle,
            &paint(color),
            FillRule::Winding,
            Transform::identity(),
            None,
        );
    }
    let ring = PathBuilder::from_circle(x, y, radius + 3.0).filter(|_| front);
    if let Some(ring) = ring {
        let paint = paint(FRONT_RED);
        pixmap.stroke_path(&ring, &paint, &stroke(2.5), Transform::identity(), None);
    }
}

fn line(pixmap: &mut Pixmap, a: (f32, f32), b: (f32, f32), paint: &Paint, width: f32) {
    let mut builder = PathBuilder::new();
    builder.move_to(a.0, a.1);
    builder.line_to(b.0, b.1);
    if let Some(path) = builder.finish() {
        pixmap.stroke_path(&path, paint, &stroke(width), Transform::identity(), None);
    }
}

fn paint(rgb: [u8; 3]) -> Paint<'static> {
    let mut paint = Paint::default();
    paint.set_color_rgba8(rgb[0], rgb[1], rgb[2], 255);
    paint.anti_alias = true;
    paint
}

fn stroke(width: f32) -> Stroke {
    Stroke {
        width,
        ..Stroke::default()
    }
}

fn draw_number(pixmap: &mut Pixmap, x: f32, y: f32, number: u32, rgb: [u8; 3]) {
    draw_text(pixmap, x, y, &number.to_string(), rgb);
}

fn draw_text(pixmap: &mut Pixmap, x: f32, y: f32, text: &str, rgb: [u8; 3]) {
    draw_text_scaled(pixmap, x, y, text, rgb, GLYPH_SCALE);
}

/// `text` with its top-left corner at (x, y), `scale` image pixels per font pixel.
fn draw_text_scaled(pixmap: &mut Pixmap, x: f32, y: f32, text: &str, rgb: [u8; 3], scale: u32) {
    let mut paint = paint(rgb);
    paint.anti_alias = false;
    for (dx, dy) in text_pixels(text, scale) {
        if let Some(rect) = Rect::from_xywh(x + dx as f32, y + dy as f32, 1.0, 1.0) {
            pixmap.fill_rect(rect, &paint, Transform::identity(), None);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::label_font::glyph;

    #[test]
    fn every_bench_variant_name_and_unit_draws_without_blanks() {
        let names = crate::bench::variants().into_iter().map(|v| v.name);
        for text in names.chain(["ms", "dB", "deg", "0123456789*"].map(String::from)) {
            for c in text.chars() {
                assert_ne!(glyph(c), [0; 7], "'{c}' of {text}");
            }
        }
    }

    #[test]
    fn every_srgb_byte_survives_the_trip_through_linear_light() {
        for code in 0..=255u8 {
            let linear = srgb_to_linear(code as f32 / 255.0);
            assert_eq!(crate::raster::linear_to_srgb8(linear), code);
        }
    }

    #[test]
    fn a_front_of_one_variant_still_shows_in_red() {
        let variants = crate::bench::variants();
        let summary = |i: usize, ms: f64, db: f64| Summary {
            variant: variants[i].clone(),
            total_median_ms: ms,
            mean_psnr_db: db,
            mean_normal_degrees: 0.0,
        };
        // The second is both the fastest and the most accurate: the front is it alone.
        let summaries = [summary(0, 2.0, 30.0), summary(1, 1.0, 150.0)];
        let chart = draw_chart(&summaries, ChartMetric::Psnr);
        let srgb = |c: f32| crate::raster::linear_to_srgb8(c);
        let red = chart.color().iter().filter(|c| {
            let [r, g, b] = [c.x, c.y, c.z].map(srgb);
            r > 180 && g < 120 && b < 120
        });
        let red = red.count();
        assert!(red > 100, "{red} red pixels");
    }

    #[test]
    fn tick_steps_are_round_and_give_a_handful_of_ticks() {
        for span in [1.0, 3.7, 12.0, 45.0, 250.0] {
            let step = nice_step(span);
            let ticks = span / step;
            assert!((1.5..=11.0).contains(&ticks), "span {span}: step {step}");
            let mantissa = step / 10f64.powf(step.log10().floor());
            assert!([1.0, 2.0, 5.0].iter().any(|m| (m - mantissa).abs() < 1e-9));
        }
    }
}
