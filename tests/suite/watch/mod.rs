//! Watching files: reloads, churn and a long soak.

mod churn;
mod reload;
mod soak;
pub mod support;
