//! The exact reference ray caster and the rasterizer measured against it.

mod accuracy;
mod extremes;
mod properties;
mod round_trip;
pub mod support;
