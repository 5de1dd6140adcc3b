//! Showing pictures in a terminal, safely.
//!
//! A picture (sRGB, 8 bits) is [`encode`]d into a [`CellGrid`] of block glyphs in the chosen
//! [`ColorMode`] and [`GlyphSet`]; the grid is drawn either as a ratatui widget (`&CellGrid` implements
//! `Widget`) or, faster, by a [`FrameWriter`] that writes only the cells that changed. [`TerminalGuard`]
//! and [`ShutdownSignals`] get the terminal back to how it was however the workbench ends, and
//! [`sanitize`] keeps text from files from steering the terminal.

mod ansi_writer;
mod cell;
mod color;
mod color_mode;
mod cursor;
mod dither;
mod encode;
mod glyphs;
mod guard;
pub mod palette;
mod picture;
mod quantize;
mod ratatui_widget;
mod sanitize;
mod sgr;
mod signals;
mod split;

pub use ansi_writer::{FrameOptions, FrameWriter, SYNC_BEGIN, SYNC_END, encode_frame};
pub use cell::{Cell, CellGrid};
pub use color::Color;
pub use color_mode::{
    ColorChoice, ColorMode, UnknownColorMode, detect_color_mode, detect_from_process_env,
};
pub use dither::threshold_u8;
pub use encode::{EncodeOptions, encode};
pub use glyphs::{GlyphSet, complement};
pub use guard::{
    TerminalGuard, TerminalModes, install_panic_hook, restore_terminal, restore_terminal_to,
    write_enter_sequence, write_restore_sequence,
};
pub use picture::{Picture, PictureSizeError};
pub use quantize::{Palette, Quantizer, monochrome_lit, quantize};
pub use sanitize::sanitize;
pub use signals::{DEFAULT_GRACE, ShutdownSignal, ShutdownSignals, is_ctrl_c};
pub use split::{Split, best_split, split_error};
