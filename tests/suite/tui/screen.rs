//! The workbench's screen without a terminal: frames are drawn only when something changed, tiny
//! and empty screens do not panic, and the export key writes a PNG.

use bumpwork::export::metadata::{RECIPE, SCENE, read_png_text};
use bumpwork::export::read_png_rgb8;
use bumpwork::still::Recipe;
use bumpwork::term::{ColorChoice, ColorMode, SYNC_BEGIN, SYNC_END};
use bumpwork::tui::{Action, App, Message, Screen, ViewMode, WorkbenchOptions};
use std::path::Path;
use std::time::{Duration, Instant};

fn app() -> App {
    App::new(&options(), ColorMode::TrueColor).unwrap()
}

fn options() -> WorkbenchOptions {
    WorkbenchOptions {
        scenes: vec!["plane-dimples".into(), "sphere-on-plane-dimples".into()],
        colors: ColorChoice::Fixed(ColorMode::TrueColor),
        ..WorkbenchOptions::default()
    }
}

/// [`app`] exporting `size` stills of `samples` samples into `dir`.
fn app_exporting(dir: &Path, size: (u32, u32), samples: u32) -> App {
    let options = WorkbenchOptions {
        export_dir: dir.to_path_buf(),
        export_size: size,
        export_samples: samples,
        ..options()
    };
    App::new(&options, ColorMode::TrueColor).unwrap()
}

fn draw(screen: &mut Screen, app: &mut App) -> Vec<u8> {
    let mut out = Vec::new();
    screen.draw(app, &mut out).unwrap();
    out
}

#[test]
fn an_idle_screen_writes_nothing_and_each_frame_is_one_synchronized_update() {
    let mut app = app();
    let mut screen = Screen::new(60, 20);
    let first = draw(&mut screen, &mut app);
    assert!(first.starts_with(SYNC_BEGIN) && first.ends_with(SYNC_END));
    assert!(
        draw(&mut screen, &mut app).is_empty(),
        "idle frame wrote bytes"
    );
    app.apply(Action::Orbit(10.0, 0.0));
    let orbit = draw(&mut screen, &mut app);
    assert!(!orbit.is_empty() && orbit.len() < first.len() * 2);
    assert!(orbit.starts_with(SYNC_BEGIN) && orbit.ends_with(SYNC_END));
    assert!(draw(&mut screen, &mut app).is_empty());
}

#[test]
fn tiny_screens_do_not_panic_and_empty_ones_say_they_have_no_size() {
    let mut app = app();
    for (cols, rows) in [
        (0, 0),
        (1, 0),
        (0, 1),
        (1, 1),
        (2, 1),
        (1, 2),
        (3, 3),
        (7, 2),
    ] {
        let mut screen = Screen::new(cols, rows);
        app.invalidate();
        let out = draw(&mut screen, &mut app);
        if cols == 0 || rows == 0 {
            // No picture, only the note that the terminal reports no size.
            let text = String::from_utf8_lossy(&out);
            assert!(text.contains("0×0 cells"), "{text}");
            assert!(!text.contains('▀') && !text.contains('▄'), "{text}");
        }
        for action in [Action::NextScene, Action::ToggleHelp, Action::NextViewMode] {
            app.apply(action);
            draw(&mut screen, &mut app);
        }
        app.apply(Action::ToggleHelp);
    }
}

#[test]
fn every_view_mode_glyph_set_and_colour_mode_draws() {
    let mut app = app();
    let mut screen = Screen::new(30, 10);
    for _ in 0..6 {
        for _ in 0..3 {
            for _ in 0..4 {
                app.apply(Action::NextColors);
                assert!(!draw(&mut screen, &mut app).is_empty());
            }
            app.apply(Action::NextGlyphs);
        }
        app.apply(Action::NextViewMode);
    }
}

/// An empty directory of its own, named after `name`, removed when dropped.
fn fresh_dir(name: &str) -> tempfile::TempDir {
    tempfile::Builder::new()
        .prefix(&format!("bumpwork-tui-{name}-"))
        .tempdir()
        .expect("a temporary directory")
}

