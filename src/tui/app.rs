//! The workbench's state and how each action changes it. Drawing reads this state; nothing here
//! touches the terminal. Changes mark what must be redrawn, so an idle screen costs nothing.

mod displacement;
mod scene_files;
mod scene_switching;
mod workbench_state;

use super::action::Action;
use super::clock::Clock;
use super::diagnostic_box::DiagnosticBox;
use super::export::ExportJob;
use super::frame_report::FrameReport;
use super::help::Help;
use super::image_shelf::ImageShelf;
use super::kept_scene::KeptScene;
use super::keymap::action_for;
use super::light::move_lights;
use super::material_controls as controls;
use super::message_history::Log;
use super::message_log::LogView;
use super::options::WorkbenchOptions;
use super::orbit::Orbit;
use super::overlay::{Overlay, OverlayKind, Reply, WorkbenchState};
use super::param_panel::ParamPanel;
use super::render::View;
use super::scene_picker::ScenePicker;
use super::scene_setup::{check_settings, dress, first_bumped_object, prepare, shelf_for};
use super::status_message::{INFO_LIFETIME, Message};
use super::view_mode::ViewMode;
use crate::Error;
use crate::overrides::Override;
use crate::quality::Preset;
use crate::quality::Quality;
use crate::scene::Camera;
use crate::scene::PreparedScene;
use crate::scene::{Material, MaterialChoice, Scene};
use crate::shadow::ShadowCache;
use crate::surface::Surface;
use crate::term::graphics::Protocol;
use crate::term::{ColorMode, GlyphSet};
use crate::watch::Reloader;
use crate::watch::open_watched;
use crossterm::event::KeyEvent;
use std::path::PathBuf;
use std::time::{Duration, Instant};

pub struct App {
    pub(super) scenes: Vec<String>,
    pub(super) scene_index: usize,
    pub(super) prepared: PreparedScene,
    pub(super) orbit: Orbit,
    /// The object the material keys edit, and its selected bump parameter.
    pub(super) object: usize,
    pub(super) param: usize,
    pub(super) view_mode: ViewMode,
    /// The preset `Q` cycles.
    pub(super) quality: Preset,
    /// What is rendered: the preset with the scene file's `[quality]` settings and the `--set`
    /// ones over it.
    pub(super) quality_in_use: Quality,
    /// The shadow maps of the last frame, drawn again when the view or the lights change.
    pub(super) shadow_cache: ShadowCache,
    pub(super) glyphs: GlyphSet,
    /// The pixel protocol the picture is sent in; `None` draws it in `glyphs`.
    pub(super) graphics: Option<Protocol>,
    /// The protocols the terminal speaks, which `g` cycles through after the glyph sets.
    pub(super) graphics_supported: Vec<Protocol>,
    pub(super) colors: ColorMode,
    /// `--cell-size`: a cell's pixels, for terminals that do not report them.
    pub(super) cell_size: Option<(u32, u32)>,
    /// `--set` settings, applied at every load.
    settings: Vec<Override>,
    /// `--bump` and `--texture`, applied at every load before the settings.
    choice: MaterialChoice,
    pub(super) clock: Clock,
    /// The boxes over the picture, the topmost last; it takes keys first.
    overlays: Vec<Box<dyn Overlay>>,
    pub(super) quit: bool,
    message: Message,
    /// Every message of the run.
    log: Log,
    started: Instant,
    /// Whether `q` has said what quitting would cancel.
    quit_warned: bool,
    /// The scenes shown before, as they were left, by their place in `scenes`.
    kept: Vec<Option<KeptScene>>,
    /// Until when the edited object's edges are drawn over the picture (after `o`).
    marked_until: Option<Instant>,
    pub(super) report: FrameReport,
    export_size: (u32, u32),
    export_samples: u32,
    export_dir: PathBuf,
    /// The export rendering in the background, if any.
    pub(super) export_job: Option<ExportJob>,
    pub(super) dirty: Dirty,
    /// The images the pattern and texture keys offer.
    images: ImageShelf,
    /// Watches the current scene's files; None for built-in scenes.
    reloader: Option<Reloader>,
    /// Whether files are watched (`--no-watch` turns it off).
    watch: bool,
    /// The message on show and when it first was, to let an `Info` expire.
    message_seen: (Message, Instant),
}

