//! `render --watch`: the still follows every save of the files it reads, a save that does not load
//! keeps the last still, and Ctrl-C ends the watch quietly.

use crate::cli_support::{assert_user_error, bumpwork, temp_dir, wait_until};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

#[test]
fn the_still_follows_each_save_and_a_broken_save_keeps_the_last() {
    let dir = temp_dir("render-watch");
    let pattern = dir.join("live.pat");
    let still = dir.join("live.png");
    std::fs::write(&pattern, "height = 0.5 * sin(u / 10)\n").unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_bumpwork"))
        .args([
            "render",
            pattern.to_str().unwrap(),
            "--size",
            "48x32",
            "--watch",
            "-o",
        ])
        .arg(&still)
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let read = || std::fs::read(&still).ok();
    wait_until("the first still", Duration::from_secs(20), || {
        read().is_some()
    });
    let first = read().unwrap();
    std::fs::write(&pattern, "height = 3 * sin(u / 3)\n").unwrap();
    wait_until("the still made again", Duration::from_secs(20), || {
        read().is_some_and(|b| b != first)
    });
    let second = read().unwrap();
    std::fs::write(&pattern, "height = 3 *\n").unwrap();
    std::thread::sleep(Duration::from_millis(600));
    assert_eq!(
        read().unwrap(),
        second,
        "a broken save keeps the last still"
    );
    // SAFETY: kill only sends a signal to the process we started.
    assert_eq!(unsafe { libc::kill(child.id() as i32, libc::SIGINT) }, 0);
    let deadline = Instant::now() + Duration::from_secs(5);
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        assert!(Instant::now() < deadline, "still watching after Ctrl-C");
        std::thread::sleep(Duration::from_millis(20));
    };
    let mut messages = String::new();
    std::io::Read::read_to_string(&mut child.stderr.take().unwrap(), &mut messages).unwrap();
    assert_eq!(status.code(), Some(0), "{messages}");
    assert!(
        messages.contains("rendered") && messages.contains("again"),
        "{messages}"
    );
    assert!(
        messages.contains("live.pat:2:1: expected an expression"),
        "{messages}"
    );
    assert!(messages.contains("is kept"), "{messages}");
}

#[test]
fn watch_needs_a_file_to_follow() {
    let dir = temp_dir("render-watch-builtin");
    let out = dir.join("x.png");
    let output = bumpwork(&[
        "render",
        "plane-dimples",
        "--watch",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_user_error(&output, "the built-in scene 'plane-dimples' never changes");
    assert!(!out.exists());
}
