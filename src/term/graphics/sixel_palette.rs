//! A palette of at most 256 colours chosen for one picture (median cut over its colours at five
//! bits a channel) and the picture mapped onto it with Floyd–Steinberg error diffusion.

/// Colours a sixel palette holds at most (the terminals that take more are rare).
pub const MAX_COLOURS: usize = 256;

/// Bits a channel keeps in the histogram and in the nearest-colour table.
const BITS: u32 = 5;
const LEVELS: usize = 1 << BITS;

/// A picture as palette indices, and the palette (sRGB, 8 bits a channel).
pub struct Indexed {
    pub palette: Vec<[u8; 3]>,
    pub indices: Vec<u8>,
}

/// `rgb` (3 bytes a pixel, `width` across) on a palette of its own, dithered.
pub fn indexed(rgb: &[u8], width: usize) -> Indexed {
    let palette = median_cut(&histogram(rgb));
    let indices = dither(rgb, width, &palette);
    Indexed { palette, indices }
}

/// One colour of the histogram: its bucket's pixel count and channel sums.
#[derive(Clone, Copy)]
struct Bucket {
    key: [u8; 3],
    count: u64,
    sum: [u64; 3],
}

fn bucket_of(pixel: &[u8]) -> usize {
    let k = |c: u8| usize::from(c >> (8 - BITS));
    (k(pixel[0]) * LEVELS + k(pixel[1])) * LEVELS + k(pixel[2])
}

fn histogram(rgb: &[u8]) -> Vec<Bucket> {
    let mut counts = vec![(0u64, [0u64; 3]); LEVELS * LEVELS * LEVELS];
    for pixel in rgb.chunks_exact(3) {
        let slot = &mut counts[bucket_of(pixel)];
        slot.0 += 1;
        for (sum, &c) in slot.1.iter_mut().zip(pixel) {
            *sum += u64::from(c);
        }
    }
    counts
        .into_iter()
        .enumerate()
        .filter(|(_, (count, _))| *count > 0)
        .map(|(index, (count, sum))| Bucket {
            key: [
                (index / (LEVELS * LEVELS)) as u8,
                (index / LEVELS % LEVELS) as u8,
                (index % LEVELS) as u8,
            ],
            count,
            sum,
        })
        .collect()
}

/// Splits the colours into at most `MAX_COLOURS` boxes, always the box that spans most (range
/// times pixels) along its longest axis at its median pixel; each box's mean is a colour.
fn median_cut(buckets: &[Bucket]) -> Vec<[u8; 3]> {
    if buckets.is_empty() {
        return vec![[0, 0, 0]];
    }
    let mut boxes: Vec<Vec<Bucket>> = vec![buckets.to_vec()];
    while boxes.len() < MAX_COLOURS {
        let widest = boxes
            .iter()
            .enumerate()
            .filter(|(_, b)| b.len() > 1)
            .max_by_key(|(_, b)| {
                let (_, range) = longest_axis(b);
                u64::from(range) * b.iter().map(|x| x.count).sum::<u64>()
            });
        let Some((index, _)) = widest else {
            break;
        };
        let mut cut = boxes.swap_remove(index);
        let (axis, _) = longest_axis(&cut);
        cut.sort_unstable_by_key(|b| b.key[axis]);
        let half = cut.iter().map(|b| b.count).sum::<u64>() / 2;
        let mut seen = 0;
        let split = cut
            .iter()
            .position(|b| {
                seen += b.count;
                seen > half
            })
            .unwrap_or(0)
            .clamp(1, cut.len() - 1);
        let upper = cut.split_off(split);
        boxes.push(cut);
        boxes.push(upper);
    }
    boxes.iter().map(|b| mean(b)).collect()
}

/// The axis along which `colours` spread most, and how far.
fn longest_axis(colours: &[Bucket]) -> (usize, u8) {
    (0..3)
        .map(|axis| {
            let keys = colours.iter().map(|b| b.key[axis]);
            let range = keys.clone().max().unwrap_or(0) - keys.min().unwrap_or(0);
            (axis, range)
        })
        .max_by_key(|&(_, range)| range)
        .expect("three axes")
}

