//! PNG row filters for 8-bit RGB rows, chosen as the png crate's adaptive filter chooses them:
//! of Up, Sub, Average and Paeth tried in that order, the one whose filtered bytes, read as
//! signed, have the least sum of magnitudes (a tie goes to the later one, and the first that
//! sums to zero is taken at once). The png crate works out the four one after another and is
//! compiled for baseline x86-64; here one pass over the row works out all four at once, 32
//! bytes an instruction where the CPU has AVX2. The choices, and so the files, are the same.

/// Bytes per pixel of the rows filtered: 8-bit RGB.
const PIXEL_BYTES: usize = 3;

/// Zero bytes before each row in its buffer, so the left neighbours of the first pixel (and of
/// the pixel above it) read as the zeros PNG defines there, and a lane may load from before it.
const PAD: usize = 32;

/// The filters tried, in the png crate's order, by their PNG filter-type byte.
const TRIED: [u8; 4] = [UP, SUB, AVERAGE, PAETH];
const SUB: u8 = 1;
const UP: u8 = 2;
const AVERAGE: u8 = 3;
const PAETH: u8 = 4;

/// Filters the rows of one image, top first, keeping the row above.
pub struct RowFilter {
    row_len: usize,
    /// The row above, after `PAD` zeros (all zero above the first row).
    above: Vec<u8>,
    /// The row being filtered, after `PAD` zeros.
    row: Vec<u8>,
    /// By filter tried: its type byte, then the row filtered by it.
    filtered: [Vec<u8>; 4],
    path: FilterPath,
}

/// Which path rows take: the AVX2 one only where the CPU has been seen to have AVX2.
#[derive(Clone, Copy, Debug)]
pub struct FilterPath {
    avx2: bool,
}

impl FilterPath {
    /// A byte at a time, on any CPU.
    pub const PORTABLE: FilterPath = FilterPath { avx2: false };

    /// The fastest path this CPU has.
    pub fn detect() -> FilterPath {
        #[cfg(target_arch = "x86_64")]
        if std::is_x86_feature_detected!("avx2") {
            return FilterPath { avx2: true };
        }
        FilterPath::PORTABLE
    }
}

impl RowFilter {
    /// For rows of `width` RGB pixels.
    pub fn new(width: usize, path: FilterPath) -> RowFilter {
        let row_len = width * PIXEL_BYTES;
        let filtered = TRIED.map(|kind| {
            let mut bytes = vec![0; 1 + row_len];
            bytes[0] = kind;
            bytes
        });
        RowFilter {
            row_len,
            above: vec![0; PAD + row_len],
            row: vec![0; PAD + row_len],
            filtered,
            path,
        }
    }

    /// Filters the next row (`row_len` bytes): its filter-type byte, then its filtered bytes.
    pub fn filter(&mut self, row: &[u8]) -> &[u8] {
        assert_eq!(row.len(), self.row_len, "a whole row");
        self.row[PAD..].copy_from_slice(row);
        let costs = self.filter_all();
        std::mem::swap(&mut self.above, &mut self.row);
        &self.filtered[chosen(costs)]
    }

    /// Fills every `filtered` buffer; the sums of their magnitudes.
    fn filter_all(&mut self) -> [u64; 4] {
        let [up, sub, average, paeth] = &mut self.filtered;
        let outputs = [
            &mut up[1..],
            &mut sub[1..],
            &mut average[1..],
            &mut paeth[1..],
        ];
        let (row, above) = (&self.row[..], &self.above[..]);
        #[cfg(target_arch = "x86_64")]
        if self.path.avx2 {
            // SAFETY: `path` says the CPU has AVX2.
            return unsafe { filter_avx2(row, above, outputs) };
        }
        filter_bytes(row, above, outputs, 0)
    }
}

/// The filter the png crate's adaptive search takes, by index into `TRIED`.
fn chosen(costs: [u64; 4]) -> usize {
    let mut choice = 0;
    let mut least = u64::MAX;
    for (k, &cost) in costs.iter().enumerate() {
        if cost <= least {
            (choice, least) = (k, cost);
            if cost == 0 {
                break;
            }
        }
    }
    choice
}

/// The Paeth predictor of PNG: whichever of left `a`, above `b` and above-left `c` is nearest
/// a + b − c, preferring a, then b.
#[inline(always)]
fn paeth(a: u8, b: u8, c: u8) -> u8 {
    let (a16, b16, c16) = (i16::from(a), i16::from(b), i16::from(c));
    let p = a16 + b16 - c16;
    let (pa, pb, pc) = ((p - a16).abs(), (p - b16).abs(), (p - c16).abs());
    if pa <= pb && pa <= pc {
        a
    } else if pb <= pc {
        b
    } else {
        c
    }
}

/// A filtered byte's cost: its magnitude read as signed.
#[inline(always)]
fn magnitude(byte: u8) -> u64 {
    u64::from((byte as i8).unsigned_abs())
}

