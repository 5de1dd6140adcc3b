//! A user's model shown as it is given on the command line (`bumpwork view model.obj`, or
//! `model.obj+my.pat` for a pattern of one's own on it): on the rounded cube's stage, scaled so
//! its largest side is the cube's and resting on the floor, with the default dimples or the
//! pattern file as its bump (a colour pattern as its texture).

use super::binding_file::BindingFile;
use super::file::{Point, Positive, SceneFile, SurfaceFile};
use crate::Error;
use crate::pattern::OutputKind;
use glam::{DVec3, Vec3};
use std::path::Path;

/// The stage a model is shown on.
const MODEL_STAGE: &str = "rounded-cube-dimples";
/// The size a model is scaled to: its largest side.
const SHOWN_SIZE: f32 = 160.0;

/// A model source: `MODEL.obj`, or `MODEL.obj+PATTERN.pat`.
pub struct ModelSource<'a> {
    pub model: &'a str,
    pub pattern: Option<&'a str>,
}

impl ModelSource<'_> {
    /// `name` as a model source, if it is one: a name ending in `.obj`, `.gltf` or `.glb` (any
    /// case), or one joined by `+` to a name ending in `.pat`, and not an existing file of
    /// another kind.
    pub fn parse(name: &str) -> Option<ModelSource<'_>> {
        let is_model = crate::model::is_model_file;
        if is_model(name) {
            return Some(ModelSource {
                model: name,
                pattern: None,
            });
        }
        let (model, pattern) = name.rsplit_once('+')?;
        (is_model(model) && pattern.ends_with(".pat") && !Path::new(name).exists()).then_some(
            ModelSource {
                model,
                pattern: Some(pattern),
            },
        )
    }

    /// The files the scene reads, to watch.
    pub fn files(&self) -> Vec<std::path::PathBuf> {
        [Some(self.model), self.pattern]
            .into_iter()
            .flatten()
            .map(Into::into)
            .collect()
    }

    /// The stage with the model on it, as a scene file.
    pub fn scene_file(&self) -> Result<SceneFile, Error> {
        // Only where the model lies is needed here: its triangles are made when the scene is.
        let raw = crate::model::read_triangles(Path::new(self.model))?;
        let (min, max) = bounds(&raw);
        let size = (max - min).max_element();
        if !(size > 0.0 && size.is_finite()) {
            return Err(Error::read(
                Path::new(self.model),
                "its triangles have no extent",
            ));
        }
        let scale = SHOWN_SIZE / size;
        let centre = (min + max) / 2.0;
        let position = DVec3::new(
            f64::from(-centre.x * scale),
            f64::from(-min.y * scale),
            f64::from(-centre.z * scale),
        );
        let mut file = super::preset_file(MODEL_STAGE).expect("the stage is a built-in scene");
        file.name = Some(self.shown_name());
        file.objects[0].bump = None;
        let shown = &mut file.objects[1];
        shown.surface = SurfaceFile::Mesh {
            file: self.model.to_string(),
            position: Point(position),
            scale: Positive(scale),
            uv_scale: Positive(crate::model::AS_IT_IS.uv_scale),
        };
        shown.bump = Some(pattern_binding("dimples"));
        if let Some(pattern) = self.pattern {
            let compiled = crate::pattern::Pattern::load(Path::new(pattern))
                .map_err(|e| Error::Diagnostic(e.to_string()))?;
            match compiled.output() {
                OutputKind::Color => shown.texture = Some(pattern_binding(pattern)),
                _ => shown.bump = Some(pattern_binding(pattern)),
            }
        }
        Ok(file)
    }

    fn shown_name(&self) -> String {
        let stem = |n: &str| {
            Path::new(n)
                .file_name()
                .map_or_else(|| n.to_string(), |f| f.to_string_lossy().into_owned())
        };
        match self.pattern {
            Some(pattern) => format!("{} with {}", stem(self.model), stem(pattern)),
            None => stem(self.model),
        }
    }
}

fn pattern_binding(pattern: &str) -> BindingFile {
    BindingFile {
        pattern: Some(pattern.to_string()),
        ..BindingFile::default()
    }
}

/// The box of the model's finite corners, in its own units.
fn bounds(raw: &crate::model::RawTriangles) -> (Vec3, Vec3) {
    raw.positions
        .iter()
        .flatten()
        .filter(|p| p.is_finite())
        .fold(
            (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY)),
            |(min, max), &p| (min.min(p), max.max(p)),
        )
}
