//! Patterns: the language, its built-ins, gradients, precision and errors.

mod builtins;
mod errors;
mod fuzz;
mod gradients;
mod non_finite;
mod precision;
mod seed_dimples;
pub mod support;
mod textures;
