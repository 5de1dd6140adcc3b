//! Where adaptive supersampling must sample a pixel fully, read off a pass at pixel centres.

use crate::raster::Framebuffer;
use rayon::prelude::*;

/// Marks the pixels of a centre pass that adaptive supersampling must sample fully: where a
/// neighbour differs in coverage (surface against background), or where the picture is not
/// locally linear: in any of the four directions through the pixel (across, down, both
/// diagonals) |c₋ + c₊ − 2c| exceeds `threshold` in a channel of √colour (a cheap perceptual
/// scale: a step in a dark region counts as much as a brighter one).
///
/// Why that suffices: the resolve filters are symmetric and reach at most a pixel from the
/// centre, and over a linear ramp a symmetric filter returns the centre value, so smooth shading
/// needs no samples however steep it is. A step (an edge, a rim, a check) crossing a pixel's
/// filter square separates its centre from some neighbour's, so the second difference towards
/// that neighbour is the full step and the pixel is marked: on flat regions the result is that
/// of full supersampling. What no centre sees (detail below a pixel, a corner poking between
/// centres) is missed, the usual limit of adaptive schemes.
///
/// Rows and columns are clamped at the pass's border (a one-sided difference there). Rows are
/// marked in parallel, each from the keys of itself and its two neighbours.
pub fn contrast_mask(pass: &Framebuffer, threshold: f32, mask: &mut Vec<bool>) {
    let (w, h) = (pass.width as usize, pass.height as usize);
    crate::huge_pages::resize_for_overwrite(mask, w * h);
    if w == 0 {
        return;
    }
    let pixels_of_row = |y: usize| y * w..(y + 1) * w;
    // Each job marks a run of rows, reading every row's keys once: the three in hand roll down.
    let rows_per_job = 16;
    mask.par_chunks_mut(w * rows_per_job)
        .enumerate()
        .for_each(|(job, marks)| {
            let first = job * rows_per_job;
            let mut rows = <[RowKeys; 3]>::default();
            // The keys' square roots and the marking's compares vectorise: AVX2 where there.
            crate::simd::widest(
                #[inline(always)]
                || {
                    rows[0].fill(pass, pixels_of_row(first.saturating_sub(1)));
                    rows[1].fill(pass, pixels_of_row(first));
                    for (y, marks) in (first..).zip(marks.chunks_mut(w)) {
                        rows[2].fill(pass, pixels_of_row((y + 1).min(h - 1)));
                        let [up, row, down] = &rows;
                        mark_row([up, row, down], threshold, marks);
                        rows.rotate_left(1);
                    }
                },
            )
        });
}

/// One row of a pass as the contrast test reads it: √colour by channel, and coverage.
#[derive(Default)]
struct RowKeys {
    channels: [Vec<f32>; 3],
    covered: Vec<bool>,
}

impl RowKeys {
    /// Takes the keys of `pixels` of `pass`.
    #[inline(always)]
    fn fill(&mut self, pass: &Framebuffer, pixels: std::ops::Range<usize>) {
        let (colors, depth) = (&pass.color()[pixels.clone()], &pass.depth()[pixels]);
        for (c, channel) in self.channels.iter_mut().enumerate() {
            channel.clear();
            channel.extend(colors.iter().map(|colour| colour[c].max(0.0).sqrt()));
        }
        self.covered.clear();
        self.covered.extend(depth.iter().map(|d| d.is_finite()));
    }
}

/// Marks one row from the keys of the rows above, at and below it.
#[inline(always)]
fn mark_row(rows: [&RowKeys; 3], threshold: f32, marks: &mut [bool]) {
    let last = marks.len() - 1;
    if last >= 2 {
        mark_interior(rows, threshold, &mut marks[1..last]);
    }
    marks[0] = marked_at(rows, threshold, 0, last);
    marks[last] = marked_at(rows, threshold, last, last);
}

/// Whether pixel `x` of a row whose last pixel is `last` is marked: any pixel, columns clamped.
fn marked_at([up, row, down]: [&RowKeys; 3], threshold: f32, x: usize, last: usize) -> bool {
    let (left, right) = (x.saturating_sub(1), (x + 1).min(last));
    // Each direction through the pixel: the rows and columns of its two ends.
    let directions = [
        ((row, left), (row, right)),
        ((up, x), (down, x)),
        ((up, left), (down, right)),
        ((up, right), (down, left)),
    ];
    let covered = row.covered[x];
    directions.iter().any(|&((a, xa), (b, xb))| {
        a.covered[xa] != covered
            || b.covered[xb] != covered
            || (0..3).any(|c| {
                let twice = 2.0 * row.channels[c][x];
                (a.channels[c][xa] + b.channels[c][xb] - twice).abs() > threshold
            })
    })
}