/// `material_controls::cycle_bump` or `cycle_texture`.
type Cycle = fn(&mut Material, &Surface, i32, &mut ImageShelf) -> Result<String, String>;

/// How long the object `o` moves to stays marked in the picture.
const MARK_LIFETIME: Duration = Duration::from_millis(1500);

/// What must be redrawn: the picture (re-render) or only the text around it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Dirty {
    pub picture: bool,
    pub text: bool,
}

impl Dirty {
    const ALL: Dirty = Dirty {
        picture: true,
        text: true,
    };
}

impl App {
    /// Loads the first scene; every named scene is checked first, so a typo fails before the
    /// terminal is taken over.
    pub fn new(options: &WorkbenchOptions, colors: ColorMode) -> Result<App, Error> {
        if options.scenes.is_empty() {
            return Err(Error::InvalidArgument("no scene to show".into()));
        }
        check_settings(&options.scenes, &options.settings, &options.choice)?;
        let (mut scene, reloader) = open_watched(&options.scenes[0], options.watch)?;
        dress(&options.settings, &options.choice, &mut scene)?;
        let quality = options.quality;
        let orbit = Orbit::from_camera(&scene.camera);
        let (prepared, quality_in_use) = prepare(scene, quality, &options.settings)?;
        let start_time = prepared.scene.time;
        let images = shelf_for(&prepared.scene, &options.scenes[0]);
        Ok(App {
            scenes: options.scenes.clone(),
            watch: options.watch,
            scene_index: 0,
            object: first_bumped_object(&prepared.scene),
            param: 0,
            prepared,
            orbit,
            view_mode: ViewMode::default(),
            shadow_cache: ShadowCache::default(),
            quality,
            quality_in_use,
            glyphs: options.glyphs,
            graphics: None,
            graphics_supported: Vec::new(),
            colors,
            cell_size: options.cell_size,
            settings: options.settings.clone(),
            choice: options.choice.clone(),
            clock: Clock::new(options.fps, start_time),
            overlays: Vec::new(),
            quit: false,
            message: Message::None,
            log: Log::default(),
            started: Instant::now(),
            quit_warned: false,
            kept: (0..options.scenes.len()).map(|_| None).collect(),
            marked_until: None,
            report: FrameReport::default(),
            export_size: options.export_size,
            export_samples: options.export_samples,
            export_dir: options.export_dir.clone(),
            export_job: None,
            dirty: Dirty::ALL,
            reloader,
            images,
            message_seen: (Message::None, Instant::now()),
        })
    }

    pub fn camera(&self) -> Camera {
        self.orbit.camera()
    }

    pub fn scene(&self) -> &Scene {
        &self.prepared.scene
    }

    /// What the last frame cost.
    pub fn frame_report(&self) -> &FrameReport {
        &self.report
    }

    pub fn view_mode(&self) -> ViewMode {
        self.view_mode
    }

    /// The preset `Q` cycles.
    pub fn quality_preset(&self) -> Preset {
        self.quality
    }

    /// What is rendered: the preset with the scene's and the `--set` settings over it.
    pub fn quality_in_use(&self) -> &Quality {
        &self.quality_in_use
    }

    /// Sends the picture in `protocol`'s pixels, or in glyphs for `None`.
    pub fn set_graphics(&mut self, protocol: Option<Protocol>) {
        self.graphics = protocol;
        self.dirty = Dirty::ALL;
    }

    pub fn set_colors(&mut self, colors: ColorMode) {
        self.colors = colors;
        self.dirty = Dirty::ALL;
    }

    /// Whether the workbench has been asked to end.
    pub fn quitting(&self) -> bool {
        self.quit
    }

    /// Whether an export is rendering in the background.
    pub fn exporting(&self) -> bool {
        self.export_job.is_some()
    }

