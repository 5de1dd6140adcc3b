//! Shadows and terminators.

mod shadows;
mod terminators;
