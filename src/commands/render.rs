//! `bumpwork render`: a scene to a PNG still.

use bumpwork::Error;
use bumpwork::raster::{PreparedScene, RenderTarget, Viewport, render};
use bumpwork::surface::Tessellation;
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct RenderArgs {
    /// A built-in scene name (see --list) or a path to a scene file (.toml).
    #[arg(required_unless_present = "list")]
    scene: Option<String>,
    /// The PNG to write.
    #[arg(short, long, required_unless_present = "list")]
    output: Option<PathBuf>,
    /// Output size in pixels, WIDTHxHEIGHT.
    #[arg(long, default_value = "800x600", value_parser = super::parse_size)]
    size: (u32, u32),
    /// Tessellation density: cells per half turn of a curved surface.
    #[arg(long, default_value_t = Tessellation::default().density,
          value_parser = clap::value_parser!(u32).range(1..=4096))]
    tessellation: u32,
    /// Print the built-in scene names and exit.
    #[arg(long)]
    list: bool,
}

pub fn run(args: RenderArgs) -> Result<(), Error> {
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
