//! Every error is one line with one `bumpwork: error:` prefix, in the user's words; hints (usage,
//! a caret under the place) come after it, and quotes from files are short.

use crate::cli_support::{assert_user_error, bumpwork, stderr, temp_dir};

/// Status 1, the first line is the message and the only one that says "error".
fn assert_one_message(output: &std::process::Output, expected: &str) -> String {
    assert_user_error(output, expected);
    let message = stderr(output);
    let first = message.lines().next().unwrap_or_default();
    assert!(first.starts_with("bumpwork: error: "), "{message}");
    assert!(
        first.contains(expected),
        "expected '{expected}' on the first line: {message}"
    );
    assert_eq!(message.matches("error").count(), 1, "{message}");
    message
}

#[test]
fn argument_errors_are_one_line_with_usage_after() {
    let message = assert_one_message(
        &bumpwork(&["render", "plane-dimples", "-o", "x.png", "--size", "abc"]),
        "invalid value 'abc' for '--size <SIZE>'",
    );
    assert!(message.contains("--help"), "{message}");
    let message = assert_one_message(
        &bumpwork(&["render"]),
        "the following required arguments were not provided: --output <OUTPUT>, <SCENE>",
    );
    assert!(
        message.contains("\nUsage: bumpwork render"),
        "usage follows: {message}"
    );
    let message = assert_one_message(&bumpwork(&["rendr"]), "unrecognized subcommand 'rendr'");
    assert!(message.contains("'render'"), "the tip follows: {message}");
}

#[test]
fn a_pattern_error_says_error_once() {
    let dir = temp_dir("messages-pattern");
    let path = dir.join("x.pat");
    std::fs::write(&path, "height = 1 +\n  * 2\n").unwrap();
    let name = path.to_str().unwrap();
    let expected = format!("{name}:2:3: expected an expression");
    assert_one_message(&bumpwork(&["check", name]), &expected);
    assert_one_message(&bumpwork(&["render", name, "-o", "x.png"]), &expected);
}

#[test]
fn scene_file_type_errors_are_in_the_users_words() {
    let dir = temp_dir("messages-toml");
    let scene = |camera: &str, surface: &str| {
        let path = dir.join("s.toml");
        std::fs::write(
            &path,
            format!("[camera]\n{camera}\ntarget = [0, 0, 0]\n\n[[object]]\nsurface.{surface}\n"),
        )
        .unwrap();
        bumpwork(&["check", path.to_str().unwrap()])
    };
    let sphere = "sphere = { center = [0, 0, 0], radius = 1 }";
    for (camera, surface, expected) in [
        (
            "eye = [0, 0, true]",
            sphere,
            "s.toml:2:14: expected a number, found true",
        ),
        (
            "eye = \"far\"",
            sphere,
            "expected a list in brackets, found the text \"far\"",
        ),
        (
            "eye = [0, 0, 5]\nfov = \"wide\"",
            sphere,
            "expected a number, found the text \"wide\"",
        ),
        // A fourth coordinate is refused, not dropped.
        (
            "eye = [0, 0, 5, 1]",
            sphere,
            "expected a point: three finite numbers",
        ),
        (
            "eye = [0, 0, 5]",
            "plane = { origin = [0, 0, 0], normal = [0, 0, 1], u-axis = [1, 0, 0], size = [1, 2, 3] }",
            "expected a list of 2 values in brackets, found 3 values",
        ),
    ] {
        let message = assert_one_message(&scene(camera, surface), expected);
        assert!(!message.contains("f64"), "{message}");
    }
}

#[test]
fn view_answers_an_unknown_scene_as_render_does() {
    let render = bumpwork(&["render", "plane-dimple", "-o", "x.png"]);
    let view = bumpwork(&["view", "plane-dimple"]);
    let expected = "unknown scene 'plane-dimple'";
    assert_one_message(&render, expected);
    assert_one_message(&view, expected);
    assert!(
        stderr(&view).contains("did you mean 'plane-dimples'"),
        "{}",
        stderr(&view)
    );
    assert_eq!(stderr(&render), stderr(&view));
}

