//! glTF 2.0 models (`.gltf` with its buffers, or one `.glb`) to triangles, with the `gltf`
//! crate's parser and accessor readers. Buffers are read here, not by the crate, so each is
//! bounded and a buffer file must lie in the model's own directory: a model from anywhere cannot
//! make us read `../../etc/passwd` or a device. Every triangle primitive of the default scene's
//! nodes is taken, placed by the nodes' transforms; glTF's v runs down its images, so v is
//! turned to run up as in OBJ files and Blender.

use super::{BYTES_PER_TRIANGLE, RawTriangles};
use crate::Error;
use glam::{Mat3, Mat4, Vec2, Vec3};
use std::path::Path;

/// The triangles of the glTF or GLB `bytes`; buffer files are looked for in `directory` (none
/// for an embedded model), and `file` names the model in messages.
pub fn parse_gltf(
    bytes: &[u8],
    file: &Path,
    directory: Option<&Path>,
) -> Result<RawTriangles, Error> {
    let fail = |reason: String| Error::read(file, reason);
    check_glb_header(bytes).map_err(|why| fail(format!("not a readable glTF model: {why}")))?;
    check_position_indices(bytes)
        .map_err(|why| fail(format!("not a readable glTF model: {why}")))?;
    let gltf = gltf::Gltf::from_slice(bytes)
        .map_err(|e| fail(format!("not a readable glTF model: {e}")))?;
    let budget = crate::memory_budget::budget_bytes();
    let declared: u64 = gltf.buffers().map(|b| b.length() as u64).sum();
    if declared > budget {
        return Err(fail(format!(
            "its buffers declare {}, over the {} memory budget",
            crate::memory_budget::size_words(declared),
            crate::memory_budget::size_words(budget)
        )));
    }
    let triangles = triangle_count(&gltf);
    let need = triangles.saturating_mul(BYTES_PER_TRIANGLE);
    if need > budget {
        return Err(fail(format!(
            "its {triangles} triangles would take {}, over the {} memory budget",
            crate::memory_budget::size_words(need),
            crate::memory_budget::size_words(budget)
        )));
    }
    let buffers = gltf
        .buffers()
        .map(|buffer| buffer_data(&gltf, buffer, file, directory))
        .collect::<Result<Vec<Vec<u8>>, Error>>()?;
    let mut raw = RawTriangles {
        positions: Vec::with_capacity(triangles as usize),
        normals: Vec::with_capacity(triangles as usize),
        uvs: Vec::with_capacity(triangles as usize),
    };
    for mesh in gltf.meshes() {
        for primitive in mesh.primitives() {
            check_accessors(&primitive)
                .map_err(|why| fail(format!("not a readable glTF model: {why}")))?;
        }
    }
    let scene = gltf.default_scene().or_else(|| gltf.scenes().next());
    let Some(scene) = scene else {
        return Err(fail("it has no scene".into()));
    };
    for node in scene.nodes() {
        append_node(&node, Mat4::IDENTITY, &buffers, &mut raw, 0);
    }
    if raw.positions.is_empty() {
        return Err(fail("it has no triangles".into()));
    }
    if raw.uvs.iter().all(|uvs| uvs.iter().all(|uv| uv.is_nan())) {
        return Err(fail(
            "it has no texture coordinates (TEXCOORD_0): bumps and textures need them; export \
             the model with UVs"
                .into(),
        ));
    }
    Ok(raw)
}

/// A GLB's header, checked before the crate reads it: its length field must cover the header
/// and no more than the file (the crate's parser takes it on trust).
fn check_glb_header(bytes: &[u8]) -> Result<(), String> {
    let Some(header) = bytes.strip_prefix(b"glTF") else {
        return Ok(());
    };
    let field = |at: usize| {
        header
            .get(at..at + 4)
            .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
    };
    let (Some(_version), Some(length)) = (field(0), field(4)) else {
        return Err("the GLB header is cut short".into());
    };
    match length as usize {
        12.. if length as usize <= bytes.len() => Ok(()),
        _ => Err(format!(
            "the GLB header says {length} bytes, the file has {}",
            bytes.len()
        )),
    }
}

