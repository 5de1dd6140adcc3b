//! The status line: what is shown and what it cost, shortened to fit by dropping the least
//! important parts first.

use super::app::App;
use super::frame_report::FrameReport;
use super::material_controls::{ParamRow, ParamSlot};
use super::mode_names::{colors_name, picture_name};
use super::overlay::WorkbenchState;
use super::status_message::Message;
use crate::scene::{BumpSource, Material, Texturing};
use crate::term::sanitize;

const SEPARATOR: &str = " │ ";

/// One part of the status line; lower `rank` survives longer when the line is short.
struct Segment {
    rank: u8,
    text: String,
}

/// Segments of this rank or better are truncated rather than dropped: the scene, and the message
/// that says what just happened or went wrong.
const KEPT_RANK: u8 = 1;

/// The help hint at the status line's end, from this width up.
const HELP_HINT: &str = "? help";
const HELP_HINT_FROM: usize = 40;

/// The status line, and how many of its first characters are an error to show as one.
#[derive(Clone, Debug, PartialEq)]
pub struct StatusLine {
    pub text: String,
    pub error_chars: usize,
}

/// The status line for `app`, at most `width` characters, ending in `? help` from 40 up.
pub fn status_line(app: &App, width: usize) -> StatusLine {
    let hint = width >= HELP_HINT_FROM;
    // Whether the picture is still coming stands at the right, beside the hint, at every width
    // that has one: over a slow link the settled picture can be seconds away.
    let progress = progress_text(&app.report).filter(|_| hint);
    let tail = match &progress {
        Some(progress) => format!("{SEPARATOR}{progress}{SEPARATOR}{HELP_HINT}"),
        None => format!("{SEPARATOR}{HELP_HINT}"),
    };
    let room = match hint {
        true => width - tail.chars().count(),
        false => width,
    };
    let mut segments = segments(app);
    let error = matches!(app.message(), Message::Error(_));
    let error_chars = segments
        .first()
        .filter(|_| error)
        .map_or(0, |s| s.text.chars().count());
    let mut text = loop {
        let line = join(&segments);
        let least = segments.iter().map(|s| s.rank).max().unwrap_or(0);
        if line.chars().count() <= room || least <= KEPT_RANK {
            break truncate(&line, room);
        }
        let position = segments.iter().rposition(|s| s.rank == least).unwrap_or(0);
        segments.remove(position);
    };
    let error_chars = error_chars.min(text.chars().count());
    if hint {
        let pad = room - text.chars().count();
        text = format!("{text}{}{tail}", " ".repeat(pad));
    }
    StatusLine { text, error_chars }
}

/// `refining` while more passes of the picture are coming, with the link's throughput where it
/// holds them back.
fn progress_text(report: &FrameReport) -> Option<String> {
    match (report.refining, report.link_throughput) {
        (false, _) => None,
        (true, None) => Some("refining".into()),
        (true, Some(rate)) => Some(format!("refining, link {} B/s", si(rate as usize))),
    }
}

/// The error view's figure: PSNR of the frame against the exact reference.
fn psnr_text(db: f64) -> String {
    if db.is_finite() {
        format!("PSNR {db:.1} dB vs reference")
    } else {
        "identical to reference".into()
    }
}

fn segments(app: &App) -> Vec<Segment> {
    let report = &app.report;
    let mut list = vec![
        segment(
            0,
            format!(
                "{}/{} {}",
                app.scene_index + 1,
                app.scenes.len(),
                sanitize(&app.scene().name)
            ),
        ),
        segment(2, app.view_mode.name().into()),
        segment(1, material_text(app)),
        segment(
            3,
            format!(
                "{} {} {}",
                app.quality.name(),
                picture_name(app.graphics, app.glyphs),
                colors_name(app.colors)
            ),
        ),
        segment(2, cost_text(app)),
        segment(
            4,
            format!(
                "{} tri {} frag",
                si(report.stats.triangles),
                si(report.stats.fragments)
            ),
        ),
    ];
    // The bytes of a frame are known once it is written: none yet on the first.
    if app.graphics.is_some() && report.picture_bytes > 0 {
        list.push(segment(
            3,
            format!("picture {} B", si(report.picture_bytes)),
        ));
    } else if report.bytes > 0 {
        let sent = si(report.bytes_sent.max(report.bytes as u64) as usize);
        list.push(segment(4, format!("{} B, {sent} B sent", si(report.bytes))));
    }

    if let Some(db) = report.psnr_db {
        list.insert(2, segment(1, psnr_text(db)));
    }
    if !app.clock.is_running() {
        list.push(segment(3, format!("paused t={:.2}s", app.clock.time())));
    }
    if let Some(percent) = app.export_job.as_ref().map(|job| job.percent_done()) {
        list.insert(2, segment(1, format!("exporting {percent}%")));
    }
    if report.stats.flattened > 0 {
        let flat = si(report.stats.flattened);
        list.insert(2, segment(2, format!("{flat} non-finite spots drawn flat")));
    }
    match app.message() {
        Message::None => {}
        // What a key just did is read before the rest: right after the scene.
        Message::Info(text) => list.insert(1, segment(1, first_line(text))),
        // An error matters more than anything else on a short line: it goes first.
        Message::Error(text) => list.insert(0, segment(0, error_text(text))),
    }
    list
}

