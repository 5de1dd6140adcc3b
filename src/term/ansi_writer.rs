//! The fast path to the screen: a cell grid as escape sequences, only the cells that changed since the
//! grid last shown, inside one synchronized-output update.

use std::io::{self, Write};

use super::cell::{Cell, CellGrid};
use super::color::Color;
use super::cursor::{Cursor, move_cost, move_to};
use super::glyphs::complement;
use super::sgr::{Need, Pen, RESET, push_decimal};

/// Asks the terminal to hold the screen until the end mark, so a frame never shows half drawn.
/// Terminals that do not know mode 2026 ignore it.
pub const SYNC_BEGIN: &[u8] = b"\x1b[?2026h";
pub const SYNC_END: &[u8] = b"\x1b[?2026l";

/// Where and how [`encode_frame`] draws.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FrameOptions {
    /// Screen cell (column, row), 0-based, of the grid's top-left cell.
    pub origin: (u16, u16),
    /// Draw runs of identical solid cells as one space and REP (`ESC[nb`, repeat the last character):
    /// far fewer bytes for flat areas. xterm, VTE, kitty, foot and tmux know it (tmux only after an ASCII
    /// character, hence spaces only), but not every terminal (the Linux console, older ones), so it is
    /// off unless the terminal is known to support it (terminfo `rep`).
    pub repeat: bool,
}

/// Appends to `out` what turns the screen from `previous` (`None`: unknown, redraw all) into `next`.
/// Writes nothing when nothing changed. Leaves the colours reset to the defaults, so other drawing is
/// not tinted.
pub fn encode_frame(
    previous: Option<&CellGrid>,
    next: &CellGrid,
    options: FrameOptions,
    out: &mut Vec<u8>,
) {
    encode_rows(previous, next, options, out, None);
}

/// What ends a frame cut short at one of its [`FrameWriter::cut_points`]: default colours, and
/// the end of the synchronized update.
pub const CUT_FRAME_END: &[u8] = b"\x1b[m\x1b[?2026l";

/// [`encode_frame`], noting in `row_starts` where in `out` each row with a change begins
/// (offset, row).
fn encode_rows(
    previous: Option<&CellGrid>,
    next: &CellGrid,
    options: FrameOptions,
    out: &mut Vec<u8>,
    mut row_starts: Option<&mut Vec<(usize, usize)>>,
) {
    let previous = previous.filter(|p| p.cols() == next.cols() && p.rows() == next.rows());
    let changed =
        |x: usize, y: usize| previous.is_none_or(|p| !p.get(x, y).looks_same(next.get(x, y)));
    let mut frame = FrameState {
        pen: Pen::default(),
        cursor: None,
        origin: options.origin,
        out,
    };
    let start = frame.out.len();
    frame.out.extend_from_slice(SYNC_BEGIN);
    let mut drew = false;
    for y in 0..next.rows() {
        let row = next.row(y);
        let mut x = 0;
        let mut drew_row = false;
        while x < row.len() {
            if !changed(x, y) {
                x += 1;
                continue;
            }
            if let Some(starts) = row_starts.as_deref_mut().filter(|_| !drew_row) {
                starts.push((frame.out.len(), y));
            }
            drew_row = true;
            frame.go_to(row, x, y);
            let run = || {
                row[x + 1..]
                    .iter()
                    .enumerate()
                    .take_while(|&(i, c)| changed(x + 1 + i, y) && c.looks_same(row[x]))
                    .count()
            };
            let run = if options.repeat { run() } else { 0 };
            if frame.repeating_is_shorter(row[x], run) {
                frame.draw_space(row[x].canonical().bg);
                frame.repeat(run, x + 1 + run == row.len());
                x += 1 + run;
            } else {
                frame.draw(row[x], x + 1 == row.len());
                x += 1;
            }
        }
        drew |= drew_row;
    }
    if !drew {
        frame.out.truncate(start);
        return;
    }
    if frame.pen
        != (Pen {
            fg: Some(Color::Default),
            bg: Some(Color::Default),
        })
    {
        frame.out.extend_from_slice(RESET);
    }
    frame.out.extend_from_slice(SYNC_END);
}

/// A frame's bytes without its synchronized-update brackets.
fn unwrapped(frame: &[u8]) -> &[u8] {
    let inner = frame.strip_prefix(SYNC_BEGIN).unwrap_or(frame);
    inner.strip_suffix(SYNC_END).unwrap_or(inner)
}

fn repeat_len(count: usize) -> usize {
    if count == 0 {
        return usize::MAX; // nothing to repeat: never worth it
    }
    b"\x1b[b".len()
        + if count == 1 {
            0
        } else {
            count.to_string().len()
        }
}

struct FrameState<'a> {
    pen: Pen,
    cursor: Option<Cursor>,
    origin: (u16, u16),
    out: &'a mut Vec<u8>,
}

