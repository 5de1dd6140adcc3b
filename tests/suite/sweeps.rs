//! `bumpwork sweep`: every combination of the varied settings is one still that renders again
//! from its own recipe, the sheet and `sweep.json` say which values made which still, shards run
//! at once write the unsharded run's stills, and `sheet` makes the same index after them.
//! `gallery --shard` splits the gallery the same way.

use crate::cli_support::{assert_user_error, bumpwork, decode_png, stderr, temp_dir};
use crate::shards::{files, owned, run_shards_at_once};

fn sweep_args<'a>(output: &'a str, extra: &[&'a str]) -> Vec<&'a str> {
    let mut args = vec!["sweep", "plane-cobbles", "--size", "48x36", "-o", output];
    args.extend(["--vary", "bump.size=20..60:3", "--vary", "bump.rise=2,8"]);
    args.extend(extra);
    args
}

fn index(dir: &std::path::Path) -> serde_json::Value {
    let text = std::fs::read_to_string(dir.join("sweep.json")).expect("sweep.json");
    serde_json::from_str(&text).expect("sweep.json is JSON")
}

#[test]
fn every_combination_is_a_still_the_index_and_its_recipe_describe() {
    let dir = temp_dir("sweep-whole");
    let run = bumpwork(&sweep_args(dir.to_str().unwrap(), &[]));
    assert!(run.status.success(), "{}", stderr(&run));
    let index = index(&dir);
    let stills = index["stills"].as_array().unwrap();
    assert_eq!(stills.len(), 6);
    // The last --vary changes fastest.
    let values: Vec<(i64, i64)> = stills
        .iter()
        .map(|s| {
            let v = &s["values"];
            (
                v["bump.size"].as_i64().unwrap(),
                v["bump.rise"].as_i64().unwrap(),
            )
        })
        .collect();
    assert_eq!(
        values,
        [(20, 2), (20, 8), (40, 2), (40, 8), (60, 2), (60, 8)]
    );
    let hashes: std::collections::BTreeSet<&str> = stills
        .iter()
        .map(|s| s["recipe"].as_str().unwrap())
        .collect();
    assert_eq!(hashes.len(), 6, "each combination has a recipe of its own");
    // The stills differ, and each renders again from its recipe to the same pixels.
    let pictures: Vec<Vec<u8>> = stills
        .iter()
        .map(|s| decode_png(&dir.join(s["file"].as_str().unwrap())).2)
        .collect();
    assert!(pictures.windows(2).all(|pair| pair[0] != pair[1]));
    let again = dir.join("again.png");
    let still = dir.join(stills[3]["file"].as_str().unwrap());
    let rerun = bumpwork(&[
        "render",
        "--from",
        still.to_str().unwrap(),
        "-o",
        again.to_str().unwrap(),
    ]);
    assert!(rerun.status.success(), "{}", stderr(&rerun));
    assert_eq!(decode_png(&again).2, pictures[3]);
    // A sheet with a column per value of the last --vary: two across, three down.
    let (width, height, _) = decode_png(&dir.join("contact-sheet.png"));
    assert!(height > width, "{width}×{height}");
}

#[test]
fn shards_at_once_write_the_unsharded_stills_and_sheet_makes_the_same_index() {
    let (whole, sharded) = (temp_dir("sweep-one"), temp_dir("sweep-shards"));
    let one = bumpwork(&sweep_args(whole.to_str().unwrap(), &[]));
    assert!(one.status.success(), "{}", stderr(&one));
    let output = sharded.to_str().unwrap();
    run_shards_at_once(3, |shard| owned(sweep_args(output, &["--shard", shard])));
    let (mut expected, got) = (files(&whole), files(&sharded));
    let sheet = expected.remove("contact-sheet.png").expect("a sheet");
    let index_bytes = expected.remove("sweep.json").expect("an index");
    assert_eq!(expected.len(), 6);
    assert!(expected == got, "the shards wrote other files than one run");
    let incomplete = temp_dir("sweep-part");
    let part = bumpwork(&sweep_args(
        incomplete.to_str().unwrap(),
        &["--shard", "2/3"],
    ));
    assert!(part.status.success(), "{}", stderr(&part));
    assert_user_error(
        &bumpwork(&["sheet", incomplete.to_str().unwrap()]),
        "4 frames are missing: sweep-0000.png, sweep-0002.png",
    );
    let made = bumpwork(&["sheet", output]);
    assert!(made.status.success(), "{}", stderr(&made));
    assert_eq!(
        std::fs::read(sharded.join("sweep.json")).unwrap(),
        index_bytes
    );
    assert_eq!(
        std::fs::read(sharded.join("contact-sheet.png")).unwrap(),
        sheet
    );
    // A sheet made elsewhere leaves the directory's own sheet out of it.
    let elsewhere = incomplete.join("again.png");
    let again = bumpwork(&["sheet", output, "-o", elsewhere.to_str().unwrap()]);
    assert!(again.status.success(), "{}", stderr(&again));
    assert!(String::from_utf8_lossy(&again.stdout).starts_with("6 stills"));
}

#[test]
fn a_bad_axis_is_one_line_before_anything_is_written() {
    let dir = temp_dir("sweep-bad");
    let output = dir.join("out");
    let output = output.to_str().unwrap();
    let sweep = |vary: &str| bumpwork(&["sweep", "plane-cobbles", "-o", output, "--vary", vary]);
    assert_user_error(
        &sweep("bump.depth=1,2"),
        "--vary bump.depth=1: no such parameter; the parameters there are radius, rise, size",
    );
    assert_user_error(
        &sweep("quality.samples=0,4"),
        "samples 0 is outside 1..=1024",
    );
    assert_user_error(&sweep("bump.size=1..9"), "expected START..END:COUNT");
    let huge = bumpwork(&[
        "sweep",
        "plane-cobbles",
        "-o",
        output,
        "--vary",
        "bump.size=4..300:1000",
        "--vary",
        "bump.rise=0..50:11",
    ]);
    assert_user_error(&huge, "the sweep has 1000 × 11 combinations; at most 10000");
    assert!(!std::path::Path::new(output).exists(), "nothing is written");
}

#[test]
fn gallery_shards_split_the_scenes_and_sheet_names_what_is_missing() {
    let dir = temp_dir("gallery-shards");
    let output = dir.to_str().unwrap();
    let gallery = |shard: &str| {
        bumpwork(&[
            "gallery",
            "-o",
            output,
            "--size",
            "40x30",
            "--samples",
            "1",
            "--scenes",
            "plane-stucco,plane-cobbles,cone-bark",
            "--shard",
            shard,
        ])
    };
    let first = gallery("1/2");
    assert!(first.status.success(), "{}", stderr(&first));
    let names: Vec<String> = files(&dir).into_keys().collect();
    assert_eq!(names, ["cone-bark.png", "plane-stucco.png"]);
    assert_user_error(
        &bumpwork(&["sheet", output]),
        "1 frame is missing: still 2 of 3",
    );
    let second = gallery("2/2");
    assert!(second.status.success(), "{}", stderr(&second));
    let made = bumpwork(&["sheet", output]);
    assert!(made.status.success(), "{}", stderr(&made));
    assert!(dir.join("contact-sheet.png").exists());
    assert!(!dir.join("sweep.json").exists(), "a gallery is no sweep");
}
