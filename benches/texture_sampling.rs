//! Samples per second for each filter on a 2048² texture, magnified (4 samples per
//! texel) and minified (8 texels per sample, mip level 3), over a slightly rotated
//! 1024² grid of screen pixels visited in scanline order, as a rasterizer would.
//! Prints the median of 9 runs with the min–max spread.

use std::hint::black_box;
use std::time::Instant;

use bumpwork::texture::{Filter, Footprint, Raster, Sampler, Texel, Texture, Wrap};
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
    Texture::from_raster(Raster::from_fn(SIDE, SIDE, |_, _| {
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

fn main() {
    let texture = noise_texture();
    println!(
        "texture sampling, {SIDE}×{SIDE} RGBA f32, {} samples per run, median of {RUNS} runs",
        GRID * GRID
    );
    println!(
        "{:<10} {:<10} {:>8} {:>14} {:>14}",
        "filter", "case", "lod", "Msamples/s", "min–max"
    );
    for filter in [Filter::Nearest, Filter::Bilinear, Filter::Trilinear] {
        for (case, texels_per_pixel) in [("magnified", 0.25), ("minified", 8.0)] {
            let sampler = Sampler::new(filter, Wrap::Repeat);
            let lod = texture.level_of_detail(screen_to_texture(texels_per_pixel).1);
            let mut rates: Vec<f64> = (0..RUNS)
                .map(|_| run(&texture, &sampler, texels_per_pixel) / 1e6)
                .collect();
            rates.sort_by(f64::total_cmp);
            println!(
                "{:<10} {:<10} {:>8.2} {:>14.1} {:>8.1}–{:<6.1}",
                format!("{filter:?}"),
                case,
                lod,
                rates[RUNS / 2],
                rates[0],
                rates[RUNS - 1]
            );
        }
    }
}