/// Filters the row's bytes from `from` on, a byte at a time; the sums of the magnitudes.
/// `row` and `above` start with `PAD` zeros.
fn filter_bytes(row: &[u8], above: &[u8], outputs: [&mut [u8]; 4], from: usize) -> [u64; 4] {
    let [up, sub, average, paeth_out] = outputs;
    let mut costs = [0u64; 4];
    for i in from..up.len() {
        let at = PAD + i;
        let (x, a, b, c) = (
            row[at],
            row[at - PIXEL_BYTES],
            above[at],
            above[at - PIXEL_BYTES],
        );
        let mean = ((u16::from(a) + u16::from(b)) / 2) as u8;
        let filtered = [
            x.wrapping_sub(b),
            x.wrapping_sub(a),
            x.wrapping_sub(mean),
            x.wrapping_sub(paeth(a, b, c)),
        ];
        (up[i], sub[i], average[i], paeth_out[i]) = filtered.into();
        for (cost, byte) in costs.iter_mut().zip(filtered) {
            *cost += magnitude(byte);
        }
    }
    costs
}

/// `filter_bytes` for the whole row, 32 bytes an instruction; the bytes past the last whole
/// 32 a byte at a time.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn filter_avx2(row: &[u8], above: &[u8], outputs: [&mut [u8]; 4]) -> [u64; 4] {
    use std::arch::x86_64::*;
    const LANES: usize = 32;
    let len = outputs[0].len();
    let whole = len / LANES * LANES;
    let zero = _mm256_setzero_si256();
    let mut sums = [zero; 4];
    let [up, sub, average, paeth_out] = outputs;
    for i in (0..whole).step_by(LANES) {
        let at = PAD + i;
        let load = |bytes: &[u8]| -> __m256i {
            let lane: &[u8; LANES] = bytes[..LANES].try_into().expect("32 bytes");
            // SAFETY: `lane` is 32 readable bytes; the load needs no alignment.
            unsafe { _mm256_loadu_si256(lane.as_ptr().cast()) }
        };
        let x = load(&row[at..]);
        let a = load(&row[at - PIXEL_BYTES..]);
        let b = load(&above[at..]);
        let c = load(&above[at - PIXEL_BYTES..]);
        let mean = _mm256_sub_epi8(
            _mm256_avg_epu8(a, b),
            _mm256_and_si256(_mm256_xor_si256(a, b), _mm256_set1_epi8(1)),
        );
        let filtered = [
            _mm256_sub_epi8(x, b),
            _mm256_sub_epi8(x, a),
            _mm256_sub_epi8(x, mean),
            _mm256_sub_epi8(x, paeth_lanes(a, b, c)),
        ];
        for ((out, sum), value) in [&mut *up, &mut *sub, &mut *average, &mut *paeth_out]
            .into_iter()
            .zip(&mut sums)
            .zip(filtered)
        {
            let lane: &mut [u8; LANES] = (&mut out[i..i + LANES]).try_into().expect("32 bytes");
            // SAFETY: `lane` is 32 writable bytes; the store needs no alignment.
            unsafe { _mm256_storeu_si256(lane.as_mut_ptr().cast(), value) };
            *sum = _mm256_add_epi64(*sum, _mm256_sad_epu8(_mm256_abs_epi8(value), zero));
        }
    }
    let rest = filter_bytes(row, above, [up, sub, average, paeth_out], whole);
    let mut costs = [0u64; 4];
    for ((cost, sum), rest) in costs.iter_mut().zip(sums).zip(rest) {
        let mut parts = [0u64; 4];
        // SAFETY: `parts` is 32 writable bytes; the store needs no alignment.
        unsafe { _mm256_storeu_si256(parts.as_mut_ptr().cast(), sum) };
        *cost = parts.iter().sum::<u64>() + rest;
    }
    costs
}

