//! End to end: the real binary in a pseudo-terminal, read back through a terminal emulator
//! (vt100). Start, wait for the first frame, orbit, change scene and view mode, export, quit, and
//! check the terminal was given back (main screen, cursor shown, line discipline cooked again).
//!
//! Every wait polls the emulated screen until a condition holds, with a generous deadline, so a
//! loaded machine makes the test slower, not flaky.

#![cfg(unix)]

use portable_pty::{CommandBuilder, PtySize, native_pty_system};
use std::io::{Read, Write};
use std::num::NonZeroU16;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

const COLS: u16 = 100;
const ROWS: u16 = 30;
const DEADLINE: Duration = Duration::from_secs(90);

struct Session {
    screen: Arc<Mutex<vt100::Parser>>,
    writer: Box<dyn Write + Send>,
}

impl Session {
    fn send(&mut self, keys: &str) {
        self.writer.write_all(keys.as_bytes()).unwrap();
        self.writer.flush().unwrap();
    }

    /// Polls the screen until `condition` holds; panics with the screen after the deadline.
    fn wait_for(&self, what: &str, condition: impl Fn(&vt100::Screen) -> bool) {
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
            std::thread::sleep(Duration::from_millis(50));
        }
    }

    fn status_line(&self) -> String {
        let parser = self.screen.lock().unwrap();
        parser
            .screen()
            .rows(0, COLS)
            .nth(ROWS as usize - 1)
            .unwrap_or_default()
    }

    fn picture(&self) -> Vec<(vt100::Color, vt100::Color)> {
        picture(self.screen.lock().unwrap().screen())
    }
}

/// The picture's colours, to see that it changed.
fn picture(screen: &vt100::Screen) -> Vec<(vt100::Color, vt100::Color)> {
    (0..ROWS - 1)
        .flat_map(|row| (0..COLS).map(move |col| (row, col)))
        .filter_map(|(row, col)| screen.cell(row, col))
        .map(|cell| (cell.fgcolor(), cell.bgcolor()))
        .collect()
}

fn status_contains(text: &'static str) -> impl Fn(&vt100::Screen) -> bool {
    move |screen| {
        screen
            .rows(0, COLS)
            .nth(ROWS as usize - 1)
            .is_some_and(|line| line.contains(text))
    }
}

#[test]
fn the_workbench_runs_in_a_real_terminal_and_gives_it_back() {
    let dir = std::env::temp_dir().join(format!("bumpwork-pty-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let pty = native_pty_system()
        .openpty(PtySize {
            rows: ROWS,
            cols: COLS,
            pixel_width: 0,
            pixel_height: 0,
        })
        .unwrap();
    // The shell reports the exit status and the line discipline after the workbench ends.
    let mut command = CommandBuilder::new("sh");
    command.args([
        "-c",
        "\"$0\" view plane-dimples sphere-on-plane-dimples; echo \"exit=$?\"; stty -a; echo DONE",
        env!("CARGO_BIN_EXE_bumpwork"),
    ]);
    command.cwd(&dir);
    command.env("TERM", "xterm-256color");
    command.env("COLORTERM", "truecolor");
    command.env_remove("NO_COLOR");
    let mut child = pty.slave.spawn_command(command).unwrap();
    drop(pty.slave);

    let rows = NonZeroU16::new(ROWS).unwrap();
    let cols = NonZeroU16::new(COLS).unwrap();
    let screen = Arc::new(Mutex::new(vt100::Parser::new(rows, cols, 0)));
    let mut reader = pty.master.try_clone_reader().unwrap();
    let feed = Arc::clone(&screen);
    std::thread::spawn(move || {
        let mut buffer = [0u8; 65536];
        while let Ok(n @ 1..) = reader.read(&mut buffer) {
            feed.lock().unwrap().process(&buffer[..n]);
        }
    });
    let mut session = Session {
        screen,
        writer: pty.master.take_writer().unwrap(),
    };

    session.wait_for("the first frame", status_contains("1/2 plane-dimples"));
    session.wait_for("the alternate screen, cursor hidden", |s| {
        s.alternate_screen() && s.hide_cursor()
    });
    let before = session.picture();

    session.send("lll");
    session.wait_for("the orbit to change the picture", |s| picture(s) != before);

    session.send("\t");
    session.wait_for(
        "the next scene",
        status_contains("2/2 sphere-on-plane-dimples"),
    );

    session.send("v");
    session.wait_for("the height view", status_contains("│ height │"));

    session.send("p");
    session.wait_for(
        "the next bump pattern",
        status_contains(" dimples ×1.00 period="),
    );

    session.send("e");
    session.wait_for("the export to finish", status_contains("exported"));
    let exported: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| e.ok())
        .filter(|e| e.path().extension().is_some_and(|x| x == "png"))
        .collect();
    assert_eq!(exported.len(), 1, "status: {}", session.status_line());
    let png = std::fs::read(exported[0].path()).unwrap();
    assert_eq!(&png[1..4], b"PNG");

    session.send("q");
    session.wait_for("the shell after the workbench", |s| {
        s.contents().contains("DONE")
    });
    let status = child.wait().unwrap();
    assert!(status.success());
    let parser = session.screen.lock().unwrap();
    let screen = parser.screen();
    let text = screen.contents();
    assert!(text.contains("exit=0"), "{text}");
    assert!(!screen.alternate_screen(), "still on the alternate screen");
    assert!(!screen.hide_cursor(), "cursor still hidden");
    // Raw mode off: canonical input and echo are back.
    assert!(text.contains(" icanon") && text.contains(" echo"), "{text}");
    assert!(!text.contains("-icanon"), "{text}");
    drop(parser);
    std::fs::remove_dir_all(&dir).unwrap();
}
