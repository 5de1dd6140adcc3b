//! The whole terminal screen as one cell grid: the picture, the status line below it and the help
//! over it, drawn by the term layer's diffing writer so each frame is one synchronized update
//! with only the changed cells.

use super::app::App;
use super::pixel_picture::{PixelPicture, PixelRoute};
use super::refinement::Accumulation;
use super::render::{
    CellShape, DEFAULT_CELL_ASPECT, Sampling, empty_framebuffer, encode_cells, render_picture_pass,
};
use super::status::{StatusLine, status_line};
use super::status_message::error_style;
use super::view_mode::ViewMode;
use crate::raster::Framebuffer;
use crate::term::graphics::Protocol;
use crate::term::{Cell, CellGrid, Color, ColorMode, EncodeOptions, FrameWriter};
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Style;
use ratatui::widgets::Widget;
use std::io::{self, Write};
use std::time::Instant;

/// sRGB levels by which a cell's colour may differ from the settled picture's over a slow link
/// rather than be sent again: under 2 ΔE at mid-grey, less than side-by-side comparison shows.
const UNSEEN_CHANGE: u8 = 4;

/// Where things go on a screen of a given size.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Layout {
    pub cols: u16,
    pub rows: u16,
    /// Rows of picture, from the top.
    pub picture_rows: u16,
    /// The status line's row, if there is room for one.
    pub status_row: Option<u16>,
    /// The terminal reported no size (0 columns or rows), as some do before their window is
    /// mapped: the layout is a guess, with no picture in it.
    pub size_unknown: bool,
}

/// The screen assumed where the terminal reports none; only the status line is drawn on it.
const ASSUMED_SIZE: (u16, u16) = (80, 24);

/// The status line while the terminal reports no size.
pub const NO_SIZE_NOTE: &str =
    "the terminal reports its size as 0×0 cells: no picture until it tells one (resize it)";

impl Layout {
    /// The picture takes all but the last row, which is the status line; a one-row screen shows
    /// only the status line. A terminal that reports 0 columns or rows gets a status line where
    /// the usual 24th row would be, and no picture.
    pub fn new(cols: u16, rows: u16) -> Layout {
        if cols == 0 || rows == 0 {
            let (cols, rows) = ASSUMED_SIZE;
            return Layout {
                cols,
                rows,
                picture_rows: 0,
                status_row: Some(rows - 1),
                size_unknown: true,
            };
        }
        Layout {
            cols,
            rows,
            picture_rows: rows - 1,
            status_row: Some(rows - 1),
            size_unknown: false,
        }
    }
}

pub struct Screen {
    layout: Layout,
    writer: FrameWriter,
    picture: CellGrid,
    framebuffer: Framebuffer,
    /// The passes of the picture on screen, while nothing changes.
    accumulation: Accumulation,
    /// Cell height / width as the terminal draws them.
    cell_aspect: f32,
    /// The picture in pixels, when the app shows one.
    pixels: Option<PixelPicture>,
    /// How pixels reach this terminal.
    pixel_route: PixelRoute,
    /// The picture rows of the grid last drawn over a pixel picture: the text over it.
    text_over_pixels: Vec<Cell>,
    /// Whether refinement sends only the settled picture, not the passes on the way (a slow link).
    settled_only: bool,
    /// See [`Screen::cut_points`].
    cut_points: Vec<(usize, usize)>,
}

impl Screen {
    pub fn new(cols: u16, rows: u16) -> Screen {
        Screen {
            layout: Layout::new(cols, rows),
            writer: FrameWriter::new((0, 0)),
            picture: CellGrid::new(0, 0),
            framebuffer: empty_framebuffer(),
            accumulation: Accumulation::default(),
            cell_aspect: DEFAULT_CELL_ASPECT,
            pixels: None,
            pixel_route: PixelRoute::default(),
            text_over_pixels: Vec::new(),
            settled_only: false,
            cut_points: Vec::new(),
        }
    }

