//! The scene as a POV-Ray 3.7 scene file, for what POV-Ray can express: the same tessellated
//! meshes (mesh2 with our normals and (u,v)), camera, point and parallel lights, Blinn-Phong-like
//! finishes, and each object's colour and bump baked over its (u,v) domain into image maps
//! (`image_map` and `bump_map` with `uv_mapping`). Slope-only bump patterns define no height,
//! so they cannot be baked: they are left out with a warning. POV-Ray tilts a bump map's normal
//! along the normal crossed with world y, not along the map's u and v, so bumps match ours where
//! u runs along x and v along −z (docs/baking.md). POV-Ray is left-handed: z is negated
//! throughout.

use super::output_file::OutputFile;
use super::png_file::PngStill;
use super::{HEIGHT_RANGE, MapPng};
use crate::Error;
use crate::scene::Camera;
use crate::scene::{Light, Object, Scene};
use crate::scene::{PreparedObject, PreparedScene};
use crate::still::RowSink;
use crate::surface::Surface;
use glam::{DVec3, Vec2, Vec3};
use std::io::Write;
use std::path::{Path, PathBuf};

/// Side of the baked colour and bump images.
pub const BAKE_SIDE: u32 = 1024;

/// Writes `path` (the .pov file) and its baked images beside it; returns warnings for what
/// POV-Ray cannot be given.
pub fn write_pov(
    prepared: &PreparedScene,
    camera: &Camera,
    size: (u32, u32),
    time: f64,
    path: &Path,
) -> Result<Vec<String>, Error> {
    let scene = &prepared.scene;
    let (file, handle) = OutputFile::create(path)?;
    let mut out = std::io::BufWriter::new(handle);
    let fail = |e: std::io::Error| Error::write(path, crate::bounded_read::io_words(&e));
    write_pov_header(&mut out, scene, camera, size).map_err(fail)?;
    let mut warnings = Vec::new();
    for (index, object) in prepared.objects.iter().enumerate() {
        let maps = bake_maps(&scene.objects[index], index, time, path, &mut warnings)?;
        write_object(&mut out, object, scene.ambient, &maps).map_err(fail)?;
    }
    out.flush().map_err(fail)?;
    drop(out);
    file.commit()?;
    Ok(warnings)
}

/// Text for a `//` comment: one line, whatever the scene's name holds.
fn comment_text(text: &str) -> String {
    text.chars()
        .map(|c| {
            if c.is_control() || matches!(c, '\u{2028}' | '\u{2029}') {
                ' '
            } else {
                c
            }
        })
        .collect()
}

/// A POV-Ray string literal: quotes and backslashes escaped, control characters dropped.
fn pov_string(text: &str) -> String {
    let mut literal = String::from("\"");
    for c in text.chars().filter(|c| !c.is_control()) {
        if matches!(c, '"' | '\\') {
            literal.push('\\');
        }
        literal.push(c);
    }
    literal.push('"');
    literal
}

/// A point or direction in POV-Ray's left-handed coordinates.
pub fn pov(v: DVec3) -> String {
    format!("<{}, {}, {}>", v.x, v.y, -v.z)
}

/// A linear colour in POV-Ray's words.
pub fn rgb(c: Vec3) -> String {
    format!("rgb <{}, {}, {}>", c.x, c.y, c.z)
}

