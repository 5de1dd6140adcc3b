//! The workbench: cells, views, graphics, a real pty, refinement.

mod cells;
mod displacement;
mod error_view;
mod graphics;
mod pty;
mod refinement;
mod screen;
mod workbench;

/// A workbench on `scene` in true colour, watching no files.
fn true_colour_app(scene: &str) -> bumpwork::tui::App {
    let options = bumpwork::tui::WorkbenchOptions {
        scenes: vec![scene.into()],
        colors: bumpwork::term::ColorChoice::Fixed(bumpwork::term::ColorMode::TrueColor),
        watch: false,
        ..bumpwork::tui::WorkbenchOptions::default()
    };
    bumpwork::tui::App::new(&options, bumpwork::term::ColorMode::TrueColor).unwrap()
}