    /// Whether refinement sends only the settled picture (over a slow link, where each pass on
    /// the way would delay it by a whole frame), or also the passes at 4 and 16 samples.
    pub fn send_settled_only(&mut self, settled_only: bool) {
        self.settled_only = settled_only;
    }

    /// How pixel pictures reach the terminal now.
    pub fn pixel_route(&self) -> PixelRoute {
        self.pixel_route
    }

    /// How pixel pictures reach the terminal.
    pub fn set_pixel_route(&mut self, route: PixelRoute, app: &mut App) {
        if route != self.pixel_route {
            self.pixel_route = route;
            self.pixels = None;
            app.invalidate();
        }
    }

    /// Follows the app's choice of picture: a pixel protocol or cells. Leaving kitty's pixels
    /// deletes its image. Returns the bytes written.
    fn follow_graphics(&mut self, app: &mut App, out: &mut Vec<u8>) -> io::Result<usize> {
        if self.pixels.as_ref().map(|p| p.protocol) == app.graphics {
            return Ok(0);
        }
        let removal = self.pixels.take().map(|p| p.removal()).unwrap_or_default();
        crate::term::graphics::kitty::note_image(None);
        out.write_all(&removal)?;
        out.flush()?;
        if let Some(protocol) = app.graphics {
            self.pixels = Some(PixelPicture::new(protocol, self.pixel_route));
            self.picture =
                CellGrid::new(self.layout.cols as usize, self.layout.picture_rows as usize);
        }
        self.writer.invalidate();
        app.invalidate();
        Ok(removal.len())
    }

    /// How tall the terminal's cells are for their width; a change redraws the picture.
    pub fn set_cell_aspect(&mut self, aspect: f32, app: &mut App) {
        if aspect != self.cell_aspect {
            self.cell_aspect = aspect;
            app.invalidate();
        }
    }

    pub fn layout(&self) -> Layout {
        self.layout
    }

    /// The cells the picture takes (all but the status line).
    pub fn picture_area(&self) -> Rect {
        Rect::new(0, 0, self.layout.cols, self.layout.picture_rows)
    }

    /// A new terminal size: everything is drawn again in full.
    pub fn resize(&mut self, cols: u16, rows: u16, app: &mut App) {
        self.layout = Layout::new(cols, rows);
        self.invalidate(app);
    }

    /// Forgets what the terminal shows, so the next frame is drawn in full.
    pub fn invalidate(&mut self, app: &mut App) {
        self.writer.invalidate();
        if let Some(pixels) = &mut self.pixels {
            pixels.on_screen = false;
        }
        app.invalidate();
    }

    /// Draws what `app` marked as changed; returns the bytes written (0 when nothing changed).
    pub fn draw(&mut self, app: &mut App, out: &mut Vec<u8>) -> io::Result<usize> {
        let switched = self.follow_graphics(app, out)?;
        if !(app.dirty.picture || app.dirty.text) {
            return Ok(switched);
        }
        if self.layout.size_unknown {
            return self.draw_without_picture(app, out);
        }
        if app.dirty.picture {
            let start = Instant::now();
            match self.pixels.is_some() {
                true => self.render_pixels(app),
                false => self.render_picture(app),
            }
            // Before the status line is composed, so the first frame reports its own cost.
            app.report.render_time = start.elapsed();
        }
        if self.pixels.is_some() {
            return self.draw_over_pixels(app, out);
        }
        let grid = self.compose(app);
        let result = self.write_cells(out, &grid);
        app.mark_drawn();
        let bytes = result?;
        if bytes > 0 {
            app.report.bytes = bytes;
        }
        Ok(bytes)
    }

    /// The status line alone, for a terminal that reports no size; a kitty image shown before
    /// is deleted (sixel and iTerm2 pictures are text the new frame overwrites).
    fn draw_without_picture(&mut self, app: &mut App, out: &mut Vec<u8>) -> io::Result<usize> {
        let mut removed = 0;
        // Whether it was on screen is forgotten by the resize that brought this layout.
        if let Some(pixels) = self.pixels.as_mut() {
            let removal = pixels.removal();
            out.write_all(&removal)?;
            pixels.on_screen = false;
            removed = removal.len();
        }
        self.picture = CellGrid::new(0, 0);
        let grid = self.compose(app);
        let result = self.write_cells(out, &grid);
        app.mark_drawn();
        Ok(removed + result?)
    }