    /// What must be drawn again.
    pub fn dirty(&self) -> Dirty {
        self.dirty
    }

    /// What the link to the terminal has carried and how fast, for the next status line.
    pub(super) fn set_link(&mut self, throughput: Option<f64>, bytes_sent: u64) {
        self.report.link_throughput = throughput;
        self.report.bytes_sent = bytes_sent;
    }

    /// Whether the picture changes with time, so frames must keep coming while the clock runs.
    pub fn animates(&self) -> bool {
        self.prepared
            .objects
            .iter()
            .any(|o| o.material.moves_with_time())
    }

    /// The material the material keys edit.
    /// The edited object's material; a displaced object's bump is its shape, and is read from
    /// the scene.
    pub fn material(&self) -> Option<&Material> {
        match self.is_displaced() {
            true => self
                .prepared
                .scene
                .objects
                .get(self.object)
                .map(|o| &o.material),
            false => self.prepared.objects.get(self.object).map(|o| &o.material),
        }
    }

    /// A key: the topmost overlay's if it takes it, else the key map's.
    pub fn key(&mut self, key: &KeyEvent) {
        self.dirty.text = true;
        let Some(mut top) = self.overlays.pop() else {
            if let Some(action) = action_for(key) {
                self.apply(action);
            }
            return;
        };
        let reply = top.key(key, self);
        let stays = !matches!(reply, Reply::Close | Reply::CloseAnd(_));
        if stays {
            self.overlays.push(top);
        }
        match reply {
            Reply::Taken | Reply::Close => {}
            Reply::Act(action) | Reply::CloseAnd(action) => self.apply(action),
            Reply::Pass => {
                if let Some(action) = action_for(key) {
                    self.apply(action);
                }
            }
        }
    }

    /// The open overlays, the topmost last.
    pub fn overlays(&self) -> impl Iterator<Item = &dyn Overlay> {
        self.overlays.iter().map(|o| o.as_ref())
    }

    /// Opens `overlay` on top, or closes one of its kind that is open.
    fn toggle(&mut self, overlay: Box<dyn Overlay>) {
        let kind = overlay.kind();
        match self.is_open(kind) {
            true => self.close(kind),
            false => self.overlays.push(overlay),
        }
    }

    fn close(&mut self, kind: OverlayKind) {
        self.overlays.retain(|o| o.kind() != kind);
    }

    pub fn message(&self) -> &Message {
        &self.message
    }

    /// Shows `message` in the status line and keeps it in the log.
    pub fn tell(&mut self, message: Message) {
        self.log
            .keep(self.started.elapsed().as_secs_f64(), &message);
        self.message = message;
        self.dirty.text = true;
    }

    /// Shows `brief` in the status line and keeps `whole`, which says more, in the log.
    pub fn tell_briefly(&mut self, brief: String, whole: &[String]) {
        let seconds = self.started.elapsed().as_secs_f64();
        for line in whole {
            self.log.keep(seconds, &Message::Info(line.clone()));
        }
        self.message = Message::Info(brief);
        self.dirty.text = true;
    }

    /// The object marked in the picture, while the mark lasts.
    pub fn marked_object(&self) -> Option<usize> {
        self.marked_until.map(|_| self.object)
    }

    pub fn apply(&mut self, action: Action) {
        self.dirty.text = true;
        match action {
            Action::Quit => self.quit_unless_busy(),
            Action::QuitNow => self.quit = true,
            Action::ToggleHelp => self.toggle(Box::<Help>::default()),
            Action::TogglePanel => self.toggle(Box::<ParamPanel>::default()),
            Action::ToggleLog => self.toggle(Box::<LogView>::default()),
            Action::OpenPicker => {
                self.close(OverlayKind::Picker);
                self.overlays.push(Box::<ScenePicker>::default());
            }
            Action::Back => match self.overlays.pop() {
                Some(_) => {}
                None => self.tell(Message::Info("nothing to close; q quits".into())),
            },
            Action::NextScene => self.switch_scene(1),
            Action::PreviousScene => self.switch_scene(-1),
            Action::GoToScene(index) => self.go_to_picked(index),
            Action::Export => self.export(),
            Action::SaveScene => self.save_scene(),
            _ => self.apply_to_picture(action),
        }
    }

