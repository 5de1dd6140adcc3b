//! Every kind of error names the right line and column, shows the line with a caret under the
//! spot, and never crashes.

use bumpwork::pattern::{MAX_SOURCE_BYTES, Pattern, PatternError};

fn error(source: &str) -> PatternError {
    match Pattern::compile(source, "bad.pat") {
        Ok(_) => panic!("compiled without error:\n{source}"),
        Err(e) => e,
    }
}

/// Asserts the error's place, message, and that the caret sits under the reported column.
fn assert_error(source: &str, line: usize, column: usize, says: &str) {
    let e = error(source);
    assert_eq!((e.line, e.column), (line, column), "{e}");
    assert!(
        e.message.contains(says),
        "message {:?} lacks {says:?}",
        e.message
    );
    let text = e.to_string();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 4, "{text}");
    assert!(lines[0].starts_with(&format!("bad.pat:{line}:{column}: ")));
    let source_line = source.lines().nth(line - 1).unwrap_or("");
    assert_eq!(lines[2], format!("{line} | {source_line}"));
    let caret = lines[3].find('^').expect("caret");
    let prefix = format!("{line} | ").len();
    assert_eq!(caret - prefix, column - 1, "caret column\n{text}");
}

#[test]
fn unknown_name_suggests_the_closest_known_name() {
    assert_error(
        "param depth = 2 in 0..5\nheight = dpeth * u",
        2,
        10,
        "unknown name `dpeth`; did you mean `depth`?",
    );
    assert_error("height = sine(u)", 1, 10, "did you mean `sin`?");
    assert_error("height = zebra", 1, 10, "unknown name `zebra`");
}

#[test]
fn a_colour_where_a_number_is_needed() {
    assert_error(
        "let c = rgb(1, 0, 0)\nheight = 2 * c",
        2,
        14,
        "expected a number, found a colour",
    );
    assert_error("color = 1 + u", 1, 9, "expected a colour, found a number");
}

#[test]
fn wrong_argument_count() {
    assert_error(
        "height = u + clamp(u, 0)",
        1,
        14,
        "`clamp` expects 3 arguments, found 2",
    );
    assert_error("height = noise(u)", 1, 10, "2 or 3 arguments");
}

#[test]
fn conditions_and_numbers_do_not_mix() {
    assert_error("height = if u then 1 else 0", 1, 13, "expected a condition");
    assert_error(
        "height = (u < 1) + 1",
        1,
        11,
        "expected a number, found a condition",
    );
}

#[test]
fn param_ranges_are_checked() {
    assert_error(
        "param p = 7 in 0..5\nheight = p",
        1,
        11,
        "default 7 is outside the range 0..5",
    );
    assert_error("param p = 1 in 5..-5\nheight = p", 1, 16, "MIN < MAX");
}

#[test]
fn exactly_one_output() {
    assert_error("let a = u\n", 2, 1, "expected an output");
    assert_error("height = u\nslope = (u, v)", 2, 1, "found a second one");
}

#[test]
fn syntax_errors_point_at_the_token() {
    assert_error(
        "let a = u +\nheight = a",
        2,
        1,
        "expected an expression, found `height`",
    );
    assert_error(
        "height = (u * 2",
        1,
        16,
        "expected `)`, found the end of the file",
    );
    assert_error("height = u $ 2", 1, 12, "unexpected character `$`");
    assert_error("hieght = u", 1, 1, "expected `param`, `let`");
}

#[test]
fn a_million_nested_parentheses_is_an_error_not_a_crash() {
    let source = format!(
        "height = {}u{}",
        "(".repeat(1_000_000),
        ")".repeat(1_000_000)
    );
    assert!(source.len() > MAX_SOURCE_BYTES);
    assert!(error(&source).message.contains("too large"));
    let source = format!("height = {}u{}", "(".repeat(400_000), ")".repeat(400_000));
    let e = error(&source);
    assert!(e.message.contains("nests too deeply"), "{}", e.message);
    assert_eq!(e.line, 1);
    let source = format!("height = {}u", "-".repeat(400_000));
    assert!(error(&source).message.contains("nests too deeply"));
}

#[test]
fn long_operator_chains_are_depth_limited_too() {
    let source = format!("height = u{}", " + u".repeat(100_000));
    assert!(error(&source).message.contains("nests too deeply"));
}

#[test]
fn control_characters_never_reach_the_terminal() {
    let e = error("height = u \u{1b}[2J + \u{7}");
    let text = e.to_string();
    assert!(
        !text.chars().any(|c| c.is_control() && c != '\n'),
        "{text:?}"
    );
    assert!(text.contains("\\e[2J"));
    let e = error("height = \u{202e}u");
    assert!(!e.to_string().contains('\u{202e}'));
}

#[test]
fn unreadable_and_oversized_files_are_errors() {
    let missing = Pattern::load("/nonexistent/dir/x.pat".as_ref()).unwrap_err();
    assert!(
        missing
            .to_string()
            .starts_with("/nonexistent/dir/x.pat: cannot read")
    );
    let dir = tempfile::tempdir().expect("a temporary directory");
    let dir = dir.path();
    std::fs::create_dir_all(dir).unwrap();
    let big = dir.join("big.pat");
    std::fs::write(&big, "#".repeat(MAX_SOURCE_BYTES + 1)).unwrap();
    assert!(
        Pattern::load(&big)
            .unwrap_err()
            .message
            .contains("too large")
    );
    let binary = dir.join("binary.pat");
    std::fs::write(&binary, b"height = u\n# \xff\xfe").unwrap();
    let e = Pattern::load(&binary).unwrap_err();
    assert_eq!((e.line, e.column), (2, 3));
}

#[test]
fn names_cannot_shadow_built_ins_or_repeat() {
    assert_error("let sin = 1\nheight = sin", 1, 5, "`sin` is built in");
    assert_error(
        "param a = 1 in 0..2\nlet a = 2\nheight = a",
        2,
        5,
        "already defined",
    );
}

/// A file just under the size limit made of `let`s, each using the one before.
fn let_chain(output: &str) -> String {
    let mut source = String::from("let a0 = u\n");
    let mut i = 1;
    while source.len() < MAX_SOURCE_BYTES - 100 {
        source.push_str(&format!("let a{i} = a{} * 1.5 + v\n", i - 1));
        i += 1;
    }
    source + &output.replace("LAST", &format!("a{}", i - 1))
}

#[test]
fn a_megabyte_of_lets_compiles_quickly_or_says_it_is_too_large() {
    let start = std::time::Instant::now();
    assert!(Pattern::compile(&let_chain("height = a0"), "big.pat").is_ok());
    let e = error(&let_chain("height = LAST"));
    assert!(e.message.contains("pattern too large"), "{}", e.message);
    assert!(start.elapsed().as_secs() < 20, "took {:?}", start.elapsed());
}
