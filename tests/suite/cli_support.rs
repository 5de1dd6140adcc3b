//! Running the binary as a user would, for the command-line tests.
#![allow(dead_code)]

pub use crate::test_dir::TestDir;

use std::path::Path;
use std::process::{Command, Output};

pub fn bumpwork(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_bumpwork"))
        .args(args)
        .output()
        .expect("the binary runs")
}

/// Runs the binary and asserts it succeeded (the arguments and its stderr otherwise).
pub fn run_ok(args: &[&str]) -> Output {
    let output = bumpwork(args);
    assert!(output.status.success(), "{args:?}: {}", stderr(&output));
    output
}

pub fn temp_dir(name: &str) -> TestDir {
    TestDir::new(&format!("cli-{name}"))
}

pub fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

/// A user error: status 1, one message, no panic, no backtrace.
pub fn assert_user_error(output: &Output, expected: &str) {
    let message = stderr(output);
    assert_eq!(output.status.code(), Some(1), "status for: {message}");
    assert!(
        message.contains(expected),
        "expected '{expected}' in: {message}"
    );
    assert!(
        !message.contains("panicked") && !message.contains("RUST_BACKTRACE"),
        "{message}"
    );
}

pub fn decode_png(path: &Path) -> (u32, u32, Vec<u8>) {
    decode_png_bytes(&std::fs::read(path).unwrap())
}

pub fn decode_png_bytes(bytes: &[u8]) -> (u32, u32, Vec<u8>) {
    let decoder = png::Decoder::new(std::io::Cursor::new(bytes));
    let mut reader = decoder.read_info().unwrap();
    let mut pixels = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut pixels).unwrap();
    (info.width, info.height, pixels)
}

/// Runs the binary with `args` under a cap on its address space (`ulimit -v`, in MiB), so reading
/// a huge file into memory would fail the run, and kills it if it is still running after `secs`
/// seconds (a generous bound: hanging is the failure, not slowness). Its memory budget is half
/// the cap, the rest left for code, thread stacks and allocator arenas.
pub fn bumpwork_bounded(args: &[&std::ffi::OsStr], memory_mib: u64, secs: u64) -> Output {
    let budget = (memory_mib / 2).to_string();
    bumpwork_bounded_with(args, &[("BUMPWORK_MEMORY_MIB", &budget)], memory_mib, secs)
}

/// As `bumpwork_bounded`, with the environment variables `env` set.
pub fn bumpwork_bounded_with(
    args: &[&std::ffi::OsStr],
    env: &[(&str, &str)],
    memory_mib: u64,
    secs: u64,
) -> Output {
    let mut child = Command::new("sh")
        .arg("-c")
        .arg(format!(
            "ulimit -v {}; exec \"$0\" \"$@\"",
            memory_mib << 10
        ))
        .arg(env!("CARGO_BIN_EXE_bumpwork"))
        .args(args)
        .envs(env.iter().copied())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("the binary runs");
    let deadline = std::time::Instant::now() + std::time::Duration::from_secs(secs);
    while child.try_wait().unwrap().is_none() {
        if std::time::Instant::now() > deadline {
            let _ = child.kill();
            panic!("bumpwork {args:?} still running after {secs} s");
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    child.wait_with_output().unwrap()
}

/// The first character of `text` that could steer a terminal (any control character but a line
/// break, including the C1 range and DEL), if there is one.
pub fn raw_control(text: &[u8]) -> Option<char> {
    String::from_utf8_lossy(text)
        .chars()
        .find(|&c| c.is_control() && c != '\n')
}

/// Makes a FIFO at `path` (no reader or writer opens it).
#[cfg(unix)]
pub fn make_fifo(path: &Path) {
    use std::os::unix::ffi::OsStrExt;
    let name = std::ffi::CString::new(path.as_os_str().as_bytes()).unwrap();
    // SAFETY: mkfifo reads the NUL-terminated path it is given.
    assert_eq!(unsafe { libc::mkfifo(name.as_ptr(), 0o600) }, 0);
}

/// Polls `condition` until it holds; panics naming `what` after `limit` (a generous bound: being
/// stuck is the failure, not being slow).
pub fn wait_until(what: &str, limit: std::time::Duration, condition: impl Fn() -> bool) {
    let deadline = std::time::Instant::now() + limit;
    while !condition() {
        assert!(
            std::time::Instant::now() < deadline,
            "timed out waiting for {what}"
        );
        std::thread::sleep(std::time::Duration::from_millis(10));
    }
}
