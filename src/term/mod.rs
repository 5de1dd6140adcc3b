//! Showing pictures in a terminal, safely.
//!
//! A picture (sRGB, 8 bits) is [`encode`]d into a [`CellGrid`] of block glyphs in the chosen
//! [`ColorMode`] and [`GlyphSet`]; the grid is drawn either as a ratatui widget (`&CellGrid` implements
//! `Widget`) or, faster, by a [`FrameWriter`] that writes only the cells that changed. [`TerminalGuard`]
//! and [`ShutdownSignals`] get the terminal back to how it was however the workbench ends, and
//! [`sanitize`] keeps text from files from steering the terminal.
//!
//! An event loop using the fast path (the ratatui path is the same with `frame.render_widget(&grid,
//! area)` in place of the `FrameWriter`):
//!
//! ```no_run
//! use bumpwork::term::*;
//! use crossterm::event::{self, Event};
//! use std::time::Duration;
//!
//! # fn render_srgb(_w: usize, _h: usize) -> Vec<[u8; 3]> { Vec::new() }
//! # fn main() -> std::io::Result<()> {
//! let colors = ColorChoice::Auto.resolve(|name| std::env::var(name).ok());
//! let options = EncodeOptions::new(colors, GlyphSet::HalfBlock);
//! let signals = ShutdownSignals::register()?;
//! let guard = TerminalGuard::enter(false)?; // also installs the restoring panic hook
//! let mut writer = FrameWriter::new((0, 0));
//! let (width, height) = options.glyphs.picture_size(80, 24);
//! loop {
//!     let pixels = render_srgb(width, height);
//!     let picture = Picture::new(&pixels, width, height).expect("renderer gives width × height");
//!     // A failed write (the terminal is gone) is not fatal here: the signal ends the loop.
//!     let _ = writer.draw(&mut std::io::stdout(), &encode(&picture, options));
//!     if let Some(signal) = signals.received() {
//!         drop(guard);
//!         std::process::exit(signal.exit_code());
//!     }
//!     if event::poll(Duration::from_millis(50))? {
//!         match event::read()? {
//!             Event::Key(key) if is_ctrl_c(&key) => break,
//!             Event::Resize(..) => writer.invalidate(), // and clear the screen
//!             _ => {}
//!         }
//!     }
//! }
//! drop(guard);
//! # Ok(())
//! # }
//! ```

mod ansi_writer;
mod cell;
pub mod cielab;
mod color;
mod color_mode;
mod cursor;
mod dither;
mod dither_mix;
mod encode;
mod glyphs;
pub mod graphics;
mod guard;
pub mod palette;
mod picture;
mod quantize;
mod ratatui_widget;
mod sanitize;
mod sgr;
mod signals;
mod split;
mod terminfo;
mod tmux_query;

pub use ansi_writer::{
    CUT_FRAME_END, FrameOptions, FrameWriter, SYNC_BEGIN, SYNC_END, encode_frame,
};
pub use cell::{Cell, CellGrid};
pub use color::Color;
pub use color_mode::{
    ColorChoice, ColorMode, DetectedColors, UnknownColorMode, detect_color_mode, detect_colors,
    detect_colors_in_tmux, detect_from_process_env,
};
pub use dither::threshold_u8;
pub use encode::{EncodeOptions, encode};
pub use glyphs::{GlyphSet, complement};
pub use guard::{
    TerminalGuard, TerminalModes, install_panic_hook, restore_terminal, restore_terminal_to,
    suspend_and_resume, write_enter_sequence, write_restore_sequence,
};
pub use picture::{Picture, PictureSizeError};
pub use quantize::{Palette, Quantizer, monochrome_lit, quantize};
pub use sanitize::sanitize;
pub use signals::{DEFAULT_GRACE, ShutdownSignal, ShutdownSignals, is_ctrl_c};
pub use split::{Split, best_split, split_error};
pub use tmux_query::{in_tmux, tmux_client_features, tmux_passes_through};
