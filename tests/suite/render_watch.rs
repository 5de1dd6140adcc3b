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
    let messages = std::sync::Arc::new(std::sync::Mutex::new(String::new()));
    let mut stderr = child.stderr.take().unwrap();
    let kept = std::sync::Arc::clone(&messages);
    let reader = std::thread::spawn(move || {
        let mut buffer = [0u8; 4096];
        while let Ok(n @ 1..) = std::io::Read::read(&mut stderr, &mut buffer) {
            kept.lock()
                .unwrap()
                .push_str(&String::from_utf8_lossy(&buffer[..n]));
        }
    });
    let read = || std::fs::read(&still).ok();
    wait_until("the first still", Duration::from_secs(60), || {
        read().is_some()
    });
    let first = read().unwrap();
    std::fs::write(&pattern, "height = 3 * sin(u / 3)\n").unwrap();
    wait_until("the still made again", Duration::from_secs(60), || {
        read().is_some_and(|b| b != first)
    });
    let second = read().unwrap();
    std::fs::write(&pattern, "height = 3 *\n").unwrap();
    wait_until("the broken save reported", Duration::from_secs(60), || {
        messages
            .lock()
            .unwrap()
            .contains("is kept until the next change loads")
    });
    assert_eq!(
        read().unwrap(),
        second,
        "a broken save keeps the last still"
    );
    // SAFETY: kill only sends a signal to the process we started.
    assert_eq!(unsafe { libc::kill(child.id() as i32, libc::SIGINT) }, 0);
    let deadline = Instant::now() + Duration::from_secs(30);
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        assert!(Instant::now() < deadline, "still watching after Ctrl-C");
        std::thread::sleep(Duration::from_millis(20));
    };
    reader.join().unwrap();
    let messages = messages.lock().unwrap().clone();
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
