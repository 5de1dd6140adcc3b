//! Encode + write time and bytes per frame of the terminal picture path, for a smooth-shaded sphere:
//! full redraw, a small orbit-like change and an idle frame, per colour mode and glyph set; and chafa's
//! bytes for the same picture when chafa is installed. Run: `cargo bench --bench term_encode`.

use std::path::Path;
use std::process::Command;
use std::time::{Duration, Instant};

use bumpwork::term::{
    CellGrid, ColorMode, EncodeOptions, FrameOptions, GlyphSet, Picture, encode, encode_frame,
};

const COLS: usize = 200;
const ROWS: usize = 60;
const RUNS: usize = 15;
/// The orbit step between the two frames of the "small change": about one degree.
const ORBIT_STEP: f32 = 0.02;

/// A striped, Blinn-Phong-shaded sphere over a vertical gradient, seen from longitude `orbit`; sRGB.
fn sphere_picture(width: usize, height: usize, pixel_aspect: f32, orbit: f32) -> Vec<[u8; 3]> {
    let mut pixels = Vec::with_capacity(width * height);
    let radius = 0.42 * height as f32;
    for y in 0..height {
        for x in 0..width {
            let u = (x as f32 + 0.5 - width as f32 / 2.0) * pixel_aspect / radius;
            let v = (y as f32 + 0.5 - height as f32 / 2.0) / radius;
            let background = 0.05 + 0.15 * y as f32 / height as f32;
            let linear = match 1.0 - u * u - v * v {
                z2 if z2 > 0.0 => shade_sphere(u, v, z2.sqrt(), orbit),
                _ => [background, background, background * 1.6],
            };
            pixels.push(linear.map(linear_to_srgb));
        }
    }
    pixels
}

fn shade_sphere(x: f32, y: f32, z: f32, orbit: f32) -> [f32; 3] {
    let longitude = x.atan2(z) + orbit;
    let stripes = 0.5 + 0.5 * (longitude * 12.0).sin();
    let albedo = [0.8 * stripes + 0.1, 0.35, 0.9 - 0.6 * stripes];
    let light = [-0.5f32, -0.6, 0.62];
    let diffuse = (x * light[0] + y * light[1] + z * light[2]).max(0.0);
    // Blinn half vector between the light and a viewer on +z.
    let half = normalize([light[0], light[1], light[2] + 1.0]);
    let specular = (x * half[0] + y * half[1] + z * half[2])
        .max(0.0)
        .powf(40.0);
    albedo.map(|a| a * (0.05 + 0.9 * diffuse) + 0.6 * specular)
}

fn normalize(v: [f32; 3]) -> [f32; 3] {
    let len = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    v.map(|c| c / len)
}

fn linear_to_srgb(c: f32) -> u8 {
    let c = c.clamp(0.0, 1.0);
    let s = if c <= 0.0031308 {
        12.92 * c
    } else {
        1.055 * c.powf(1.0 / 2.4) - 0.055
    };
    (s * 255.0 + 0.5) as u8
}

struct Timing {
    median: Duration,
    min: Duration,
    max: Duration,
}

fn time_runs(mut run: impl FnMut()) -> Timing {
    run(); // warm up caches and the allocator
    let mut times: Vec<Duration> = (0..RUNS)
        .map(|_| {
            let start = Instant::now();
            run();
            start.elapsed()
        })
        .collect();
    times.sort();
    Timing {
        median: times[RUNS / 2],
        min: times[0],
        max: times[RUNS - 1],
    }
}

/// Encodes `pixels` and writes the frame that shows it over `previous`; returns the bytes.
fn encode_and_write(
    pixels: &[[u8; 3]],
    size: (usize, usize),
    options: EncodeOptions,
    previous: Option<&CellGrid>,
    frame: FrameOptions,
) -> (CellGrid, Vec<u8>) {
    let grid = encode(&Picture::new(pixels, size.0, size.1).unwrap(), options);
    let mut out = Vec::with_capacity(256 * 1024);
    encode_frame(previous, &grid, frame, &mut out);
    (grid, out)
}

fn changed_cells(a: &CellGrid, b: &CellGrid) -> usize {
    (0..a.rows())
        .map(|y| {
            (0..a.cols())
                .filter(|&x| !a.get(x, y).looks_same(b.get(x, y)))
                .count()
        })
        .sum()
}

/// A frame to time: its name, its picture and the grid shown before it (`None`: full redraw).
type Scenario<'a> = (&'a str, &'a [[u8; 3]], Option<&'a CellGrid>);