    /// Whether the picture on screen would still gain from another pass: nothing has changed
    /// since it was started, and its mode is one the passes average (the wireframe and the error
    /// view are drawn over a single pass).
    pub fn refining(&self, app: &App) -> bool {
        let wants_more = match &self.pixels {
            Some(pixels) => pixels.refining(),
            None => self.accumulation.wants_more(),
        };
        !app.dirty.picture && wants_more && refines(app.view_mode) && !self.layout.size_unknown
    }

    /// Renders one more pass into the picture and draws the cells it changed; returns the bytes
    /// written. Does nothing when `refining` is false.
    pub fn refine(&mut self, app: &mut App, out: &mut Vec<u8>) -> io::Result<usize> {
        if !self.refining(app) {
            return Ok(0);
        }
        if self.pixels.is_some() {
            return self.refine_pixels(app, out);
        }
        let sampling = Sampling {
            offset: self.accumulation.next_offset(),
            footprint: self.accumulation.next_footprint(),
        };
        let pass = self.render_pass(app, sampling);
        if pass.size != self.accumulation.size() {
            return Ok(0);
        }
        self.accumulation.add(&pass.linear);
        // Drawn when the sample count has grown fourfold: at 4, 16 and 64 passes, so a
        // converging picture costs a slow link three frames more, not one per pass.
        let passes = self.accumulation.passes();
        let quadrupled = passes.is_power_of_two() && passes.trailing_zeros().is_multiple_of(2);
        if (!quadrupled || self.settled_only) && self.accumulation.wants_more() {
            return Ok(0);
        }
        let options = EncodeOptions::new(app.colors, app.glyphs);
        let settled = encode_cells(&self.accumulation.mean(), pass.size, options);
        // Over a slow link a cell is sent again only where it changes visibly.
        self.picture = match self.settled_only {
            true => settled.keeping_close(&self.picture, UNSEEN_CHANGE),
            false => settled,
        };
        app.report.passes = self.accumulation.passes();
        app.report.refining = self.accumulation.wants_more();
        let grid = self.compose(app);
        let bytes = self.write_cells(out, &grid)?;
        if bytes > 0 {
            app.report.bytes = bytes;
        }
        Ok(bytes)
    }

    /// Appends the changes to `grid` to `out`, noting where the frame may be cut short.
    fn write_cells(&mut self, out: &mut Vec<u8>, grid: &CellGrid) -> io::Result<usize> {
        let frame_start = out.len();
        let bytes = self.writer.draw(out, grid)?;
        self.cut_points.clear();
        let points = self.writer.cut_points().iter();
        (self.cut_points).extend(points.map(|&(at, row)| (frame_start + at, row)));
        Ok(bytes)
    }

    /// Where the bytes last appended to a frame may be cut short: (offset in them, grid row)
    /// where each changed row begins. Empty for a frame with a pixel picture.
    pub fn cut_points(&self) -> &[(usize, usize)] {
        &self.cut_points
    }

    /// The frame last drawn went out only up to grid row `row`: the rows from there on are
    /// drawn with the next frame.
    pub fn frame_cut(&mut self, row: usize, app: &mut App) {
        self.writer.cut_before_row(row);
        app.redraw_text();
    }

    /// The frame last drawn did not reach the terminal: the next one is drawn in full.
    pub fn frame_lost(&mut self) {
        self.writer.invalidate();
    }

    /// The cells the picture covers, across and down.
    fn picture_cells(&self) -> (u16, u16) {
        (self.layout.cols, self.layout.picture_rows)
    }