/// Whether a triangle primitive's accessors are what their semantics say (the crate's readers
/// take them on trust): positions and normals three floats, texture coordinates two numbers,
/// indices whole numbers, none empty, none sparse.
fn check_accessors(primitive: &gltf::Primitive) -> Result<(), String> {
    use gltf::accessor::{DataType, Dimensions};
    if primitive.mode() != gltf::mesh::Mode::Triangles {
        return Ok(());
    }
    let expect = |what: &str,
                  accessor: gltf::Accessor,
                  dimensions: Dimensions,
                  kinds: &[DataType]| {
        let fits = accessor.dimensions() == dimensions && kinds.contains(&accessor.data_type());
        let stride = accessor.view().and_then(|view| view.stride());
        let overlapping = stride.is_some_and(|stride| stride < accessor.size());
        let empty = accessor.count() == 0 || accessor.view().is_none();
        if !fits || empty || overlapping || accessor.sparse().is_some() {
            return Err(format!(
                "accessor {} for {what} is {:?} {:?} × {}, expected {dimensions:?} of {kinds:?} \
                 stored in a buffer",
                accessor.index(),
                accessor.dimensions(),
                accessor.data_type(),
                accessor.count()
            ));
        }
        Ok(())
    };
    let floats = [DataType::F32];
    for (semantic, accessor) in primitive.attributes() {
        match semantic {
            gltf::Semantic::Positions => expect("POSITION", accessor, Dimensions::Vec3, &floats)?,
            gltf::Semantic::Normals => expect("NORMAL", accessor, Dimensions::Vec3, &floats)?,
            gltf::Semantic::TexCoords(0) => {
                let kinds = [DataType::U8, DataType::U16, DataType::F32];
                expect("TEXCOORD_0", accessor, Dimensions::Vec2, &kinds)?
            }
            _ => {}
        }
    }
    if let Some(indices) = primitive.indices() {
        let kinds = [DataType::U8, DataType::U16, DataType::U32];
        expect("indices", indices, Dimensions::Scalar, &kinds)?;
    }
    Ok(())
}

/// Every primitive's POSITION names an accessor there is: the crate's validation looks the
/// accessor up before it checks the index.
fn check_position_indices(bytes: &[u8]) -> Result<(), String> {
    let json = match bytes.starts_with(b"glTF") {
        true => gltf::Glb::from_slice(bytes)
            .map_err(|e| e.to_string())?
            .json
            .into_owned(),
        false => bytes.to_vec(),
    };
    // What does not parse is the crate's to report.
    let Ok(root) = gltf::json::Root::from_slice(&json) else {
        return Ok(());
    };
    let positions = root
        .meshes
        .iter()
        .flat_map(|mesh| &mesh.primitives)
        .filter_map(|p| {
            p.attributes.get(&gltf::json::validation::Checked::Valid(
                gltf::Semantic::Positions,
            ))
        });
    match positions
        .map(|index| index.value())
        .find(|&i| i >= root.accessors.len())
    {
        Some(index) => Err(format!(
            "a POSITION names accessor {index}, and there is none"
        )),
        None => Ok(()),
    }
}

/// The triangles every triangle primitive declares, before anything is read.
fn triangle_count(gltf: &gltf::Gltf) -> u64 {
    gltf.meshes()
        .flat_map(|mesh| mesh.primitives().collect::<Vec<_>>())
        .filter(|p| p.mode() == gltf::mesh::Mode::Triangles)
        .map(|p| {
            let corners = match p.indices() {
                Some(indices) => indices.count(),
                None => p.get(&gltf::Semantic::Positions).map_or(0, |a| a.count()),
            };
            corners as u64 / 3
        })
        .sum()
}

/// A buffer's bytes: the GLB's own, a `data:` URI's, or a file beside the model, each exactly as
/// long as the buffer says.
fn buffer_data(
    gltf: &gltf::Gltf,
    buffer: gltf::Buffer,
    file: &Path,
    directory: Option<&Path>,
) -> Result<Vec<u8>, Error> {
    let length = buffer.length();
    let data = match buffer.source() {
        gltf::buffer::Source::Bin => gltf
            .blob
            .clone()
            .ok_or_else(|| Error::read(file, "a buffer is the GLB's own, and it has none"))?,
        gltf::buffer::Source::Uri(uri) if uri.starts_with("data:") => data_uri(uri, file)?,
        gltf::buffer::Source::Uri(uri) => buffer_file(uri, file, directory, length)?,
    };
    if data.len() < length {
        return Err(Error::read(
            file,
            format!(
                "a buffer holds {} bytes of the {length} it declares",
                data.len()
            ),
        ));
    }
    Ok(data)
}