fn mean(colours: &[Bucket]) -> [u8; 3] {
    let count: u64 = colours.iter().map(|b| b.count).sum();
    let channel = |c: usize| {
        let sum: u64 = colours.iter().map(|b| b.sum[c]).sum();
        ((sum + count / 2) / count.max(1)) as u8
    };
    [channel(0), channel(1), channel(2)]
}

/// The palette index nearest each 5-bit bucket, found when first asked for.
struct Nearest<'a> {
    palette: &'a [[u8; 3]],
    table: Vec<u16>,
}

impl Nearest<'_> {
    const UNKNOWN: u16 = u16::MAX;

    fn of(&mut self, pixel: [u8; 3]) -> u8 {
        let bucket = bucket_of(&pixel);
        if self.table[bucket] == Self::UNKNOWN {
            self.table[bucket] = u16::from(closest(self.palette, pixel));
        }
        self.table[bucket] as u8
    }
}

fn closest(palette: &[[u8; 3]], pixel: [u8; 3]) -> u8 {
    let distance = |c: &[u8; 3]| {
        (0..3)
            .map(|i| (i32::from(c[i]) - i32::from(pixel[i])).pow(2))
            .sum::<i32>()
    };
    let (index, _) = palette
        .iter()
        .enumerate()
        .min_by_key(|(_, c)| distance(c))
        .expect("a palette has a colour");
    index as u8
}

/// Floyd–Steinberg: each pixel takes the palette colour nearest it plus the error carried from
/// its neighbours, and passes its own error on (7/16 right; 3/16, 5/16, 1/16 below).
fn dither(rgb: &[u8], width: usize, palette: &[[u8; 3]]) -> Vec<u8> {
    let mut nearest = Nearest {
        palette,
        table: vec![Nearest::UNKNOWN; LEVELS * LEVELS * LEVELS],
    };
    let height = rgb.len() / 3 / width.max(1);
    let mut indices = vec![0u8; width * height];
    // Errors in sixteenths, for this row and the next, one pixel of margin on each side.
    let mut this_row = vec![[0i32; 3]; width + 2];
    let mut next_row = vec![[0i32; 3]; width + 2];
    for y in 0..height {
        for x in 0..width {
            let at = (y * width + x) * 3;
            let mut wanted = [0u8; 3];
            for c in 0..3 {
                let value = i32::from(rgb[at + c]) + this_row[x + 1][c] / 16;
                wanted[c] = value.clamp(0, 255) as u8;
            }
            let index = nearest.of(wanted);
            indices[y * width + x] = index;
            let got = palette[usize::from(index)];
            for c in 0..3 {
                let error = i32::from(wanted[c]) - i32::from(got[c]);
                this_row[x + 2][c] += error * 7;
                next_row[x][c] += error * 3;
                next_row[x + 1][c] += error * 5;
                next_row[x + 2][c] += error;
            }
        }
        std::mem::swap(&mut this_row, &mut next_row);
        next_row.iter_mut().for_each(|e| *e = [0; 3]);
    }
    indices
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn few_colours_are_kept_exactly_and_many_fit_the_limit() {
        let two: Vec<u8> = [[200, 10, 10], [10, 10, 200]].repeat(50).concat();
        let picture = indexed(&two, 10);
        assert_eq!(picture.palette.len(), 2);
        for (pixel, &index) in two.chunks(3).zip(&picture.indices) {
            assert_eq!(picture.palette[usize::from(index)], pixel);
        }
        let ramp: Vec<u8> = (0..256 * 64)
            .flat_map(|i| [(i % 256) as u8, (i / 256 * 4) as u8, 128])
            .collect();
        let picture = indexed(&ramp, 256);
        assert!(picture.palette.len() <= MAX_COLOURS);
        let error: f64 = ramp
            .chunks(3)
            .zip(&picture.indices)
            .map(|(p, &i)| {
                let q = picture.palette[usize::from(i)];
                (0..3)
                    .map(|c| (f64::from(p[c]) - f64::from(q[c])).abs())
                    .sum::<f64>()
            })
            .sum::<f64>()
            / ramp.len() as f64;
        assert!(error < 6.0, "mean error {error} a channel");
    }
}
