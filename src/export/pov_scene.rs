//! The scene as a POV-Ray 3.7 scene file, for what POV-Ray can express: the same tessellated
//! meshes (mesh2 with our normals and (u,v)), camera, point and parallel lights, Blinn-Phong-like
//! finishes, and each object's colour and bump baked over its (u,v) domain into image maps
//! (`image_map` and `bump_map` with `uv_mapping`). Slope-only bump patterns define no height,
//! so they cannot be baked: they are left out with a warning. POV-Ray scales bump maps its own
//! way, so the bumps look alike, not equal. POV-Ray is left-handed: z is negated throughout.

use super::output_file::OutputFile;
use super::png_file::PngStill;
use crate::Error;
use crate::raster::{Camera, PreparedObject, PreparedScene};
use crate::scene::{Light, Object, Scene};
use crate::still::RowSink;
use glam::{DVec3, Vec2, Vec3};
use std::fmt::Write as _;
use std::io::Write as _;
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
    let mut sdl = header(scene, camera, size);
    let mut warnings = Vec::new();
    for (index, object) in prepared.objects.iter().enumerate() {
        let maps = bake_maps(&scene.objects[index], index, time, path, &mut warnings)?;
        write_object(&mut sdl, object, scene.ambient, &maps);
    }
    let (file, mut handle) = OutputFile::create(path)?;
    handle
        .write_all(sdl.as_bytes())
        .map_err(|e| Error::write(path, e))?;
    drop(handle);
    file.commit()?;
    Ok(warnings)
}

fn pov(v: DVec3) -> String {
    format!("<{}, {}, {}>", v.x, v.y, -v.z)
}

fn rgb(c: Vec3) -> String {
    format!("rgb <{}, {}, {}>", c.x, c.y, c.z)
}

fn header(scene: &Scene, camera: &Camera, (width, height): (u32, u32)) -> String {
    let aspect = width as f64 / height as f64;
    let half_v = (camera.vfov_degrees as f64).to_radians() / 2.0;
    let hfov = 2.0 * (half_v.tan() * aspect).atan();
    let mut sdl = String::new();
    let _ = writeln!(sdl, "// {} — written by {}", scene.name, crate::PROGRAM);
    let _ = writeln!(
        sdl,
        "// povray +W{width} +H{height} (+A0.3 for antialiasing)"
    );
    let _ = writeln!(
        sdl,
        "#version 3.7;\nglobal_settings {{ assumed_gamma 1.0 ambient_light rgb 1 }}"
    );
    let _ = writeln!(sdl, "background {{ {} }}", rgb(scene.background));
    let _ = writeln!(
        sdl,
        "camera {{ perspective location {} look_at {} sky {} right x*{aspect} up y angle {} }}",
        pov(camera.eye),
        pov(camera.target),
        pov(camera.up.as_dvec3()),
        hfov.to_degrees()
    );
    for light in &scene.lights {
        let _ = match *light {
            Light::Point { position, color } => {
                writeln!(
                    sdl,
                    "light_source {{ {} {} shadowless }}",
                    pov(position),
                    rgb(color)
                )
            }
            Light::Directional { towards, color } => writeln!(
                sdl,
                "light_source {{ {} {} parallel point_at <0, 0, 0> shadowless }}",
                pov(towards.as_dvec3() * 1e6),
                rgb(color)
            ),
        };
    }
    sdl
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
                // A height range over the object's size, in steps of the baked image: POV-Ray's
                // bump_size scales the map's per-texel slope (found by eye, not derived).
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
    let (lo, hi) = heights
        .iter()
        .filter(|h| h.is_finite())
        .fold((f32::MAX, f32::MIN), |(a, b), &h| (a.min(h), b.max(h)));
    let range = if hi > lo { hi - lo } else { 1.0 };
    let bytes: Vec<u8> = heights
        .iter()
        .flat_map(|&h| {
            let level = if h.is_finite() { (h - lo) / range } else { 0.0 };
            ((level.clamp(0.0, 1.0) * 65535.0).round() as u16).to_be_bytes()
        })
        .collect();
    let (file, handle) = OutputFile::create(path)?;
    let fail = |e: png::EncodingError| Error::write(path, e);
    let mut encoder = png::Encoder::new(handle, BAKE_SIDE, BAKE_SIDE);
    encoder.set_color(png::ColorType::Grayscale);
    encoder.set_depth(png::BitDepth::Sixteen);
    let mut writer = encoder.write_header().map_err(fail)?;
    writer.write_image_data(&bytes).map_err(fail)?;
    writer.finish().map_err(fail)?;
    file.commit()?;
    Ok(if hi > lo { range } else { 0.0 })
}

/// One object as a mesh2; without normal and uv indices POV-Ray uses the face indices for both.
fn write_object(sdl: &mut String, object: &PreparedObject, ambient: Vec3, maps: &BakedMaps) {
    let surface = &object.surface;
    let mesh = &object.mesh;
    let origin = surface.origin();
    let domain = surface.domain();
    let extent = domain.max - domain.min;
    let list = |items: Vec<String>| format!("{},\n    {}", items.len(), items.join(",\n    "));
    let vertices = mesh
        .positions
        .iter()
        .map(|&p| pov(origin + p.as_dvec3()))
        .collect();
    let normals = mesh
        .uvs
        .iter()
        .map(|uv| pov(surface.frame(uv.x, uv.y).n.as_dvec3()))
        .collect();
    let uvs = mesh
        .uvs
        .iter()
        .map(|&uv| {
            let t = (uv - domain.min) / extent.max(Vec2::splat(1e-30));
            format!("<{}, {}>", t.x, t.y)
        })
        .collect();
    let faces = mesh
        .indices
        .iter()
        .map(|[a, b, c]| format!("<{a}, {b}, {c}>"))
        .collect();
    let material = &object.material;
    let pigment = match &maps.color {
        Some(file) => format!("uv_mapping image_map {{ png \"{file}\" interpolate 2 }}"),
        None => rgb(material.color),
    };
    let normal = match &maps.bump {
        Some((file, depth)) => format!(
            "normal {{ uv_mapping bump_map {{ png \"{file}\" interpolate 2 bump_size {depth} }} }}"
        ),
        None => String::new(),
    };
    let _ = writeln!(
        sdl,
        "mesh2 {{\n  vertex_vectors {{ {} }}\n  normal_vectors {{ {} }}\n  uv_vectors {{ {} }}\n  \
         face_indices {{ {} }}\n  \
         texture {{ pigment {{ {pigment} }} {normal}\n    finish {{ ambient {} diffuse 1 specular {} roughness {} }} }}\n}}",
        list(vertices),
        list(normals),
        list(uvs),
        list(faces),
        rgb(ambient),
        material.specular,
        1.0 / material.shininess.max(1e-3),
    );
}
