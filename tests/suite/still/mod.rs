//! Stills rendered in bands.

mod bands;
