//! `bumpwork view` (and `bumpwork` alone): the terminal workbench.

use bumpwork::Error;
use bumpwork::quality::Preset;
use bumpwork::term::graphics::GraphicsChoice;
use bumpwork::term::{ColorChoice, GlyphSet};
use bumpwork::tui::WorkbenchOptions;

#[derive(clap::Args, Default)]
pub struct ViewArgs {
    /// Built-in scene names, scene files, pattern files or model files (`model.obj my.pat` shows
    /// the pattern on the model); none opens the gallery of every built-in scene.
    scenes: Vec<String>,
    /// Colours: truecolor, 256, 16, none or auto (from COLORTERM, TERM and NO_COLOR).
    #[arg(long, default_value = "auto", value_parser = parse_colors)]
    colors: Option<ColorChoice>,
    /// Cell glyphs: half (works everywhere), quadrant or sextant (needs a font with them).
    #[arg(long, default_value = "half", value_parser = parse_glyphs)]
    glyphs: Option<GlyphSet>,
    /// Animation frame rate cap.
    #[arg(long, default_value_t = 30, value_parser = clap::value_parser!(u32).range(1..=240))]
    fps: u32,
    /// Leave the mouse to the terminal (text selection) instead of orbiting with it.
    #[arg(long)]
    no_mouse: bool,
    /// Do not reload scene, pattern and image files when they change on disk.
    #[arg(long)]
    no_watch: bool,
    /// Quality preset to start with: draft, interactive, high or exact (`Q` cycles them).
    #[arg(long, default_value = "interactive", value_parser = Preset::named)]
    quality: Option<Preset>,
    /// Size of PNGs the export key writes, WIDTHxHEIGHT.
    #[arg(long, default_value = "1920x1080", value_parser = super::parse_size)]
    export_size: Option<(u32, u32)>,
    /// A character cell's size in pixels, WIDTHxHEIGHT, for terminals that do not report it
    /// (circles come out round) [default: as the terminal reports, else 1x2].
    #[arg(long, value_parser = super::parse_size)]
    cell_size: Option<(u32, u32)>,
    /// The picture: real pixels where the terminal shows them (kitty graphics, sixel, iTerm2
    /// images; auto asks the terminal), or blocks of the --glyphs set; `g` cycles through what
    /// the terminal speaks.
    #[arg(long, default_value = "auto", value_parser = GraphicsChoice::parse)]
    graphics: Option<GraphicsChoice>,
    /// A setting, KEY=VALUE (repeatable), as for `render --set`: quality.KNOB (over every
    /// preset `Q` picks), [OBJECT.]bump.PARAM, [OBJECT.]texture.PARAM, [OBJECT.]bump.strength,
    /// [OBJECT.]bump.params.PARAM; kept over reloads.
    #[arg(long = "set", value_name = "KEY=VALUE", value_parser = bumpwork::overrides::Override::parse)]
    set: Vec<bumpwork::overrides::Override>,
    /// The bump on every object: a shipped pattern or image by name, a pattern file (.pat) or an
    /// image file (grey, lighter is higher).
    #[arg(long, value_name = "NAME|FILE")]
    bump: Option<String>,
    /// The texture on every object: a shipped colour pattern or image by name, a colour pattern
    /// file or an image file.
    #[arg(long, value_name = "NAME|FILE")]
    texture: Option<String>,
    /// Directory the export key writes PNGs to and the save key scenes to.
    #[arg(long, value_name = "DIR", default_value = ".")]
    export_dir: std::path::PathBuf,
    /// Samples per pixel of PNGs the export key writes.
    #[arg(long, default_value_t = 4,
          value_parser = clap::value_parser!(u32).range(1..=bumpwork::still::MAX_SAMPLES as i64))]
    export_samples: u32,
}

pub fn run(args: ViewArgs) -> Result<(), Error> {
    let defaults = WorkbenchOptions::default();
    let options = WorkbenchOptions {
        scenes: if args.scenes.is_empty() {
            defaults.scenes
        } else {
            patterns_on_models(args.scenes)
        },
        colors: args.colors.unwrap_or_default(),
        glyphs: args.glyphs.unwrap_or_default(),
        fps: if args.fps == 0 {
            defaults.fps
        } else {
            args.fps
        },
        mouse: !args.no_mouse,
        export_size: args.export_size.unwrap_or(defaults.export_size),
        export_samples: if args.export_samples == 0 {
            defaults.export_samples
        } else {
            args.export_samples
        },
        export_dir: existing_directory(args.export_dir)?,
        watch: !args.no_watch,
        quality: args.quality.unwrap_or_default(),
        cell_size: args.cell_size,
        graphics: args.graphics.unwrap_or_default(),
        settings: args.set,
        choice: bumpwork::scene::MaterialChoice {
            bump: args.bump,
            texture: args.texture,
        },
    };
    bumpwork::tui::run(&options)
}

/// `model.obj my.pat` as one source, `model.obj+my.pat`: the pattern shown on the model.
/// `--export-dir`, checked before the workbench starts rather than at the first export.
fn existing_directory(dir: std::path::PathBuf) -> Result<std::path::PathBuf, Error> {
    if dir.is_dir() {
        Ok(dir)
    } else {
        Err(Error::write(&dir, "--export-dir: not a directory"))
    }
}

fn patterns_on_models(names: Vec<String>) -> Vec<String> {
    let mut joined: Vec<String> = Vec::with_capacity(names.len());
    for name in names {
        let on_a_model = joined.last().is_some_and(|last| {
            bumpwork::scene::ModelSource::parse(last).is_some_and(|m| m.pattern.is_none())
        });
        match joined.last_mut() {
            Some(last) if on_a_model && name.ends_with(".pat") => {
                last.push('+');
                last.push_str(&name);
            }
            _ => joined.push(name),
        }
    }
    joined
}

fn parse_colors(text: &str) -> Result<ColorChoice, String> {
    text.parse()
        .map_err(|e: bumpwork::term::UnknownColorMode| e.to_string())
}

fn parse_glyphs(text: &str) -> Result<GlyphSet, String> {
    match text {
        "half" => Ok(GlyphSet::HalfBlock),
        "quadrant" => Ok(GlyphSet::Quadrant),
        "sextant" => Ok(GlyphSet::Sextant),
        _ => Err(format!(
            "expected half, quadrant or sextant; got '{}'",
            bumpwork::diagnostic::shown_input(text)
        )),
    }
}