impl FrameState<'_> {
    /// Moves to cell `x` of grid row `y`, by reprinting the unchanged cells in between when that is
    /// shorter than a cursor move and needs no colour change.
    fn go_to(&mut self, row: &[Cell], x: usize, y: usize) {
        let (screen_row, screen_col) = (self.origin.1 + y as u16, self.origin.0 + x as u16);
        let move_bytes = move_cost(self.cursor, screen_row, screen_col);
        if let Some(gap) = self.gap_from_cursor(screen_row, screen_col) {
            let start = x - gap;
            let reprint: Option<usize> =
                row[start..x].iter().map(|&c| self.free_glyph_len(c)).sum();
            if reprint.is_some_and(|bytes| bytes < move_bytes) {
                for &cell in &row[start..x] {
                    self.draw(cell, false);
                }
                return;
            }
        }
        move_to(self.cursor, screen_row, screen_col, self.out);
        self.cursor = Some(Cursor {
            row: screen_row,
            col: Some(screen_col),
        });
    }

    /// Cells between the cursor and the target on the same row, if the cursor is before it there.
    fn gap_from_cursor(&self, screen_row: u16, screen_col: u16) -> Option<usize> {
        let cursor = self.cursor.filter(|c| c.row == screen_row)?;
        let col = cursor.col.filter(|&c| c < screen_col)?;
        Some((screen_col - col) as usize)
    }

    /// The glyph bytes of `cell` if the pen can draw it without any colour change.
    fn free_glyph_len(&self, cell: Cell) -> Option<usize> {
        forms(cell)
            .into_iter()
            .flatten()
            .find(|(_, need)| self.pen.cost(*need) == 0)
            .map(|(glyph, _)| glyph.len_utf8())
    }

    /// Whether `cell` and `run` more like it are shorter as a space and REP than written out. Only
    /// spaces are repeated: tmux 3.3 ignores REP after a non-ASCII character.
    fn repeating_is_shorter(&self, cell: Cell, run: usize) -> bool {
        let canonical = cell.canonical();
        if canonical.glyph != ' ' || run == 0 {
            return false;
        }
        let space = Need {
            fg: None,
            bg: Some(canonical.bg),
        };
        let repeated = self.pen.cost(space) + 1 + repeat_len(run);
        let (glyph, need) = self.cheapest_form(cell);
        let written = self.pen.cost(need) + (1 + run) * glyph.len_utf8();
        repeated < written
    }

    /// Draws a space in background `bg`, never the equivalent `█`, so that REP can repeat it.
    fn draw_space(&mut self, bg: Color) {
        self.pen.apply(
            Need {
                fg: None,
                bg: Some(bg),
            },
            self.out,
        );
        self.out.push(b' ');
        self.advance(1, false);
    }

    /// Draws `cell` at the cursor in whichever equivalent form costs the fewest bytes from the current
    /// pen.
    fn draw(&mut self, cell: Cell, last_column: bool) {
        let (glyph, need) = self.cheapest_form(cell);
        self.pen.apply(need, self.out);
        let mut utf8 = [0u8; 4];
        self.out
            .extend_from_slice(glyph.encode_utf8(&mut utf8).as_bytes());
        self.advance(1, last_column);
    }

    /// The equivalent form of `cell` that costs the fewest bytes from the current pen.
    fn cheapest_form(&self, cell: Cell) -> (char, Need) {
        let cheapest = forms(cell)
            .into_iter()
            .flatten()
            .min_by_key(|(glyph, need)| self.pen.cost(*need) + glyph.len_utf8());
        cheapest.unwrap_or((
            cell.glyph,
            Need {
                fg: Some(cell.fg),
                bg: Some(cell.bg),
            },
        ))
    }

    /// Repeats the last glyph `count` more times.
    fn repeat(&mut self, count: usize, reaches_last_column: bool) {
        self.out.extend_from_slice(b"\x1b[");
        if count > 1 {
            push_decimal(count as u32, self.out);
        }
        self.out.push(b'b');
        self.advance(count, reaches_last_column);
    }

    fn advance(&mut self, cells: usize, reaches_last_column: bool) {
        if let Some(cursor) = &mut self.cursor {
            // After the grid's last column the terminal may hold a pending wrap: the column is not known.
            let col = cursor.col.filter(|_| !reaches_last_column);
            cursor.col = col.map(|c| c + cells as u16);
        }
    }
}

/// The ways to draw a cell: as it is, with the side that does not show left free, and for block glyphs
/// in real colours, the complement glyph with fg and bg swapped.
fn forms(cell: Cell) -> [Option<(char, Need)>; 2] {
    let Cell { glyph, fg, bg } = cell.canonical();
    let need = |glyph: char, fg: Color, bg: Color| Need {
        fg: (glyph != ' ').then_some(fg),
        bg: (glyph != '█').then_some(bg),
    };
    let alternative = match glyph {
        ' ' if bg.is_concrete() => Some(('█', need('█', bg, bg))),
        _ if fg.is_concrete() && bg.is_concrete() => {
            complement(glyph).map(|other| (other, need(other, bg, fg)))
        }
        _ => None,
    };
    [Some((glyph, need(glyph, fg, bg))), alternative]
}

