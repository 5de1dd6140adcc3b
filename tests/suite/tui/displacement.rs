//! The workbench's displacement key: the edited object drawn as the surface its bump moves it
//! to, or back as the unmoved surface with Blinn's bump, and the bump still edited either way.

use bumpwork::tui::{Action, App, Screen};

fn app(scene: &str) -> App {
    super::true_colour_app(scene)
}

fn status(app: &App) -> String {
    let screen = Screen::new(120, 30);
    let grid = screen.compose(app);
    let row = screen.layout().status_row.unwrap() as usize;
    grid.row(row).iter().map(|c| c.glyph).collect()
}

#[test]
fn the_key_displaces_the_edited_object_and_back_and_its_bump_stays_editable() {
    let mut app = app("big-sphere-dimples-displaced");
    assert!(app.is_displaced(), "the scene asks for displacement");
    assert!(status(&app).contains("displaced"), "{}", status(&app));
    app.apply(Action::ToggleDisplacement);
    assert!(!app.is_displaced());
    assert!(status(&app).contains("bump only"), "{}", status(&app));
    app.apply(Action::ToggleDisplacement);
    assert!(app.is_displaced());
    let strength = |app: &App| app.material().unwrap().bump.as_ref().unwrap().strength;
    let before = strength(&app);
    app.apply(Action::ScaleBump(2.0));
    assert_eq!(strength(&app), 2.0 * before);
    assert!(
        app.is_displaced(),
        "a stronger bump is cut again, still displaced"
    );
}

#[test]
fn a_slope_pattern_says_it_has_no_height_to_displace_by() {
    let mut app = app("big-sphere-dimples");
    app.apply(Action::ToggleDisplacement);
    assert!(!app.is_displaced());
    assert!(status(&app).contains("only a slope"), "{}", status(&app));
}