fn bench_mode(colors: ColorMode, glyphs: GlyphSet, dither: bool) {
    let size = glyphs.picture_size(COLS, ROWS);
    let aspect = glyphs.pixel_aspect();
    let before = sphere_picture(size.0, size.1, aspect, 0.0);
    let after = sphere_picture(size.0, size.1, aspect, ORBIT_STEP);
    let options = EncodeOptions {
        dither,
        ..EncodeOptions::new(colors, glyphs)
    };
    let plain = FrameOptions {
        origin: (0, 0),
        repeat: false,
    };
    let repeating = FrameOptions {
        repeat: true,
        ..plain
    };
    let (grid_before, _) = encode_and_write(&before, size, options, None, plain);
    let (grid_after, _) = encode_and_write(&after, size, options, None, plain);
    let scenarios: [Scenario; 3] = [
        ("full", &after, None),
        ("small change", &after, Some(&grid_before)),
        ("idle", &after, Some(&grid_after)),
    ];
    let label = format!("{colors:?}{}", if dither { "" } else { "/near" });
    for (name, pixels, previous) in scenarios {
        let mut bytes = 0;
        let timing = time_runs(|| {
            bytes = encode_and_write(pixels, size, options, previous, plain)
                .1
                .len();
        });
        let with_rep = encode_and_write(pixels, size, options, previous, repeating)
            .1
            .len();
        let changed = previous.map_or(COLS * ROWS, |p| changed_cells(p, &grid_after));
        println!(
            "{label:<15} {:<9} {name:<13} {:>5}x{:<4} {:>8.3} {:>8.3} {:>8.3} {bytes:>9} {with_rep:>9} {changed:>8}",
            format!("{glyphs:?}"),
            size.0,
            size.1,
            ms(timing.median),
            ms(timing.min),
            ms(timing.max),
        );
    }
}

fn ms(d: Duration) -> f64 {
    d.as_secs_f64() * 1e3
}

fn write_png(path: &Path, pixels: &[[u8; 3]], width: usize, height: usize) -> std::io::Result<()> {
    let file = std::io::BufWriter::new(std::fs::File::create(path)?);
    let mut encoder = png::Encoder::new(file, width as u32, height as u32);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header().map_err(std::io::Error::other)?;
    writer
        .write_image_data(pixels.as_flattened())
        .map_err(std::io::Error::other)?;
    writer.finish().map_err(std::io::Error::other)
}

fn bench_chafa() {
    let Ok(found) = Command::new("which").arg("chafa").output() else {
        println!("chafa: skipped, `which` could not run");
        return;
    };
    if !found.status.success() {
        println!("chafa: skipped, not installed (apt-get install chafa)");
        return;
    }
    let size = GlyphSet::HalfBlock.picture_size(COLS, ROWS);
    let pixels = sphere_picture(size.0, size.1, 1.0, ORBIT_STEP);
    let temp = tempfile::tempdir().expect("a temporary directory");
    let path = temp.path().join("sphere.png");
    if let Err(error) = write_png(&path, &pixels, size.0, size.1) {
        println!(
            "chafa: skipped, could not write {}: {error}",
            path.display()
        );
        return;
    }
    println!(
        "\nchafa on the same {}x{} picture, half blocks, {COLS}x{ROWS} cells (full frame; chafa has no diff):",
        size.0, size.1
    );
    println!(
        "{:<8} {:<8} {:>10} {:>12}",
        "colors", "dither", "bytes", "wall ms"
    );
    let runs = [
        ("full", "none"),
        ("256", "none"),
        ("256", "ordered"),
        ("16", "none"),
        ("16", "ordered"),
    ];
    for (colors, dither) in runs {
        let start = Instant::now();
        let output = Command::new("chafa")
            .args([
                "-f",
                "symbols",
                "--symbols",
                "half",
                "--animate",
                "off",
                "--stretch",
                "-O",
                "9",
            ])
            .args([
                "--colors",
                colors,
                "--dither",
                dither,
                "--size",
                &format!("{COLS}x{ROWS}"),
            ])
            .arg(&path)
            .output();
        let elapsed = start.elapsed();
        match output {
            Ok(o) if o.status.success() => {
                println!(
                    "{colors:<8} {dither:<8} {:>10} {:>12.1}",
                    o.stdout.len(),
                    ms(elapsed)
                )
            }
            Ok(o) => println!(
                "{colors:<8} {dither:<8} failed: {}",
                String::from_utf8_lossy(&o.stderr).trim()
            ),
            Err(error) => println!("{colors:<8} {dither:<8} failed to run: {error}"),
        }
    }
}

fn main() {
    println!(
        "encode + write of a {COLS}x{ROWS}-cell frame, {RUNS} runs (ms); bytes per frame; cells changed"
    );
    println!(
        "{:<15} {:<9} {:<13} {:>10} {:>8} {:>8} {:>8} {:>9} {:>9} {:>8}",
        "colors",
        "glyphs",
        "frame",
        "pixels",
        "median",
        "min",
        "max",
        "bytes",
        "with REP",
        "changed"
    );
    for glyphs in [GlyphSet::HalfBlock, GlyphSet::Quadrant, GlyphSet::Sextant] {
        bench_mode(ColorMode::TrueColor, glyphs, true);
        for colors in [ColorMode::Ansi256, ColorMode::Ansi16] {
            bench_mode(colors, glyphs, true);
            bench_mode(colors, glyphs, false);
        }
        bench_mode(ColorMode::Monochrome, glyphs, true);
    }
    bench_chafa();
}
