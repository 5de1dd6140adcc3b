//! Where each light's shadow maps look from: an orthographic map fitted to what the camera sees
//! for a directional light; for a point light one perspective map fitted around what the camera
//! sees, or a cube of six maps when that would need too wide a view.

use super::bounds::Bounds;
use crate::raster::DepthView;
use glam::{DVec3, Vec3};

/// The widest half-angle a single map around a point light covers; wider views use a cube.
const WIDEST_FITTED_HALF_ANGLE: f64 = 60.0;

/// A map's view and the size of its texels in the world.
#[derive(Clone, Copy, Debug)]
pub struct MapView {
    pub view: DepthView,
    /// A texel's width in world units at depth d along the view is `texel_at_zero + texel_per_depth · d`.
    pub texel_at_zero: f32,
    pub texel_per_depth: f32,
    /// The world directions of the map's +x and +y (up the map), square to `view.forward`.
    pub right: Vec3,
    pub up: Vec3,
    /// Whether it is one of a cube's six faces (chosen by the major axis from the light).
    pub cube_face: bool,
    /// The greatest depth it covers (where its texels are widest).
    pub deepest: f32,
}

impl MapView {
    /// Whether a map-relative point lies clearly outside what the map covers, a texel's margin
    /// or more, told without projecting it: past the cone around a fitted perspective map's axis
    /// that holds its corners, or farther from an orthographic map's axis than its corners. (A
    /// cube face's neighbours cover what it does not.)
    pub fn clearly_misses(&self, q: Vec3) -> bool {
        if self.cube_face {
            return false;
        }
        let along = self.view.forward.dot(q);
        let across_squared = (q.length_squared() - along * along).max(0.0);
        let half_diagonal = std::f32::consts::SQRT_2 * (self.view.size as f32 / 2.0 + 2.0);
        if self.is_perspective() {
            let tan_limit = self.texel_per_depth * half_diagonal;
            along <= 0.0 || across_squared > (tan_limit * along).powi(2)
        } else {
            across_squared > (self.texel_at_zero * half_diagonal).powi(2)
        }
    }
}

impl MapView {
    pub fn texel(&self, depth: f32) -> f32 {
        self.texel_at_zero + self.texel_per_depth * depth.max(0.0)
    }

    /// Whether it looks out from a point (a point light's map), not along parallel rays.
    pub fn is_perspective(&self) -> bool {
        self.texel_per_depth > 0.0
    }

    /// The plane through `q` (map-relative) with normal `n`, met along each texel's ray.
    pub fn tap_plane(&self, q: Vec3, n: Vec3) -> TapPlane {
        let size = self.view.size as f32;
        // Texel i's centre lies at i·step + start across the map (−1 to 1), row j's at
        // −start − j·step up it.
        let (step, start) = (2.0 / size, 1.0 / size - 1.0);
        let forward = self.view.forward;
        if self.is_perspective() {
            let tan_half = self.texel_per_depth * size / 2.0;
            TapPlane::Perspective {
                towards: n.dot(q),
                along: n.dot(forward),
                across: n.dot(self.right) * tan_half,
                up: n.dot(self.up) * tan_half,
                tan_half_squared: tan_half * tan_half,
                step,
                start,
            }
        } else {
            let half = self.texel_at_zero * size / 2.0;
            let facing = n.dot(forward);
            let (across, up) = (n.dot(self.right) * half, n.dot(self.up) * half);
            // n·(q − x·half·right − y·half·up) / n·forward, affine in (i, j).
            TapPlane::Orthographic {
                at_origin: (n.dot(q) - across * start + up * start) / facing,
                per_column: -across * step / facing,
                per_row: up * step / facing,
            }
        }
    }
}

/// A receiver's tangent plane as each texel's ray meets it: how far along (as the map measures,
/// depth along the view for an orthographic map, distance from the light for a perspective
/// one), +∞ where the ray never meets it ahead (it shows nothing of the receiver, so no light
/// reaching it).
#[derive(Clone, Copy, Debug)]
pub enum TapPlane {
    /// Affine in the texel's column and row.
    Orthographic {
        at_origin: f32,
        per_column: f32,
        per_row: f32,
    },
    /// n·q · |ray| / n·ray, with ray = forward + x·tan·right + y·tan·up.
    Perspective {
        towards: f32,
        along: f32,
        across: f32,
        up: f32,
        tan_half_squared: f32,
        step: f32,
        start: f32,
    },
}

