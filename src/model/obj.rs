//! Wavefront OBJ text to triangles: a first pass over the lines checks what `tobj` does not
//! (UTF-8, finite numbers, the triangle count against the memory budget) and says where;
//! `tobj` then parses, triangulating polygons and giving each corner one index.

use super::{BYTES_PER_TRIANGLE, RawTriangles};
use crate::Error;
use glam::{Vec2, Vec3};

/// The most model memory one byte of OBJ text can make: the shortest face line, `f 1 2 3`
/// and its newline (8 bytes), is one triangle.
pub const MAX_OBJ_EXPANSION: u64 = BYTES_PER_TRIANGLE.div_ceil(8);

/// The triangles of the OBJ text `bytes`; `file` names it in messages.
pub fn parse_obj(bytes: &[u8], file: &str) -> Result<RawTriangles, Error> {
    let text = std::str::from_utf8(bytes).map_err(|e| {
        let source = String::from_utf8_lossy(bytes);
        Error::Diagnostic(crate::diagnostic::render(
            file,
            &source,
            e.valid_up_to(),
            "expected UTF-8 text, found an invalid byte",
        ))
    })?;
    let triangles = check_lines(text, file)?;
    let need = triangles.saturating_mul(BYTES_PER_TRIANGLE);
    let budget = crate::memory_budget::budget_bytes();
    if need > budget {
        return Err(Error::read(
            std::path::Path::new(file),
            format!(
                "its {triangles} triangles would take {}, over the {} memory budget; raise {} or \
                 use a smaller model",
                crate::memory_budget::size_words(need),
                crate::memory_budget::size_words(budget),
                crate::memory_budget::MEMORY_BUDGET_VAR
            ),
        ));
    }
    let options = tobj::LoadOptions {
        single_index: true,
        triangulate: true,
        ignore_points: true,
        ignore_lines: true,
    };
    let mut reader = std::io::BufReader::new(text.as_bytes());
    // Materials are not ours to read: a model's look comes from its scene's material.
    let no_materials = |_: &std::path::Path| Err(tobj::LoadError::OpenFileFailed);
    let (models, _) = tobj::load_obj_buf(&mut reader, &options, no_materials).map_err(|e| {
        Error::read(
            std::path::Path::new(file),
            format!("not a readable OBJ: {e}"),
        )
    })?;
    let mut raw = RawTriangles {
        positions: Vec::with_capacity(triangles as usize),
        normals: Vec::with_capacity(triangles as usize),
        uvs: Vec::with_capacity(triangles as usize),
    };
    for model in &models {
        append_mesh(&model.mesh, &mut raw);
    }
    if raw.positions.is_empty() {
        return Err(Error::read(
            std::path::Path::new(file),
            "it has no triangles (no `f` lines with three or more corners)",
        ));
    }
    if raw.uvs.iter().all(|uvs| uvs.iter().all(|uv| uv.is_nan())) {
        return Err(Error::read(
            std::path::Path::new(file),
            "it has no texture coordinates (`vt` lines, used by its faces): bumps and textures \
             need them; export the model with UVs",
        ));
    }
    Ok(raw)
}

/// Checks every `v`, `vt` and `vn` line's numbers are finite (an error at the first that is
/// not) and counts the triangles the `f` lines make.
fn check_lines(text: &str, file: &str) -> Result<u64, Error> {
    let mut triangles = 0u64;
    let mut offset = 0;
    for line in text.split_inclusive('\n') {
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v" | "vt" | "vn") => check_numbers(text, line, offset, file)?,
            Some("f") => triangles += (words.count() as u64).saturating_sub(2),
            _ => {}
        }
        offset += line.len();
    }
    Ok(triangles)
}

/// An error at the first word after the keyword of `line` (at `offset` in `text`) that is not
/// a finite number.
fn check_numbers(text: &str, line: &str, offset: usize, file: &str) -> Result<(), Error> {
    let trimmed = line.trim_start();
    let keyword_end = trimmed.find(char::is_whitespace).unwrap_or(trimmed.len());
    let start = line.len() - trimmed.len() + keyword_end;
    let mut at = start;
    for word in line[start..].split_inclusive(char::is_whitespace) {
        let number = word.trim();
        let column = at + (word.len() - word.trim_start().len());
        at += word.len();
        if number.starts_with('#') {
            break;
        }
        if number.is_empty() {
            continue;
        }
        // tobj reads f32: 1e39 is finite as f64 but infinite there.
        if !number.parse::<f32>().is_ok_and(f32::is_finite) {
            return Err(Error::Diagnostic(crate::diagnostic::render(
                file,
                text,
                offset + column,
                &format!(
                    "expected a finite number, found '{}'",
                    crate::diagnostic::shown_input(number)
                ),
            )));
        }
    }
    Ok(())
}

/// The mesh's triangles, appended to `raw`; corners without a normal or (u,v) get zero and NaN.
fn append_mesh(mesh: &tobj::Mesh, raw: &mut RawTriangles) {
    let position = |i: usize| Vec3::from_slice(&mesh.positions[3 * i..3 * i + 3]);
    let normal = |i: usize| match mesh.normals.get(3 * i..3 * i + 3) {
        Some(n) => Vec3::from_slice(n),
        None => Vec3::ZERO,
    };
    let uv = |i: usize| match mesh.texcoords.get(2 * i..2 * i + 2) {
        Some(t) => Vec2::from_slice(t),
        None => Vec2::NAN,
    };
    for corners in mesh.indices.chunks_exact(3) {
        let corners = [0, 1, 2].map(|k| corners[k] as usize);
        raw.positions.push(corners.map(position));
        raw.normals.push(corners.map(normal));
        raw.uvs.push(corners.map(uv));
    }
}
