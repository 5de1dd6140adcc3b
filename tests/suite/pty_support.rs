//! The real binary in a pseudo-terminal, its screen kept by a terminal emulator (vt100).
#![allow(dead_code)]

use portable_pty::{Child, CommandBuilder, PtySize, native_pty_system};
use std::io::{Read, Write};
use std::num::NonZeroU16;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

pub const DEADLINE: Duration = Duration::from_secs(90);

/// How long a program asked to quit may take to end, on a loaded machine.
pub const QUIT_DEADLINE: Duration = Duration::from_secs(30);

/// Bytes of the program's output kept for `output` at most.
const KEPT_OUTPUT: usize = 64 << 20;

pub struct Session {
    pub screen: Arc<Mutex<vt100::Parser>>,
    master: Box<dyn portable_pty::MasterPty + Send>,
    /// Everything the program wrote, as written.
    raw: Arc<Mutex<Vec<u8>>>,
    /// Set when the reader has read the last of it (the program's end of the terminal closed).
    read_all: Arc<std::sync::atomic::AtomicBool>,
    writer: Arc<Mutex<Box<dyn Write + Send>>>,
    pub child: Box<dyn Child + Send + Sync>,
    rows: u16,
    cols: u16,
}

impl Session {
    /// Runs `bumpwork ARGS` (TERM=xterm-256color) in `cwd` in a fresh pseudo-terminal of
    /// `cols` × `rows`, and waits until its status line shows `first` (the first frame is up).
    pub fn bumpwork(
        args: &[&str],
        cwd: Option<&std::path::Path>,
        (cols, rows): (u16, u16),
        first: &'static str,
    ) -> Session {
        let mut command = CommandBuilder::new(env!("CARGO_BIN_EXE_bumpwork"));
        command.args(args);
        if let Some(cwd) = cwd {
            command.cwd(cwd);
        }
        command.env("TERM", "xterm-256color");
        let session = Session::start(command, (cols, rows), true);
        session.wait_for("the first frame", status_contains(first));
        session
    }

    /// Runs `command` in a fresh pseudo-terminal of `cols` × `rows` that answers no queries
    /// (the test answers them, or tests that nothing does).
    pub fn spawn(command: CommandBuilder, cols: u16, rows: u16) -> Session {
        Session::start(command, (cols, rows), false)
    }

    /// As `spawn`; with `answer_queries`, the terminal answers the primary device attributes
    /// query (DA1) as a VT220 without graphics and the cursor position report, as every real
    /// terminal answers them, so the program need not wait out its time-outs for replies.
    fn start(command: CommandBuilder, (cols, rows): (u16, u16), answer_queries: bool) -> Session {
        let pty = native_pty_system()
            .openpty(PtySize {
                rows,
                cols,
                pixel_width: 0,
                pixel_height: 0,
            })
            .unwrap();
        let child = pty.slave.spawn_command(command).unwrap();
        drop(pty.slave);
        // A terminal that reports 0×0 is shown here at a size the emulator can take.
        let size = |n, or| NonZeroU16::new(n).unwrap_or(NonZeroU16::new(or).unwrap());
        let screen = Arc::new(Mutex::new(vt100::Parser::new(
            size(rows, 24),
            size(cols, 80),
            0,
        )));
        let mut reader = pty.master.try_clone_reader().unwrap();
        let feed = Arc::clone(&screen);
        let raw = Arc::new(Mutex::new(Vec::new()));
        let keep = Arc::clone(&raw);
        let read_all = Arc::new(std::sync::atomic::AtomicBool::new(false));
        let done = Arc::clone(&read_all);
        let writer = Arc::new(Mutex::new(pty.master.take_writer().unwrap()));
        let answers = Arc::clone(&writer);
        std::thread::spawn(move || {
            let mut buffer = [0u8; 65536];
            let mut attributes = QueryFinder::new(QueryFinder::DEVICE_ATTRIBUTES);
            let mut position = QueryFinder::new(QueryFinder::CURSOR_POSITION);
            while let Ok(n @ 1..) = reader.read(&mut buffer) {
                let piece = &buffer[..n];
                let mut answer = Vec::new();
                if answer_queries && attributes.found_in(piece) {
                    answer.extend_from_slice(b"\x1b[?62;22c");
                }
                let mut parser = feed.lock().unwrap();
                parser.process(piece);
                if answer_queries && position.found_in(piece) {
                    // Where the cursor is once all that came before is drawn, as a terminal answers.
                    let (row, col) = parser.screen().cursor_position();
                    answer.extend_from_slice(format!("\x1b[{};{}R", row + 1, col + 1).as_bytes());
                }
                drop(parser);
                if !answer.is_empty() {
                    let mut answers = answers.lock().unwrap();
                    let _ = answers.write_all(&answer).and_then(|()| answers.flush());
                }
                let mut kept = keep.lock().unwrap();
                if kept.len() + n <= KEPT_OUTPUT {
                    kept.extend_from_slice(&buffer[..n]);
                }
            }
            done.store(true, std::sync::atomic::Ordering::Release);
        });
        Session {
            master: pty.master,
            raw,
            read_all,
            screen,
            writer,
            child,
            rows: if rows == 0 { 24 } else { rows },
            cols: if cols == 0 { 80 } else { cols },
        }
    }

