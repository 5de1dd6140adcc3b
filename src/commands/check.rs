//! `bumpwork check FILE…`: validates pattern files, scene files and images exactly as the
//! renderer would load them, without rendering. One line per good file on stdout; each bad file's
//! message on stderr; exit status 1 if any file is bad.

use bumpwork::Error;
use bumpwork::diagnostic::sanitize;
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
pub struct CheckArgs {
    /// Pattern files (.pat), scene files (.toml) or images (.png, .jpg, .ppm, .pgm, .bmp, .tga).
    #[arg(required = true)]
    files: Vec<PathBuf>,
}

pub fn run(args: CheckArgs) -> Result<(), Error> {
    let mut bad = 0;
    for path in &args.files {
        match check(path) {
            Ok(summary) => say!("{}: ok: {summary}", sanitize(&path.display().to_string())),
            Err(message) => {
                let message = bumpwork::diagnostic::sanitize_lines(&message);
                eprintln!("bumpwork: error: {message}");
                bad += 1;
            }
        }
    }
    match bad {
        0 => Ok(()),
        _ if args.files.len() == 1 => Err(Error::Reported),
        n => Err(Error::InvalidArgument(format!(
            "{n} of {} files failed the check",
            args.files.len()
        ))),
    }
}

fn check(path: &Path) -> Result<String, String> {
    let extension = path
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase());
    match extension.as_deref() {
        Some("pat") => bumpwork::pattern::check_file(path)
            .map(|s| s.to_string())
            .map_err(|e| e.to_string()),
        Some("toml") => {
            let scene = bumpwork::scene::load_scene_file(path).map_err(|e| e.to_string())?;
            bumpwork::quality::Quality::default().with_settings(&scene.quality)?;
            let models = scene
                .objects
                .iter()
                .enumerate()
                .filter_map(|(i, o)| match &o.surface {
                    bumpwork::surface::Surface::Model(m) => Some(format!(
                        "; object {}: {}",
                        i + 1,
                        bumpwork::model::describe(&m.data)
                    )),
                    _ => None,
                });
            Ok(format!(
                "scene '{}', {} objects, {} lights{}",
                sanitize(&scene.name),
                scene.objects.len(),
                scene.lights.len(),
                models.collect::<String>()
            ))
        }
        Some("obj" | "gltf" | "glb") => {
            bumpwork::model::load_model(path, bumpwork::model::AS_IT_IS)
                .map(|data| bumpwork::model::describe(&data))
                .map_err(|e| e.to_string())
        }
        Some(ext) if bumpwork::texture::IMAGE_EXTENSIONS.contains(&ext) => {
            bumpwork::texture::check_image(path)
                .map(|info| info.to_string())
                .map_err(|e| e.to_string())
        }
        _ => Err(format!(
            "{}: not a pattern (.pat), scene (.toml), model (.obj, .gltf, .glb) or image ({}) file",
            sanitize(&path.display().to_string()),
            bumpwork::texture::IMAGE_EXTENSIONS.join(", ")
        )),
    }
}
