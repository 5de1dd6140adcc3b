//! Camera, clipping, triangle setup, edge-function scan conversion into tiles, framebuffer.
//! `render` (render.rs) is the front door: the frame's objects (any type that gives a
//! `PlacedMesh`), one or more passes (`RenderTarget`) and a `FragmentShader` in, pixels out.
//!
//! The stages follow the GL pipeline: vertices are moved into camera-relative space (in f64, so
//! scenes far from the origin keep their precision) and projected to clip space; triangles are
//! culled and clipped in homogeneous space, snapped to fixed point and binned into tiles; each tile
//! resolves visibility into a small buffer (depth and triangle per pixel) and then shades only the
//! visible pixels (deferred shading: no fragment is shaded twice).

mod bin;
mod clip;
mod depth_map;
mod fragment;
mod frame_stats;
mod framebuffer;
mod interpolation;
mod pixel_rect;
mod placed_mesh;
mod refine;
mod render;
mod render_target;
mod row_cover;
mod row_runs;
mod sample_rays;
mod scan;
mod screen_triangles;
mod setup;
mod strips;
mod tile;
mod tile_rows;
mod top_first;
mod view_rays;
mod wanted_spans;
mod window;

pub use bin::{TILE_SIZE, TileBins};
pub use clip::{ClipVertex, clip_triangle};
pub use depth_map::{DepthMap, DepthView, render_depth};
pub use fragment::{Fragment, FragmentShader};
pub use frame_stats::FrameStats;
pub use framebuffer::{Blend, Framebuffer, encode_srgb8, linear_to_srgb8};
pub use interpolation::Interpolation;
pub use pixel_rect::PixelRect;
pub use placed_mesh::PlacedMesh;
pub use refine::{Refine, Refinement, TileRows};
pub use render::{render, render_pass};
pub use render_target::{FrameOutput, RenderTarget, Srgb8Strips};
pub use sample_rays::SampleRays;
pub use scan::{scan_shifted, scan_triangle};
pub use screen_triangles::screen_triangles;
pub use setup::{SUBPIXEL_BITS, SampleShift, ScreenTriangle, ShiftSpan, TrianglePlanes, Viewport};
pub use strips::STRIP_ROWS;
pub use view_rays::ViewRays;
pub use window::ImageWindow;
