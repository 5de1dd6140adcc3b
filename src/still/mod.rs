//! Stills: a scene rendered at any size with supersampling, in bands so memory stays bounded,
//! and the recipe that lets a still be rendered again from its own metadata.

mod bands;
mod contrast;
mod in_order;
mod recipe;
mod refine_rule;
mod row_sink;
mod samples;
mod saved_view;
mod stream;

pub use crate::quality::{MAX_DENSITY, MAX_SAMPLES, check_quality};
pub use bands::{
    BAND_BUDGET_BYTES, BandBuffers, BandJob, band_bytes, band_rows, render_supersampled,
};
pub use recipe::{
    FileHash, MAX_SIDE, MAX_TIME_SECONDS, ObjectState, Recipe, RecipeCamera, StillSettings,
    recipe_hash, source_directory,
};
pub use refine_rule::RefineRule;
pub use row_sink::RowSink;
pub use samples::{RefiningOrder, ResolveFilter, Supersampling};
pub use saved_view::saved_view;
pub use stream::{StillStop, stream_still};
