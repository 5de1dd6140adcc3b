//! The event loop: draw what changed, wait for input or the next animation frame, repeat; and
//! give the terminal back however it ends.

use super::app::App;
use super::frame_pacing::FramePacer;
use super::input::{Input, InputState};
use super::mode_names::colors_name;
use super::options::WorkbenchOptions;
use super::pixel_picture::PixelRoute;
use super::render::DEFAULT_CELL_ASPECT;
use super::screen::Screen;
use crate::Error;
use crate::term::graphics::{GraphicsChoice, GraphicsFound, Replies, decide, query_terminal};
use crate::term::{
    ShutdownSignals, TerminalGuard, in_tmux, tmux_client_features, tmux_passes_through,
};
use crossterm::event;
use std::io::{self, Write};
use std::path::Path;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

/// Longest wait for input, so shutdown signals are noticed promptly.
const SIGNAL_POLL: Duration = Duration::from_millis(100);

/// Runs the workbench until the user quits. A shutdown signal restores the terminal and exits
/// the process with 128 + the signal number.
pub fn run(options: &WorkbenchOptions) -> Result<(), Error> {
    use std::io::IsTerminal;
    // A misspelt scene is answered as `render` answers it, terminal or not.
    if let Some(error) = options
        .scenes
        .iter()
        .find_map(|name| crate::scene::unknown_scene(name))
    {
        return Err(error);
    }
    let colors =
        (options.colors).resolve_with_reason(|name| std::env::var(name).ok(), tmux_client_features);
    // Bad files and settings are told first, terminal or not.
    let mut app = App::new(options, colors.mode)?;
    if !io::stdin().is_terminal() || !io::stdout().is_terminal() {
        return Err(Error::InvalidArgument(
            "the workbench needs a terminal, and its standard input or output is not one \
             (`bumpwork render` makes a still without one)"
                .into(),
        ));
    }
    let signals = ShutdownSignals::register().map_err(terminal_error)?;
    signals.watch_terminal().map_err(terminal_error)?;
    let guard = TerminalGuard::enter(options.mouse).map_err(terminal_error)?;
    let found = find_graphics(options.graphics).map_err(terminal_error)?;
    app.graphics = found.chosen;
    app.graphics_supported = found.supported.clone();
    let picture = found.chosen.map_or("blocks", |p| p.name());
    let colours = colors_name(colors.mode);
    app.tell_briefly(
        format!("{picture}, {colours} colours; M says why"),
        &[
            format!("picture: {picture} ({})", found.reason),
            format!("colours: {colours} ({}; --colors sets them)", colors.reason),
        ],
    );
    let route = PixelRoute {
        through_tmux: found.through_tmux,
        cell_pixels: cell_pixels(options.cell_size, found.cell_pixels),
        sixel_limit: found.sixel_limit,
    };
    let result = event_loop(&mut app, &signals, options.mouse, route);
    drop(guard);
    // On the normal screen now: say what became of an export still running.
    if let Some(job) = app.export_job.take() {
        let path = job.path.clone();
        // Dropped: cancelled and waited for, its temporary file removed.
        drop(job);
        eprintln!(
            "bumpwork: the export of {} was cancelled on quitting; nothing was written",
            crate::term::sanitize(&path.display().to_string())
        );
    }
    if let Some(signal) = signals.received() {
        // Cancels an export under way and waits for it, so its temporary file is removed.
        drop(app);
        std::process::exit(signal.exit_code());
    }
    result.map_err(terminal_error)
}

fn event_loop(
    app: &mut App,
    signals: &ShutdownSignals,
    mouse: bool,
    route: PixelRoute,
) -> io::Result<()> {
    // SIGTSTP (the shell's `kill -TSTP`, a terminal's suspend key outside raw mode) suspends as
    // Ctrl-Z does, instead of stopping the process with the terminal raw.
    let suspend_asked = Arc::new(AtomicBool::new(false));
    let _tstp = Registered(signal_hook::flag::register(
        signal_hook::consts::SIGTSTP,
        suspend_asked.clone(),
    )?);
    let (cols, rows) = crossterm::terminal::size()?;
    let mut screen = Screen::new(cols, rows);
    screen.set_cell_aspect(cell_aspect(app.cell_size), app);
    screen.set_pixel_route(route, app);
    let mut pacer = FramePacer::default();
    pacer.probe((cols, rows));
    let mut session = Session {
        app,
        screen,
        input: InputState::default(),
        pacer,
        signals,
        suspend: false,
        frame: Vec::new(),
    };
    let mut last_frame = Instant::now();
    while !session.over() {
        let app = &mut *session.app;
        app.reload_if_changed();
        app.poll_export();
        app.expire_message(Instant::now());
        if app.animates()
            && app.clock.is_running()
            && last_frame.elapsed() >= app.clock.frame_interval()
        {
            app.dirty.picture = true;
        }
        if app.dirty.picture {
            last_frame = Instant::now();
        }
        session.draw()?;
        // While the picture refines, input is only looked at between its passes: a key waits
        // for at most the pass in flight.
        let wait = match session.screen.refining(session.app) {
            true => Duration::ZERO,
            false => wait_time(session.app, last_frame),
        };
        session.suspend |= suspend_asked.swap(false, Ordering::SeqCst);
        if !session.over() && !session.suspend {
            if event::poll(wait)? {
                session.handle_pending_events()?;
            } else {
                session.refine()?;
            }
        }
        if std::mem::take(&mut session.suspend) && signals.received().is_none() {
            suspend_until_continued(session.app, &mut session.screen, mouse)?;
        }
    }
    Ok(())
}