    /// Actions that change what the picture shows.
    fn apply_to_picture(&mut self, action: Action) {
        self.dirty.picture = true;
        match action {
            Action::Orbit(yaw, pitch) => self.orbit.rotate(yaw, pitch),
            Action::Pan(right, up) => self.orbit.pan(right, up),
            Action::Zoom(factor) => self.orbit.zoom(factor),
            Action::ResetCamera => self.orbit = Orbit::from_camera(&self.scene().camera),
            Action::MoveLight(azimuth, elevation) => {
                let center = self.orbit.target;
                move_lights(&mut self.prepared.scene.lights, center, azimuth, elevation);
            }
            Action::ResetLights => match self.scene_as_saved() {
                Ok(saved) => self.prepared.scene.lights = saved.lights,
                Err(e) => self.tell(Message::Error(e.to_string())),
            },
            Action::ToggleShadows => {
                let scene = &mut self.prepared.scene;
                scene.shadows = !scene.shadows;
                let state = if scene.shadows { "on" } else { "off" };
                self.tell(Message::Info(format!("shadows {state}")));
            }
            Action::DropLiveValues => self.drop_live_values(),
            Action::NextViewMode => self.view_mode = self.view_mode.cycled(1),
            Action::PreviousViewMode => self.view_mode = self.view_mode.cycled(-1),
            Action::NextQuality => {
                self.reprepare(self.quality.next());
                self.tell(Message::Info(format!("quality: {}", self.quality.name())));
            }
            Action::NextGlyphs => {
                self.next_picture_kind();
                let name = super::mode_names::picture_name(self.graphics, self.glyphs);
                self.tell(Message::Info(format!("picture: {name}")));
            }
            Action::NextColors => {
                self.colors = next_colors(self.colors);
                let name = super::mode_names::colors_name(self.colors);
                self.tell(Message::Info(format!("colours: {name}")));
            }
            Action::TogglePause => self.toggle_clock(),
            Action::StepClock => self.clock.step(),
            _ => self.apply_to_material(action),
        }
    }

    fn apply_to_material(&mut self, action: Action) {
        if self.prepared.objects.is_empty() {
            self.tell(Message::Info("this scene has no objects".into()));
            return;
        }
        let param = self.param;
        let done = match action {
            Action::NextObject => {
                self.object = (self.object + 1) % self.prepared.objects.len();
                self.param = 0;
                self.marked_until = Some(Instant::now() + MARK_LIFETIME);
                let name = self.object_name();
                return self.tell(Message::Info(format!("editing object {name}")));
            }
            Action::NextPattern => return self.cycle(controls::cycle_bump, 1),
            Action::PreviousPattern => return self.cycle(controls::cycle_bump, -1),
            Action::NextTexture => return self.cycle(controls::cycle_texture, 1),
            Action::PreviousTexture => return self.cycle(controls::cycle_texture, -1),
            Action::ScaleBump(factor) => self.edit_material(|m| controls::scale_bump(m, factor)),
            Action::InvertBump => self.edit_material(controls::invert_bump),
            Action::ToggleDisplacement => return self.toggle_displacement(),
            Action::SelectParam(step) => self.select_param(step),
            Action::AdjustParam(steps) => {
                self.edit_material(|m| controls::adjust_param(m, param, steps))
            }
            Action::SelectParamAt(row) => {
                let found = row < self.param_rows().len();
                self.param = if found { row } else { self.param };
                found
            }
            Action::AdjustParamAt(row, steps) => {
                self.param = row;
                self.edit_material(|m| controls::adjust_param(m, row, steps))
            }
            Action::SetParam(row, value) => {
                self.param = row;
                self.edit_material(|m| controls::set_param(m, row, value))
            }
            _ => true,
        };
        self.tell(match done {
            true => Message::None,
            false => Message::Info(
                "this object has no pattern parameters (p adds a bump pattern, t a texture)".into(),
            ),
        });
    }

