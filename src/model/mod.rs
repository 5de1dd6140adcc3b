//! A user's model read from a file (Wavefront OBJ with the `tobj` crate, glTF 2.0 with the
//! `gltf` crate) into a surface: its triangles with normals, texture (u,v) and MikkTSpace
//! tangents, checked against the memory budget before they are made. Degenerate triangles are
//! left out and counted; an OBJ's non-finite numbers are refused at their line.

mod gltf_file;
mod obj;
mod shipped;
mod tangents;

pub use gltf_file::parse_gltf;
pub use obj::{MAX_OBJ_EXPANSION, parse_obj};
pub use shipped::{BUILTIN_MODELS, builtin_model};

use crate::Error;
use crate::surface::{Corner, Domain, ModelData};
use glam::{Vec2, Vec3};
use std::path::Path;

/// How a model is placed and mapped: scaled about its own origin, then moved; its texture
/// (u,v) run 0..1, scaled to `uv_scale` pattern units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placement {
    pub scale: f32,
    pub uv_scale: f32,
}

/// Memory a triangle takes once loaded: three corners and its share of the hierarchy and the
/// rasterizer's mesh.
pub const BYTES_PER_TRIANGLE: u64 = 3 * std::mem::size_of::<Corner>() as u64 + 160;

/// Triangles as their corners' positions, normals (zero where the file has none) and (u,v),
/// before any is checked.
pub struct RawTriangles {
    pub positions: Vec<[Vec3; 3]>,
    pub normals: Vec<[Vec3; 3]>,
    pub uvs: Vec<[Vec2; 3]>,
}

/// The model a scene names: a shipped one by its name, else the file `name` relative to `base`.
pub fn load_named_model(name: &str, base: &Path, placement: Placement) -> Result<ModelData, Error> {
    match builtin_model(name) {
        Some(bytes) => Ok(model_data(parse_obj(bytes, name)?, placement)),
        None => load_model(&base.join(name), placement),
    }
}

/// Whether a model file is glTF (`.gltf` or `.glb`) rather than OBJ, by its name.
pub fn is_gltf(path: &Path) -> bool {
    let extension = path
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase());
    matches!(extension.as_deref(), Some("gltf" | "glb"))
}

/// Whether a name is a model file's: `.obj`, `.gltf` or `.glb`, any case.
pub fn is_model_file(name: &str) -> bool {
    let lower = name.to_ascii_lowercase();
    [".obj", ".gltf", ".glb"].iter().any(|e| lower.ends_with(e))
}

/// What a loaded model is, for `check`: its triangles, and those left out.
pub fn describe(data: &ModelData) -> String {
    let triangles = data.corners.len() / 3;
    match data.degenerate {
        0 => format!("a model of {triangles} triangles"),
        1 => format!("a model of {triangles} triangles (1 degenerate triangle left out)"),
        n => format!("a model of {triangles} triangles ({n} degenerate triangles left out)"),
    }
}

/// The placement a model file has alone (`check`, `view model.obj`): as it is, one texture unit
/// the lecture's plane.
pub const AS_IT_IS: Placement = Placement {
    scale: 1.0,
    uv_scale: 400.0,
};

/// Reads the model at `path` into a surface's data.
pub fn load_model(path: &Path, placement: Placement) -> Result<ModelData, Error> {
    Ok(model_data(read_triangles(path)?, placement))
}

/// The model file at `path` as its raw triangles, before anything is made of them (enough to
/// know where a model lies).
pub fn read_triangles(path: &Path) -> Result<RawTriangles, Error> {
    let budget = crate::memory_budget::budget_bytes();
    let size = std::fs::metadata(path)
        .map_err(|e| Error::read(path, crate::bounded_read::io_words(&e)))?
        .len();
    // A byte of OBJ text makes at most MAX_OBJ_EXPANSION bytes of model (a face line of
    // 8 bytes, one triangle): refused before it is read where that could pass the budget. (A
    // glTF model's triangles are counted from its accessors before its buffers are read.)
    let worst = size.saturating_mul(MAX_OBJ_EXPANSION);
    if worst > budget {
        return Err(Error::read(
            path,
            format!(
                "a model of {} may take up to {} once read, over the {} memory budget; raise {} \
                 or use a smaller model",
                crate::memory_budget::size_words(size),
                crate::memory_budget::size_words(worst),
                crate::memory_budget::size_words(budget),
                crate::memory_budget::MEMORY_BUDGET_VAR
            ),
        ));
    }
    let bytes =
        crate::bounded_read::read_bounded(path, size.max(1)).map_err(|e| Error::read(path, e))?;
    if is_gltf(path) {
        parse_gltf(&bytes, path, Some(path.parent().unwrap_or(Path::new("."))))
    } else {
        parse_obj(&bytes, &path.display().to_string())
    }
}

/// The model from its raw triangles: degenerate ones (no area in space or in (u,v), or not
/// finite once scaled) left out, normals made where missing, tangents generated, positions and
/// (u,v) scaled.
pub fn model_data(raw: RawTriangles, placement: Placement) -> ModelData {
    let mut corners = Vec::with_capacity(raw.positions.len() * 3);
    let mut degenerate = 0;
    for ((positions, normals), uvs) in raw.positions.iter().zip(&raw.normals).zip(&raw.uvs) {
        let positions = positions.map(|p| p * placement.scale);
        let uvs = uvs.map(|uv| uv * placement.uv_scale);
        let face = (positions[1] - positions[0]).cross(positions[2] - positions[0]);
        let uv_area = (uvs[1] - uvs[0]).perp_dot(uvs[2] - uvs[0]);
        let scale = (positions[1] - positions[0])
            .length_squared()
            .max((positions[2] - positions[0]).length_squared());
        let has_area = face.length_squared() > 1e-12 * scale * scale;
        // Scaling can overflow what a file gave finite.
        let finite = positions.iter().all(|p| p.is_finite()) && uvs.iter().all(|t| t.is_finite());
        if !finite || !has_area || !uv_area.is_finite() || uv_area.abs() <= 1e-12 {
            degenerate += 1;
            continue;
        }
        let flat = face.normalize();
        for k in 0..3 {
            let n = normals[k];
            corners.push(Corner {
                p: positions[k],
                n: if n.length_squared() > 0.0 {
                    n.normalize()
                } else {
                    flat
                },
                tangent: Default::default(),
                uv: uvs[k],
            });
        }
    }
    tangents::generate(&mut corners);
    let side = placement.uv_scale;
    let domain = Domain {
        min: Vec2::ZERO,
        max: Vec2::splat(side),
    };
    ModelData::new(corners, domain, degenerate)
}
