//! Ordered (Bayer) dithering thresholds.
//!
//! A threshold in (0, 1) per pixel position; a colour that lies a fraction `t` of the way from one palette
//! entry to the next takes the farther entry where `threshold < t`. Over any 8×8 tile a flat colour then
//! mixes the two entries in the right proportion, without the crawling noise error diffusion shows in motion.

const BAYER8: [[u8; 8]; 8] = [
    [0, 32, 8, 40, 2, 34, 10, 42],
    [48, 16, 56, 24, 50, 18, 58, 26],
    [12, 44, 4, 36, 14, 46, 6, 38],
    [60, 28, 52, 20, 62, 30, 54, 22],
    [3, 35, 11, 43, 1, 33, 9, 41],
    [51, 19, 59, 27, 49, 17, 57, 25],
    [15, 47, 7, 39, 13, 45, 5, 37],
    [63, 31, 55, 23, 61, 29, 53, 21],
];

/// The threshold at pixel (x, y) scaled to 0..=255 exclusive of both ends' meaning: values are
/// `(rank + 0.5) * 4`, i.e. 2, 6, …, 254, so a fraction of exactly 0 never moves and of 255 always does.
pub fn threshold_u8(x: usize, y: usize) -> u8 {
    BAYER8[y % 8][x % 8] * 4 + 2
}
