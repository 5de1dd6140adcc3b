//! A sphere around each caster of a light, to tell without a map that a point is in no caster's
//! shadow: when its segment to the light (its ray, for a directional light) passes no sphere.
//! Most of a floor under a sphere is told so.

use super::bounds::Bounds;
use crate::raster::PreparedScene;
use crate::scene::Light;
use crate::surface::Surface;
use glam::{DVec3, Vec3};

/// The most casters whose spheres a point is tested against: past that, testing each would cost
/// more per fragment than the lookup it saves.
pub const MOST_SPHERES: usize = 16;

/// The casters' spheres and the light, relative to the camera's eye (f32, subtracted in f64).
pub struct CasterSpheres {
    /// `None` for more casters than `MOST_SPHERES`: no point is told clear.
    spheres: Option<Vec<CasterSphere>>,
    light: LightAt,
}

#[derive(Clone, Copy)]
struct CasterSphere {
    /// The caster's index among the scene's objects.
    object: usize,
    centre: Vec3,
    radius: f32,
}

enum LightAt {
    Point(Vec3),
    /// The unit direction towards the light.
    Directional(Vec3),
}

impl CasterSpheres {
    /// Spheres around `casters`, grown by `margin` world units (what a lookup's taps and lift
    /// may reach past a caster's outline).
    pub fn new(
        prepared: &PreparedScene,
        casters: &[usize],
        boxes: &[Option<Bounds>],
        light: &Light,
        eye: DVec3,
        margin: f32,
    ) -> CasterSpheres {
        let spheres = (casters.len() <= MOST_SPHERES).then(|| {
            casters
                .iter()
                .filter_map(|&index| {
                    let (centre, radius) = match &prepared.objects[index].surface {
                        Surface::Sphere(s) => (s.center, f64::from(s.radius)),
                        _ => {
                            let b = boxes[index]?;
                            (b.centre(), b.min.distance(b.max) / 2.0)
                        }
                    };
                    Some(CasterSphere {
                        object: index,
                        centre: (centre - eye).as_vec3(),
                        radius: radius as f32 + margin,
                    })
                })
                .collect()
        });
        let light = match *light {
            Light::Point { position, .. } => LightAt::Point((position - eye).as_vec3()),
            Light::Directional { towards, .. } => {
                LightAt::Directional(crate::surface::normalize_or(towards, Vec3::Y))
            }
        };
        CasterSpheres { spheres, light }
    }

    /// Whether the camera-relative point `p` sees the light past the sphere of every caster
    /// but object `except`.
    #[inline(always)]
    pub fn clear_of_all(&self, p: Vec3, except: Option<usize>) -> bool {
        let Some(spheres) = &self.spheres else {
            return false;
        };
        let mut others = spheres.iter().filter(|s| Some(s.object) != except);
        others.all(|&CasterSphere { centre, radius, .. }| {
            let to_centre = centre - p;
            let closest = match self.light {
                LightAt::Point(light) => {
                    let to_light = light - p;
                    let t = (to_centre.dot(to_light) / to_light.length_squared()).clamp(0.0, 1.0);
                    to_light * t
                }
                LightAt::Directional(towards) => towards * to_centre.dot(towards).max(0.0),
            };
            (to_centre - closest).length_squared() > radius * radius
        })
    }

    /// The cosine between the unit normal `n` at camera-relative point `p` and the way to the
    /// light (NaN where `p` is at a point light).
    #[inline(always)]
    pub fn facing(&self, p: Vec3, n: Vec3) -> f32 {
        match self.light {
            LightAt::Point(light) => n.dot((light - p).normalize()),
            LightAt::Directional(towards) => n.dot(towards),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spheres(light: LightAt) -> CasterSpheres {
        CasterSpheres {
            spheres: Some(vec![CasterSphere {
                object: 0,
                centre: Vec3::new(0.0, 1.0, 0.0),
                radius: 1.0,
            }]),
            light,
        }
    }

    #[test]
    fn only_points_whose_way_to_the_light_passes_a_sphere_are_not_clear() {
        let above = spheres(LightAt::Point(Vec3::new(0.0, 10.0, 0.0)));
        assert!(
            !above.clear_of_all(Vec3::new(0.3, 0.0, 0.0), None),
            "under the sphere"
        );
        assert!(
            above.clear_of_all(Vec3::new(3.0, 0.0, 0.0), None),
            "beside it"
        );
        assert!(
            above.clear_of_all(Vec3::new(0.3, 0.0, 0.0), Some(0)),
            "under the sphere, with the sphere left out"
        );
        // Between the sphere and the light: the segment stops before the sphere.
        assert!(above.clear_of_all(Vec3::new(0.0, 5.0, 0.0), None));
        let sun = spheres(LightAt::Directional(Vec3::new(1.0, 1.0, 0.0).normalize()));
        assert!(
            !sun.clear_of_all(Vec3::new(-1.0, 0.0, 0.0), None),
            "in the shadow's path"
        );
        assert!(
            sun.clear_of_all(Vec3::new(2.5, 0.0, 0.0), None),
            "on the lit side"
        );
    }
}
