//! A palette of at most 256 colours chosen for one picture (median cut over its colours at five
//! or six bits a channel, `Precision`) and the picture mapped onto it with Floyd–Steinberg error diffusion: the one
//! quantizer behind sixel pictures and GIF frames.

/// Colours a palette holds at most: a GIF's limit, and a sixel's on all but rare terminals.
pub const MAX_COLOURS: usize = 256;

/// How finely colours are told apart while the palette is chosen and looked up: the bits of
/// each channel kept in the histogram and in the nearest-colour table.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Precision {
    /// Five bits: fewer distinct colours, so fewer and longer colour runs, in less time; for
    /// the terminal, where a picture's bytes cross the link every frame.
    Coarse,
    /// Six bits: a smooth gradient keeps four times the steps; for files (GIF frames).
    Fine,
}

impl Precision {
    fn bits(self) -> u32 {
        match self {
            Precision::Coarse => 5,
            Precision::Fine => 6,
        }
    }
}

/// The histogram's cells: colours with the same leading bits in each channel share one.
#[derive(Clone, Copy)]
struct Cells {
    bits: u32,
}

impl Cells {
    fn levels(self) -> usize {
        1 << self.bits
    }

    fn count(self) -> usize {
        self.levels().pow(3)
    }

    fn of(self, pixel: &[u8]) -> usize {
        let k = |c: u8| usize::from(c >> (8 - self.bits));
        (k(pixel[0]) * self.levels() + k(pixel[1])) * self.levels() + k(pixel[2])
    }
}

/// A picture as palette indices, and the palette (sRGB, 8 bits a channel).
pub struct Indexed {
    pub palette: Vec<[u8; 3]>,
    pub indices: Vec<u8>,
}

/// `rgb` (3 bytes a pixel, `width` across) on a palette of its own, dithered.
pub fn indexed(rgb: &[u8], width: usize, precision: Precision) -> Indexed {
    let cells = Cells {
        bits: precision.bits(),
    };
    let palette = median_cut(&histogram(rgb, cells));
    let indices = dither(rgb, width, &palette, cells);
    Indexed { palette, indices }
}

/// One colour of the histogram: its bucket's pixel count and channel sums.
#[derive(Clone, Copy)]
struct Bucket {
    key: [u8; 3],
    count: u64,
    sum: [u64; 3],
}

fn histogram(rgb: &[u8], cells: Cells) -> Vec<Bucket> {
    let mut counts = vec![(0u64, [0u64; 3]); cells.count()];
    for pixel in rgb.chunks_exact(3) {
        let slot = &mut counts[cells.of(pixel)];
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
                (index / cells.levels().pow(2)) as u8,
                (index / cells.levels() % cells.levels()) as u8,
                (index % cells.levels()) as u8,
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

/// The palette index nearest each cell's colours, found when first asked for.
struct Nearest<'a> {
    palette: &'a [[u8; 3]],
    cells: Cells,
    table: Vec<u16>,
}

impl Nearest<'_> {
    const UNKNOWN: u16 = u16::MAX;

    fn of(&mut self, pixel: [u8; 3]) -> u8 {
        let bucket = self.cells.of(&pixel);
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
fn dither(rgb: &[u8], width: usize, palette: &[[u8; 3]], cells: Cells) -> Vec<u8> {
    let mut nearest = Nearest {
        palette,
        cells,
        table: vec![Nearest::UNKNOWN; cells.count()],
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

    /// Mean absolute error a channel of `rgb` on its own palette.
    fn mean_error(rgb: &[u8], width: usize, precision: Precision) -> f64 {
        let picture = indexed(rgb, width, precision);
        assert!(picture.palette.len() <= MAX_COLOURS);
        let total: f64 = rgb
            .chunks(3)
            .zip(&picture.indices)
            .map(|(p, &i)| {
                let q = picture.palette[usize::from(i)];
                (0..3)
                    .map(|c| (f64::from(p[c]) - f64::from(q[c])).abs())
                    .sum::<f64>()
            })
            .sum();
        total / rgb.len() as f64
    }

    #[test]
    fn few_colours_are_kept_exactly_at_either_precision() {
        let two: Vec<u8> = [[200, 10, 10], [10, 10, 200]].repeat(50).concat();
        for precision in [Precision::Coarse, Precision::Fine] {
            let picture = indexed(&two, 10, precision);
            assert_eq!(picture.palette.len(), 2);
            for (pixel, &index) in two.chunks(3).zip(&picture.indices) {
                assert_eq!(picture.palette[usize::from(index)], pixel);
            }
        }
    }

    #[test]
    fn many_colours_fit_the_limit_and_fine_precision_keeps_a_gradient_closer() {
        let ramp: Vec<u8> = (0..256 * 64)
            .flat_map(|i| [(i % 256) as u8, (i / 256 * 4) as u8, 128])
            .collect();
        let coarse = mean_error(&ramp, 256, Precision::Coarse);
        assert!(coarse < 6.0, "mean error {coarse} a channel");
        // A slow grey ramp, as a lit surface shades: 256 levels over a wide picture.
        let grey: Vec<u8> = (0..512 * 32)
            .flat_map(|i| [(i % 512 / 2) as u8; 3])
            .collect();
        let (coarse, fine) = (
            mean_error(&grey, 512, Precision::Coarse),
            mean_error(&grey, 512, Precision::Fine),
        );
        assert!(
            fine < 0.75 * coarse,
            "fine {fine}, coarse {coarse} a channel"
        );
    }
}
