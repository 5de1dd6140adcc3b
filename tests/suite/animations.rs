//! `render --time-range … -o anim.apng|anim.gif`: one file holding every frame of the sequence,
//! the APNG's frames exactly the numbered PNGs' pixels, the GIF's within its palette's error, the
//! frame times adding up to the range, the first frame's recipe in the file; what cannot be
//! made is refused before anything is written.

use crate::cli_support::{assert_user_error, bumpwork, decode_png, stderr, temp_dir};
use crate::graphics_support::psnr;
use std::path::Path;

const SCENE: [&str; 4] = ["plane-ripples", "--set", "bump.speed=40", "--size=64x48"];

fn render(output: &Path, extra: &[&str]) -> std::process::Output {
    let mut args = vec!["render"];
    args.extend(SCENE);
    args.extend([
        "-o",
        output.to_str().unwrap(),
        "--time-range",
        "0..1",
        "--fps",
        "6",
    ]);
    args.extend(extra);
    bumpwork(&args)
}

/// The numbered PNG frames of the same sequence, in order.
fn png_frames(dir: &Path) -> Vec<Vec<u8>> {
    let run = render(&dir.join("frame.png"), &[]);
    assert!(run.status.success(), "{}", stderr(&run));
    (0..6)
        .map(|i| decode_png(&dir.join(format!("frame-{i:04}.png"))).2)
        .collect()
}

#[test]
fn an_apng_holds_the_sequence_exactly_with_its_times_and_recipe() {
    let dir = temp_dir("apng");
    let expected = png_frames(&dir);
    let apng = dir.join("ripples.apng");
    let run = render(&apng, &[]);
    assert!(run.status.success(), "{}", stderr(&run));
    let decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(&apng).unwrap()));
    let mut reader = decoder.read_info().unwrap();
    let control = reader.info().animation_control.expect("an animated PNG");
    assert_eq!((control.num_frames, control.num_plays), (6, 0));
    let mut pixels = vec![0; reader.output_buffer_size().unwrap()];
    for (i, frame) in expected.iter().enumerate() {
        reader.next_frame(&mut pixels).unwrap();
        let timing = reader
            .info()
            .frame_control
            .expect("each frame has its timing");
        assert_eq!((timing.delay_num, timing.delay_den), (1, 6), "frame {i}");
        assert_eq!(&pixels, frame, "frame {i} differs from frame-{i:04}.png");
    }
    // The first frame's recipe: `render --from` makes frame 0 again.
    let again = dir.join("again.png");
    let from = bumpwork(&[
        "render",
        "--from",
        apng.to_str().unwrap(),
        "-o",
        again.to_str().unwrap(),
    ]);
    assert!(from.status.success(), "{}", stderr(&from));
    assert_eq!(decode_png(&again).2, expected[0]);
}

#[test]
fn a_gif_holds_the_sequence_within_its_palette_error() {
    let dir = temp_dir("gif");
    let expected = png_frames(&dir);
    let gif_path = dir.join("ripples.gif");
    let run = render(&gif_path, &[]);
    assert!(run.status.success(), "{}", stderr(&run));
    let mut options = gif::DecodeOptions::new();
    options.set_color_output(gif::ColorOutput::RGBA);
    let file = std::fs::File::open(&gif_path).unwrap();
    let mut decoder = options.read_info(std::io::BufReader::new(file)).unwrap();
    let mut total_delay = 0;
    let mut frames = 0;
    while let Some(frame) = decoder.read_next_frame().unwrap() {
        assert_eq!((frame.width, frame.height), (64, 48));
        total_delay += u32::from(frame.delay);
        let rgb: Vec<u8> = frame
            .buffer
            .chunks_exact(4)
            .flat_map(|p| [p[0], p[1], p[2]])
            .collect();
        let psnr = psnr(&rgb, &expected[frames]);
        assert!(psnr > 32.0, "frame {frames}: {psnr:.1} dB against its PNG");
        frames += 1;
    }
    assert_eq!(frames, 6);
    assert_eq!(total_delay, 100, "six frames at 6 fps last one second");
    let bytes = std::fs::read(&gif_path).unwrap();
    let text = String::from_utf8_lossy(&bytes);
    assert!(
        text.contains("bumpwork-recipe"),
        "the recipe is in a comment"
    );
}

#[test]
fn what_an_animation_cannot_be_is_refused_before_anything_is_written() {
    let dir = temp_dir("animation-refused");
    let gif = dir.join("a.gif");
    let still = bumpwork(&["render", "plane-ripples", "-o", gif.to_str().unwrap()]);
    assert_user_error(&still, "is an animation: give --time-range");
    let fast = bumpwork(&[
        "render",
        "plane-ripples",
        "-o",
        gif.to_str().unwrap(),
        "--time-range",
        "0..1",
        "--fps",
        "60",
    ]);
    assert_user_error(&fast, "a GIF shows at most 50 frames a second");
    assert_user_error(
        &render(&dir.join("a.apng"), &["--shard", "1/2"]),
        "shards cannot split",
    );
    let huge = std::process::Command::new(env!("CARGO_BIN_EXE_bumpwork"))
        .args(["render", "plane-ripples", "--size", "16000x16000", "-o"])
        .arg(&gif)
        .args(["--time-range", "0..1", "--fps", "2"])
        .env("BUMPWORK_MEMORY_MIB", "512")
        .output()
        .unwrap();
    assert_user_error(&huge, "over the 512 MiB memory budget");
    let left: Vec<_> = std::fs::read_dir(&*dir).unwrap().collect();
    assert!(left.is_empty(), "{left:?}");
}

/// A sequence of a scene where nothing moves with time says so before it writes a frame.
#[test]
fn an_animation_of_a_still_scene_says_every_frame_is_the_same() {
    let dir = temp_dir("still-animation");
    let output = dir.join("still.gif");
    let args = [
        "render",
        "plane-ripples",
        "--size=32x24",
        "-o",
        output.to_str().unwrap(),
    ];
    let run = bumpwork(&[&args[..], &["--time-range", "0..1", "--fps", "4"]].concat());
    assert!(run.status.success(), "{}", stderr(&run));
    assert!(
        stderr(&run).contains("all 4 frames are the same picture"),
        "{}",
        stderr(&run)
    );
    let moving = render(&dir.join("moving.gif"), &[]);
    assert!(
        !stderr(&moving).contains("same picture"),
        "{}",
        stderr(&moving)
    );
}