    /// Puts the next (`step` 1) or previous pattern or image on the edited object with `cycle`
    /// (`cycle_bump` or `cycle_texture`); an image that does not load is reported.
    fn cycle(&mut self, cycle: Cycle, step: i32) {
        let Some(object) = self.prepared.scene.objects.get(self.object) else {
            return;
        };
        let mut material = object.material.clone();
        match cycle(&mut material, &object.surface, step, &mut self.images) {
            Ok(name) => {
                self.edit_material(|m| {
                    *m = material.clone();
                    true
                });
                self.param = 0;
                self.tell(Message::Info(format!(
                    "now {}",
                    crate::term::sanitize(&name)
                )));
            }
            Err(e) => self.tell(Message::Error(crate::term::sanitize(&e).into_owned())),
        }
    }

    /// Applies `edit` to the current object's material, both as rendered and as kept in the scene
    /// (which a quality change re-prepares from). Returns what `edit` returned. A displaced
    /// object's bump is its shape, so it is cut again.
    fn edit_material(&mut self, edit: impl Fn(&mut Material) -> bool) -> bool {
        let index = self.object;
        if let Some(object) = self.prepared.scene.objects.get_mut(index)
            && object.displace
        {
            let edited = edit(&mut object.material);
            self.reprepare(self.quality);
            return edited;
        }
        let rendered = self
            .prepared
            .objects
            .get_mut(index)
            .is_some_and(|o| edit(&mut o.material));
        if let Some(object) = self.prepared.scene.objects.get_mut(index) {
            edit(&mut object.material);
        }
        rendered
    }

    /// The next glyph set, and after the last one each pixel protocol the terminal speaks.
    fn next_picture_kind(&mut self) {
        let supported = &self.graphics_supported;
        match self.graphics {
            None if self.glyphs == GlyphSet::Sextant && !supported.is_empty() => {
                self.graphics = Some(supported[0]);
            }
            None => self.glyphs = next_glyphs(self.glyphs),
            Some(protocol) => {
                let index = supported.iter().position(|&p| p == protocol);
                self.graphics = index.and_then(|i| supported.get(i + 1)).copied();
                if self.graphics.is_none() {
                    self.glyphs = GlyphSet::HalfBlock;
                }
            }
        }
    }

    fn select_param(&mut self, step: i32) -> bool {
        let count = self.param_rows().len();
        if count == 0 {
            return false;
        }
        self.param = (self.param as i32 + step).rem_euclid(count as i32) as usize;
        true
    }

    /// `q`: quits, but while an export is under way first says once what that cancels.
    fn quit_unless_busy(&mut self) {
        match &self.export_job {
            Some(job) if !self.quit_warned => {
                let path = crate::term::sanitize(&job.path.display().to_string()).into_owned();
                self.quit_warned = true;
                self.tell(Message::Info(format!(
                    "quitting cancels the export of {path}: q again quits, or wait for it"
                )));
            }
            _ => self.quit = true,
        }
    }

    /// Shows `error`: its first line in the status line, a message of several lines (a file's
    /// line and caret) whole over the picture.
    fn show_error(&mut self, error: &Error) {
        let text = error.to_string();
        let first = text.lines().next().unwrap_or_default().to_string();
        self.close(OverlayKind::Diagnostic);
        if first.len() < text.len() {
            self.overlays
                .push(Box::new(DiagnosticBox { message: text }));
        }
        self.tell(Message::Error(first));
    }

    /// Pauses or runs the clock, saying so, and saying when nothing shown moves with it.
    fn toggle_clock(&mut self) {
        self.clock.toggle();
        let state = match self.clock.is_running() {
            true => "running",
            false => "paused",
        };
        self.tell(Message::Info(match self.animates() {
            true => format!("clock {state}"),
            false => format!(
                "clock {state}; nothing here moves with time (a pattern's speed of 0 stands still)"
            ),
        }));
    }