/// The scene's settings, background, camera and lights in POV-Ray's words (its z axis mirrored:
/// POV-Ray is left-handed), for a `size` image; the objects follow.
pub fn write_pov_header(
    sdl: &mut impl Write,
    scene: &Scene,
    camera: &Camera,
    (width, height): (u32, u32),
) -> std::io::Result<()> {
    let aspect = width as f64 / height as f64;
    let half_v = (camera.vfov_degrees as f64).to_radians() / 2.0;
    let hfov = 2.0 * (half_v.tan() * aspect).atan();
    let name = comment_text(&scene.name);
    writeln!(sdl, "// {name} — written by {}", crate::PROGRAM)?;
    writeln!(
        sdl,
        "// povray +W{width} +H{height} (+A0.3 for antialiasing)"
    )?;
    writeln!(
        sdl,
        "#version 3.7;\nglobal_settings {{ assumed_gamma 1.0 ambient_light rgb 1 }}"
    )?;
    writeln!(sdl, "background {{ {} }}", rgb(scene.background))?;
    writeln!(
        sdl,
        "camera {{ perspective location {} look_at {} sky {} right x*{aspect} up y angle {} }}",
        pov(camera.eye),
        pov(camera.target),
        pov(camera.up.as_dvec3()),
        hfov.to_degrees()
    )?;
    // POV-Ray's lights cast shadows unless told not to, as ours do unless the scene says not.
    let shadowless = if scene.shadows { "" } else { " shadowless" };
    for light in &scene.lights {
        match *light {
            Light::Point { position, color } => {
                writeln!(
                    sdl,
                    "light_source {{ {} {}{shadowless} }}",
                    pov(position),
                    rgb(color)
                )
            }
            Light::Directional { towards, color } => writeln!(
                sdl,
                "light_source {{ {} {} parallel point_at <0, 0, 0>{shadowless} }}",
                pov(towards.as_dvec3() * 1e6),
                rgb(color)
            ),
        }?;
    }
    Ok(())
}

/// File names (relative to the .pov file) of an object's baked maps, and the bump map's depth.
#[derive(Default)]
struct BakedMaps {
    color: Option<String>,
    bump: Option<(String, f32)>,
}

fn bake_maps(
    object: &Object,
    index: usize,
    time: f64,
    path: &Path,
    warnings: &mut Vec<String>,
) -> Result<BakedMaps, Error> {
    let mut maps = BakedMaps::default();
    let material = &object.material;
    if let crate::surface::Surface::Model(_) = object.surface
        && (material.texture.is_some() || material.bump.is_some())
    {
        warnings.push(format!(
            "object {}: a model's colour and bump are not baked for POV-Ray (a model has no \
             point for each (u,v) of a map); bake its pattern with `bumpwork bake` instead",
            index + 1
        ));
        return Ok(maps);
    }
    if material.texture.is_some() {
        let colors = crate::shade::bake_color(&object.surface, material, time, BAKE_SIDE);
        let file = asset_path(path, index, "color");
        let rgb: Vec<u8> = colors
            .iter()
            .flat_map(|c| c.to_array().map(crate::raster::linear_to_srgb8))
            .collect();
        let mut png = PngStill::create(&file, (BAKE_SIDE, BAKE_SIDE), &[])?;
        png.write_rows(&rgb).map_err(|e| Error::write(&file, e))?;
        png.finish()?;
        maps.color = Some(file_name(&file));
    }
    if let Some(bump) = &material.bump {
        match crate::shade::bake_height(&object.surface, bump, time, BAKE_SIDE) {
            Some(heights) => {
                let file = asset_path(path, index, "bump");
                let depth = write_height_png(&file, &heights)?;
                // POV-Ray tilts the normal by bump_size times the map's step to the next texel
                // (0..1 over the range), so range × texels / size makes the tilt the slope.
                let bump_size = depth / world_extent(object) * BAKE_SIDE as f32;
                maps.bump = Some((file_name(&file), bump_size));
            }
            None => warnings.push(format!(
                "object {}: its bump is a slope pattern, which has no height to bake; left out",
                index + 1
            )),
        }
    }
    Ok(maps)
}

fn asset_path(path: &Path, index: usize, kind: &str) -> PathBuf {
    let stem = path
        .file_stem()
        .map_or("scene".into(), |s| s.to_string_lossy().into_owned());
    path.with_file_name(format!("{stem}-{}-{kind}.png", index + 1))
}

fn file_name(path: &Path) -> String {
    path.file_name()
        .map_or_else(String::new, |n| n.to_string_lossy().into_owned())
}