/// Waits for the export the app started and returns its final status message.
fn finished_export_message(app: &mut App) -> String {
    assert!(app.exporting());
    let started = Instant::now();
    while app.exporting() && started.elapsed() < Duration::from_secs(30) {
        app.poll_export();
        std::thread::sleep(Duration::from_millis(10));
    }
    match app.message() {
        Message::Info(text) => text.clone(),
        other => panic!("{other:?}"),
    }
}

#[test]
fn a_wireframe_export_is_a_picture_and_says_it_carries_no_recipe() {
    let temp = fresh_dir("wire");
    let dir = temp.path().to_path_buf();
    let mut app = app_exporting(&dir, (48, 32), 4);
    while app.view_mode() != ViewMode::Wireframe {
        app.apply(Action::NextViewMode);
    }
    app.apply(Action::Export);
    let text = finished_export_message(&mut app);
    let (path, note) = text
        .strip_prefix("exported ")
        .and_then(|t| t.split_once(" (a picture only"))
        .unwrap_or_else(|| panic!("{text}"));
    let (width, height, _) = read_png_rgb8(Path::new(path)).unwrap();
    assert_eq!((width, height), (48, 32));
    assert!(note.contains("no recipe"), "{note}");
    assert!(
        read_png_text(Path::new(path))
            .unwrap()
            .iter()
            .all(|(k, _)| k != RECIPE)
    );
}

