//! Every write goes where a plain write would put it and never destroys what is there: `-o -`
//! streams to standard output, symbolic links are written through, hard links and modes kept,
//! FIFOs and devices written into (never replaced), and a destination that cannot be written is
//! refused before any rendering.

#![cfg(unix)]

use crate::cli_support::{assert_user_error, bumpwork, stderr, temp_dir};
use std::io::Read;
use std::os::unix::fs::{FileTypeExt, MetadataExt, PermissionsExt};
use std::path::Path;
use std::process::{Command, Stdio};

const SMALL: [&str; 2] = ["--size", "64x48"];

fn render_to(out: &Path) -> std::process::Output {
    bumpwork(&[
        "render",
        "plane-dimples",
        SMALL[0],
        SMALL[1],
        "-o",
        out.to_str().unwrap(),
    ])
}

fn assert_png(bytes: &[u8]) {
    assert!(
        bytes.len() > 100 && bytes.starts_with(b"\x89PNG\r\n\x1a\n"),
        "{} bytes",
        bytes.len()
    );
    let (width, height, _) = crate::cli_support::decode_png_bytes(bytes);
    assert_eq!((width, height), (64, 48));
}

fn is_root() -> bool {
    // SAFETY: geteuid has no preconditions.
    unsafe { libc::geteuid() == 0 }
}

#[test]
fn a_dash_streams_the_still_to_standard_output() {
    let dir = temp_dir("out-dash");
    let output = Command::new(env!("CARGO_BIN_EXE_bumpwork"))
        .args(["render", "plane-dimples", SMALL[0], SMALL[1], "-o", "-"])
        .current_dir(&dir)
        .stdin(Stdio::null())
        .output()
        .unwrap();
    assert!(output.status.success(), "{}", stderr(&output));
    assert_png(&output.stdout);
    assert!(!dir.join("-").exists(), "a file named '-' was written");
}

#[test]
fn links_are_written_through_and_mode_and_hard_links_kept() {
    let dir = temp_dir("out-links");
    let target = dir.join("target.png");
    let link = dir.join("link.png");
    std::fs::write(&target, b"old").unwrap();
    std::os::unix::fs::symlink("target.png", &link).unwrap();
    assert!(render_to(&link).status.success());
    assert!(
        std::fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink()
    );
    assert_png(&std::fs::read(&target).unwrap());

    let dangling = dir.join("dangling.png");
    std::os::unix::fs::symlink("made-by-render.png", &dangling).unwrap();
    assert!(render_to(&dangling).status.success());
    assert_png(&std::fs::read(dir.join("made-by-render.png")).unwrap());

    let private = dir.join("private.png");
    std::fs::write(&private, b"old").unwrap();
    std::fs::set_permissions(&private, std::fs::Permissions::from_mode(0o600)).unwrap();
    assert!(render_to(&private).status.success());
    assert_eq!(std::fs::metadata(&private).unwrap().mode() & 0o777, 0o600);

    let first = dir.join("first.png");
    let second = dir.join("second.png");
    std::fs::write(&first, b"old").unwrap();
    std::fs::hard_link(&first, &second).unwrap();
    assert!(render_to(&first).status.success());
    let (a, b) = (
        std::fs::metadata(&first).unwrap(),
        std::fs::metadata(&second).unwrap(),
    );
    assert_eq!(
        (a.ino(), a.nlink()),
        (b.ino(), 2),
        "the hard link was broken"
    );
    assert_png(&std::fs::read(&second).unwrap());
}

#[test]
fn a_fifo_is_written_into_not_replaced() {
    let dir = temp_dir("out-fifo");
    let fifo = dir.join("pipe.png");
    assert!(
        Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .unwrap()
            .success()
    );
    let reader_end = fifo.clone();
    let reader = std::thread::spawn(move || {
        let mut bytes = Vec::new();
        std::fs::File::open(reader_end)
            .unwrap()
            .read_to_end(&mut bytes)
            .unwrap();
        bytes
    });
    let output = render_to(&fifo);
    assert!(output.status.success(), "{}", stderr(&output));
    assert_png(&reader.join().unwrap());
    assert!(
        std::fs::symlink_metadata(&fifo)
            .unwrap()
            .file_type()
            .is_fifo()
    );
}

#[test]
#[ignore = "needs root to make a device node; bash .ci/run runs as root and runs the ignored tests"]
fn a_device_is_written_into_not_replaced() {
    assert!(is_root(), "making a device node (mknod) needs root");
    let dir = temp_dir("out-device");
    let null = dir.join("null.png");
    let name = std::ffi::CString::new(null.as_os_str().as_encoded_bytes()).unwrap();
    // SAFETY: mknod reads the NUL-terminated path; 1:3 is the kernel's null device.
    let made = unsafe { libc::mknod(name.as_ptr(), libc::S_IFCHR | 0o666, libc::makedev(1, 3)) };
    assert_eq!(made, 0, "mknod: {}", std::io::Error::last_os_error());
    let output = render_to(&null);
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(
        std::fs::symlink_metadata(&null)
            .unwrap()
            .file_type()
            .is_char_device()
    );
    let full = render_to(Path::new("/dev/full"));
    assert_user_error(&full, "No space left on device");
    assert!(
        Path::new("/dev/full")
            .metadata()
            .unwrap()
            .file_type()
            .is_char_device()
    );
}

