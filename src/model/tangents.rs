//! MikkTSpace tangents (the `bevy_mikktspace` crate, a faithful port of Mikkelsen's reference):
//! the frame Blender and the game engines bake and read normal maps in, so a map baked for a
//! model there shades it the same here.

use crate::surface::{Corner, normalize_or};
use bevy_mikktspace::{Geometry, StdOps, TangentSpace, generate_tangents};
use glam::{Vec3, Vec4};

/// Triangles as corners, three a face, for the generator to read and write.
struct Faces<'a>(&'a mut [Corner]);

impl Geometry for Faces<'_> {
    fn num_faces(&self) -> usize {
        self.0.len() / 3
    }

    fn num_vertices_of_face(&self, _face: usize) -> usize {
        3
    }

    fn position(&self, face: usize, vert: usize) -> [f32; 3] {
        self.0[3 * face + vert].p.to_array()
    }

    fn normal(&self, face: usize, vert: usize) -> [f32; 3] {
        self.0[3 * face + vert].n.to_array()
    }

    fn tex_coord(&self, face: usize, vert: usize) -> [f32; 2] {
        self.0[3 * face + vert].uv.to_array()
    }

    fn set_tangent(&mut self, tangent: Option<TangentSpace>, face: usize, vert: usize) {
        if let Some(space) = tangent {
            self.0[3 * face + vert].tangent = Vec4::from_array(space.tangent_encoded());
        }
    }
}

/// Sets every corner's tangent; where the generator gives none (a face with no neighbour to
/// borrow from), the direction of increasing u on its own triangle.
pub fn generate(corners: &mut [Corner]) {
    if corners.is_empty() {
        return;
    }
    let _ = generate_tangents::<_, StdOps>(&mut Faces(corners));
    for face in corners.chunks_exact_mut(3) {
        let along_u = own_tangent(face);
        for corner in face {
            if corner.tangent.truncate().length_squared() == 0.0 {
                corner.tangent = along_u.extend(1.0);
            }
        }
    }
}

/// The direction of increasing u across one triangle.
fn own_tangent(face: &[Corner]) -> Vec3 {
    let (e1, e2) = (face[1].p - face[0].p, face[2].p - face[0].p);
    let (d1, d2) = (face[1].uv - face[0].uv, face[2].uv - face[0].uv);
    let det = d1.x * d2.y - d2.x * d1.y;
    normalize_or((e1 * d2.y - e2 * d1.y) / det, Vec3::X)
}
