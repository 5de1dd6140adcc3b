//! The rasterizer: clipping, extremes, perspective, reuse of buffers, watertightness.

mod clipping;
mod extremes;
mod perspective;
mod reuse;
mod watertight;
