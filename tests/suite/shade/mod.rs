//! Shading: bumps, and fragments at the true surface.

mod bump_shading;
mod exact_points;
