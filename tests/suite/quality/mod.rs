//! The quality knobs.

mod knobs;
