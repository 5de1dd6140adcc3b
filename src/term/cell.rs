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

    /// The cells of row `y`.
    pub fn row(&self, y: usize) -> &[Cell] {
        &self.cells[y * self.cols..(y + 1) * self.cols]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