    pub fn send(&mut self, keys: &str) {
        let mut writer = self.writer.lock().unwrap();
        writer.write_all(keys.as_bytes()).unwrap();
        writer.flush().unwrap();
    }

    /// Polls the screen until `condition` holds; panics with the screen after the deadline.
    pub fn wait_for(&self, what: &str, condition: impl Fn(&vt100::Screen) -> bool) {
        let start = Instant::now();
        loop {
            {
                let parser = self.screen.lock().unwrap();
                if condition(parser.screen()) {
                    return;
                }
                if start.elapsed() > DEADLINE {
                    panic!(
                        "timed out waiting for {what}; screen:\n{}",
                        parser.screen().contents()
                    );
                }
            }
            std::thread::sleep(Duration::from_millis(20));
        }
    }

    /// Gives the terminal a new size in cells and pixels (the program gets SIGWINCH); the
    /// emulator keeps its size.
    pub fn resize(&self, cols: u16, rows: u16, pixel_width: u16, pixel_height: u16) {
        let size = PtySize {
            rows,
            cols,
            pixel_width,
            pixel_height,
        };
        self.master.resize(size).unwrap();
    }

    /// Everything the program has written so far.
    pub fn output(&self) -> Vec<u8> {
        self.raw.lock().unwrap().clone()
    }

    /// The screen's text now, a line a row.
    pub fn contents(&self) -> String {
        self.screen.lock().unwrap().screen().contents()
    }

    pub fn status_line(&self) -> String {
        let parser = self.screen.lock().unwrap();
        parser
            .screen()
            .rows(0, self.cols)
            .nth(self.rows as usize - 1)
            .unwrap_or_default()
    }

    /// Waits up to `limit` for the program to end: its exit code, or `None` if it still runs
    /// (then it is killed). After an exit, waits (up to `limit` again) until everything it wrote
    /// has been read, so `output` holds its last bytes even on a loaded machine.
    pub fn exit_within(&mut self, limit: Duration) -> Option<u32> {
        let start = Instant::now();
        while start.elapsed() < limit {
            if let Some(status) = self.child.try_wait().unwrap() {
                let exited = Instant::now();
                let read_all = || self.read_all.load(std::sync::atomic::Ordering::Acquire);
                while !read_all() && exited.elapsed() < limit {
                    std::thread::sleep(Duration::from_millis(5));
                }
                return Some(status.exit_code());
            }
            std::thread::sleep(Duration::from_millis(5));
        }
        let _ = self.child.kill();
        None
    }
}

/// The last row of `screen` contains `text`.
pub fn status_contains(text: &'static str) -> impl Fn(&vt100::Screen) -> bool {
    move |screen| {
        let (rows, cols) = screen.size();
        screen
            .rows(0, cols.get())
            .nth(rows.get() as usize - 1)
            .is_some_and(|line| line.contains(text))
    }
}

/// Finds a query (`ESC [ c`, `ESC [ 6 n`) in output read in pieces, so a query split between two
/// reads is found too.
struct QueryFinder {
    query: &'static [u8],
    /// The last bytes of the previous piece.
    tail: Vec<u8>,
}

impl QueryFinder {
    const DEVICE_ATTRIBUTES: &'static [u8] = b"\x1b[c";
    const CURSOR_POSITION: &'static [u8] = b"\x1b[6n";

    fn new(query: &'static [u8]) -> QueryFinder {
        QueryFinder {
            query,
            tail: Vec::new(),
        }
    }

    fn found_in(&mut self, piece: &[u8]) -> bool {
        let mut seen = std::mem::take(&mut self.tail);
        seen.extend_from_slice(piece);
        let found = seen.windows(self.query.len()).any(|w| w == self.query);
        let keep = seen.len().min(self.query.len() - 1);
        self.tail = seen[seen.len() - keep..].to_vec();
        found
    }
}