    fn render_pixels(&mut self, app: &mut App) {
        let cells = self.picture_cells();
        self.picture = CellGrid::new(cells.0 as usize, cells.1 as usize);
        let supersampling = super::quality::terminal_supersampling(&app.quality_in_use);
        let pixels = self.pixels.as_mut().expect("in pixel mode");
        let view = app.view();
        let refined = refines(app.view_mode);
        let pass = pixels.first(&view, cells, supersampling, refined, &mut self.framebuffer);
        app.report.stats = pass.rendered.stats;
        app.report.psnr_db = pass.rendered.psnr_db;
        app.report.passes = pixels.passes();
        app.report.refining = pixels.refining();
    }

    fn refine_pixels(&mut self, app: &mut App, out: &mut Vec<u8>) -> io::Result<usize> {
        let cells = self.picture_cells();
        let supersampling = super::quality::terminal_supersampling(&app.quality_in_use);
        let pixels = self.pixels.as_mut().expect("in pixel mode");
        let ready = pixels.refine(&app.view(), cells, supersampling, &mut self.framebuffer);
        app.report.passes = pixels.passes();
        app.report.refining = pixels.refining();
        match ready {
            true => self.draw_over_pixels(app, out),
            false => Ok(0),
        }
    }

    /// Draws the text of the screen over the pixel picture, sending the picture first when the
    /// terminal does not show it yet, or shows it under text that has changed (sixel and iTerm2
    /// pictures live in the cells, so text drawn over them takes their place).
    fn draw_over_pixels(&mut self, app: &mut App, out: &mut Vec<u8>) -> io::Result<usize> {
        let pixels = self.pixels.as_ref().expect("in pixel mode");
        let send = !pixels.on_screen;
        // Before the status line is composed, so it shows the bytes of the picture it goes with.
        app.report.picture_bytes = pixels.image().len();
        let grid = self.compose(app);
        let over: Vec<Cell> = (0..self.layout.picture_rows as usize)
            .flat_map(|row| grid.row(row).iter().copied())
            .collect();
        let text_moved = over != self.text_over_pixels && pixels.protocol != Protocol::Kitty;
        self.cut_points.clear();
        let result = if send || text_moved {
            let under = self.compose_under(app);
            let written = self.writer.draw_around(out, &under, pixels.image(), &grid);
            if pixels.protocol == Protocol::Kitty {
                crate::term::graphics::kitty::note_image(Some(self.pixel_route.through_tmux));
            }
            self.pixels.as_mut().expect("in pixel mode").on_screen = written.is_ok();
            written
        } else {
            self.write_cells(out, &grid)
        };
        self.text_over_pixels = over;
        app.mark_drawn();
        let bytes = result?;
        if bytes > 0 {
            app.report.bytes = bytes;
        }
        Ok(bytes)
    }

    /// The screen as `compose` makes it without the overlays over the picture: blank cells
    /// where the picture goes, and the status line.
    fn compose_under(&self, app: &App) -> CellGrid {
        let mut under = self.compose(app);
        let blank = Cell::solid(Color::Default);
        for row in 0..self.layout.picture_rows as usize {
            for col in 0..self.layout.cols as usize {
                under.set(col, row, blank);
            }
        }
        under
    }

    fn render_picture(&mut self, app: &mut App) {
        let pass = self.render_pass(app, Sampling::CENTRE);
        let options = EncodeOptions::new(app.colors, app.glyphs);
        self.picture = encode_cells(&pass.linear, pass.size, options);
        app.report.stats = pass.rendered.stats;
        app.report.psnr_db = pass.rendered.psnr_db;
        self.accumulation.restart(pass.linear, pass.size);
        app.report.passes = 1;
        app.report.refining = refines(app.view_mode) && self.accumulation.wants_more();
    }

    fn render_pass(&mut self, app: &App, sampling: Sampling) -> super::render::PicturePass {
        let cells = (self.layout.cols as usize, self.layout.picture_rows as usize);
        let shape = CellShape {
            glyphs: app.glyphs,
            aspect: self.cell_aspect,
        };
        render_picture_pass(
            &app.view(),
            cells,
            shape,
            super::quality::terminal_supersampling(&app.quality_in_use),
            sampling,
            &mut self.framebuffer,
        )
    }

