//! `render --time-range --shard K/N`: shards run at once in separate processes write, between
//! them, exactly the files of one unsharded run, none twice; `sheet` assembles them, or names the
//! frames still missing; a shard stopped by its scheduler leaves only whole frames, and run
//! again alone it finishes its share.

use crate::cli_support::{assert_user_error, bumpwork, stderr, temp_dir};
use std::collections::BTreeMap;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

fn sequence_args<'a>(output: &'a str, extra: &[&'a str]) -> Vec<&'a str> {
    let mut args = vec!["render", "plane-ripple", "--size", "48x36", "-o", output];
    args.extend(["--fps", "6", "--time-range", "0..2"]);
    args.extend(extra);
    args
}

/// Every file in `dir` by name, with its bytes.
pub fn files(dir: &Path) -> BTreeMap<String, Vec<u8>> {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap())
        .map(|e| {
            (
                e.file_name().to_string_lossy().into_owned(),
                std::fs::read(e.path()).unwrap(),
            )
        })
        .collect()
}

/// Runs shards 1/`count` … `count`/`count` at once, each in its own process with the
/// arguments `args` gives for its `K/N`; each succeeds, and none finds another's file to replace
/// (none writes a file twice).
pub fn run_shards_at_once(count: u32, args: impl Fn(&str) -> Vec<String>) {
    let shards: Vec<String> = (1..=count).map(|k| format!("{k}/{count}")).collect();
    let children: Vec<_> = shards
        .iter()
        .map(|shard| {
            Command::new(env!("CARGO_BIN_EXE_bumpwork"))
                .args(args(shard))
                .stdout(Stdio::null())
                .stderr(Stdio::piped())
                .spawn()
                .unwrap()
        })
        .collect();
    for child in children {
        let done = child.wait_with_output().unwrap();
        let said = String::from_utf8_lossy(&done.stderr);
        assert!(done.status.success(), "{said}");
        assert!(!said.contains("replaced"), "{said}");
    }
}

/// Arguments as owned strings.
pub fn owned(args: Vec<&str>) -> Vec<String> {
    args.into_iter().map(str::to_string).collect()
}

#[test]
fn four_shards_at_once_write_the_files_of_one_run_each_once() {
    let (whole, sharded) = (temp_dir("shards-whole"), temp_dir("shards-four"));
    let output = whole.join("frame.png");
    let one = bumpwork(&sequence_args(output.to_str().unwrap(), &[]));
    assert!(one.status.success(), "{}", stderr(&one));
    let output = sharded.join("frame.png");
    let output = output.to_str().unwrap();
    run_shards_at_once(4, |shard| owned(sequence_args(output, &["--shard", shard])));
    let (expected, got) = (files(&whole), files(&sharded));
    assert_eq!(expected.len(), 12);
    assert_eq!(
        got.keys().collect::<Vec<_>>(),
        expected.keys().collect::<Vec<_>>()
    );
    assert!(
        expected == got,
        "the sharded frames differ from the unsharded run's"
    );
    // After all the shards, `sheet` makes the contact sheet of the twelve.
    let sheet = bumpwork(&["sheet", sharded.to_str().unwrap()]);
    assert!(sheet.status.success(), "{}", stderr(&sheet));
    assert!(sharded.join("contact-sheet.png").exists());
    // Shard 2 of 4 alone writes frames 1, 5 and 9 only; `sheet` names the nine missing.
    let alone = temp_dir("shards-alone");
    let output = alone.join("frame.png");
    let run = bumpwork(&sequence_args(
        output.to_str().unwrap(),
        &["--shard", "2/4"],
    ));
    assert!(run.status.success(), "{}", stderr(&run));
    let names: Vec<String> = files(&alone).into_keys().collect();
    assert_eq!(
        names,
        ["frame-0001.png", "frame-0005.png", "frame-0009.png"]
    );
    let incomplete = bumpwork(&["sheet", alone.to_str().unwrap()]);
    assert_user_error(
        &incomplete,
        "9 frames are missing: frame-0000.png, frame-0002.png",
    );
    assert!(
        !alone.join("contact-sheet.png").exists(),
        "a sheet of part of a sequence"
    );
    // More shards than frames: the extra ones have nothing to do, and say so.
    let extra = bumpwork(&sequence_args(
        output.to_str().unwrap(),
        &["--shard", "20/20"],
    ));
    assert!(extra.status.success(), "{}", stderr(&extra));
    assert!(stderr(&extra).contains("none of the sequence's frames"));
}

#[test]
fn a_shard_stopped_by_its_scheduler_leaves_whole_frames_and_finishes_when_rerun() {
    let dir = temp_dir("shards-stopped");
    let output = dir.join("big.png");
    let output = output.to_str().unwrap();
    // Big frames, so the shard is stopped in the middle of one; small ones for the rerun.
    let args = |size: &'static str, extra: &[&'static str]| {
        let mut args = vec!["render", "plane-ripple", "--size", size, "-o", output];
        args.extend(["--samples", "16", "--fps", "8", "--time-range", "0..2"]);
        args.extend(extra);
        args.into_iter().map(str::to_string).collect::<Vec<_>>()
    };
    let mut shard = Command::new(env!("CARGO_BIN_EXE_bumpwork"))
        .args(args("1600x1200", &["--shard", "1/2"]))
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    // Stopped as Slurm and Kubernetes stop a job, by SIGTERM, once its first frame is written.
    let deadline = Instant::now() + Duration::from_secs(120);
    while !dir.join("big-0000.png").exists() {
        assert!(Instant::now() < deadline, "no frame written");
        assert!(
            shard.try_wait().unwrap().is_none(),
            "the shard ended before it was stopped"
        );
        std::thread::sleep(Duration::from_millis(20));
    }
    // SAFETY: kill only sends a signal to the process we started.
    assert_eq!(unsafe { libc::kill(shard.id() as i32, libc::SIGTERM) }, 0);
    let status = shard.wait().unwrap();
    assert!(!status.success(), "a stopped shard does not report success");
    for (name, bytes) in files(&dir) {
        assert!(!name.starts_with('.'), "a temporary file was left: {name}");
        let decoder = png::Decoder::new(std::io::Cursor::new(bytes));
        let mut reader = decoder.read_info().unwrap();
        let mut pixels = vec![0; reader.output_buffer_size().unwrap()];
        reader
            .next_frame(&mut pixels)
            .unwrap_or_else(|e| panic!("{name} is cut: {e}"));
    }
    let rerun = Command::new(env!("CARGO_BIN_EXE_bumpwork"))
        .args(args("160x120", &["--shard", "1/2"]))
        .output()
        .unwrap();
    assert!(rerun.status.success(), "{}", stderr(&rerun));
    let names: Vec<String> = files(&dir).into_keys().collect();
    let evens: Vec<String> = (0..16)
        .step_by(2)
        .map(|i| format!("big-{i:04}.png"))
        .collect();
    assert_eq!(names, evens);
}