#[test]
fn the_export_key_writes_the_live_view_in_the_background_and_from_makes_it_again() {
    let temp = fresh_dir("export");
    let dir = temp.path().to_path_buf();
    let mut app = app_exporting(&dir, (64, 36), 4);
    // Live edits a still must carry: the camera, a light, a pattern parameter, the bump.
    app.apply(Action::Orbit(0.3, 0.1));
    app.apply(Action::MoveLight(0.5, 0.0));
    app.apply(Action::AdjustParam(10.0));
    app.apply(Action::ScaleBump(2.0));
    app.apply(Action::Export);
    let Message::Info(text) = app.message() else {
        panic!("{:?}", app.message());
    };
    assert!(text.starts_with("exporting "), "{text}");
    let text = finished_export_message(&mut app);
    let path = Path::new(text.strip_prefix("exported ").unwrap());
    let texts = read_png_text(path).unwrap();
    let recipe_text = &texts.iter().find(|(k, _)| k == RECIPE).unwrap().1;
    let recipe = Recipe::parse(recipe_text, "export").unwrap();
    assert_eq!((recipe.width, recipe.height), (64, 36));
    let live = app.quality_preset().quality();
    assert_eq!(
        recipe.quality,
        bumpwork::quality::Quality { samples: 4, ..live }
    );
    let scene = recipe
        .scene(
            &texts.iter().find(|(k, _)| k == SCENE).unwrap().1,
            &recipe.source_directory(),
        )
        .unwrap();
    assert_eq!(scene.camera, app.camera());
    assert_eq!(scene.lights, app.scene().lights);
    assert_eq!(scene.objects[0].material, app.scene().objects[0].material);

    let again = dir.join("again.png");
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_bumpwork"))
        .args([
            "render",
            "--from",
            path.to_str().unwrap(),
            "-o",
            again.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(read_png_rgb8(&again).unwrap(), read_png_rgb8(path).unwrap());
}

#[test]
fn quitting_during_an_export_leaves_no_file() {
    let temp = fresh_dir("cancel");
    let dir = temp.path().to_path_buf();
    let mut app = app_exporting(&dir, (4000, 3000), 64);
    app.apply(Action::Export);
    std::thread::sleep(Duration::from_millis(200));
    drop(app);
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 0);
}

#[test]
fn material_keys_edit_the_bump_and_redraw() {
    use bumpwork::scene::BumpSource;
    let mut app = app();
    let mut screen = Screen::new(60, 20);
    draw(&mut screen, &mut app);
    let params = |app: &App| match &app.material().unwrap().bump.as_ref().unwrap().source {
        BumpSource::Pattern(binding) => (binding.name.clone(), binding.params.clone()),
        _ => panic!("the preset's bump is a pattern"),
    };
    let (name, before) = params(&app);
    app.apply(Action::AdjustParam(10.0));
    assert_ne!(params(&app).1, before, "parameter unchanged");
    assert!(!draw(&mut screen, &mut app).is_empty());
    app.apply(Action::NextPattern);
    assert_ne!(params(&app).0, name);
    assert!(!draw(&mut screen, &mut app).is_empty());
    let strength = |app: &App| app.material().unwrap().bump.as_ref().unwrap().scale();
    let s = strength(&app);
    app.apply(Action::InvertBump);
    assert_eq!(strength(&app), -s);
    app.apply(Action::ScaleBump(2.0));
    assert_eq!(strength(&app), -2.0 * s);
    assert!(!draw(&mut screen, &mut app).is_empty());
}

#[test]
fn an_edited_pattern_file_reloads_and_a_broken_one_keeps_the_view_and_shows_where() {
    let temp = fresh_dir("reload");
    let dir = temp.path().to_path_buf();
    let path = dir.join("live.pat");
    std::fs::write(
        &path,
        "param period = 20 in 2..100\nheight = sin(u / period)\n",
    )
    .unwrap();
    let options = WorkbenchOptions {
        scenes: vec![path.to_str().unwrap().into()],
        ..WorkbenchOptions::default()
    };
    let mut app = App::new(&options, ColorMode::Ansi256).unwrap();
    let mut screen = Screen::new(40, 12);
    draw(&mut screen, &mut app);
    app.reload_if_changed();
    assert_eq!(*app.message(), Message::None, "unchanged file reloaded");

    // The watcher reports asynchronously, after its debounce: poll until the message arrives.
    let wait_for = |app: &mut App, wanted: &dyn Fn(&Message) -> bool| {
        let start = std::time::Instant::now();
        while !wanted(app.message()) {
            assert!(
                start.elapsed().as_secs() < 60,
                "no reload: {:?}",
                app.message()
            );
            std::thread::sleep(std::time::Duration::from_millis(20));
            app.reload_if_changed();
        }
    };
    std::fs::write(&path, "height = u + )\n").unwrap();
    wait_for(&mut app, &|m| matches!(m, Message::Error(_)));
    let Message::Error(error) = app.message() else {
        unreachable!()
    };
    assert!(error.contains("live.pat:1:"), "{error}");
    assert!(
        !draw(&mut screen, &mut app).is_empty(),
        "the error is shown"
    );

    std::fs::write(&path, "height = cos(v / 7)\n").unwrap();
    wait_for(&mut app, &|m| *m == Message::Info("reloaded".into()));
    assert!(!draw(&mut screen, &mut app).is_empty());
}

#[test]
fn with_watching_off_an_edited_file_is_not_reloaded() {
    let temp = fresh_dir("nowatch");
    let dir = temp.path().to_path_buf();
    let path = dir.join("still.pat");
    std::fs::write(&path, "height = sin(u / 20)\n").unwrap();
    let options = WorkbenchOptions {
        scenes: vec![path.to_str().unwrap().into()],
        watch: false,
        ..WorkbenchOptions::default()
    };
    let mut app = App::new(&options, ColorMode::Ansi256).unwrap();
    std::fs::write(&path, "height = u + )\n").unwrap();
    // Longer than the watcher's debounce, several times over: nothing may arrive.
    for _ in 0..25 {
        std::thread::sleep(std::time::Duration::from_millis(20));
        app.reload_if_changed();
    }
    assert_eq!(*app.message(), Message::None);
}

#[test]
fn information_expires_and_errors_stay() {
    let mut app = app();
    let start = Instant::now();
    app.tell(Message::Info("reloaded".into()));
    app.expire_message(start);
    app.expire_message(start + Duration::from_secs(2));
    assert_eq!(*app.message(), Message::Info("reloaded".into()));
    app.expire_message(start + bumpwork::tui::INFO_LIFETIME + Duration::from_millis(1));
    assert_eq!(*app.message(), Message::None);
    assert!(
        app.dirty().text,
        "the status line is drawn again without it"
    );
    app.tell(Message::Error("x.pat:1:1: expected an expression".into()));
    app.expire_message(start + Duration::from_secs(10));
    app.expire_message(start + Duration::from_secs(100));
    assert!(matches!(app.message(), Message::Error(_)));
}

/// The whole screen as text, a line a row.
fn screen_text(screen: &Screen, app: &App) -> String {
    let grid = screen.compose(app);
    (0..screen.layout().rows as usize)
        .map(|row| grid.row(row).iter().map(|c| c.glyph).collect::<String>() + "\n")
        .collect()
}

/// Presses `code` as a terminal sends it.
fn press(app: &mut App, code: crossterm::event::KeyCode) {
    app.key(&crossterm::event::KeyEvent::new(
        code,
        crossterm::event::KeyModifiers::NONE,
    ));
}

#[test]
fn at_80_by_24_the_help_shows_every_key_at_once_and_esc_closes_it() {
    use crossterm::event::KeyCode;
    let mut app = app();
    let screen = Screen::new(80, 24);
    press(&mut app, KeyCode::Char('?'));
    let text = screen_text(&screen, &app);
    let missing: Vec<_> = bumpwork::tui::keymap::help_entries()
        .filter(|(keys, words)| !text.contains(keys) || !text.contains(words))
        .collect();
    assert!(
        missing.is_empty(),
        "not shown at 80x24: {missing:?}\n{text}"
    );
    assert!(text.contains("keys (Esc closes)"), "{text}");
    for needed in ["Esc", "q ", "C-z", "C-l", "drag", "wheel", "click"] {
        assert!(text.contains(needed), "{needed} missing:\n{text}");
    }
    press(&mut app, KeyCode::Esc);
    use bumpwork::tui::WorkbenchState;
    assert!(!app.is_open(bumpwork::tui::OverlayKind::Help));
    assert!(!app.quitting(), "Esc only closes");
    press(&mut app, KeyCode::Esc);
    assert!(!app.quitting(), "Esc with nothing open does not quit");
}

#[test]
fn scene_settings_from_the_command_line_apply_to_the_scenes_that_have_them() {
    let with = |settings: &[&str]| {
        let options = WorkbenchOptions {
            scenes: vec!["plane-dimples".into(), "textured-sphere".into()],
            colors: ColorChoice::Fixed(ColorMode::TrueColor),
            settings: settings
                .iter()
                .map(|s| bumpwork::overrides::Override::parse(s).unwrap())
                .collect(),
            ..WorkbenchOptions::default()
        };
        App::new(&options, ColorMode::TrueColor)
    };
    let app = with(&["bump.params.strength=3", "bump.strength=0.5"]).unwrap();
    let bump = app.scene().objects[0].material.bump.as_ref().unwrap();
    assert_eq!(bump.strength, 0.5);
    let bumpwork::scene::BumpSource::Pattern(binding) = &bump.source else {
        panic!("plane-dimples has a pattern bump");
    };
    assert_eq!(binding.params, vec![3.0]);
    let refused = |settings: &[&str], expected: &str| match with(settings) {
        Err(e) => assert!(e.to_string().contains(expected), "{e}"),
        Ok(_) => panic!("{settings:?} was taken"),
    };
    refused(&["quality.samples=0"], "samples 0 is outside");
    refused(&["bump.nope=1"], "no scene shown has that parameter");
    refused(&["bump.params.strength=9"], "outside strength's range");
}

#[test]
fn keys_take_the_lights_and_the_materials_back_to_the_file() {
    let mut app = app();
    let lights = app.scene().lights.clone();
    let material = app.scene().objects[0].material.clone();
    app.apply(Action::MoveLight(45.0, 10.0));
    app.apply(Action::ScaleBump(2.0));
    app.apply(Action::AdjustParam(5.0));
    assert_ne!(app.scene().lights, lights);
    assert_ne!(app.scene().objects[0].material, material);
    let camera = app.camera();
    app.apply(Action::DropLiveValues);
    assert_eq!(app.scene().objects[0].material, material);
    assert_ne!(app.scene().lights, lights, "the lights have their own key");
    app.apply(Action::ResetLights);
    assert_eq!(app.scene().lights, lights);
    assert_eq!(app.camera(), camera, "the camera has its own key");
}

/// PSNR in dB between two 8-bit pictures of the same size.
fn psnr(a: &[u8], b: &[u8]) -> f64 {
    let squared: f64 = a
        .iter()
        .zip(b)
        .map(|(&p, &q)| (f64::from(p) - f64::from(q)).powi(2))
        .sum();
    10.0 * (255.0f64.powi(2) * a.len() as f64 / squared.max(1e-9)).log10()
}

#[test]
fn the_saved_scene_renders_what_the_export_key_exports() {
    let temp = fresh_dir("save");
    let dir = temp.path().to_path_buf();
    let mut app = app_exporting(&dir, (64, 36), 4);
    app.apply(Action::NextScene);
    // The same live edits as an export carries: camera, light, parameter, bump, quality, time.
    app.apply(Action::TogglePause);
    app.apply(Action::StepClock);
    app.apply(Action::NextQuality);
    app.apply(Action::Orbit(20.0, 5.0));
    app.apply(Action::MoveLight(30.0, 0.0));
    app.apply(Action::AdjustParam(10.0));
    app.apply(Action::ScaleBump(2.0));
    // An image put on by the keys: the texture and the bump go back past the patterns.
    app.apply(Action::PreviousTexture);
    assert_eq!(*app.message(), Message::Info("now gravel".into()));
    app.apply(Action::NextObject);
    let image_bump = |app: &App| {
        matches!(
            app.material().unwrap().bump.as_ref().unwrap().source,
            bumpwork::scene::BumpSource::Image(_)
        )
    };
    for _ in 0..100 {
        if image_bump(&app) {
            break;
        }
        app.apply(Action::NextPattern);
    }
    assert!(image_bump(&app), "the bump keys reach the images");
    app.apply(Action::SaveScene);
    let Message::Info(text) = app.message().clone() else {
        panic!("{:?}", app.message());
    };
    let saved = Path::new(text.strip_prefix("saved the view as ").unwrap()).to_path_buf();
    app.apply(Action::Export);
    let exported = finished_export_message(&mut app);
    let exported = Path::new(exported.strip_prefix("exported ").unwrap()).to_path_buf();
    let render = |args: &[&std::ffi::OsStr], out: &Path| {
        let output = std::process::Command::new(env!("CARGO_BIN_EXE_bumpwork"))
            .args(args)
            .args(["--size", "64x36", "-o"])
            .arg(out)
            .output()
            .unwrap();
        assert!(
            output.status.success(),
            "{}",
            String::from_utf8_lossy(&output.stderr)
        );
        read_png_rgb8(out).unwrap().2
    };
    let from_scene = render(
        &["render".as_ref(), saved.as_os_str()],
        &dir.join("scene.png"),
    );
    let from_still = render(
        &["render".as_ref(), "--from".as_ref(), exported.as_os_str()],
        &dir.join("still.png"),
    );
    let saved_text = std::fs::read_to_string(&saved).unwrap();
    let saved_scene = bumpwork::scene::parse_scene(&saved_text, "saved.toml").unwrap();
    assert!(saved_scene.time > 0.0, "the clock's time is saved");
    let quality = bumpwork::quality::Quality::high().with_settings(&saved_scene.quality);
    assert_eq!(
        quality.unwrap().samples,
        4,
        "the export's samples are saved"
    );
    let db = psnr(&from_scene, &from_still);
    assert!(
        db >= 40.0,
        "the saved scene and the export agree to {db:.1} dB"
    );
    // A second save takes a new name.
    app.apply(Action::SaveScene);
    let Message::Info(again) = app.message().clone() else {
        panic!("{:?}", app.message());
    };
    assert_ne!(again, text);
}
