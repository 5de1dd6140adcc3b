//! The terminal workbench: a live view of a scene that the keyboard (and mouse) orbits, relights,
//! re-patterns and exports.
//!
//! State ([`App`]) is changed only by [`Action`]s, which keys ([`keymap`]) and mouse gestures
//! produce; the [`Screen`] draws only what the state marks dirty, as one synchronized update of
//! the changed cells, so an idle workbench writes nothing.

mod action;
mod app;
mod clock;
mod diagnostic_box;
mod error_view;
mod event_loop;
mod export;
mod frame_pacing;
mod frame_report;
mod help;
mod image_shelf;
mod input;
mod kept_scene;
pub mod keymap;
mod light;
mod material_controls;
mod message_history;
mod message_log;
mod mode_names;
mod options;
mod orbit;
mod overlay;
mod param_panel;
mod pixel_picture;
mod popup;
mod quality;
mod refinement;
mod render;
mod resample;
mod scene_picker;
mod scene_setup;
mod screen;
mod status;
mod status_message;
mod view_mode;
mod wireframe;

pub use action::Action;
pub use app::{App, Dirty};
pub use event_loop::run;
pub use frame_report::FrameReport;
pub use options::WorkbenchOptions;
pub use orbit::Orbit;
pub use overlay::{OverlayKind, WorkbenchState};
pub use pixel_picture::PixelRoute;
pub use quality::MAX_TERMINAL_SAMPLES;
pub use refinement::{Accumulation, MAX_PASSES};
pub use render::{
    CellShape, DEFAULT_CELL_ASPECT, PicturePass, Sampling, View, render_cells, render_frame,
    render_picture_pass,
};
pub use screen::{Layout, Screen};
pub use status_message::{INFO_LIFETIME, Message};
pub use view_mode::{RenderedFrame, ViewMode};
