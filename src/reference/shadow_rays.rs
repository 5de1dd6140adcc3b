//! Exact shadows: from each shaded point a ray to each light, intersected analytically with every
//! exact surface. The judge of the rasterizer's shadow maps, as the view rays are of its meshes.

use super::intersect::intersect;
use super::ray::Ray;
use crate::quality::Quality;
use crate::raster::PreparedScene;
use crate::scene::{Camera, Light};
use crate::shade::{LitShader, Shadowing};
use crate::shadow::can_shadow;
use crate::surface::Surface;
use glam::{DVec3, Vec3};
use std::sync::Arc;

/// How far a shadow ray starts off its surface, relative to the point's distance from the eye
/// (plus one unit): past the f32 rounding of the shaded point, far below a pixel.
const START_OFF_SURFACE: f64 = 1e-4;
/// How far a shadow ray towards a directional light looks: past any scene (finite, as the
/// intersections clip to boxes).
const DIRECTIONAL_REACH: f64 = 1e12;

/// The reference's fragment program: the `exact` preset's shading, and exact shadow rays where
/// the scene has shadows.
pub fn exact_shader(prepared: &PreparedScene, camera: &Camera) -> LitShader {
    let mut shader = LitShader::new(&prepared.scene, camera);
    Quality::exact().configure(&mut shader, prepared);
    shader.shadows =
        ShadowRays::new(prepared, camera).map(|rays| Arc::new(rays) as Arc<dyn Shadowing>);
    shader
}

/// Shadow rays through the exact scene, for points relative to one camera's eye.
pub struct ShadowRays {
    eye: DVec3,
    lights: Vec<Light>,
    surfaces: Vec<Surface>,
}

impl ShadowRays {
    /// `None` where the scene has shadows off or nothing in it can shadow anything.
    pub fn new(prepared: &PreparedScene, camera: &Camera) -> Option<ShadowRays> {
        let scene = &prepared.scene;
        (scene.shadows && can_shadow(scene)).then(|| ShadowRays {
            eye: camera.eye,
            lights: scene.lights.clone(),
            surfaces: prepared.objects.iter().map(|o| o.surface.clone()).collect(),
        })
    }

    /// Whether anything lies between the world point `from` and the light.
    fn blocked(&self, light: &Light, from: DVec3) -> bool {
        let (direction, distance) = match *light {
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
        self.surfaces.iter().any(|surface| {
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
        let light = &self.lights[light];
        for ((out, &p), &n) in out.iter_mut().zip(points).zip(normals) {
            let lift = START_OFF_SURFACE * (1.0 + f64::from(p.length()));
            let from = self.eye + p.as_dvec3() + n.as_dvec3() * lift;
            *out = if self.blocked(light, from) { 0.0 } else { 1.0 };
        }
    }
}