impl TapPlane {
    #[inline]
    pub fn at(&self, i: u32, j: u32) -> f32 {
        match *self {
            TapPlane::Orthographic {
                at_origin,
                per_column,
                per_row,
            } => at_origin + per_column * i as f32 + per_row * j as f32,
            TapPlane::Perspective {
                towards,
                along,
                across,
                up,
                tan_half_squared,
                step,
                start,
            } => {
                let (x, y) = (i as f32 * step + start, -start - j as f32 * step);
                let meets = along + across * x + up * y;
                if meets >= 0.0 {
                    return f32::INFINITY;
                }
                towards * (1.0 + tan_half_squared * (x * x + y * y)).sqrt() / meets
            }
        }
    }
}

/// The map of a directional light shining `towards` (from the surface to the light) over the
/// `region` box: across it and through its depth.
pub fn directional_view(towards: Vec3, region: &Bounds, size: u32) -> MapView {
    let forward = -crate::surface::normalize_or(towards, Vec3::Y).as_dvec3();
    let (right, up) = axes_across(forward);
    let centre = region.centre();
    let across = |c: &DVec3| ((*c - centre).dot(right), (*c - centre).dot(up));
    let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for (x, y) in region.corners().iter().map(across) {
        (x0, x1, y0, y1) = (x0.min(x), x1.max(x), y0.min(y), y1.max(y));
    }
    let half = ((x1 - x0).max(y1 - y0) / 2.0).max(1e-6) * 1.001;
    let origin = centre + right * ((x0 + x1) / 2.0) + up * ((y0 + y1) / 2.0);
    let along = region.corners().map(|c| (c - origin).dot(forward));
    let (near, far) = along
        .iter()
        .fold((f64::MAX, f64::MIN), |(a, b), &d| (a.min(d), b.max(d)));
    let margin = (far - near).max(half) * 1e-3;
    let view = glam::camera::rh::view::look_to_mat4(Vec3::ZERO, forward.as_vec3(), up.as_vec3());
    let h = half as f32;
    let projection = glam::camera::rh::proj::directx::orthographic(
        -h,
        h,
        -h,
        h,
        (near - margin) as f32,
        (far + margin) as f32,
    );
    MapView {
        view: DepthView {
            origin,
            view_projection: projection * view,
            forward: forward.as_vec3(),
            size,
        },
        texel_at_zero: 2.0 * h / size as f32,
        texel_per_depth: 0.0,
        right: right.as_vec3(),
        up: up.as_vec3(),
        cube_face: false,
        deepest: (far + margin - near) as f32,
    }
}

/// The maps of a point light at `position` over the `region` box: one fitted perspective map
/// of `size` texels, or six cube faces (`cube_face_size`) where the box surrounds the light or
/// spans too wide a view. `margin_texels` widens each cube face past 90° so the filter's taps
/// at a face's edge stay on it.
pub fn point_views(
    position: DVec3,
    region: &Bounds,
    size: u32,
    margin_texels: f32,
) -> Vec<MapView> {
    let corners = region.corners();
    let farthest = corners
        .iter()
        .map(|c| c.distance(position))
        .fold(0.0, f64::max)
        .max(1e-6)
        * 1.01;
    if let Some(view) = fitted_view(position, region, farthest, size) {
        return vec![view];
    }
    let face_size = cube_face_size(size);
    let widen = 1.0 + 2.0 * margin_texels / face_size as f32;
    CUBE_FACES
        .iter()
        .map(|&(forward, up)| {
            perspective_view(
                position,
                forward,
                up,
                widen.atan() * 2.0,
                farthest,
                face_size,
                true,
            )
        })
        .collect()
}

