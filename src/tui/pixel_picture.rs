//! The picture in real pixels, for terminals that show them (kitty graphics, sixel, iTerm2):
//! the terminal's own resolution, a cheap picture first after each change (half the size where
//! the terminal scales it, else one pass), then, once the passes have converged, the full
//! picture; nothing while nothing changes.

use super::refinement::Accumulation;
use super::render::{PicturePass, Sampling, View, render_pixels_pass};
use super::resample::to_srgb8;
use crate::raster::Framebuffer;
use crate::term::graphics::{Protocol, tmux_passthrough};

/// A cell's pixels when the terminal tells nothing and `--cell-size` is not given.
pub const FALLBACK_CELL_PIXELS: (u32, u32) = (10, 20);

/// How pixel pictures reach a terminal.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PixelRoute {
    /// Sequences go through tmux's passthrough.
    pub through_tmux: bool,
    /// A cell's width and height in pixels.
    pub cell_pixels: (u32, u32),
    /// The largest sixel picture the terminal takes (XTSMGRAPHICS), if it said.
    pub sixel_limit: Option<(u32, u32)>,
}

impl Default for PixelRoute {
    fn default() -> Self {
        PixelRoute {
            through_tmux: false,
            cell_pixels: FALLBACK_CELL_PIXELS,
            sixel_limit: None,
        }
    }
}

pub struct PixelPicture {
    pub protocol: Protocol,
    route: PixelRoute,
    accumulation: Accumulation,
    /// The sequences of the picture last made, to send again when the terminal lost it.
    image: Vec<u8>,
    /// Whether the terminal shows `image`.
    pub on_screen: bool,
}

impl PixelPicture {
    pub fn new(protocol: Protocol, route: PixelRoute) -> PixelPicture {
        PixelPicture {
            protocol,
            route,
            accumulation: Accumulation::default(),
            image: Vec::new(),
            on_screen: false,
        }
    }

    /// The picture's pixels over `cells`: exactly the cells' pixels (for sixel, no more than
    /// the terminal takes).
    pub fn size(&self, (cols, rows): (u16, u16)) -> (usize, usize) {
        let (w, h) = self.route.cell_pixels;
        let size = (cols as usize * w as usize, rows as usize * h as usize);
        match (self.protocol, self.route.sixel_limit) {
            (Protocol::Sixel, Some((max_w, max_h))) => {
                (size.0.min(max_w as usize), size.1.min(max_h as usize))
            }
            _ => size,
        }
    }

    /// The first picture after a change, made ready to send: half the size where the terminal
    /// scales it and passes will follow (`refined`), else the full size; returns the pass.
    pub fn first(
        &mut self,
        view: &View,
        cells: (u16, u16),
        supersampling: usize,
        refined: bool,
        framebuffer: &mut Framebuffer,
    ) -> PicturePass {
        let (width, height) = self.size(cells);
        let preview = refined && self.protocol.scales();
        let size = match preview {
            true => (width.div_ceil(2), height.div_ceil(2)),
            false => (width, height),
        };
        let pass = render_pixels_pass(view, size, supersampling, Sampling::CENTRE, framebuffer);
        self.accumulation = Accumulation::default();
        if !preview {
            self.accumulation.restart(pass.linear.clone(), pass.size);
        }
        self.make_image(&pass.linear, pass.size, cells);
        pass
    }

    /// Whether another pass would change the picture.
    pub fn refining(&self) -> bool {
        self.accumulation.passes() == 0 || self.accumulation.wants_more()
    }

    /// Renders one more full-size pass; returns whether a new picture is ready to send (the
    /// passes have converged).
    pub fn refine(
        &mut self,
        view: &View,
        cells: (u16, u16),
        supersampling: usize,
        framebuffer: &mut Framebuffer,
    ) -> bool {
        let size = self.size(cells);
        let sampling = Sampling {
            offset: self.accumulation.next_offset(),
            footprint: self.accumulation.next_footprint(),
        };
        let pass = render_pixels_pass(view, size, supersampling, sampling, framebuffer);
        if self.accumulation.passes() == 0 || self.accumulation.size() != pass.size {
            self.accumulation.restart(pass.linear, pass.size);
        } else {
            self.accumulation.add(&pass.linear);
        }
        if self.accumulation.wants_more() {
            return false;
        }
        self.make_image(&self.accumulation.mean(), size, cells);
        true
    }

    /// Passes in the picture last made (0 for a preview).
    pub fn passes(&self) -> u32 {
        self.accumulation.passes()
    }

    fn make_image(&mut self, linear: &[glam::Vec3], size: (usize, usize), cells: (u16, u16)) {
        let rgb: Vec<u8> = to_srgb8(linear).into_iter().flatten().collect();
        let size = (size.0 as u32, size.1 as u32);
        let sequences = self.protocol.encode(&rgb, size, cells);
        self.image = b"\x1b[H".to_vec();
        for sequence in sequences {
            match self.route.through_tmux && self.protocol != Protocol::Sixel {
                true => self.image.extend(tmux_passthrough(&sequence)),
                false => self.image.extend(sequence),
            }
        }
        self.on_screen = false;
    }

    /// The sequences that show the picture last made, from the top left corner.
    pub fn image(&self) -> &[u8] {
        &self.image
    }

    /// The sequence that takes the picture off the screen where text does not (kitty's images
    /// stay under the text until deleted); empty for the others.
    pub fn removal(&self) -> Vec<u8> {
        match (self.protocol, self.route.through_tmux) {
            (Protocol::Kitty, false) => crate::term::graphics::kitty::delete(),
            (Protocol::Kitty, true) => tmux_passthrough(&crate::term::graphics::kitty::delete()),
            _ => Vec::new(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_picture_has_the_cells_pixels_and_sixel_keeps_to_the_terminals_limit() {
        let route = PixelRoute {
            through_tmux: false,
            cell_pixels: (10, 20),
            sixel_limit: Some((800, 300)),
        };
        let kitty = PixelPicture::new(Protocol::Kitty, route);
        assert_eq!(kitty.size((100, 29)), (1000, 580));
        let sixel = PixelPicture::new(Protocol::Sixel, route);
        assert_eq!(sixel.size((100, 29)), (800, 300));
        assert_eq!(sixel.size((50, 10)), (500, 200));
    }
}
