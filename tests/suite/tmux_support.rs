//! A tmux server of the test's own (its own socket), for driving the workbench in a real
//! terminal emulator: send keys, read the screen, resize, read the pane's title.
#![allow(dead_code)]

use std::process::{Command, Output};
use std::time::{Duration, Instant};

/// Polls are this far apart; deadlines are generous so a loaded machine is slower, not flaky.
const POLL: Duration = Duration::from_millis(100);
pub const DEADLINE: Duration = Duration::from_secs(60);

pub struct Tmux {
    socket: String,
}

/// Fails the test, naming the tool, unless every one of `tools` is installed. Tests that call
/// it are `#[ignore]`d with the reason; `bash .ci/run` installs the tools and runs them.
pub fn require(tools: &[&str]) {
    let missing = tools.iter().find(|tool| {
        let found = Command::new("sh")
            .args(["-c", &format!("command -v {tool}")])
            .output()
            .is_ok_and(|o| o.status.success());
        !found && !std::path::Path::new(tool).exists()
    });
    if let Some(tool) = missing {
        panic!("{tool} is not installed (bash .ci/run installs what these tests need)");
    }
}

impl Tmux {
    /// Starts a detached session `cols`×`rows` running `command` (a shell command line).
    pub fn start(name: &str, cols: u16, rows: u16, command: &str) -> Tmux {
        let tmux = Tmux {
            socket: format!("bumpwork-{name}-{}", std::process::id()),
        };
        let output = tmux.run(&[
            "new-session",
            "-d",
            "-x",
            &cols.to_string(),
            "-y",
            &rows.to_string(),
            "-e",
            "TERM=xterm-256color",
            command,
        ]);
        assert!(output.status.success(), "tmux: {output:?}");
        // The pane stays after its program ends, so its last screen can be read.
        tmux.run(&["set-option", "-g", "remain-on-exit", "on"]);
        tmux
    }

    pub fn run(&self, args: &[&str]) -> Output {
        Command::new("tmux")
            .args(["-L", &self.socket, "-f", "/dev/null"])
            .args(args)
            .output()
            .expect("tmux runs")
    }

    /// The screen as text (escape sequences and all control characters left out by tmux).
    pub fn screen(&self) -> String {
        String::from_utf8_lossy(&self.run(&["capture-pane", "-p"]).stdout).into_owned()
    }

    /// A tmux format about the pane, e.g. `#{pane_title}`.
    pub fn pane(&self, format: &str) -> String {
        let output = self.run(&["display-message", "-p", format]);
        String::from_utf8_lossy(&output.stdout).trim().to_string()
    }

    pub fn send_keys(&self, keys: &[&str]) {
        let mut args = vec!["send-keys"];
        args.extend(keys);
        self.run(&args);
    }

    pub fn resize(&self, cols: u16, rows: u16) {
        let output = self.run(&[
            "resize-window",
            "-x",
            &cols.to_string(),
            "-y",
            &rows.to_string(),
        ]);
        assert!(output.status.success(), "resize: {output:?}");
    }

    /// Polls the screen until `condition` holds; panics with the screen after the deadline.
    pub fn wait_for(&self, what: &str, condition: impl Fn(&str) -> bool) -> String {
        let start = Instant::now();
        loop {
            let screen = self.screen();
            if condition(&screen) {
                return screen;
            }
            assert!(
                start.elapsed() < DEADLINE,
                "timed out waiting for {what}; screen:\n{screen}"
            );
            std::thread::sleep(POLL);
        }
    }
}

impl Drop for Tmux {
    fn drop(&mut self) {
        self.run(&["kill-server"]);
    }
}

/// Polls `condition` until it holds or the deadline passes; returns whether it held.
pub fn eventually(deadline: Duration, condition: impl Fn() -> bool) -> bool {
    let start = Instant::now();
    while start.elapsed() < deadline {
        if condition() {
            return true;
        }
        std::thread::sleep(POLL);
    }
    condition()
}
