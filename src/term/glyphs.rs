//! The block glyph sets: how a cell is cut into sub-pixels and which character draws each fg/bg pattern.
//!
//! Sub-pixels are numbered row-major inside the cell (half: top, bottom; quadrant: TL, TR, BL, BR;
//! sextant: TL, TR, ML, MR, BL, BR) and a *mask* has bit `i` set where sub-pixel `i` shows the foreground.

/// How a cell is divided into sub-pixels.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum GlyphSet {
    /// `▀` with fg = top, bg = bottom: 1×2 square pixels per cell, exact colours. Works everywhere.
    #[default]
    HalfBlock,
    /// 2×2 sub-pixels (`▘▝▀▖▌▞▛▗▚▐▜▄▙▟█`), two colours per cell: finer edges, pixels twice as tall as wide.
    Quadrant,
    /// 2×3 sub-pixels (Unicode 13 sextants, U+1FB00…), two colours per cell; needs a font that has them.
    Sextant,
}

const HALF: [char; 4] = [' ', '▀', '▄', '█'];

const QUADRANT: [char; 16] = [
    ' ', '▘', '▝', '▀', '▖', '▌', '▞', '▛', '▗', '▚', '▐', '▜', '▄', '▙', '▟', '█',
];

const SEXTANT_LEFT_COLUMN: u8 = 0b01_0101;
const SEXTANT_RIGHT_COLUMN: u8 = 0b10_1010;
const SEXTANT_FULL: u8 = 0b11_1111;

impl GlyphSet {
    /// Sub-pixels per cell, across and down.
    pub fn cell_pixels(self) -> (usize, usize) {
        match self {
            GlyphSet::HalfBlock => (1, 2),
            GlyphSet::Quadrant => (2, 2),
            GlyphSet::Sextant => (2, 3),
        }
    }

    /// The picture size in pixels that fills `cols × rows` cells exactly.
    pub fn picture_size(self, cols: usize, rows: usize) -> (usize, usize) {
        let (w, h) = self.cell_pixels();
        (cols * w, rows * h)
    }

    /// Width / height of one sub-pixel, for a cell twice as tall as wide: renderers scale x by this to
    /// keep circles round.
    pub fn pixel_aspect(self) -> f32 {
        let (w, h) = self.cell_pixels();
        (2.0 / h as f32) / (1.0 / w as f32)
    }

    /// Number of sub-pixels in a cell.
    pub fn pixel_count(self) -> usize {
        let (w, h) = self.cell_pixels();
        w * h
    }

    /// The glyph whose foreground covers exactly the sub-pixels in `mask`.
    pub fn glyph(self, mask: u8) -> char {
        match self {
            GlyphSet::HalfBlock => HALF[mask as usize & 3],
            GlyphSet::Quadrant => QUADRANT[mask as usize & 15],
            GlyphSet::Sextant => sextant_glyph(mask & SEXTANT_FULL),
        }
    }

    /// The mask drawn by `glyph` in this set, if the glyph belongs to it.
    pub fn mask(self, glyph: char) -> Option<u8> {
        match self {
            GlyphSet::HalfBlock => HALF.iter().position(|&g| g == glyph).map(|m| m as u8),
            GlyphSet::Quadrant => QUADRANT.iter().position(|&g| g == glyph).map(|m| m as u8),
            GlyphSet::Sextant => sextant_mask(glyph),
        }
    }
}

fn sextant_glyph(mask: u8) -> char {
    match mask {
        0 => ' ',
        SEXTANT_LEFT_COLUMN => '▌',
        SEXTANT_RIGHT_COLUMN => '▐',
        SEXTANT_FULL => '█',
        // The block skips the three patterns that older blocks already had.
        m => {
            let skipped = (m > SEXTANT_LEFT_COLUMN) as u32 + (m > SEXTANT_RIGHT_COLUMN) as u32;
            char::from_u32(0x1FB00 + m as u32 - 1 - skipped).unwrap_or('?')
        }
    }
}

fn sextant_mask(glyph: char) -> Option<u8> {
    match glyph {
        ' ' => Some(0),
        '▌' => Some(SEXTANT_LEFT_COLUMN),
        '▐' => Some(SEXTANT_RIGHT_COLUMN),
        '█' => Some(SEXTANT_FULL),
        '\u{1FB00}'..='\u{1FB3B}' => {
            let mut m = (glyph as u32 - 0x1FB00 + 1) as u8;
            if m >= SEXTANT_LEFT_COLUMN {
                m += 1;
            }
            if m >= SEXTANT_RIGHT_COLUMN {
                m += 1;
            }
            Some(m)
        }
        _ => None,
    }
}

/// The glyph that draws the opposite sub-pixels of `glyph` (so `glyph` with fg/bg swapped looks the same),
/// for every block glyph of the three sets; `None` for any other character.
pub fn complement(glyph: char) -> Option<char> {
    // The quadrant set contains the half blocks, with the same complements.
    [GlyphSet::Quadrant, GlyphSet::Sextant]
        .into_iter()
        .find_map(|set| {
            let full = (1u8 << set.pixel_count()) - 1;
            set.mask(glyph).map(|m| set.glyph(full ^ m))
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sextant_table_covers_the_unicode_block_once() {
        let glyphs: Vec<char> = (0..64).map(|m| GlyphSet::Sextant.glyph(m)).collect();
        assert_eq!(glyphs[1], '\u{1FB00}');
        assert_eq!(glyphs[62], '\u{1FB3B}');
        let mut unique = glyphs.clone();
        unique.sort();
        unique.dedup();
        assert_eq!(unique.len(), 64);
    }

    #[test]
    fn complements_pair_up() {
        assert_eq!(complement('▀'), Some('▄'));
        assert_eq!(complement('▘'), Some('▟'));
        assert_eq!(complement(' '), Some('█'));
        assert_eq!(complement('▌'), Some('▐'));
        assert_eq!(complement('a'), None);
        for m in 0..64 {
            let g = GlyphSet::Sextant.glyph(m);
            assert_eq!(GlyphSet::Sextant.mask(g), Some(m));
            assert_eq!(complement(complement(g).unwrap()), Some(g));
        }
    }
}
