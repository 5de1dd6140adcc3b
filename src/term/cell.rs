//! A grid of terminal cells: what the encoders produce and the writers draw.

use super::color::Color;
use super::glyphs::complement;

/// One terminal cell: a glyph drawn in `fg` over `bg`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Cell {
    pub glyph: char,
    pub fg: Color,
    pub bg: Color,
}

impl Cell {
    /// A cell showing one colour everywhere.
    pub fn solid(color: Color) -> Self {
        Cell {
            glyph: ' ',
            fg: Color::Default,
            bg: color,
        }
    }

    /// One representative of all the cells that look like this one, so that "looks the same" is `==` of
    /// canonical forms: a space ignores its fg, `█` its bg, `█` in a real colour is a space in that bg, equal fg and bg
    /// make a solid cell, and a block glyph and its complement with the colours swapped are one cell.
    pub fn canonical(self) -> Self {
        let Cell { glyph, fg, bg } = self;
        let both_concrete = fg.is_concrete() && bg.is_concrete();
        match glyph {
            ' ' => Cell::solid(bg),
            '█' if fg.is_concrete() => Cell::solid(fg),
            '█' => Cell {
                glyph,
                fg,
                bg: Color::Default,
            },
            _ => match complement(glyph) {
                Some(_) if fg == bg && both_concrete => Cell::solid(bg),
                Some(other) if both_concrete && other < glyph => Cell {
                    glyph: other,
                    fg: bg,
                    bg: fg,
                },
                _ => self,
            },
        }
    }

    /// Whether the two cells look the same on screen.
    pub fn looks_same(self, other: Cell) -> bool {
        self == other || self.canonical() == other.canonical()
    }

    /// Whether the two cells show the same glyph in colours no channel of which differs by more
    /// than `levels` (palette colours must be equal: a step of the palette is never small).
    pub fn looks_within(self, other: Cell, levels: u8) -> bool {
        let (a, b) = (self.canonical(), other.canonical());
        a.glyph == b.glyph && colors_within(a.fg, b.fg, levels) && colors_within(a.bg, b.bg, levels)
    }
}

fn colors_within(a: Color, b: Color, levels: u8) -> bool {
    match (a, b) {
        (Color::Rgb(r, g, b), Color::Rgb(r2, g2, b2)) => {
            r.abs_diff(r2) <= levels && g.abs_diff(g2) <= levels && b.abs_diff(b2) <= levels
        }
        _ => a == b,
    }
}

/// A `cols × rows` grid of cells, row-major.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CellGrid {
    cols: usize,
    rows: usize,
    cells: Vec<Cell>,
}

impl CellGrid {
    /// A grid of default-coloured spaces.
    pub fn new(cols: usize, rows: usize) -> Self {
        CellGrid {
            cols,
            rows,
            cells: vec![Cell::solid(Color::Default); cols * rows],
        }
    }

    pub fn cols(&self) -> usize {
        self.cols
    }

    pub fn rows(&self) -> usize {
        self.rows
    }

    /// The cell at column `x`, row `y`. Panics outside the grid.
    pub fn get(&self, x: usize, y: usize) -> Cell {
        self.cells[y * self.cols + x]
    }

    /// Replaces the cell at column `x`, row `y`. Panics outside the grid.
    pub fn set(&mut self, x: usize, y: usize, cell: Cell) {
        self.cells[y * self.cols + x] = cell;
    }

    /// This grid, but where `shown` (the grid on screen) has a cell within `levels` of this
    /// one's, that cell: what changes less than that is not worth sending.
    pub fn keeping_close(&self, shown: &CellGrid, levels: u8) -> CellGrid {
        if (shown.cols, shown.rows) != (self.cols, self.rows) {
            return self.clone();
        }
        let cells = self
            .cells
            .iter()
            .zip(&shown.cells)
            .map(|(&new, &old)| {
                if new.looks_within(old, levels) {
                    old
                } else {
                    new
                }
            })
            .collect();
        CellGrid { cells, ..*self }
    }

    /// The cells of row `y`.
    pub fn row(&self, y: usize) -> &[Cell] {
        &self.cells[y * self.cols..(y + 1) * self.cols]
    }

    /// Copies `other`'s rows from `first` on into this grid of the same size.
    pub fn copy_rows_from(&mut self, other: &CellGrid, first: usize) {
        let start = (first * self.cols).min(self.cells.len());
        self.cells[start..].copy_from_slice(&other.cells[start..]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_grid_keeps_the_shown_cells_that_changed_by_less_than_the_levels() {
        let cell = |v: u8, glyph| Cell {
            glyph,
            fg: Color::Rgb(v, v, v),
            bg: Color::Rgb(0, v, 0),
        };
        let mut shown = CellGrid::new(3, 1);
        let mut next = CellGrid::new(3, 1);
        for (x, (old, new)) in [(100, 104), (100, 105), (100, 100)].into_iter().enumerate() {
            shown.set(x, 0, cell(old, '▀'));
            next.set(x, 0, cell(new, '▀'));
        }
        let kept = next.keeping_close(&shown, 4);
        assert_eq!(
            kept.get(0, 0),
            shown.get(0, 0),
            "4 levels: not worth sending"
        );
        assert_eq!(kept.get(1, 0), next.get(1, 0), "5 levels: sent");
        let indexed = Cell {
            glyph: '▀',
            fg: Color::Indexed(16),
            bg: Color::Indexed(17),
        };
        assert!(!indexed.looks_within(
            Cell {
                fg: Color::Indexed(17),
                ..indexed
            },
            255
        ));
    }

    const RED: Color = Color::Rgb(255, 0, 0);
    const BLUE: Color = Color::Indexed(4);

    #[test]
    fn equivalent_cells_look_the_same() {
        let upper = Cell {
            glyph: '▀',
            fg: RED,
            bg: BLUE,
        };
        let lower = Cell {
            glyph: '▄',
            fg: BLUE,
            bg: RED,
        };
        assert!(upper.looks_same(lower));
        assert!(
            Cell {
                glyph: '█',
                fg: RED,
                bg: BLUE
            }
            .looks_same(Cell::solid(RED))
        );
        assert!(
            Cell {
                glyph: '▀',
                fg: RED,
                bg: RED
            }
            .looks_same(Cell::solid(RED))
        );
        assert!(!upper.looks_same(Cell {
            glyph: '▀',
            fg: BLUE,
            bg: RED
        }));
    }

    #[test]
    fn default_colours_are_not_swapped() {
        let mono = Cell {
            glyph: '▀',
            fg: Color::Default,
            bg: Color::Default,
        };
        assert_eq!(mono.canonical(), mono);
        assert!(
            !Cell {
                glyph: '█',
                fg: Color::Default,
                bg: Color::Default
            }
            .looks_same(Cell::solid(Color::Default))
        );
    }
}
