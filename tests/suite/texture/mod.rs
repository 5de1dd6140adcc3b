//! Textures: loading, limits, mapping, sampling and the shipped images.

mod limits;
mod loading;
mod mapping;
mod mutations;
mod pngsuite;
mod sampling;
mod shipped;
