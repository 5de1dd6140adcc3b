//! `bumpwork bench`: time and error of every quality preset and single-knob variation on the
//! standard scenes, as a table, JSON or a chart.

use bumpwork::Error;
use bumpwork::bench::{
    ChartMetric, Measurement, STANDARD_SCENES, Summary, Variant, VariantKind, draw_chart,
    measure_scene, pareto_front, references, summarize, variants,
};
use bumpwork::raster::Viewport;
use serde::Serialize;
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct BenchArgs {
    /// Frame size in pixels, WIDTHxHEIGHT (the reference ray caster's cost grows with it).
    #[arg(long, default_value = "240x180", value_parser = super::parse_size)]
    size: (u32, u32),
    /// Timed frames per variant and scene, in rounds of one frame of each variant (after a
    /// warm-up frame); a variant stops after 1 s of timed frames. Median and min–max are shown.
    #[arg(long, default_value_t = 5, value_parser = clap::value_parser!(u32).range(1..=1000))]
    runs: u32,
    /// Comma-separated built-in scene names or scene files (default: the standard six).
    #[arg(long, value_delimiter = ',')]
    scenes: Vec<String>,
    /// Cap every variant's samples per pixel (quick runs: `exact` asks for 64, and each sample
    /// is a pass over every triangle).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
    max_samples: Option<u32>,
    /// Print JSON instead of the table.
    #[arg(long)]
    json: bool,
    /// Also draw time against error, with the Pareto front, into this PNG.
    #[arg(long)]
    chart: Option<PathBuf>,
    /// The chart's error axis: psnr (mean dB over the scenes) or normal (mean angle, degrees).
    #[arg(long, default_value = "psnr", value_parser = parse_metric)]
    chart_metric: ChartMetric,
}

fn parse_metric(text: &str) -> Result<ChartMetric, String> {
    match text {
        "psnr" => Ok(ChartMetric::Psnr),
        "normal" => Ok(ChartMetric::NormalDegrees),
        _ => Err(format!(
            "expected psnr or normal; got '{}'",
            bumpwork::diagnostic::shown_input(text)
        )),
    }
}

pub fn run(args: BenchArgs) -> Result<(), Error> {
    if let Some(chart) = &args.chart {
        bumpwork::export::check_destination(chart)?;
    }
    let names: Vec<String> = if args.scenes.is_empty() {
        STANDARD_SCENES.iter().map(|s| s.to_string()).collect()
    } else {
        args.scenes.clone()
    };
    // Every scene is loaded before anything runs, so a typo fails at once.
    let scenes = names
        .iter()
        .map(|name| bumpwork::scene::resolve(name).map(|scene| (name.clone(), scene)))
        .collect::<Result<Vec<_>, _>>()?;
    let viewport = Viewport {
        width: args.size.0,
        height: args.size.1,
    };
    let mut variants = variants();
    if let Some(cap) = args.max_samples {
        for variant in &mut variants {
            variant.quality.samples = variant.quality.samples.min(cap);
        }
    }
    let mut measurements = Vec::new();
    for (name, scene) in &scenes {
        eprintln!("bench: {name}: references…");
        let references = references(scene, viewport, &variants);
        eprintln!("bench: {name}: {} variants…", variants.len());
        let runs = args.runs as usize;
        measurements.extend(measure_scene(
            name,
            scene,
            &variants,
            viewport,
            runs,
            &references,
        )?);
    }
    let summaries = summarize(&variants, &measurements);
    if let Some(path) = &args.chart {
        bumpwork::export::write_png(&draw_chart(&summaries, args.chart_metric), path)?;
    }
    let front = front_of(&summaries, args.chart_metric);
    if args.json {
        print_json(&args, &measurements, &summaries, &front)
    } else {
        print_tables(&args, &measurements, &summaries, &front)
    }
}

/// Which summaries are on the Pareto front of summed time against the chart's error.
fn front_of(summaries: &[Summary], metric: ChartMetric) -> Vec<bool> {
    let points: Vec<(f64, f64)> = summaries
        .iter()
        .map(|s| {
            let error = match metric {
                ChartMetric::Psnr => -s.mean_psnr_db,
                ChartMetric::NormalDegrees => s.mean_normal_degrees,
            };
            (s.total_median_ms, error)
        })
        .collect();
    let front = pareto_front(&points);
    (0..summaries.len()).map(|i| front.contains(&i)).collect()
}

fn kind_name(variant: &Variant) -> &'static str {
    match variant.kind {
        VariantKind::Preset => "preset",
        VariantKind::Knob => "knob",
    }
}