#[test]
fn view_without_a_terminal_says_it_needs_one() {
    // The test harness gives the child pipes, not a terminal.
    assert_one_message(
        &bumpwork(&["view", "plane-dimples"]),
        "the workbench needs a terminal",
    );
}

#[test]
fn a_900_000_digit_literal_is_quoted_in_a_short_excerpt() {
    let dir = temp_dir("messages-long-literal");
    let digits = "1".repeat(900_000);
    let pattern = dir.join("big.pat");
    std::fs::write(&pattern, format!("height = {digits} +\n")).unwrap();
    let scene = dir.join("big.toml");
    std::fs::write(&scene, format!("[camera]\neye = [{digits}, 0, 0]\n")).unwrap();
    for path in [pattern, scene] {
        let output = bumpwork(&["check", path.to_str().unwrap()]);
        assert_user_error(&output, "big.");
        // The message line and the excerpt under it, each within 60 characters a side.
        assert!(output.stderr.len() < 1000, "{} bytes", output.stderr.len());
    }
}

#[test]
fn a_directory_that_takes_no_files_is_not_called_missing() {
    let output = bumpwork(&["render", "plane-dimples", "-o", "/proc/out.png"]);
    let message = assert_one_message(
        &output,
        "cannot create a file in /proc: it takes no new files",
    );
    assert!(!message.contains("does not exist"), "{message}");
}

#[test]
fn a_finite_number_out_of_range_is_told_as_such_with_the_range() {
    let set =
        |setting: &str| bumpwork(&["render", "plane-spheres", "-o", "x.png", "--set", setting]);
    for huge in ["1e308", "-1e308", "1e100"] {
        let message = assert_one_message(
            &set(&format!("bump.period={huge}")),
            "is outside period's range 4..300",
        );
        assert!(!message.contains("expected a number"), "{message}");
        assert_one_message(
            &set(&format!("bump.strength={huge}")),
            "is beyond ±3.4e38, the most a strength can be",
        );
    }
    assert_one_message(
        &set("bump.period=500"),
        "500 is outside period's range 4..300",
    );
    assert_one_message(&set("bump.period=wide"), "expected a number, found 'wide'");
}

#[test]
fn a_time_range_past_the_longest_time_says_so() {
    let range = |range: &str| {
        bumpwork(&[
            "render",
            "plane-spheres",
            "-o",
            "x.png",
            "--fps",
            "24",
            "--time-range",
            range,
        ])
    };
    let message = assert_one_message(&range("0..1e30"), "the time '1e30' is past the longest");
    assert!(!message.contains("START < END"), "{message}");
    assert_one_message(&range("0..1e9"), "frames; expected 1..=100000");
    assert_one_message(&range("5..1"), "expected START < END, got '5..1'");
    assert_one_message(&range("0..soon"), "expected a time in seconds, got 'soon'");
}

#[test]
fn long_arguments_are_quoted_cut_to_sixty_characters() {
    let long = "k".repeat(100_000);
    let cases = [
        vec!["render", "plane-spheres", "-o", "x.png", "--set"],
        vec!["render", "plane-spheres", "-o", "x.png", "--size"],
        vec!["render", "plane-spheres", "-o", "x.png", "--quality"],
        vec!["render", "plane-spheres", "-o", "x.png", "--time"],
    ];
    for args in cases {
        let value = format!("{long}=1");
        let mut args = args.clone();
        args.push(&value);
        let output = bumpwork(&args);
        let message = stderr(&output);
        assert_eq!(output.status.code(), Some(1), "{}", &message[..200]);
        assert!(
            message.len() < 2_000,
            "{} bytes for {args:?}",
            message.len()
        );
        assert!(
            message.contains(&format!("{}…", "k".repeat(60))),
            "{message}"
        );
    }
    let unknown = format!("--{long}");
    let message = stderr(&bumpwork(&["render", "plane-spheres", &unknown]));
    assert!(message.len() < 2_000, "{} bytes", message.len());
    let message = stderr(&bumpwork(&[&long]));
    assert!(message.len() < 2_000, "{} bytes", message.len());
}
