//! bumpwork: a CPU rasterizer and terminal workbench for Blinn bump maps and texture maps.

pub mod pattern;
pub mod term;
pub mod texture;
