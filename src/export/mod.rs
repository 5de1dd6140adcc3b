//! Writing rendered frames to files.

mod png_file;

pub use png_file::write_png;