/// The scene is broken, so only a check made before loading it can name the destination.
#[test]
fn unwritable_destinations_are_refused_before_any_work() {
    let dir = temp_dir("out-refused");
    let broken = dir.join("broken.toml");
    std::fs::write(&broken, "[camera\n").unwrap();
    let broken = broken.to_str().unwrap();
    let cases = [
        (dir.to_path_buf(), "it is a directory"),
        (
            dir.join("no-such-dir/out.png"),
            "no-such-dir does not exist",
        ),
    ];
    for (out, expected) in cases {
        let output = bumpwork(&["render", broken, "-o", out.to_str().unwrap()]);
        assert_user_error(&output, expected);
    }
    if !is_root() {
        let locked = dir.join("locked.png");
        std::fs::write(&locked, b"keep").unwrap();
        std::fs::set_permissions(&locked, std::fs::Permissions::from_mode(0o444)).unwrap();
        assert_user_error(&render_to(&locked), "read-only");
        assert_eq!(std::fs::read(&locked).unwrap(), b"keep");
    }
    let afile = dir.join("afile");
    std::fs::write(&afile, b"keep").unwrap();
    let gallery = bumpwork(&["gallery", "-o", afile.to_str().unwrap()]);
    assert_user_error(&gallery, "is not a directory");
    // The bench runs for minutes: refusing at once is what lets this test finish.
    let bench = bumpwork(&["bench", "--chart", dir.to_str().unwrap()]);
    assert_user_error(&bench, "it is a directory");
}

#[test]
fn a_full_or_closed_standard_output_ends_cleanly() {
    let list = Command::new(env!("CARGO_BIN_EXE_bumpwork"))
        .args(["render", "--list"])
        .stdout(
            std::fs::File::options()
                .write(true)
                .open("/dev/full")
                .unwrap(),
        )
        .output()
        .unwrap();
    assert_user_error(
        &list,
        "cannot write standard output: No space left on device",
    );
    assert_eq!(stderr(&list).lines().count(), 1, "{}", stderr(&list));

    let mut check = Command::new(env!("CARGO_BIN_EXE_bumpwork"));
    check.arg("check");
    let pattern = concat!(env!("CARGO_MANIFEST_DIR"), "/patterns/bumps.pat");
    check.args(std::iter::repeat_n(pattern, 3000));
    let mut child = check
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = [0u8; 16];
    child.stdout.take().unwrap().read_exact(&mut first).unwrap();
    // The pipe is closed here, with thousands of lines still to print.
    let output = child.wait_with_output().unwrap();
    use std::os::unix::process::ExitStatusExt;
    assert_eq!(
        output.status.signal(),
        Some(libc::SIGPIPE),
        "{}",
        stderr(&output)
    );
    assert!(stderr(&output).is_empty(), "{}", stderr(&output));
}

#[test]
fn frames_that_replace_files_are_counted_and_no_clobber_refuses_before_rendering() {
    let dir = temp_dir("no-clobber");
    let output = dir.join("anim.png");
    let output = output.to_str().unwrap();
    let frames = |range: &str, extra: &[&str]| {
        let mut args = vec!["render", "plane-spheres", "--size", "16x12", "-o", output];
        args.extend(["--fps", "4", "--time-range", range]);
        args.extend(extra);
        bumpwork(&args)
    };
    let first = frames("0..1", &[]);
    assert!(first.status.success(), "{}", stderr(&first));
    assert!(!stderr(&first).contains("replaced"), "{}", stderr(&first));
    let kept = std::fs::read(dir.join("anim-0002.png")).unwrap();
    let again = frames("0..2", &[]);
    assert!(again.status.success(), "{}", stderr(&again));
    assert!(
        stderr(&again).contains("4 of the 8 frames replaced files of the same names"),
        "{}",
        stderr(&again)
    );
    // Refused before anything renders: no frame is written, none replaced.
    std::fs::remove_file(dir.join("anim-0007.png")).unwrap();
    std::fs::write(dir.join("anim-0002.png"), &kept).unwrap();
    let refused = frames("0..2", &["--no-clobber"]);
    assert_user_error(&refused, "--no-clobber: ");
    assert_user_error(
        &refused,
        "anim-0000.png exists (and 6 more of the 8 files to write)",
    );
    assert!(!dir.join("anim-0007.png").exists(), "a frame was rendered");
    assert_eq!(std::fs::read(dir.join("anim-0002.png")).unwrap(), kept);
    let still = dir.join("still.png");
    let still = still.to_str().unwrap();
    let render = || {
        bumpwork(&[
            "render",
            "plane-spheres",
            "--size",
            "8x8",
            "-o",
            still,
            "--no-clobber",
        ])
    };
    assert!(render().status.success());
    assert_user_error(&render(), "still.png exists; nothing was rendered");
}