/// The object's size across its (u,v) domain: relates a baked height range to POV's bump depth.
fn world_extent(object: &Object) -> f32 {
    let domain = object.surface.domain();
    let middle = (domain.min + domain.max) / 2.0;
    let frame = object.surface.frame(middle.x, middle.y);
    let extent = domain.max - domain.min;
    ((frame.pu * extent.x).length() + (frame.pv * extent.y).length()).max(1e-6) / 2.0
}

/// Heights as a 16-bit grey PNG scaled to their range; returns the range.
fn write_height_png(path: &Path, heights: &[f32]) -> Result<f32, Error> {
    let (levels, (lo, hi)) = super::height_levels(heights);
    let range = (HEIGHT_RANGE, format!("{lo}..{hi}"));
    let size = (BAKE_SIDE, BAKE_SIDE);
    super::write_map_png(path, size, MapPng::Grey16(&levels), &[range])?;
    Ok(hi - lo)
}

/// One object as a mesh2; without normal and uv indices POV-Ray uses the face indices for both.
/// Streamed list by list: a finely tessellated object's text is never held whole.
fn write_object(
    sdl: &mut impl Write,
    object: &PreparedObject,
    ambient: Vec3,
    maps: &BakedMaps,
) -> std::io::Result<()> {
    let surface = &object.surface;
    let mesh = &object.mesh;
    let origin = surface.origin();
    let domain = surface.domain();
    let extent = domain.max - domain.min;
    write!(sdl, "mesh2 {{\n  vertex_vectors {{ ")?;
    write_list(
        sdl,
        mesh.positions.iter().map(|&p| pov(origin + p.as_dvec3())),
    )?;
    write!(sdl, " }}\n  normal_vectors {{ ")?;
    let normal_at = |uv: &Vec2| pov(surface.frame(uv.x, uv.y).n.as_dvec3());
    write_list(sdl, mesh.uvs.iter().map(normal_at))?;
    write!(sdl, " }}\n  uv_vectors {{ ")?;
    let uv_of = |uv: Vec2| {
        let t = (uv - domain.min) / extent.max(Vec2::splat(1e-30));
        format!("<{}, {}>", t.x, t.y)
    };
    match surface {
        // A model's mesh carries its chart; POV-Ray is given the texture's (u,v).
        Surface::Model(model) => write_list(sdl, model.data.corners.iter().map(|c| uv_of(c.uv)))?,
        _ => write_list(sdl, mesh.uvs.iter().map(|&uv| uv_of(uv)))?,
    }
    write!(sdl, " }}\n  face_indices {{ ")?;
    let face = |[a, b, c]: &[u32; 3]| format!("<{a}, {b}, {c}>");
    write_list(sdl, mesh.indices.iter().map(face))?;
    let material = &object.material;
    let pigment = match &maps.color {
        Some(file) => format!(
            "uv_mapping image_map {{ png {} interpolate 2 }}",
            pov_string(file)
        ),
        None => rgb(material.color),
    };
    let normal = match &maps.bump {
        Some((file, depth)) => format!(
            "normal {{ uv_mapping bump_map {{ png {} interpolate 2 bump_size {depth} }} }}",
            pov_string(file)
        ),
        None => String::new(),
    };
    writeln!(
        sdl,
        " }}\n  texture {{ pigment {{ {pigment} }} {normal}\n    finish {{ ambient {} diffuse 1 specular {} roughness {} }} }}\n}}",
        rgb(ambient),
        material.specular,
        1.0 / material.shininess.max(1e-3),
    )
}

/// `N,` then the items, one a line.
fn write_list(
    sdl: &mut impl Write,
    items: impl ExactSizeIterator<Item = String>,
) -> std::io::Result<()> {
    write!(sdl, "{},", items.len())?;
    let mut first = true;
    for item in items {
        let separator = if first { "" } else { "," };
        write!(sdl, "{separator}\n    {item}")?;
        first = false;
    }
    Ok(())
}
