//! The command line: parses arguments and calls the library. Exit status 0 on success, 1 on any
//! user error with one message on stderr.

use bumpwork::Error;
use bumpwork::raster::{PreparedScene, RenderTarget, Viewport, render};
use bumpwork::surface::Tessellation;
use clap::{Parser, Subcommand};
use std::path::PathBuf;
use std::process::ExitCode;

/// Largest output side accepted; 16384² linear-light RGB is 3 GiB, the most an export should take.
const MAX_SIDE: u32 = 16384;

#[derive(Parser)]
#[command(
    name = "bumpwork",
    version,
    about = "Bump maps and texture maps, rasterized on the CPU"
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand)]
enum Command {
    /// Render a built-in scene or a scene file to a PNG still.
    Render(RenderArgs),
}

#[derive(clap::Args)]
struct RenderArgs {
    /// A built-in scene name (see --list) or a path to a scene file (.toml).
    #[arg(required_unless_present = "list")]
    scene: Option<String>,
    /// The PNG to write.
    #[arg(short, long, required_unless_present = "list")]
    output: Option<PathBuf>,
    /// Output size in pixels, WIDTHxHEIGHT.
    #[arg(long, default_value = "800x600", value_parser = parse_size)]
    size: (u32, u32),
    /// Tessellation density: cells per half turn of a curved surface.
    #[arg(long, default_value_t = Tessellation::default().density,
          value_parser = clap::value_parser!(u32).range(1..=4096))]
    tessellation: u32,
    /// Print the built-in scene names and exit.
    #[arg(long)]
    list: bool,
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) if !e.use_stderr() => {
            let _ = e.print();
            return ExitCode::SUCCESS;
        }
        Err(e) => {
            let _ = e.print();
            return ExitCode::FAILURE;
        }
    };
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("bumpwork: error: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run(cli: Cli) -> Result<(), Error> {
    match cli.command {
        Some(Command::Render(args)) => render_command(args),
        None => {
            use clap::CommandFactory;
            let _ = Cli::command().print_help();
            Ok(())
        }
    }
}

fn render_command(args: RenderArgs) -> Result<(), Error> {
    if args.list {
        for name in bumpwork::scene::PRESET_NAMES {
            println!("{name}");
        }
        return Ok(());
    }
    let (Some(scene_name), Some(output)) = (args.scene, args.output) else {
        unreachable!("clap requires both unless --list");
    };
    let scene = bumpwork::scene::resolve(&scene_name)?;
    let camera = scene.camera.clone();
    let prepared = PreparedScene::new(
        scene,
        Tessellation {
            density: args.tessellation,
        },
    );
    let viewport = Viewport {
        width: args.size.0,
        height: args.size.1,
    };
    let (framebuffer, _) = render(
        &prepared,
        &RenderTarget {
            camera: &camera,
            viewport,
            interpolation: Default::default(),
        },
    );
    bumpwork::export::write_png(&framebuffer, &output)
}

fn parse_size(text: &str) -> Result<(u32, u32), String> {
    let expected = || {
        format!("expected WIDTHxHEIGHT with each side 1..={MAX_SIDE}, like 1920x1080; got '{text}'")
    };
    let (w, h) = text.split_once(['x', 'X']).ok_or_else(expected)?;
    let side = |s: &str| {
        s.trim()
            .parse::<u32>()
            .ok()
            .filter(|n| (1..=MAX_SIDE).contains(n))
    };
    match (side(w), side(h)) {
        (Some(w), Some(h)) => Ok((w, h)),
        _ => Err(expected()),
    }
}