/// `paeth` on 32 lanes of bytes, without widening: |b − c| and |a − c| are differences of
/// maxima and minima, and |a + b − 2c| is their sum where a − c and b − c share a sign (which
/// may saturate at 255 without changing a comparison with either), else their difference.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn paeth_lanes(
    a: std::arch::x86_64::__m256i,
    b: std::arch::x86_64::__m256i,
    c: std::arch::x86_64::__m256i,
) -> std::arch::x86_64::__m256i {
    use std::arch::x86_64::*;
    let distance = |x, y| _mm256_sub_epi8(_mm256_max_epu8(x, y), _mm256_min_epu8(x, y));
    let at_most = |x, y| _mm256_cmpeq_epi8(_mm256_min_epu8(x, y), x);
    let (pa, pb) = (distance(b, c), distance(a, c));
    let a_not_below_c = at_most(c, a);
    let b_not_below_c = at_most(c, b);
    let same_side = _mm256_cmpeq_epi8(a_not_below_c, b_not_below_c);
    let pc = _mm256_blendv_epi8(distance(pa, pb), _mm256_adds_epu8(pa, pb), same_side);
    let take_a = _mm256_and_si256(at_most(pa, pb), at_most(pa, pc));
    let b_or_c = _mm256_blendv_epi8(c, b, at_most(pb, pc));
    _mm256_blendv_epi8(b_or_c, a, take_a)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rows of every kind a filter choice turns on: noise, smooth ramps, flat runs (costs of
    /// zero, ties), and widths either side of whole 32-byte lanes.
    fn rows(width: usize, height: usize, seed: u32) -> Vec<Vec<u8>> {
        let mut state = seed.wrapping_mul(2_654_435_761).max(1);
        let mut noise = move || {
            state ^= state << 13;
            state ^= state >> 17;
            state ^= state << 5;
            state
        };
        (0..height)
            .map(|y| {
                (0..width * PIXEL_BYTES)
                    .map(|i| match (y + seed as usize) % 5 {
                        0 => noise() as u8,
                        1 => (i / 3 + y) as u8,
                        2 => 7,
                        3 => ((i * y) % 251) as u8 ^ (noise() % 4) as u8,
                        _ => {
                            if i % 9 < 4 {
                                255
                            } else {
                                0
                            }
                        }
                    })
                    .collect()
            })
            .collect()
    }

    /// The png crate's own adaptive filtering of the rows: each row's type byte and filtered
    /// bytes, read back from its file.
    fn png_crate_filtered(width: usize, rows: &[Vec<u8>]) -> Vec<u8> {
        let mut file = Vec::new();
        let mut encoder = png::Encoder::new(&mut file, width as u32, rows.len() as u32);
        encoder.set_color(png::ColorType::Rgb);
        encoder.set_filter(png::Filter::Adaptive);
        encoder.set_deflate_compression(png::DeflateCompression::Level(1));
        let mut writer = encoder.write_header().unwrap();
        writer.write_image_data(&rows.concat()).unwrap();
        writer.finish().unwrap();
        inflated_image_data(&file)
    }

    /// The image data of a PNG, inflated: every row's type byte and filtered bytes.
    fn inflated_image_data(file: &[u8]) -> Vec<u8> {
        let mut zlib = Vec::new();
        let mut at = 8;
        while at + 8 <= file.len() {
            let len = u32::from_be_bytes(file[at..at + 4].try_into().unwrap()) as usize;
            if &file[at + 4..at + 8] == b"IDAT" {
                zlib.extend_from_slice(&file[at + 8..at + 8 + len]);
            }
            at += 12 + len;
        }
        fdeflate::decompress_to_vec(&zlib).unwrap()
    }

    #[test]
    fn rows_are_filtered_as_the_png_crate_filters_them() {
        for width in [1, 2, 10, 11, 21, 22, 64, 100] {
            for seed in 0..5 {
                let rows = rows(width, 12, seed);
                let expected = png_crate_filtered(width, &rows);
                for path in [FilterPath::PORTABLE, FilterPath::detect()] {
                    let mut filter = RowFilter::new(width, path);
                    let ours: Vec<u8> = rows
                        .iter()
                        .flat_map(|r| filter.filter(r).to_vec())
                        .collect();
                    assert!(
                        ours == expected,
                        "width {width}, seed {seed}, {path:?}\n{ours:?}\n{expected:?}\n{rows:?}"
                    );
                }
            }
        }
    }

    #[test]
    fn the_paeth_lanes_predict_as_the_definition_for_every_neighbourhood() {
        #[cfg(target_arch = "x86_64")]
        if FilterPath::detect().avx2 {
            use std::arch::x86_64::*;
            // Every (a, b) pair against a spread of c, 32 at a time.
            let cs: Vec<u8> = (0..=255).step_by(3).chain([1, 127, 128, 254]).collect();
            for &c in &cs {
                for a in 0..=255u8 {
                    let bs: Vec<u8> = (0..=255).collect();
                    for b32 in bs.chunks(32) {
                        let load = |v: &[u8; 32]| unsafe { _mm256_loadu_si256(v.as_ptr().cast()) };
                        let b: [u8; 32] = b32.try_into().unwrap();
                        // SAFETY: the test runs this only where the CPU has AVX2.
                        let got = unsafe { paeth_lanes(load(&[a; 32]), load(&b), load(&[c; 32])) };
                        let mut out = [0u8; 32];
                        unsafe { _mm256_storeu_si256(out.as_mut_ptr().cast(), got) };
                        for (k, &b) in b.iter().enumerate() {
                            assert_eq!(out[k], paeth(a, b, c), "a {a}, b {b}, c {c}");
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn the_search_takes_the_last_least_cost_and_stops_at_the_first_zero() {
        assert_eq!(chosen([5, 3, 3, 4]), 2);
        assert_eq!(chosen([0, 0, 0, 0]), 0);
        assert_eq!(chosen([9, 0, 0, 5]), 1);
        assert_eq!(chosen([2, 2, 2, 2]), 3);
    }
}
