//! Writing stills to files: PNG (with the recipe in text chunks) and the seed's PPM, never
//! half-written (see `output_file`).

mod animation_file;
mod contact_sheet;
mod map_png;
pub mod metadata;
mod output_file;
mod png_file;
mod png_image_data;
mod pov_scene;
mod ppm_file;
mod still_file;
mod still_start;
mod writeback;

pub use animation_file::{AnimationFile, AnimationFormat, GIF_MAX_FPS};
pub use contact_sheet::{ContactSheet, SheetLayout, SheetPicture};
pub use map_png::{
    BAKE_RECIPE, HEIGHT_RANGE, MapPng, NORMAL_CONVENTION, height_levels, write_map_png,
};
pub use metadata::read_png_text;
pub use output_file::{OutputFile, STANDARD_OUTPUT, check_destination, write_whole};
pub use png_file::{PngStill, read_png_rgb8, write_png, write_png_with_text};
pub use pov_scene::{BAKE_SIDE, pov, rgb, write_pov, write_pov_header};
pub use ppm_file::PpmStill;
pub use still_file::{PreparedStill, StillAt, StillFormat, StillPlace, StillWritten};
pub use still_start::StillStart;
