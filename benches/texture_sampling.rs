//! Samples per second for each filter on a 2048² texture, magnified (4 samples per
//! texel) and minified (8 texels per sample, mip level 3), over a slightly rotated
//! 1024² grid of screen pixels visited in scanline order, as a rasterizer would.
//! Each point one at a time (`Texture::sample`) and a row of the grid at a time
//! (`Texture::sample_many`, as the shader samples a batch of fragments). Prints the median of
//! 9 runs with the min–max spread.

use std::hint::black_box;
use std::time::Instant;

use bumpwork::texture::{Filter, Footprint, Sampler, Texel, TexelGrid, Texture, Wrap};
use glam::{Mat2, Vec2};

const SIDE: u32 = 2048;
const GRID: u32 = 1024;
const RUNS: usize = 9;

fn noise_texture() -> Texture {
    let mut state = 0x9e37_79b9u32;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        (state >> 8) as f32 / (1 << 24) as f32
    };
    Texture::from_raster(TexelGrid::from_fn(SIDE, SIDE, |_, _| {
        Texel::new(next(), next(), next(), 1.0)
    }))
}

/// Screen pixel (x, y) → st, with `texels_per_pixel` texels between neighbouring pixels.
fn screen_to_texture(texels_per_pixel: f32) -> (Mat2, Footprint) {
    let scale = texels_per_pixel / SIDE as f32;
    let m = Mat2::from_angle(0.3) * scale;
    let footprint = Footprint {
        dx: m.x_axis,
        dy: m.y_axis,
    };
    (m, footprint)
}

/// Samples the whole grid once; returns samples per second.
fn run(texture: &Texture, sampler: &Sampler, texels_per_pixel: f32) -> f64 {
    let (m, footprint) = screen_to_texture(texels_per_pixel);
    let start = Instant::now();
    let mut sum = Texel::ZERO;
    for y in 0..GRID {
        for x in 0..GRID {
            let st = m * Vec2::new(x as f32, y as f32) + Vec2::splat(0.1);
            sum += texture.sample(sampler, black_box(st), footprint);
        }
    }
    black_box(sum);
    f64::from(GRID * GRID) / start.elapsed().as_secs_f64()
}

/// The same grid a row at a time through `sample_many`; returns samples per second.
fn run_batched(texture: &Texture, sampler: &Sampler, texels_per_pixel: f32) -> f64 {
    let (m, footprint) = screen_to_texture(texels_per_pixel);
    let footprints = vec![footprint; GRID as usize];
    let given: &[Footprint] = if sampler.filter.uses_footprint() {
        &footprints
    } else {
        &[]
    };
    let mut st = vec![Vec2::ZERO; GRID as usize];
    let mut out = vec![Texel::ZERO; GRID as usize];
    let start = Instant::now();
    let mut sum = Texel::ZERO;
    for y in 0..GRID {
        for (x, st) in st.iter_mut().enumerate() {
            *st = m * Vec2::new(x as f32, y as f32) + Vec2::splat(0.1);
        }
        texture.sample_many(sampler, black_box(&st), given, &mut out);
        sum += out.iter().copied().sum::<Texel>();
    }
    black_box(sum);
    f64::from(GRID * GRID) / start.elapsed().as_secs_f64()
}

/// Median and extremes of `RUNS` rates in M/s.
fn spread(rate: impl Fn() -> f64) -> (f64, f64, f64) {
    let mut rates: Vec<f64> = (0..RUNS).map(|_| rate() / 1e6).collect();
    rates.sort_by(f64::total_cmp);
    (rates[RUNS / 2], rates[0], rates[RUNS - 1])
}

fn main() {
    let texture = noise_texture();
    println!(
        "texture sampling, {SIDE}×{SIDE} RGBA f32, {} samples per run, median of {RUNS} runs",
        GRID * GRID
    );
    println!(
        "{:<10} {:<10} {:>6} {:>24} {:>24}",
        "filter", "case", "lod", "one at a time Msamples/s", "a row at a time"
    );
    for filter in [Filter::Nearest, Filter::Bilinear, Filter::Trilinear] {
        for (case, texels_per_pixel) in [("magnified", 0.25), ("minified", 8.0)] {
            let sampler = Sampler::new(filter, Wrap::Repeat);
            let lod = texture.level_of_detail(screen_to_texture(texels_per_pixel).1);
            let one = spread(|| run(&texture, &sampler, texels_per_pixel));
            let row = spread(|| run_batched(&texture, &sampler, texels_per_pixel));
            let shown =
                |(median, min, max): (f64, f64, f64)| format!("{median:.1} ({min:.1}–{max:.1})");
            println!(
                "{:<10} {:<10} {:>6.2} {:>24} {:>24}",
                format!("{filter:?}"),
                case,
                lod,
                shown(one),
                shown(row)
            );
        }
    }
}