fn print_tables(
    args: &BenchArgs,
    rows: &[Measurement],
    summaries: &[Summary],
    front: &[bool],
) -> Result<(), Error> {
    say!(
        "{}x{} pixels, {} timed runs each; error against the exact reference (ray cast, shaded as `exact`)",
        args.size.0,
        args.size.1,
        args.runs
    );
    say!(
        "variants with n samples per pixel are measured against the reference ray cast through the same n sample positions{}",
        args.max_samples
            .map(|cap| format!("; samples capped at {cap}"))
            .unwrap_or_default()
    );
    let mut scene = "";
    for m in rows {
        if m.scene != scene {
            scene = &m.scene;
            say!("\n{scene}");
            say!(
                "  {:<24} {:>8} {:>26} {:>8} {:>5} {:>16} {:>6}",
                "variant",
                "tris",
                "time ms (min-max) xruns",
                "PSNR dB",
                "max",
                "normal mean/max°",
                "silh."
            );
        }
        let t = &m.timing;
        let ms = |d: std::time::Duration| d.as_secs_f64() * 1e3;
        let e = &m.error;
        say!(
            "  {:<24} {:>8} {:>26} {:>8} {:>5.0} {:>16} {:>6}",
            m.variant.name,
            m.triangles,
            format!(
                "{:.2} ({:.2}-{:.2}) x{}",
                ms(t.median),
                ms(t.min),
                ms(t.max),
                t.runs
            ),
            psnr_text(e.psnr_db),
            e.max_pixel_error,
            format!(
                "{:.3} / {:.2}",
                e.mean_normal_angle_degrees, e.max_normal_angle_degrees
            ),
            e.silhouette_mismatch
        );
    }
    say!("\nall scenes (# numbers the chart's dots; * on the Pareto front)");
    say!(
        "  {:>3} {:<24} {:>14} {:>13} {:>14}  quality",
        "#",
        "variant",
        "sum of ms",
        "mean PSNR dB",
        "mean normal°"
    );
    for (i, (s, on_front)) in summaries.iter().zip(front).enumerate() {
        say!(
            "  {:>3} {:<24} {:>14.2} {:>13.2} {:>14.3}  {}",
            format!("{}{}", i + 1, if *on_front { "*" } else { "" }),
            s.variant.name,
            s.total_median_ms,
            s.mean_psnr_db,
            s.mean_normal_degrees,
            s.variant.quality.describe()
        );
    }
    Ok(())
}

fn psnr_text(db: f64) -> String {
    if db.is_finite() {
        format!("{db:.2}")
    } else {
        "inf".to_string()
    }
}

#[derive(Serialize)]
struct JsonReport<'a> {
    width: u32,
    height: u32,
    runs: u32,
    max_samples: Option<u32>,
    rows: Vec<JsonRow<'a>>,
    summary: Vec<JsonSummary<'a>>,
}

#[derive(Serialize)]
struct JsonRow<'a> {
    scene: &'a str,
    variant: &'a str,
    kind: &'static str,
    quality: String,
    samples: u32,
    triangles: usize,
    time_ms: JsonTiming,
    /// `null` for a frame identical to the reference (infinite PSNR).
    psnr_db: Option<f64>,
    max_pixel_error: f32,
    mean_normal_degrees: f64,
    max_normal_degrees: f64,
    silhouette_pixels: usize,
}

#[derive(Serialize)]
struct JsonTiming {
    median: f64,
    min: f64,
    max: f64,
    runs: usize,
}

#[derive(Serialize)]
struct JsonSummary<'a> {
    variant: &'a str,
    kind: &'static str,
    total_median_ms: f64,
    mean_psnr_db: f64,
    mean_normal_degrees: f64,
    pareto: bool,
}

fn print_json(
    args: &BenchArgs,
    rows: &[Measurement],
    summaries: &[Summary],
    front: &[bool],
) -> Result<(), Error> {
    let ms = |d: std::time::Duration| d.as_secs_f64() * 1e3;
    let report = JsonReport {
        width: args.size.0,
        height: args.size.1,
        runs: args.runs,
        max_samples: args.max_samples,
        rows: rows
            .iter()
            .map(|m| JsonRow {
                scene: &m.scene,
                variant: &m.variant.name,
                kind: kind_name(&m.variant),
                quality: m.variant.quality.describe(),
                samples: m.variant.quality.samples,
                triangles: m.triangles,
                time_ms: JsonTiming {
                    median: ms(m.timing.median),
                    min: ms(m.timing.min),
                    max: ms(m.timing.max),
                    runs: m.timing.runs,
                },
                psnr_db: m.error.psnr_db.is_finite().then_some(m.error.psnr_db),
                max_pixel_error: m.error.max_pixel_error,
                mean_normal_degrees: m.error.mean_normal_angle_degrees,
                max_normal_degrees: m.error.max_normal_angle_degrees,
                silhouette_pixels: m.error.silhouette_mismatch,
            })
            .collect(),
        summary: summaries
            .iter()
            .zip(front)
            .map(|(s, &pareto)| JsonSummary {
                variant: &s.variant.name,
                kind: kind_name(&s.variant),
                total_median_ms: s.total_median_ms,
                mean_psnr_db: s.mean_psnr_db,
                mean_normal_degrees: s.mean_normal_degrees,
                pareto,
            })
            .collect(),
    };
    say!(
        "{}",
        serde_json::to_string_pretty(&report).expect("plain data serialises")
    );
    Ok(())
}
