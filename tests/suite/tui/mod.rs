//! The workbench: cells, views, graphics, a real pty, refinement.

mod cells;
mod displacement;
mod error_view;
mod graphics;
mod pty;
mod refinement;
mod screen;
mod workbench;
