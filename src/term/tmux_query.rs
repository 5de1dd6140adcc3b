//! Asking the tmux server the workbench runs under: its options and what it knows of the
//! terminal outside it. Every question is answered within a second or not at all, and the answer
//! is read up to a few kilobytes.

use std::io::Read;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// How long tmux has to answer.
const ANSWER_WITHIN: Duration = Duration::from_secs(1);
/// The most of an answer that is read.
const ANSWER_BYTES: u64 = 4096;

/// Whether this process runs inside tmux (`TMUX` is set), looked up through `var`.
pub fn in_tmux(var: impl Fn(&str) -> Option<String>) -> bool {
    var("TMUX").is_some_and(|v| !v.is_empty())
}

/// `tmux ARGS`'s standard output, trimmed; `None` if tmux cannot be run, fails, or takes longer
/// than a second.
pub fn tmux_answer(args: &[&str]) -> Option<String> {
    let mut child = Command::new("tmux")
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .ok()?;
    let deadline = Instant::now() + ANSWER_WITHIN;
    while Instant::now() < deadline {
        match child.try_wait() {
            Ok(Some(status)) => {
                let mut text = String::new();
                let out = child.stdout.take()?;
                out.take(ANSWER_BYTES).read_to_string(&mut text).ok()?;
                return status.success().then(|| text.trim().to_string());
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(10)),
            Err(_) => break,
        }
    }
    let _ = child.kill();
    let _ = child.wait();
    None
}

/// Whether tmux's `allow-passthrough` is on, so pixel protocols reach the terminal outside.
pub fn tmux_passes_through() -> bool {
    let answer = tmux_answer(&["show-options", "-gqv", "allow-passthrough"]);
    matches!(answer.as_deref(), Some("on" | "all"))
}

/// The features tmux knows the terminal outside it (the client this pane is shown on) has, as
/// `#{client_termfeatures}` lists them (`256,RGB,title,…`, tmux 3.2 and later); `None` where
/// tmux does not say (no client attached, an older tmux).
pub fn tmux_client_features() -> Option<String> {
    tmux_answer(&["display-message", "-p", "#{client_termfeatures}"]).filter(|f| !f.is_empty())
}
