//! The workbench in a real terminal emulator (tmux) on a pattern file whose name, and then whose
//! content and error message, hold escape sequences: the screen shows them as visible escapes,
//! and none reaches the terminal (the pane's title is not set, the screen is not cleared, the
//! character set is not switched). Skips, saying why, where tmux is require.

#![cfg(unix)]

use crate::tmux_support::{Tmux, require};

const TITLE: &str = "pwned";

#[test]
#[ignore = "needs tmux; bash .ci/run installs it and runs the ignored tests"]
fn escapes_from_files_reach_the_screen_only_as_text() {
    require(&["tmux"]);
    let dir = tempfile::tempdir().expect("a temporary directory");
    let dir = dir.path();
    // OSC 0 sets the title, ESC ( 0 switches to line drawing, BEL rings.
    let name = format!("t\x1b]0;{TITLE}\x07\x1b(0q.pat");
    let file = dir.join(&name);
    std::fs::write(&file, "height = sin(u / 7)\n").unwrap();
    let tmux = Tmux::start(
        "hostile",
        120,
        30,
        &format!(
            "cd '{}' && exec '{}' view ./t*.pat",
            dir.display(),
            env!("CARGO_BIN_EXE_bumpwork")
        ),
    );
    let screen = tmux.wait_for("the escaped file name in the status line", |s| {
        s.contains("t\\e]0;pwned\\x07\\e(0q.pat")
    });
    assert!(!screen.contains('─'), "line drawing switched on:\n{screen}");

    // A bad save whose text and error hold escapes: the last good view stays, the error shows.
    std::fs::write(&file, "height = u +\x1b]2;owned\x07\x1b[2J\x1b(0q\n").unwrap();
    let screen = tmux.wait_for("the escaped error", |s| {
        s.contains("q.pat:1:13: unexpected character `\\e`")
    });
    // The diagnostic box draws its own lines; under line drawing its text's `q` would be one too.
    assert!(
        screen.contains("\\e(0q"),
        "line drawing switched on:\n{screen}"
    );
    let title = tmux.pane("#{pane_title}");
    assert!(
        !title.contains(TITLE) && !title.contains("owned"),
        "title set to {title:?}"
    );
    // The picture is still there: a cleared screen would be blank above the status line.
    let drawn = screen.lines().filter(|l| l.trim().len() > 20).count();
    assert!(drawn > 10, "the picture was cleared:\n{screen}");
    tmux.send_keys(&["q"]);
    assert!(
        crate::tmux_support::eventually(crate::tmux_support::DEADLINE, || tmux
            .pane("#{pane_dead}")
            == "1"),
        "the workbench did not quit"
    );
}