/// The texels on a side of each cube face for maps of `size`: as many, up to `LARGEST_CUBE_FACE`
/// (six faces of 4096² would take 400 MB).
pub fn cube_face_size(size: u32) -> u32 {
    size.min(LARGEST_CUBE_FACE)
}

/// The largest cube face, in texels on a side.
const LARGEST_CUBE_FACE: u32 = 2048;

/// One perspective map around the light's view of the box, if its half-angle is narrow enough.
fn fitted_view(position: DVec3, region: &Bounds, farthest: f64, size: u32) -> Option<MapView> {
    if region.grown(1e-9 * farthest).contains(position) {
        return None;
    }
    let axis = (region.centre() - position).normalize();
    let half_angle = region
        .corners()
        .iter()
        .map(|c| {
            axis.dot((*c - position).normalize())
                .clamp(-1.0, 1.0)
                .acos()
        })
        .fold(0.0, f64::max);
    if half_angle.is_nan() || half_angle >= WIDEST_FITTED_HALF_ANGLE.to_radians() {
        return None;
    }
    let fov = (half_angle * 1.01 + 1e-4) * 2.0;
    let (_, up) = axes_across(axis);
    Some(perspective_view(
        position, axis, up, fov as f32, farthest, size, false,
    ))
}

fn perspective_view(
    origin: DVec3,
    forward: DVec3,
    up: DVec3,
    fov: f32,
    far: f64,
    size: u32,
    cube_face: bool,
) -> MapView {
    let right = forward.cross(up).normalize();
    let up = right.cross(forward);
    let view = glam::camera::rh::view::look_to_mat4(Vec3::ZERO, forward.as_vec3(), up.as_vec3());
    // Depth is kept linear, so a near plane this close costs no precision.
    let (far, near) = (far as f32, (far * 1e-5) as f32);
    let projection = glam::camera::rh::proj::directx::perspective(fov, 1.0, near, far);
    MapView {
        view: DepthView {
            origin,
            view_projection: projection * view,
            forward: forward.as_vec3(),
            size,
        },
        texel_at_zero: 0.0,
        texel_per_depth: 2.0 * (fov / 2.0).tan() / size as f32,
        right: right.as_vec3(),
        up: up.as_vec3(),
        cube_face,
        deepest: far,
    }
}

/// The cube's faces in the order `cube_face_of` numbers them: +x, −x, +y, −y, +z, −z.
const CUBE_FACES: [(DVec3, DVec3); 6] = [
    (DVec3::X, DVec3::NEG_Y),
    (DVec3::NEG_X, DVec3::NEG_Y),
    (DVec3::Y, DVec3::Z),
    (DVec3::NEG_Y, DVec3::NEG_Z),
    (DVec3::Z, DVec3::NEG_Y),
    (DVec3::NEG_Z, DVec3::NEG_Y),
];

/// The cube face that holds the direction `d` from the light: its major axis.
pub fn cube_face_of(d: Vec3) -> usize {
    let a = d.abs();
    if a.x >= a.y && a.x >= a.z {
        usize::from(d.x < 0.0)
    } else if a.y >= a.z {
        2 + usize::from(d.y < 0.0)
    } else {
        4 + usize::from(d.z < 0.0)
    }
}

