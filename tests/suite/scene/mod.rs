//! Scene files and their quality tables.

mod files;
mod quality;