/// `marked_at` for the pixels between a row's ends, where no column is clamped: whole slices
/// shifted by a pixel, which the compiler turns into vector code.
#[inline(always)]
fn mark_interior([up, row, down]: [&RowKeys; 3], threshold: f32, marks: &mut [bool]) {
    let n = marks.len();
    // Each key row as (left neighbours, the pixels, right neighbours) of the n interior pixels.
    fn shifted<T>(keys: &[T], n: usize) -> [&[T]; 3] {
        [&keys[..n], &keys[1..n + 1], &keys[2..n + 2]]
    }
    let [ul, uc, ur] = shifted(&up.covered, n);
    let [ml, mc, mr] = shifted(&row.covered, n);
    let [dl, dc, dr] = shifted(&down.covered, n);
    for i in 0..n {
        let c = mc[i];
        marks[i] = (ml[i] != c) | (mr[i] != c) | (uc[i] != c) | (dc[i] != c);
        marks[i] |= (ul[i] != c) | (dr[i] != c) | (ur[i] != c) | (dl[i] != c);
    }
    for c in 0..3 {
        let [ul, uc, ur] = shifted(&up.channels[c], n);
        let [ml, mc, mr] = shifted(&row.channels[c], n);
        let [dl, dc, dr] = shifted(&down.channels[c], n);
        for i in 0..n {
            let twice = 2.0 * mc[i];
            let bent = |a: f32, b: f32| (a + b - twice).abs() > threshold;
            marks[i] |= bent(ml[i], mr[i]) | bent(uc[i], dc[i]);
            marks[i] |= bent(ul[i], dr[i]) | bent(ur[i], dl[i]);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    /// The mask's definition, pixel by pixel over the whole pass.
    fn mask_by_definition(pass: &Framebuffer, threshold: f32) -> Vec<bool> {
        let (w, h) = (pass.width as usize, pass.height as usize);
        let key = |i: usize| pass.color()[i].max(Vec3::ZERO).to_array().map(f32::sqrt);
        let covered = |i: usize| pass.depth()[i].is_finite();
        let mut mask = vec![false; w * h];
        for y in 0..h {
            for x in 0..w {
                let at = |dx: i64, dy: i64| {
                    let cx = (x as i64 + dx).clamp(0, w as i64 - 1) as usize;
                    let cy = (y as i64 + dy).clamp(0, h as i64 - 1) as usize;
                    cy * w + cx
                };
                let i = at(0, 0);
                mask[i] = [(1, 0), (0, 1), (1, 1), (1, -1)].iter().any(|&(dx, dy)| {
                    let (a, b) = (at(-dx, -dy), at(dx, dy));
                    let bent =
                        (0..3).any(|c| (key(a)[c] + key(b)[c] - 2.0 * key(i)[c]).abs() > threshold);
                    bent || covered(a) != covered(i) || covered(b) != covered(i)
                });
            }
        }
        mask
    }

    /// A pass of smooth ramps, steps, specks of background and negative colours, from a small
    /// deterministic generator.
    fn pass(width: u32, height: u32, seed: u64) -> Framebuffer {
        let mut state = seed;
        let mut next = move || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (state >> 40) as f32 / (1u64 << 24) as f32
        };
        let n = (width * height) as usize;
        let mut color = Vec::with_capacity(n);
        let mut depth = Vec::with_capacity(n);
        for i in 0..n {
            let (x, y) = ((i % width as usize) as f32, (i / width as usize) as f32);
            let ramp = 0.01 * x + 0.02 * y;
            let step = if next() < 0.02 { next() - 0.5 } else { 0.0 };
            color.push(Vec3::new(ramp + step, ramp * ramp, 0.3 + 0.001 * next()));
            depth.push(if next() < 0.01 { f32::INFINITY } else { 1.0 });
        }
        Framebuffer::from_parts(width, height, color, depth)
    }

    #[test]
    fn the_row_parallel_mask_is_the_per_pixel_definition() {
        for (width, height, seed) in [(37, 23, 1), (1, 9, 2), (9, 1, 3), (1, 1, 4), (64, 3, 5)] {
            let pass = pass(width, height, seed);
            for threshold in [0.0, 0.02, 0.1, 0.5] {
                let mut mask = Vec::new();
                contrast_mask(&pass, threshold, &mut mask);
                let expected = mask_by_definition(&pass, threshold);
                assert_eq!(
                    mask, expected,
                    "{width}x{height} seed {seed} at {threshold}"
                );
                if threshold == 0.02 && width * height > 100 {
                    let marked = mask.iter().filter(|&&m| m).count();
                    assert!(0 < marked && marked < mask.len(), "{marked} marked");
                }
            }
        }
    }
}
