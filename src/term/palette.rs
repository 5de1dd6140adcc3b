//! The sRGB values of the terminal palettes the quantisers target.

/// The 16 ANSI colours as xterm draws them by default. Real terminals theme these; the values are a
/// reasonable guess of what an index will look like, which is all the quantiser can know.
pub const ANSI16: [[u8; 3]; 16] = [
    [0, 0, 0],
    [205, 0, 0],
    [0, 205, 0],
    [205, 205, 0],
    [0, 0, 238],
    [205, 0, 205],
    [0, 205, 205],
    [229, 229, 229],
    [127, 127, 127],
    [255, 0, 0],
    [0, 255, 0],
    [255, 255, 0],
    [92, 92, 255],
    [255, 0, 255],
    [0, 255, 255],
    [255, 255, 255],
];

/// The six channel levels of the xterm 6×6×6 colour cube (indices 16..232).
pub const CUBE_LEVELS: [u8; 6] = [0, 95, 135, 175, 215, 255];

/// First palette index of the 24-step grey ramp (232..256: 8, 18, …, 238).
pub const GREY_RAMP_START: u8 = 232;

/// The palette index of cube cell (r, g, b), each 0..6.
pub fn cube_index(r: usize, g: usize, b: usize) -> u8 {
    (16 + 36 * r + 6 * g + b) as u8
}

/// The grey value of ramp step `k` (0..24).
pub fn grey_ramp_level(k: usize) -> u8 {
    (8 + 10 * k) as u8
}

/// The sRGB colour xterm shows for a 256-colour palette index.
pub fn xterm256_rgb(index: u8) -> [u8; 3] {
    let i = index as usize;
    match index {
        0..=15 => ANSI16[i],
        16..=231 => {
            let c = i - 16;
            [
                CUBE_LEVELS[c / 36],
                CUBE_LEVELS[(c / 6) % 6],
                CUBE_LEVELS[c % 6],
            ]
        }
        _ => {
            let g = grey_ramp_level(i - GREY_RAMP_START as usize);
            [g, g, g]
        }
    }
}

/// Channel weights for comparing sRGB colours, towards green and away from red as the eye is (the
/// low-red branch of the "redmean" approximation): cheap and "perceptual enough" between palette entries.
pub const WEIGHTS: [i32; 3] = [2, 4, 3];