    /// The screen: picture, then the status line and the help drawn over it with ratatui.
    pub fn compose(&self, app: &App) -> CellGrid {
        let Layout { cols, rows, .. } = self.layout;
        let area = Rect::new(0, 0, cols, rows);
        let mut buffer = Buffer::empty(area);
        (&self.picture).render(area, &mut buffer);
        let style = text_style(app.colors);
        if let Some(row) = self.layout.status_row {
            let line = match self.layout.size_unknown {
                true => StatusLine {
                    text: NO_SIZE_NOTE.to_string(),
                    error_chars: 0,
                },
                false => status_line(app, cols as usize),
            };
            let width = cols as usize;
            let text = format!("{:<width$}", line.text);
            let (error, rest) = text.split_at(
                text.char_indices()
                    .nth(line.error_chars)
                    .map_or(text.len(), |(i, _)| i),
            );
            let (x, _) = buffer.set_stringn(0, row, error, width, error_style(style));
            buffer.set_stringn(x, row, rest, width.saturating_sub(x as usize), style);
        }
        let picture = self.picture_area();
        for overlay in app.overlays() {
            overlay.draw(app, picture, style, &mut buffer);
        }
        to_cells(&buffer)
    }
}

/// Whether a view mode's picture gains from further passes (the wireframe and the error view
/// are drawn over a single pass).
fn refines(mode: ViewMode) -> bool {
    !matches!(mode, ViewMode::Wireframe | ViewMode::Error)
}

/// Light text on dark grey, in colours every mode has; none at all without colour.
fn text_style(colors: ColorMode) -> Style {
    use ratatui::style::Color::Indexed;
    match colors {
        ColorMode::TrueColor | ColorMode::Ansi256 => Style::new().fg(Indexed(255)).bg(Indexed(236)),
        ColorMode::Ansi16 => Style::new().fg(Indexed(15)).bg(Indexed(8)),
        ColorMode::Monochrome => Style::new(),
    }
}

fn to_cells(buffer: &Buffer) -> CellGrid {
    let area = buffer.area;
    let mut grid = CellGrid::new(area.width as usize, area.height as usize);
    for y in 0..area.height {
        for x in 0..area.width {
            let cell = &buffer[(x, y)];
            grid.set(
                x as usize,
                y as usize,
                crate::term::Cell {
                    glyph: cell.symbol().chars().next().unwrap_or(' '),
                    fg: to_color(cell.fg),
                    bg: to_color(cell.bg),
                },
            );
        }
    }
    grid
}

fn to_color(color: ratatui::style::Color) -> Color {
    use ratatui::style::Color as R;
    match color {
        R::Rgb(r, g, b) => Color::Rgb(r, g, b),
        R::Indexed(i) => Color::Indexed(i),
        R::Reset => Color::Default,
        named => Color::Indexed(named_index(named)),
    }
}

fn named_index(color: ratatui::style::Color) -> u8 {
    use ratatui::style::Color as R;
    const NAMED: [ratatui::style::Color; 16] = [
        R::Black,
        R::Red,
        R::Green,
        R::Yellow,
        R::Blue,
        R::Magenta,
        R::Cyan,
        R::Gray,
        R::DarkGray,
        R::LightRed,
        R::LightGreen,
        R::LightYellow,
        R::LightBlue,
        R::LightMagenta,
        R::LightCyan,
        R::White,
    ];
    NAMED.iter().position(|&c| c == color).unwrap_or(7) as u8
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tiny_screens_keep_the_status_line_first() {
        assert_eq!(Layout::new(80, 24).picture_rows, 23);
        assert_eq!(Layout::new(1, 1).status_row, Some(0));
        assert_eq!(Layout::new(1, 1).picture_rows, 0);
        for (cols, rows) in [(5, 0), (0, 5), (0, 0)] {
            let layout = Layout::new(cols, rows);
            assert!(layout.size_unknown, "{cols}×{rows}");
            assert_eq!(
                layout.picture_rows, 0,
                "no picture for a terminal of no size"
            );
            assert_eq!(layout.status_row, Some(23));
        }
    }
}
