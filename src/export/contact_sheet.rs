//! The gallery's contact sheet: every still as a labelled thumbnail in one grid, scaled with
//! tiny-skia's filtered pixmap drawing (bicubic) so thumbnails do not alias.

use super::{PngStill, metadata::SOFTWARE};
use crate::Error;
use crate::label_font::{GLYPH_HEIGHT, text_pixels, text_width};
use crate::memory_budget::size_words;
use crate::still::MAX_SIDE;
use crate::still::RowSink;
use std::path::Path;
use tiny_skia::{Color, FilterQuality, IntSize, Pixmap, PixmapPaint, Transform};

/// One picture for the sheet: 8-bit sRGB rows.
pub struct SheetPicture {
    pub label: String,
    pub width: u32,
    pub height: u32,
    pub rgb: Vec<u8>,
}

/// The sheet's layout: thumbnail size and columns.
#[derive(Clone, Copy, Debug)]
pub struct SheetLayout {
    pub thumbnail: (u32, u32),
    pub columns: u32,
}

const GAP: u32 = 8;
const LABEL_SCALE: u32 = 2;
/// Rows of label text under a thumbnail: a long name wraps at its hyphens instead of shrinking.
const LABEL_LINES: u32 = 2;
const LINE_HEIGHT: u32 = GLYPH_HEIGHT * LABEL_SCALE + 4;
const LABEL_HEIGHT: u32 = LINE_HEIGHT * LABEL_LINES + 4;

/// The sheet being drawn: each picture is placed as soon as it is rendered, so the gallery holds
/// the sheet and one still, never every still at once.
pub struct ContactSheet {
    pixmap: Pixmap,
    layout: SheetLayout,
}

impl ContactSheet {
    /// An empty sheet for `count` pictures of `picture` size, or why it cannot be made: a side
    /// over `MAX_SIDE`, or more memory than the budget (the sheet, and one picture read back to
    /// be placed), checked before anything is allocated.
    pub fn new(
        count: usize,
        layout: SheetLayout,
        picture: (u32, u32),
    ) -> Result<ContactSheet, String> {
        let (tw, th) = layout.thumbnail;
        let columns = u64::from(layout.columns.clamp(1, count.max(1) as u32));
        let rows = (count as u64).div_ceil(columns).max(1);
        let width = columns * u64::from(tw + GAP) + u64::from(GAP);
        let height = rows * u64::from(th + LABEL_HEIGHT + GAP) + u64::from(GAP);
        let side = u64::from(MAX_SIDE);
        if width > side || height > side {
            return Err(format!(
                "the contact sheet would be {width}×{height}, over the {MAX_SIDE}×{MAX_SIDE} \
                 limit; use a smaller --thumbnail or fewer --columns"
            ));
        }
        // RGBA while drawing and RGB rows while writing; a picture as RGB and as RGBA.
        let bytes = (width * height + u64::from(picture.0) * u64::from(picture.1)) * 7;
        let budget = crate::memory_budget::budget_bytes();
        if bytes > budget {
            return Err(format!(
                "the contact sheet and a still read back onto it would take {}, over the {} \
                 memory budget; use a smaller --thumbnail or --size, or raise {}",
                size_words(bytes),
                size_words(budget),
                crate::memory_budget::MEMORY_BUDGET_VAR
            ));
        }
        let mut pixmap =
            Pixmap::new(width as u32, height as u32).ok_or("the contact sheet cannot be made")?;
        pixmap.fill(Color::from_rgba8(24, 24, 24, 255));
        let layout = SheetLayout {
            columns: columns as u32,
            ..layout
        };
        Ok(ContactSheet { pixmap, layout })
    }

    /// Draws picture `index` (row by row, `columns` across) with its label under it.
    pub fn place(&mut self, index: usize, picture: &SheetPicture) {
        let (tw, th) = self.layout.thumbnail;
        let columns = self.layout.columns;
        let cell = (tw + GAP, th + LABEL_HEIGHT + GAP);
        let (col, row) = (index as u32 % columns, index as u32 / columns);
        let (x, y) = (GAP + col * cell.0, GAP + row * cell.1);
        draw_thumbnail(&mut self.pixmap, picture, (x, y), (tw, th));
        draw_label(&mut self.pixmap, &picture.label, (x, y + th + 4), tw);
    }

    /// Writes the sheet as an RGB PNG, whole or not at all.
    pub fn write(&self, path: &Path) -> Result<(), Error> {
        let sheet = &self.pixmap;
        let rgb: Vec<u8> = sheet
            .data()
            .chunks_exact(4)
            .flat_map(|p| [p[0], p[1], p[2]])
            .collect();
        let mut png = PngStill::create(
            path,
            (sheet.width(), sheet.height()),
            &[(SOFTWARE, crate::PROGRAM.to_string())],
        )?;
        png.write_rows(&rgb).map_err(|e| Error::write(path, e))?;
        png.finish()
    }