/// What the loop drives: the app, the screen showing it, and the link to the terminal.
struct Session<'a> {
    app: &'a mut App,
    screen: Screen,
    input: InputState,
    pacer: FramePacer,
    signals: &'a ShutdownSignals,
    /// A suspend key was read.
    suspend: bool,
    /// The bytes of the frame going out.
    frame: Vec<u8>,
}

impl Session<'_> {
    /// Quitting, or a shutdown signal came.
    fn over(&self) -> bool {
        self.app.quit || self.signals.received().is_some()
    }

    /// Draws what changed.
    fn draw(&mut self) -> io::Result<()> {
        self.frame.clear();
        let new_picture = self.app.dirty.picture;
        // Into memory, so it cannot fail.
        let _ = self.screen.draw(self.app, &mut self.frame);
        if new_picture {
            self.pacer.whole_frame(self.frame.len());
        }
        self.show(new_picture)
    }

    /// Renders one more pass of a refining picture, and draws it when it is due.
    fn refine(&mut self) -> io::Result<()> {
        self.frame.clear();
        let _ = self.screen.refine(self.app, &mut self.frame);
        self.show(false)
    }

    /// Sends the frame drawn, and waits until the terminal has drawn it. Input that comes
    /// meanwhile is handled at once; it cuts a frame short when it quits or suspends, or, unless
    /// the frame is a `new_picture` (a new view is always shown whole), when it changes the
    /// picture the frame refines. The link's speed then decides how refinement proceeds and
    /// what the status line says of it.
    fn show(&mut self, new_picture: bool) -> io::Result<()> {
        if self.frame.is_empty() {
            return Ok(());
        }
        // Input may resize the screen while the frame goes out.
        let cut_points = self.screen.cut_points().to_vec();
        let (app, screen, input) = (&mut *self.app, &mut self.screen, &mut self.input);
        let (signals, suspend) = (self.signals, &mut self.suspend);
        let mut handle_input = |wait: Duration| -> io::Result<bool> {
            if signals.received().is_none() && event::poll(wait)? {
                *suspend |= handle_pending_events(app, screen, input)?;
            }
            let moved_past = !new_picture && app.dirty.picture;
            Ok(app.quit || *suspend || signals.received().is_some() || moved_past)
        };
        let sent = self.pacer.send(
            &self.frame,
            &cut_points,
            &mut write_to_terminal,
            &mut handle_input,
        );
        let sent = match sent {
            Ok(sent) => sent,
            // The terminal is gone; the hang-up signal ends the loop.
            Err(_) => {
                self.screen.frame_lost();
                return Ok(());
            }
        };
        if let Some(row) = sent.cut_before {
            self.screen.frame_cut(row, self.app);
        }
        if self.over() {
            return Ok(());
        }
        let layout = self.screen.layout();
        let signals = self.signals;
        let stop = || signals.received().is_some();
        let size = (layout.cols, layout.rows);
        self.pacer.frame_sent(sent, size, &stop);
        self.screen.send_settled_only(self.pacer.slow());
        (self.app).set_link(self.pacer.bottleneck(), self.pacer.bytes_sent());
        Ok(())
    }

    fn handle_pending_events(&mut self) -> io::Result<()> {
        self.suspend |= handle_pending_events(self.app, &mut self.screen, &mut self.input)?;
        Ok(())
    }
}

/// Writes to the terminal and flushes. Locked per write, never across a wait: the signal
/// watchdog needs stdout to restore the terminal when the loop is stuck on a hung-up tty.
fn write_to_terminal(bytes: &[u8]) -> io::Result<()> {
    let mut out = io::stdout().lock();
    out.write_all(bytes)?;
    out.flush()
}

/// A signal handler that is removed (the default action back) when this is dropped.
struct Registered(signal_hook::SigId);

impl Drop for Registered {
    fn drop(&mut self) {
        signal_hook::low_level::unregister(self.0);
    }
}

