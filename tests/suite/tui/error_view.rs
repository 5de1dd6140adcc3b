//! The workbench's error view and quality presets: the heat map against the exact reference, the
//! frame's PSNR in the status line, and the preset key cycling the crate's presets.

use bumpwork::raster::Framebuffer;
use bumpwork::tui::{Action, App, Screen, ViewMode, render_frame};
use glam::Vec3;

fn app(scene: &str) -> App {
    super::true_colour_app(scene)
}

fn status(screen: &Screen, app: &App) -> String {
    let grid = screen.compose(app);
    let row = screen.layout().status_row.unwrap() as usize;
    grid.row(row).iter().map(|c| c.glyph).collect()
}

fn error_view_psnr(app: &mut App, screen: &mut Screen) -> f64 {
    app.invalidate();
    screen.draw(app, &mut Vec::new()).unwrap();
    app.frame_report()
        .psnr_db
        .expect("the error view reports a PSNR")
}

#[test]
fn the_error_view_shows_the_psnr_and_finer_presets_raise_it() {
    let mut app = app("big-sphere-squares");
    let mut screen = Screen::new(80, 20);
    while app.view_mode() != ViewMode::Error {
        app.apply(Action::NextViewMode);
    }
    let interactive = error_view_psnr(&mut app, &mut screen);
    let status_line = status(&screen, &app);
    assert!(
        status_line.contains("PSNR") || status_line.contains("identical to reference"),
        "{status_line}"
    );
    // Round to draft: density 16, the mesh's outline and (u,v), Blinn's normal.
    for _ in 0..3 {
        app.apply(Action::NextQuality);
    }
    assert_eq!(app.quality_preset().name(), "draft");
    let draft = error_view_psnr(&mut app, &mut screen);
    assert!(
        status(&screen, &app).contains("PSNR"),
        "{}",
        status(&screen, &app)
    );
    // Interactive settles every pixel on the true surfaces: identical to the reference at
    // 64×48 in `bumpwork bench` when written, draft 29 dB; here at least a clear step up.
    assert!(draft.is_finite() && draft > 20.0, "{draft}");
    assert!(
        interactive > draft + 3.0,
        "interactive {interactive} dB vs draft {draft} dB"
    );
    app.apply(Action::NextViewMode);
    screen.draw(&mut app, &mut Vec::new()).unwrap();
    assert_eq!(
        app.frame_report().psnr_db,
        None,
        "only the error view measures"
    );
}

#[test]
fn the_heat_map_is_dark_where_the_frame_matches_the_reference() {
    let mut app = app("plane-dimples");
    while app.view_mode() != ViewMode::Error {
        app.apply(Action::NextViewMode);
    }
    let mut framebuffer = Framebuffer::new(0, 0, Vec3::ZERO);
    let rendered = render_frame(&app.view(), 48, 36, &mut framebuffer);
    // A facing plane is exact for the rasterizer: (u,v) is perspective-correct on it, so the
    // frame equals the reference to within rounding and nearly every pixel is black.
    let dark = framebuffer
        .color()
        .iter()
        .filter(|c| c.max_element() < 0.1)
        .count();
    assert!(
        dark * 10 >= framebuffer.color().len() * 9,
        "{dark} dark pixels"
    );
    assert!(rendered.psnr_db.unwrap() > 40.0, "{:?}", rendered.psnr_db);
}

#[test]
fn the_preset_key_cycles_the_crate_presets_and_the_status_counts_the_samples() {
    let mut app = app("plane-dimples");
    let screen = Screen::new(120, 10);
    let mut names = Vec::new();
    for _ in 0..4 {
        app.apply(Action::NextQuality);
        names.push(app.quality_preset().name());
    }
    assert_eq!(names, ["high", "exact", "draft", "interactive"]);
    app.apply(Action::NextQuality);
    app.apply(Action::NextQuality);
    // A frame of `exact` takes the terminal's cap of 4 samples; refinement adds the rest.
    let line = status(&screen, &app);
    assert!(line.contains("exact") && line.contains(" 4 spp"), "{line}");
}