/// The last frame's render time, and the samples per sub-pixel the picture holds so far.
fn cost_text(app: &App) -> String {
    let ms = app.report.render_time.as_secs_f64() * 1e3;
    let per_pass = super::quality::terminal_supersampling(&app.quality_in_use).pow(2) as u32;
    let samples = app.report.passes.max(1) * per_pass;
    format!("{ms:.1} ms {samples} spp")
}

/// The edited object's bump (pattern, strength, parameters with the selected one bracketed) and
/// texture.
fn material_text(app: &App) -> String {
    let Some(material) = app.material() else {
        return "no objects".into();
    };
    let rows = app.param_rows();
    let params = |slot| params_text(&rows, slot, app.param);
    let mut text = format!("{} {}", app.object_name(), bump_text(material));
    if app.is_displaced() {
        text += " displaced";
    }
    text += &params(ParamSlot::Bump);
    if let Some(texture) = &material.texture {
        let name = match texture {
            Texturing::Pattern(b) => &b.name,
            Texturing::Image(i) => &i.name,
        };
        text += &format!(" tex {}", sanitize(name));
        text += &params(ParamSlot::Texture);
    }
    text
}

/// The bump's source and strength.
fn bump_text(material: &Material) -> String {
    let Some(bump) = &material.bump else {
        return "no bump".into();
    };
    let sign = if bump.invert { "-" } else { "" };
    let name = match &bump.source {
        BumpSource::Image(image) => &image.name,
        BumpSource::NormalMap(map) => &map.name,
        BumpSource::Pattern(binding) => &binding.name,
    };
    format!("{} ×{sign}{:.2}", sanitize(name), bump.strength)
}

/// ` name=value` for each parameter of `slot`, the `selected` row's value bracketed.
fn params_text(rows: &[ParamRow], slot: ParamSlot, selected: usize) -> String {
    let mut text = String::new();
    for (i, row) in rows.iter().enumerate().filter(|(_, r)| r.slot == slot) {
        let (name, value) = (sanitize(&row.name), row.value);
        text += &match i == selected {
            true => format!(" {name}=[{value:.3}]"),
            false => format!(" {name}={value:.3}"),
        };
    }
    text
}

fn segment(rank: u8, text: String) -> Segment {
    Segment { rank, text }
}

fn join(segments: &[Segment]) -> String {
    let texts: Vec<&str> = segments.iter().map(|s| s.text.as_str()).collect();
    texts.join(SEPARATOR)
}

/// Diagnostics already say `error:` after their file:line:column; other errors get the word.
fn error_text(text: &str) -> String {
    let line = first_line(text);
    if line.contains("error:") {
        line
    } else {
        format!("error: {line}")
    }
}

/// Messages may carry a caret diagram below the line:column; the status line has room for one.
fn first_line(text: &str) -> String {
    sanitize(text.lines().next().unwrap_or("")).into_owned()
}

fn truncate(line: &str, width: usize) -> String {
    if line.chars().count() <= width {
        return line.to_string();
    }
    match width {
        0 => String::new(),
        _ => line.chars().take(width - 1).chain(['…']).collect(),
    }
}

/// 1234 → "1.2k", 1234567 → "1.2M".
fn si(n: usize) -> String {
    match n {
        0..1_000 => n.to_string(),
        1_000..1_000_000 => format!("{:.1}k", n as f64 / 1e3),
        _ => format!("{:.1}M", n as f64 / 1e6),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::term::ColorMode;

    #[test]
    fn truncates_with_an_ellipsis_and_never_exceeds_the_width() {
        assert_eq!(truncate("abcdef", 4), "abc…");
        assert_eq!(truncate("abc", 0), "");
        assert_eq!(truncate("abc", 1), "…");
        assert_eq!(si(22_876), "22.9k");
    }

    #[test]
    fn refining_and_a_slow_link_show_at_every_width_with_the_hint() {
        let options = crate::tui::WorkbenchOptions {
            scenes: vec!["sphere-on-plane-dimples".into()],
            ..Default::default()
        };
        let mut app = App::new(&options, ColorMode::TrueColor).unwrap();
        app.report.refining = true;
        app.report.link_throughput = Some(250_000.0);
        for width in [40, 80, 160] {
            let line = status_line(&app, width).text;
            assert!(
                line.ends_with("refining, link 250.0k B/s │ ? help"),
                "{width}: {line}"
            );
            assert_eq!(line.chars().count(), width);
        }
        app.report.refining = false;
        assert!(!status_line(&app, 160).text.contains("refining"));
        assert!(
            !status_line(&app, 160).text.contains("link"),
            "settled: nothing held back"
        );
    }
}
