//! Sixel images: a palette of at most 256 colours chosen for the frame, the picture dithered onto
//! it, raster attributes giving square pixels and the exact size, bands of six rows run-length
//! encoded colour by colour.

use crate::palette::{Precision, indexed};
use std::fmt::Write as _;

/// The sixel sequence that draws `rgb` (`width` × `height` pixels, 3 bytes each) from the
/// cursor.
pub fn image(rgb: &[u8], width: u32, height: u32) -> Vec<u8> {
    let (width, height) = (width as usize, height as usize);
    assert_eq!(rgb.len(), width * height * 3, "3 bytes a pixel");
    let picture = indexed(rgb, width, Precision::Coarse);
    // P2 = 1: pixels no colour is set for keep what was there (there are none).
    let mut out = format!("\x1bP0;1;0q\"1;1;{width};{height}");
    for (index, colour) in picture.palette.iter().enumerate() {
        let percent = |c: u8| (u32::from(c) * 100 + 127) / 255;
        let (r, g, b) = (percent(colour[0]), percent(colour[1]), percent(colour[2]));
        let _ = write!(out, "#{index};2;{r};{g};{b}");
    }
    let mut out = out.into_bytes();
    let mut band = Band::new(width, picture.palette.len());
    for top in (0..height).step_by(6) {
        let rows = (height - top).min(6);
        band.fill(
            &picture.indices[top * width..(top + rows) * width],
            width,
            rows,
        );
        band.write(&mut out);
        out.push(b'-');
    }
    out.extend_from_slice(b"\x1b\\");
    out
}

/// Six rows of palette indices as each colour's sixels.
struct Band {
    width: usize,
    /// Per colour, per column: the six bits of the rows that have that colour.
    bits: Vec<u8>,
    /// Per colour: the first and last column it is in, if any.
    spans: Vec<Option<(usize, usize)>>,
}

impl Band {
    fn new(width: usize, colours: usize) -> Band {
        Band {
            width,
            bits: vec![0; width * colours],
            spans: vec![None; colours],
        }
    }

    fn fill(&mut self, indices: &[u8], width: usize, rows: usize) {
        self.bits.fill(0);
        self.spans.fill(None);
        for row in 0..rows {
            for (x, &index) in indices[row * width..(row + 1) * width].iter().enumerate() {
                let colour = usize::from(index);
                self.bits[colour * self.width + x] |= 1 << row;
                let span = self.spans[colour].get_or_insert((x, x));
                span.0 = span.0.min(x);
                span.1 = span.1.max(x);
            }
        }
    }

    /// Each colour of the band over its span (`#n`, the sixels, `$` back to the band's start).
    fn write(&self, out: &mut Vec<u8>) {
        for (colour, span) in self.spans.iter().enumerate() {
            let Some((first, last)) = *span else {
                continue;
            };
            out.extend_from_slice(format!("#{colour}").as_bytes());
            let row = &self.bits[colour * self.width..(colour + 1) * self.width];
            run_length(out, &row[..first], true);
            run_length(out, &row[first..=last], false);
            out.push(b'$');
        }
    }
}

/// Sixels for `bits`, repeats as `!count`; `blank` writes them all as empty (leading columns).
fn run_length(out: &mut Vec<u8>, bits: &[u8], blank: bool) {
    let mut x = 0;
    while x < bits.len() {
        let value = if blank { 0 } else { bits[x] };
        let run = match blank {
            true => bits.len(),
            false => bits[x..].iter().take_while(|&&b| b == value).count(),
        };
        let sixel = b'?' + value;
        if run > 3 {
            out.extend_from_slice(format!("!{run}").as_bytes());
            out.push(sixel);
        } else {
            out.extend(std::iter::repeat_n(sixel, run));
        }
        x += run;
    }
}
