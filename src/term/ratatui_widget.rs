//! Drawing a cell grid through ratatui: `frame.render_widget(&grid, area)`. The grid is clipped to the
//! area; cells of the area beyond the grid are left as they are.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::widgets::Widget;

use super::cell::CellGrid;

impl Widget for &CellGrid {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let area = area.intersection(buf.area);
        let cols = self.cols().min(area.width as usize);
        let rows = self.rows().min(area.height as usize);
        for y in 0..rows {
            for (x, cell) in self.row(y)[..cols].iter().enumerate() {
                let position = (area.x + x as u16, area.y + y as u16);
                if let Some(target) = buf.cell_mut(position) {
                    target
                        .set_char(cell.glyph)
                        .set_fg(cell.fg.into())
                        .set_bg(cell.bg.into());
                }
            }
        }
    }
}
