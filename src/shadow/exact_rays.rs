//! Exact shadows: from each shaded point a ray to each light, intersected analytically with every
//! exact surface. The reference's shadows, the judge of the shadow maps; and where a map's
//! filtered lookup is partly lit, the answer exact shadow edges take.

use super::caster_spheres::MOST_SPHERES;
use super::casting::{can_shadow, object_can_shadow_itself};
use crate::scene::PreparedScene;
use crate::scene::{Camera, Light, Scene};
use crate::shade::Shadowing;
use crate::surface::Surface;
use crate::surface::{Ray, intersect};
use glam::{DVec3, Vec3};

/// How far a shadow ray starts off its surface, relative to the point's distance from the eye
/// (plus one unit): past the f32 rounding of the shaded point, far below a pixel.
const START_OFF_SURFACE: f64 = 1e-4;
/// The cosine below which light grazes a surface (about 6°): there a receiver's depth and the
/// map's depth of the same surface differ by less than the map's own spread of depth in a texel.
pub(super) const GRAZING: f32 = 0.1;
/// How far a shadow ray towards a directional light looks: past any scene (finite, as the
/// intersections clip to boxes).
const DIRECTIONAL_REACH: f64 = 1e12;

/// Whether exact rays shadow `scene` for less than maps would: every object is a sphere, plane or
/// triangle, which a ray meets in closed form and which shadows itself only where a sphere is
/// seen from within, and they are few enough to test one by one (each point is first tested
/// against their spheres, all of them, which settles nearly every point a map lookup would
/// have settled).
pub fn rays_cheaper_than_maps(scene: &Scene) -> bool {
    scene.objects.len() <= MOST_SPHERES
        && scene.objects.iter().all(|o| !object_can_shadow_itself(o))
}

/// Shadow rays through the exact scene, for points relative to one camera's eye.
pub struct ShadowRays {
    eye: DVec3,
    lights: Vec<Light>,
    surfaces: Vec<Surface>,
    /// Per light, the surfaces (by index) a ray towards it is tested against.
    casting: Vec<Vec<usize>>,
}

impl ShadowRays {
    /// Rays tested against every surface: the reference's. `None` where the scene has shadows
    /// off or nothing in it can shadow anything.
    pub fn new(prepared: &PreparedScene, camera: &Camera) -> Option<ShadowRays> {
        let every = (0..prepared.objects.len()).collect::<Vec<_>>();
        let casting = vec![every; prepared.scene.lights.len()];
        ShadowRays::against(prepared, camera, casting)
    }

    /// Rays towards each light tested only against `casting[light]`: the objects that can
    /// cast a shadow from it onto anything (`casters`).
    pub fn against(
        prepared: &PreparedScene,
        camera: &Camera,
        casting: Vec<Vec<usize>>,
    ) -> Option<ShadowRays> {
        let scene = &prepared.scene;
        (scene.shadows && can_shadow(scene)).then(|| ShadowRays {
            eye: camera.eye,
            lights: scene.lights.clone(),
            surfaces: prepared.objects.iter().map(|o| o.surface.clone()).collect(),
            casting,
        })
    }

    /// Whether anything but object `except` lies between the camera-relative point `p` (on a
    /// surface whose facing normal is `n`) and light `light`.
    pub fn blocked_at(&self, light: usize, p: Vec3, n: Vec3, except: Option<usize>) -> bool {
        let lift = START_OFF_SURFACE * (1.0 + f64::from(p.length()));
        let from = self.eye + p.as_dvec3() + n.as_dvec3() * lift;
        self.blocked(light, from, except)
    }

    /// Whether anything but object `except` lies between the world point `from` and light
    /// `light`.
    fn blocked(&self, light: usize, from: DVec3, except: Option<usize>) -> bool {
        let (direction, distance) = match self.lights[light] {
            Light::Point { position, .. } => {
                let to = position - from;
                (to.normalize(), to.length())
            }
            Light::Directional { towards, .. } => (
                crate::surface::normalize_or(towards, Vec3::Y).as_dvec3(),
                DIRECTIONAL_REACH,
            ),
        };
        if !direction.is_finite() {
            return false;
        }
        let mut casting = self.casting[light].iter().filter(|&&i| Some(i) != except);
        casting.any(|&index| {
            let surface = &self.surfaces[index];
            let ray = Ray {
                origin: from - surface.origin(),
                direction,
            };
            intersect(surface, &ray, 0.0..=distance).is_some()
        })
    }
}

impl Shadowing for ShadowRays {
    fn casts(&self, light: usize) -> bool {
        light < self.lights.len()
    }

    fn reaching(
        &self,
        light: usize,
        _object: usize,
        points: &[Vec3],
        normals: &[Vec3],
        out: &mut [f32],
    ) {
        for ((out, &p), &n) in out.iter_mut().zip(points).zip(normals) {
            *out = if self.blocked_at(light, p, n, None) {
                0.0
            } else {
                1.0
            };
        }
    }
}