/// Gives the terminal back and stops; once continued, draws everything again at the window's
/// size then (the shell drew over the screen, and the window may have changed meanwhile).
fn suspend_until_continued(app: &mut App, screen: &mut Screen, mouse: bool) -> io::Result<()> {
    crate::term::suspend_and_resume(mouse)?;
    let (cols, rows) = crossterm::terminal::size()?;
    screen.resize(cols, rows, app);
    follow_cell_size(app, screen);
    Ok(())
}

/// The cells' shape and size in pixels as the terminal reports them now: a new font size or
/// zoom changes them with the window.
fn follow_cell_size(app: &mut App, screen: &mut Screen) {
    screen.set_cell_aspect(cell_aspect(app.cell_size), app);
    let route = screen.pixel_route();
    let cell_pixels = cell_pixels(app.cell_size, Some(route.cell_pixels));
    screen.set_pixel_route(
        PixelRoute {
            cell_pixels,
            ..route
        },
        app,
    );
}

/// Until the next animation frame is due, or the signal poll interval.
fn wait_time(app: &App, last_frame: Instant) -> Duration {
    if app.animates() && app.clock.is_running() {
        let due = app
            .clock
            .frame_interval()
            .saturating_sub(last_frame.elapsed());
        due.min(SIGNAL_POLL)
    } else {
        SIGNAL_POLL
    }
}

/// Applies every event already waiting, so a burst of key repeats costs one frame, not many;
/// returns whether one asked to suspend.
fn handle_pending_events(
    app: &mut App,
    screen: &mut Screen,
    input: &mut InputState,
) -> io::Result<bool> {
    let mut suspend = false;
    loop {
        match input.translate(event::read()?) {
            Input::Suspend => suspend = true,
            Input::Key(key) => app.key(&key),
            Input::Action(action) => app.apply(action),
            Input::Pointer(pointer) => {
                if let Some(action) = pointer.action(app, screen.picture_area()) {
                    app.apply(action);
                }
            }
            Input::Resize(cols, rows) => {
                screen.resize(cols, rows, app);
                follow_cell_size(app, screen);
            }
            Input::Redraw => screen.invalidate(app),
            Input::Nothing => {}
        }
        if app.quit || suspend || !event::poll(Duration::ZERO)? {
            return Ok(suspend);
        }
    }
}

/// Cell height / width: from `--cell-size`, else from the pixel size the terminal reports for
/// its window (TIOCGWINSZ), else the usual 2. A reported shape past 1:1 to 4:1 is not believed.
fn cell_aspect(fixed: Option<(u32, u32)>) -> f32 {
    if let Some((width, height)) = fixed {
        return height as f32 / width as f32;
    }
    let reported = crossterm::terminal::window_size().ok().and_then(|size| {
        let cell_w = f32::from(size.width) / f32::from(size.columns.max(1));
        let cell_h = f32::from(size.height) / f32::from(size.rows.max(1));
        (cell_w > 0.0 && cell_h > 0.0).then(|| cell_h / cell_w)
    });
    reported
        .filter(|aspect| (1.0..=4.0).contains(aspect))
        .unwrap_or(DEFAULT_CELL_ASPECT)
}

/// Asks the terminal which pixel protocols it speaks (not at all for `--graphics blocks`); inside
/// tmux, whether tmux passes them through.
fn find_graphics(choice: GraphicsChoice) -> io::Result<GraphicsFound> {
    let var = |name: &str| std::env::var(name).ok();
    let passthrough = in_tmux(var).then(tmux_passes_through);
    let replies = match choice {
        GraphicsChoice::Blocks => Replies::default(),
        _ => query_terminal(passthrough == Some(true))?,
    };
    Ok(decide(choice, &replies, var, passthrough))
}

/// A cell's size in pixels: `--cell-size`, else as the window's pixel size gives it
/// (TIOCGWINSZ), else as the terminal answered (`CSI 16 t`), else a common 10×20.
fn cell_pixels(fixed: Option<(u32, u32)>, answered: Option<(u32, u32)>) -> (u32, u32) {
    let from_window = crossterm::terminal::window_size().ok().and_then(|size| {
        let w = u32::from(size.width) / u32::from(size.columns.max(1));
        let h = u32::from(size.height) / u32::from(size.rows.max(1));
        (w > 0 && h > 0).then_some((w, h))
    });
    fixed
        .or(from_window)
        .or(answered)
        .filter(|&(w, h)| (1..=512).contains(&w) && (1..=1024).contains(&h))
        .unwrap_or(super::pixel_picture::FALLBACK_CELL_PIXELS)
}

fn terminal_error(error: io::Error) -> Error {
    Error::write(Path::new("the terminal"), error)
}