    pub fn size(&self) -> (u32, u32) {
        (self.pixmap.width(), self.pixmap.height())
    }
}

/// Scales `picture` to fit `size` (keeping its aspect) and centres it in the box at `at`.
fn draw_thumbnail(sheet: &mut Pixmap, picture: &SheetPicture, at: (u32, u32), size: (u32, u32)) {
    let Some(source) = rgba_pixmap(picture) else {
        return;
    };
    let scale = (size.0 as f32 / picture.width as f32).min(size.1 as f32 / picture.height as f32);
    let drawn = (picture.width as f32 * scale, picture.height as f32 * scale);
    let left = at.0 as f32 + (size.0 as f32 - drawn.0) / 2.0;
    let top = at.1 as f32 + (size.1 as f32 - drawn.1) / 2.0;
    let paint = PixmapPaint {
        quality: FilterQuality::Bicubic,
        ..PixmapPaint::default()
    };
    let transform = Transform::from_row(scale, 0.0, 0.0, scale, left, top);
    sheet.draw_pixmap(0, 0, source.as_ref(), &paint, transform, None);
}

fn rgba_pixmap(picture: &SheetPicture) -> Option<Pixmap> {
    let rgba = picture
        .rgb
        .chunks_exact(3)
        .flat_map(|p| [p[0], p[1], p[2], 255])
        .collect();
    Pixmap::from_vec(rgba, IntSize::from_wh(picture.width, picture.height)?)
}

/// The label centred under its thumbnail, at full size: wrapped at hyphens onto `LABEL_LINES`
/// lines, and only what still does not fit cut (marked `..`).
fn draw_label(sheet: &mut Pixmap, label: &str, at: (u32, u32), width: u32) {
    let (sheet_w, sheet_h) = (sheet.width(), sheet.height());
    let data = sheet.data_mut();
    for (row, line) in label_lines(label, width).iter().enumerate() {
        let top = at.1 + row as u32 * LINE_HEIGHT;
        let left = at.0 + (width.saturating_sub(text_width(line, LABEL_SCALE))) / 2;
        for (dx, dy) in text_pixels(line, LABEL_SCALE) {
            let (x, y) = (left + dx, top + dy);
            if x < sheet_w && y < sheet_h {
                let i = 4 * (y * sheet_w + x) as usize;
                data[i..i + 4].copy_from_slice(&[230, 230, 230, 255]);
            }
        }
    }
}

/// `label` in lines of at most `width` pixels at `LABEL_SCALE`, broken after hyphens and spaces;
/// a line the words still do not fit (past `LABEL_LINES`, or one long word) is cut, ending in
/// `..`.
fn label_lines(label: &str, width: u32) -> Vec<String> {
    let fits = |text: &str| text_width(text.trim_end(), LABEL_SCALE) <= width;
    let mut lines: Vec<String> = vec![String::new()];
    for word in label.split_inclusive(['-', ' ']) {
        let last = lines.last_mut().expect("one line at least");
        if fits(&format!("{last}{word}")) || last.is_empty() {
            last.push_str(word);
        } else {
            lines.push(word.to_string());
        }
    }
    if lines.len() > LABEL_LINES as usize {
        let rest = lines.split_off(LABEL_LINES as usize - 1).concat();
        lines.push(rest);
    }
    for line in &mut lines {
        line.truncate(line.trim_end().len());
    }
    for line in lines.iter_mut().filter(|line| !fits(line)) {
        while !line.is_empty() && !fits(&format!("{line}..")) {
            line.pop();
        }
        line.push_str("..");
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_names_wrap_at_hyphens_at_full_size() {
        let width = 240;
        assert_eq!(label_lines("plane-dimples", width), vec!["plane-dimples"]);
        let lines = label_lines("sphere-on-plane-dots-and-dimples", width);
        assert_eq!(lines.len(), 2, "{lines:?}");
        assert_eq!(lines.concat(), "sphere-on-plane-dots-and-dimples");
        assert!(
            lines.iter().all(|l| text_width(l, LABEL_SCALE) <= width),
            "{lines:?}"
        );
        assert_eq!(
            label_lines("period=10 strength=2", width),
            ["period=10 strength=2"]
        );
        let values = label_lines("period=10.5 strength=0.25 octaves=4", width);
        assert_eq!(values[0], "period=10.5");
        assert!(values[1].starts_with("strength=0.25 oct"), "{values:?}");
        let long = "a-very-long-name-that-goes-on-and-on-past-two-lines-of-text";
        let lines = label_lines(long, width);
        assert_eq!(lines.len(), 2, "{lines:?}");
        assert!(lines[1].ends_with(".."), "{lines:?}");
        assert!(
            lines.iter().all(|l| text_width(l, LABEL_SCALE) <= width),
            "{lines:?}"
        );
    }
}
