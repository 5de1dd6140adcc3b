//! Terminal output: encodings, the environment, the frame writer.

mod encode;
mod env;
mod writer;