/// A base64 `data:` URI's bytes.
fn data_uri(uri: &str, file: &Path) -> Result<Vec<u8>, Error> {
    use base64::Engine;
    let (_, encoded) = uri
        .split_once(";base64,")
        .ok_or_else(|| Error::read(file, "a data: buffer that is not base64"))?;
    base64::engine::general_purpose::STANDARD
        .decode(encoded)
        .map_err(|e| Error::read(file, format!("a data: buffer that does not decode: {e}")))
}

/// A buffer file named by a relative URI, which must lie in `directory` once links are followed.
fn buffer_file(
    uri: &str,
    file: &Path,
    directory: Option<&Path>,
    length: usize,
) -> Result<Vec<u8>, Error> {
    let shown = crate::diagnostic::shown_input(uri);
    let refuse = |why: &str| Error::read(file, format!("its buffer '{shown}' {why}"));
    let Some(directory) = directory else {
        return Err(refuse("is a file, and this model has no directory"));
    };
    let relative = Path::new(uri);
    let plain = relative
        .components()
        .all(|c| matches!(c, std::path::Component::Normal(_)));
    if uri.contains(':') || !plain {
        return Err(refuse(
            "is not a plain name in the model's directory (no '..', no absolute path, no URL)",
        ));
    }
    let path = directory.join(relative);
    let (inside, home) = (
        std::fs::canonicalize(&path),
        std::fs::canonicalize(directory),
    );
    match (inside, home) {
        (Ok(inside), Ok(home)) if inside.starts_with(&home) => {}
        (Err(e), _) => {
            return Err(refuse(&format!(
                "cannot be read: {}",
                crate::bounded_read::io_words(&e)
            )));
        }
        _ => return Err(refuse("leads outside the model's directory")),
    }
    crate::bounded_read::read_bounded(&path, length as u64)
        .map_err(|e| refuse(&format!("cannot be read: {e}")))
}

/// Appends the triangles of `node` and its children, placed by their transforms after `parent`.
fn append_node(
    node: &gltf::Node,
    parent: Mat4,
    buffers: &[Vec<u8>],
    raw: &mut RawTriangles,
    depth: usize,
) {
    // glTF nodes form a tree; a depth past any real model's is a crafted cycle.
    if depth > 64 {
        return;
    }
    let world = parent * Mat4::from_cols_array_2d(&node.transform().matrix());
    let normals_to_world = Mat3::from_mat4(world).inverse().transpose();
    if let Some(mesh) = node.mesh() {
        for primitive in mesh.primitives() {
            if primitive.mode() == gltf::mesh::Mode::Triangles {
                let placed = (world, normals_to_world);
                append_primitive(&primitive, placed, buffers, raw);
            }
        }
    }
    for child in node.children() {
        append_node(&child, world, buffers, raw, depth + 1);
    }
}

fn append_primitive(
    primitive: &gltf::Primitive,
    (world, normals_to_world): (Mat4, Mat3),
    buffers: &[Vec<u8>],
    raw: &mut RawTriangles,
) {
    let reader = primitive.reader(|buffer| buffers.get(buffer.index()).map(Vec::as_slice));
    let Some(positions) = reader.read_positions() else {
        return;
    };
    let positions: Vec<Vec3> = positions
        .map(|p| world.transform_point3(Vec3::from_array(p)))
        .collect();
    let normals: Vec<Vec3> = reader.read_normals().map_or_else(Vec::new, |n| {
        n.map(|n| (normals_to_world * Vec3::from_array(n)).normalize_or_zero())
            .collect()
    });
    let uvs: Vec<Vec2> = reader.read_tex_coords(0).map_or_else(Vec::new, |t| {
        t.into_f32().map(|[u, v]| Vec2::new(u, 1.0 - v)).collect()
    });
    let indices: Vec<u32> = match reader.read_indices() {
        Some(indices) => indices.into_u32().collect(),
        None => (0..positions.len() as u32).collect(),
    };
    for corners in indices.chunks_exact(3) {
        let corners = [0, 1, 2].map(|k| corners[k] as usize);
        if corners.iter().any(|&i| i >= positions.len()) {
            continue;
        }
        raw.positions.push(corners.map(|i| positions[i]));
        raw.normals
            .push(corners.map(|i| normals.get(i).copied().unwrap_or(Vec3::ZERO)));
        raw.uvs
            .push(corners.map(|i| uvs.get(i).copied().unwrap_or(Vec2::NAN)));
    }
}
