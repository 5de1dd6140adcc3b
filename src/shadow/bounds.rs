//! Boxes around the scene and around the part of it the camera sees: what shadow maps are fitted
//! to. Numerics: f64 world coordinates, as the camera's eye is kept.

use crate::scene::Camera;
use crate::scene::PreparedScene;
use glam::{DVec3, Vec3};

/// An axis-aligned box in world space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounds {
    pub min: DVec3,
    pub max: DVec3,
}

impl Bounds {
    /// The smallest box around `points`; `None` for no points or a non-finite one.
    pub fn around(points: impl IntoIterator<Item = DVec3>) -> Option<Bounds> {
        let mut points = points.into_iter();
        let first = points.next()?;
        let bounds = points.fold(
            Bounds {
                min: first,
                max: first,
            },
            |b, p| Bounds {
                min: b.min.min(p),
                max: b.max.max(p),
            },
        );
        (bounds.min.is_finite() && bounds.max.is_finite()).then_some(bounds)
    }

    pub fn union(self, other: Bounds) -> Bounds {
        Bounds {
            min: self.min.min(other.min),
            max: self.max.max(other.max),
        }
    }

    pub fn intersection(self, other: Bounds) -> Option<Bounds> {
        let (min, max) = (self.min.max(other.min), self.max.min(other.max));
        (min.cmple(max).all()).then_some(Bounds { min, max })
    }

    pub fn grown(self, by: f64) -> Bounds {
        Bounds {
            min: self.min - DVec3::splat(by),
            max: self.max + DVec3::splat(by),
        }
    }

    pub fn centre(&self) -> DVec3 {
        (self.min + self.max) / 2.0
    }

    pub fn contains(&self, p: DVec3) -> bool {
        p.cmpge(self.min).all() && p.cmple(self.max).all()
    }

    pub fn corners(&self) -> [DVec3; 8] {
        std::array::from_fn(|i| {
            DVec3::new(
                if i & 1 == 0 { self.min.x } else { self.max.x },
                if i & 2 == 0 { self.min.y } else { self.max.y },
                if i & 4 == 0 { self.min.z } else { self.max.z },
            )
        })
    }
}

/// Each object's box as tessellated, grown by its mesh's chord error so the true surface is
/// inside it too (`None` for an object with no finite vertex).
pub fn object_bounds(prepared: &PreparedScene) -> Vec<Option<Bounds>> {
    prepared
        .objects
        .iter()
        .map(|object| {
            let origin = object.surface.origin();
            let points = object.mesh.positions.iter().map(|p| origin + p.as_dvec3());
            Bounds::around(points).map(|b| b.grown(f64::from(object.mesh.chord_error)))
        })
        .collect()
}

/// The box around every box of `boxes`.
pub fn union_of(boxes: impl IntoIterator<Item = Option<Bounds>>) -> Option<Bounds> {
    boxes.into_iter().flatten().reduce(Bounds::union)
}

/// The part of `scene` inside the camera's view (of the full image's `aspect`), boxed: the
/// points that can be shaded, so the points a shadow map must cover. `None` when the camera sees
/// none of the scene's box.
pub fn seen_bounds(camera: &Camera, aspect: f32, scene: &Bounds) -> Option<Bounds> {
    let forward = camera.forward().as_dvec3();
    let (right, up) = view_axes(camera);
    let farthest = scene
        .corners()
        .iter()
        .map(|c| (*c - camera.eye).dot(forward))
        .fold(f64::NEG_INFINITY, f64::max);
    let near = f64::from(camera.near);
    let far = f64::from(camera.far).min(farthest);
    if far.is_nan() || far <= near {
        return None;
    }
    let half_height = (f64::from(camera.vfov_degrees.clamp(1e-3, 179.0)).to_radians() / 2.0).tan();
    let half_width = half_height * f64::from(aspect.clamp(1e-3, 1e3));
    let corners = [near, far].into_iter().flat_map(|depth| {
        [(-1.0, -1.0), (1.0, -1.0), (-1.0, 1.0), (1.0, 1.0)].map(|(sx, sy)| {
            camera.eye + (forward + right * (sx * half_width) + up * (sy * half_height)) * depth
        })
    });
    Bounds::around(corners)?.intersection(*scene)
}

/// The camera's unit right and up axes, as its view matrix takes them.
fn view_axes(camera: &Camera) -> (DVec3, DVec3) {
    let forward = camera.forward();
    let up = crate::surface::normalize_or(camera.up, Vec3::Y);
    let up = if forward.cross(up).length_squared() < 1e-12 {
        forward.any_orthonormal_vector()
    } else {
        up
    };
    let right = forward.cross(up).normalize();
    (right.as_dvec3(), right.cross(forward).as_dvec3())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn camera() -> Camera {
        Camera {
            eye: DVec3::new(0.0, 0.0, 10.0),
            target: DVec3::ZERO,
            up: Vec3::Y,
            vfov_degrees: 90.0,
            near: 1.0,
            far: 100.0,
        }
    }

    #[test]
    fn what_the_camera_sees_of_a_wide_floor_is_cut_to_its_view() {
        let floor = Bounds {
            min: DVec3::new(-1000.0, -1.0, -1000.0),
            max: DVec3::new(1000.0, 1.0, 1000.0),
        };
        let seen = seen_bounds(&camera(), 1.0, &floor).unwrap();
        // From the near plane (1 ahead) to the far plane (100 ahead), where the 90° view is
        // ±100 wide; the floor's own height.
        assert!((seen.max.z - 9.0).abs() < 1e-9, "{seen:?}");
        assert!((seen.min.z + 90.0).abs() < 1e-9, "{seen:?}");
        assert!((seen.max.x - 100.0).abs() < 1e-9 && (seen.min.x + 100.0).abs() < 1e-9);
        assert!(seen.max.y == 1.0 && seen.min.y == -1.0);
    }

    #[test]
    fn a_scene_behind_the_camera_is_not_seen() {
        let behind = Bounds {
            min: DVec3::new(-1.0, -1.0, 20.0),
            max: DVec3::new(1.0, 1.0, 30.0),
        };
        assert_eq!(seen_bounds(&camera(), 1.5, &behind), None);
    }

    #[test]
    fn corners_span_the_box() {
        let b = Bounds {
            min: DVec3::new(1.0, 2.0, 3.0),
            max: DVec3::new(4.0, 5.0, 6.0),
        };
        assert_eq!(Bounds::around(b.corners()), Some(b));
        assert!(b.contains(b.centre()) && !b.contains(DVec3::ZERO));
    }
}
