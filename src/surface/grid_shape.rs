//! The shape of a surface's (u,v) grid of cells: how many each way, and which v edges collapse
//! to a point (a pole or an apex).

/// Grid resolution (cells along u, cells along v) and which v edges collapse to a point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct GridShape {
    pub cells_u: u32,
    pub cells_v: u32,
    /// The v = min row is a single point (a pole or apex).
    pub collapsed_v_min: bool,
    pub collapsed_v_max: bool,
}

impl GridShape {
    pub fn flat(cells_u: u32, cells_v: u32) -> GridShape {
        GridShape {
            cells_u,
            cells_v,
            collapsed_v_min: false,
            collapsed_v_max: false,
        }
    }

    /// Two triangles per cell, one in a row that collapses to a point (a fan).
    pub fn triangle_count(&self) -> u64 {
        let fans = u64::from(self.collapsed_v_min) + u64::from(self.collapsed_v_max);
        let cells_u = u64::from(self.cells_u);
        2 * cells_u * u64::from(self.cells_v) - fans * cells_u
    }

    /// Whether grid row `row` (0 ..= cells_v) is a single point.
    pub fn is_collapsed(&self, row: u32) -> bool {
        (row == 0 && self.collapsed_v_min) || (row == self.cells_v && self.collapsed_v_max)
    }
}