    /// Tessellates again for the preset `quality`; one that does not fit keeps the current one.
    fn reprepare(&mut self, quality: Preset) {
        match prepare(self.prepared.scene.clone(), quality, &self.settings) {
            Ok((prepared, in_use)) => {
                if let Some(notice) = prepared.notices.first() {
                    self.tell(Message::Info(crate::term::sanitize(notice).into_owned()));
                }
                self.prepared = prepared;
                self.quality = quality;
                self.quality_in_use = in_use;
            }
            Err(e) => self.show_error(&e),
        }
    }

    /// Everything that decides the picture now, apart from its size.
    pub fn view(&self) -> View<'_> {
        View {
            prepared: &self.prepared,
            camera: self.camera(),
            mode: self.view_mode,
            time: self.clock.time(),
            quality: self.quality_in_use,
            shadows: &self.shadow_cache,
            marked: self.marked_object(),
        }
    }

    fn export(&mut self) {
        if let Some(job) = &self.export_job {
            let path = job.path.display().to_string();
            self.tell(Message::Info(format!("still exporting {path}")));
            return;
        }
        let source = &self.scenes[self.scene_index];
        let shape = (self.export_size, self.export_samples);
        let job = ExportJob::start(source, &self.view(), shape, &self.export_dir);
        let (w, h) = self.export_size;
        let path = job.path.display();
        self.tell(Message::Info(format!(
            "exporting {path} ({w}x{h}, {} spp)…",
            self.export_samples
        )));
        self.export_job = Some(job);
        self.dirty.text = true;
    }

    /// Reports a background export once it has finished.
    pub fn poll_export(&mut self) {
        let Some(outcome) = self.export_job.as_mut().and_then(ExportJob::finished) else {
            return;
        };
        let job = self.export_job.take().expect("a finished job");
        self.tell(match outcome {
            Ok(()) if job.has_recipe => Message::Info(format!("exported {}", job.path.display())),
            Ok(()) => Message::Info(format!(
                "exported {} (a picture only: this view carries no recipe for render --from)",
                job.path.display()
            )),
            Err(e) => Message::Error(e.to_string()),
        });
        self.dirty.text = true;
    }

    /// Clears an `Info` message once it has been on show for `INFO_LIFETIME`; errors stay while
    /// they hold (a broken file is reported until it is mended).
    pub fn expire_message(&mut self, now: Instant) {
        if self.marked_until.is_some_and(|until| now >= until) {
            self.marked_until = None;
            self.dirty.picture = true;
        }
        if self.message_seen.0 != self.message {
            self.message_seen = (self.message.clone(), now);
        }
        let age = now.saturating_duration_since(self.message_seen.1);
        if matches!(self.message, Message::Info(_)) && age >= INFO_LIFETIME {
            self.tell(Message::None);
            self.dirty.text = true;
        }
    }

    /// Marks everything for redrawing, as after a resize.
    pub fn invalidate(&mut self) {
        self.dirty = Dirty::ALL;
    }

    /// Marks the text for redrawing: the screen sends whatever it has not yet sent.
    pub fn redraw_text(&mut self) {
        self.dirty.text = true;
    }

    pub fn mark_drawn(&mut self) {
        self.dirty = Dirty {
            picture: false,
            text: false,
        };
    }
}

fn next_glyphs(glyphs: GlyphSet) -> GlyphSet {
    match glyphs {
        GlyphSet::HalfBlock => GlyphSet::Quadrant,
        GlyphSet::Quadrant => GlyphSet::Sextant,
        GlyphSet::Sextant => GlyphSet::HalfBlock,
    }
}

fn next_colors(colors: ColorMode) -> ColorMode {
    match colors {
        ColorMode::TrueColor => ColorMode::Ansi256,
        ColorMode::Ansi256 => ColorMode::Ansi16,
        ColorMode::Ansi16 => ColorMode::Monochrome,
        ColorMode::Monochrome => ColorMode::TrueColor,
    }
}