/// Two unit axes across `forward`, a right-handed frame with it.
fn axes_across(forward: DVec3) -> (DVec3, DVec3) {
    let helper = if forward.y.abs() < 0.9 {
        DVec3::Y
    } else {
        DVec3::Z
    };
    let right = forward.cross(helper).normalize();
    (right, right.cross(forward))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Where a world point lands in a map: texel coordinates and depth.
    fn project(view: &MapView, p: DVec3) -> (f32, f32, f32) {
        let relative = (p - view.view.origin).as_vec3();
        let clip = view.view.view_projection * relative.extend(1.0);
        let size = view.view.size as f32;
        (
            (clip.x / clip.w * 0.5 + 0.5) * size,
            (0.5 - clip.y / clip.w * 0.5) * size,
            clip.z / clip.w,
        )
    }

    fn inside(view: &MapView, p: DVec3) -> bool {
        let (x, y, z) = project(view, p);
        let size = view.view.size as f32;
        (0.0..=size).contains(&x) && (0.0..=size).contains(&y) && (0.0..=1.0).contains(&z)
    }

    #[test]
    fn a_directional_map_holds_every_seen_point_and_every_caster() {
        let seen = Bounds {
            min: DVec3::new(-2.0, 0.0, -2.0),
            max: DVec3::new(2.0, 1.0, 2.0),
        };
        let view = directional_view(Vec3::new(0.3, 1.0, 0.2), &seen, 256);
        for c in seen.corners() {
            assert!(inside(&view, c), "{c}");
        }
        // Nearer the light, nearer in depth.
        let (_, _, high) = project(&view, DVec3::new(0.0, 1.0, 0.0));
        let (_, _, low) = project(&view, DVec3::new(0.0, 0.0, 0.0));
        assert!((0.0..low).contains(&high), "{high} {low}");
        let texel = view.texel(1.0);
        assert!(texel > 4.0 / 256.0 && texel < 8.0 / 256.0, "{texel}");
    }

    #[test]
    fn the_tap_plane_meets_each_texels_ray_where_the_plane_is() {
        let region = Bounds {
            min: DVec3::new(-1.0, 0.0, -1.0),
            max: DVec3::new(1.0, 1.0, 1.0),
        };
        let light = DVec3::new(0.5, 6.0, 0.3);
        let views = [
            directional_view(Vec3::new(0.3, 1.0, 0.2), &region, 64),
            point_views(light, &region, 64, 2.0).remove(0),
        ];
        let n = Vec3::new(0.2, 0.9, -0.1).normalize();
        for view in views {
            // A point of the plane, relative to the map's origin.
            let q = (DVec3::new(0.1, 0.2, -0.3) - view.view.origin).as_vec3();
            let plane = view.tap_plane(q, n);
            let inverse = view.view.view_projection.inverse();
            for (i, j) in [(0, 0), (5, 40), (31, 32), (63, 63), (17, 3)] {
                // Texel (i, j)'s ray, from its centre's near and far points.
                let (x, y) = ((i as f32 + 0.5) / 32.0 - 1.0, 1.0 - (j as f32 + 0.5) / 32.0);
                let point = |z: f32| {
                    let p = inverse * glam::Vec4::new(x, y, z, 1.0);
                    p.truncate() / p.w
                };
                let (a, b) = (point(0.0), point(1.0));
                let t = n.dot(q - a) / n.dot(b - a);
                let hit = a + (b - a) * t;
                let want = if view.is_perspective() {
                    hit.length()
                } else {
                    view.view.forward.dot(hit)
                };
                let got = plane.at(i, j);
                assert!(
                    (got - want).abs() < 1e-3 * want.abs().max(1.0),
                    "texel {i},{j}: {got} vs {want}"
                );
            }
        }
    }

    #[test]
    fn a_light_above_a_small_box_gets_one_map_and_a_light_inside_gets_a_cube() {
        let seen = Bounds {
            min: DVec3::new(-1.0, 0.0, -1.0),
            max: DVec3::new(1.0, 1.0, 1.0),
        };
        let above = point_views(DVec3::new(0.0, 6.0, 0.0), &seen, 512, 2.0);
        assert_eq!(above.len(), 1);
        for c in seen.corners() {
            assert!(inside(&above[0], c), "{c}");
        }
        let within = point_views(DVec3::new(0.0, 0.5, 0.0), &seen, 512, 2.0);
        assert_eq!(within.len(), 6);
        assert!(within.iter().all(|v| v.cube_face && v.view.size == 512));
        // Every direction lands inside the face its major axis picks.
        for k in 0..200 {
            let t = k as f64 * 0.731;
            let d = DVec3::new(t.sin() * 3.0, (t * 1.7).cos(), (t * 0.3).sin() * 2.0 - 0.5);
            let face = cube_face_of(d.as_vec3());
            assert!(
                inside(&within[face], DVec3::new(0.0, 0.5, 0.0) + d * 0.3),
                "{d} face {face}"
            );
        }
    }
}
