//! Writing stills to files: PNG (with the recipe in text chunks) and the seed's PPM, always
//! atomically.

mod atomic;
mod contact_sheet;
pub mod label_font;
pub mod metadata;
mod png_file;
mod pov_scene;
mod ppm_file;
mod still_file;

pub use atomic::AtomicFile;
pub use contact_sheet::{SheetLayout, SheetPicture, draw_sheet, write_sheet};
pub use png_file::{PngStill, read_png_rgb8, write_png, write_png_with_text};
pub use pov_scene::{BAKE_SIDE, write_pov};
pub use ppm_file::PpmStill;
pub use still_file::{BAND_BUDGET_BYTES, StillFormat, StillRequest, write_still};