/// Draws successive grids at a fixed place on the screen, writing only what changed since the last one.
#[derive(Debug, Default)]
pub struct FrameWriter {
    options: FrameOptions,
    shown: Option<CellGrid>,
    /// What was on screen before the last frame, for the rows of a frame cut short.
    before: Option<CellGrid>,
    scratch: Vec<u8>,
    /// Where the last frame may be cut short (see [`FrameWriter::cut_points`]).
    row_starts: Vec<(usize, usize)>,
}

impl FrameWriter {
    /// A writer drawing with the grid's top-left cell at screen (column, row) `origin`, 0-based.
    pub fn new(origin: (u16, u16)) -> Self {
        FrameWriter {
            options: FrameOptions {
                origin,
                repeat: false,
            },
            shown: None,
            before: None,
            scratch: Vec::new(),
            row_starts: Vec::new(),
        }
    }

    /// Forgets what is on screen, so the next frame is drawn in full: call after a resize, a screen
    /// clear or any other drawing over the picture.
    pub fn invalidate(&mut self) {
        self.shown = None;
    }

    /// Moves the picture; the next frame is drawn in full.
    pub fn set_origin(&mut self, origin: (u16, u16)) {
        self.options.origin = origin;
        self.invalidate();
    }

    /// Whether to use REP for runs of identical cells (see [`FrameOptions::repeat`]).
    pub fn set_repeat(&mut self, repeat: bool) {
        self.options.repeat = repeat;
    }

    /// Draws `under` (the cells beneath a picture sent as pixels), then `picture` (escape
    /// sequences drawing over those cells), then `grid` over it all (the text on top), as one
    /// synchronized write; returns the bytes written. The cells `picture` covers are taken to be
    /// `under`'s afterwards.
    pub fn draw_around(
        &mut self,
        out: &mut impl Write,
        under: &CellGrid,
        picture: &[u8],
        grid: &CellGrid,
    ) -> io::Result<usize> {
        self.scratch.clear();
        self.scratch.extend_from_slice(SYNC_BEGIN);
        let mut part = Vec::new();
        encode_frame(self.shown.as_ref(), under, self.options, &mut part);
        self.scratch.extend_from_slice(unwrapped(&part));
        // The picture's sequences leave the pen and the cursor wherever they leave them.
        self.scratch.extend_from_slice(RESET);
        self.scratch.extend_from_slice(picture);
        part.clear();
        encode_frame(Some(under), grid, self.options, &mut part);
        self.scratch.extend_from_slice(unwrapped(&part));
        self.scratch.extend_from_slice(SYNC_END);
        // A picture's sequences cannot be cut short.
        self.row_starts.clear();
        self.send(out, grid)
    }

    /// Writes the changes from the last frame to `grid` in one write and flushes; returns the bytes
    /// written (0 if nothing changed). On an error (say, a terminal gone after SIGHUP) nothing panics and
    /// the next frame is drawn in full.
    pub fn draw(&mut self, out: &mut impl Write, grid: &CellGrid) -> io::Result<usize> {
        self.scratch.clear();
        self.row_starts.clear();
        let starts = Some(&mut self.row_starts);
        encode_rows(
            self.shown.as_ref(),
            grid,
            self.options,
            &mut self.scratch,
            starts,
        );
        if self.scratch.is_empty() {
            return Ok(0);
        }
        self.send(out, grid)
    }

    /// Writes the frame in `scratch` in one write and flushes, then takes `grid` to be what is
    /// on screen; after an error, nothing is (the next frame is drawn in full).
    fn send(&mut self, out: &mut impl Write, grid: &CellGrid) -> io::Result<usize> {
        if let Err(error) = out.write_all(&self.scratch).and_then(|()| out.flush()) {
            self.shown = None;
            return Err(error);
        }
        std::mem::swap(&mut self.before, &mut self.shown);
        match &mut self.shown {
            Some(shown) => shown.clone_from(grid),
            None => self.shown = Some(grid.clone()),
        }
        Ok(self.scratch.len())
    }

    /// Where the frame last written may be cut short: for each row it changes, the offset in
    /// its bytes where that row begins (whole escape sequences before it), and the row. A frame
    /// cut at one of them ends with [`CUT_FRAME_END`]; none for a frame with a pixel picture.
    pub fn cut_points(&self) -> &[(usize, usize)] {
        &self.row_starts
    }

    /// The frame last written was cut short before grid row `row`: the rows from there on still
    /// show what they showed before it.
    pub fn cut_before_row(&mut self, row: usize) {
        match (&mut self.shown, &self.before) {
            (Some(shown), Some(before))
                if (shown.cols(), shown.rows()) == (before.cols(), before.rows()) =>
            {
                shown.copy_rows_from(before, row)
            }
            _ => self.shown = None,
        }
    }
}
