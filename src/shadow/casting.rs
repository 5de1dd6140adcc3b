//! Which objects can cast a shadow from a light onto anything: a map holds only those, so it is
//! fitted to them alone (a floor under everything casts nothing and takes no texels).

use super::bounds::Bounds;
use crate::scene::PreparedScene;
use crate::scene::{Bump, Light, Object, Scene};
use crate::surface::Surface;
use glam::{DVec3, Vec3};

/// Whether a shadow can fall anywhere in the scene. One sphere, plane or triangle alone cannot
/// shadow itself (its own back side is already turned from the light), unless the camera is
/// inside the sphere; a bowl, a cone's inside or a wave can, and any two objects can shadow each
/// other.
pub fn can_shadow(scene: &Scene) -> bool {
    if scene.lights.is_empty() {
        return false;
    }
    match scene.objects.as_slice() {
        [] => false,
        [only] => object_can_shadow_itself(only) || seen_from_within(&only.surface, scene),
        _ => true,
    }
}

/// `can_shadow_itself` for a scene's object: a displaced one's bumps can shadow each other.
pub(super) fn object_can_shadow_itself(object: &Object) -> bool {
    let displaced = object.displace && object.material.bump.as_ref().is_some_and(Bump::has_height);
    displaced || can_shadow_itself(&object.surface)
}

/// Whether a surface can stand between a light and another part of itself, seen from outside.
/// A sphere cannot (where it turns from the light it is already dark), nor can anything flat.
pub(super) fn can_shadow_itself(surface: &Surface) -> bool {
    !matches!(
        surface,
        Surface::Sphere(_) | Surface::Plane(_) | Surface::Triangle(_)
    )
}

/// Whether the camera is inside a sphere: seen from within, one part of it can stand between
/// another and the light.
fn seen_from_within(surface: &Surface, scene: &Scene) -> bool {
    match surface {
        Surface::Sphere(s) => s.center.distance(scene.camera.eye) < f64::from(s.radius),
        _ => false,
    }
}

/// When a receiver may be left out of its own shadow test.
#[derive(Clone, Copy, Debug)]
pub(super) enum SelfShadowing {
    /// It can shadow itself (a cone, a bowl, a wave).
    Possible,
    /// Never: it is flat.
    Never,
    /// A sphere (its camera-relative centre): never where its outside is seen. Seen from within,
    /// the rest of it can stand between a point and the light.
    WhereOutsideSeen(Vec3),
}

impl SelfShadowing {
    pub(super) fn of(surface: &Surface, eye: DVec3) -> SelfShadowing {
        match surface {
            Surface::Sphere(s) => SelfShadowing::WhereOutsideSeen((s.center - eye).as_vec3()),
            _ if can_shadow_itself(surface) => SelfShadowing::Possible,
            _ => SelfShadowing::Never,
        }
    }

    /// `object`, where none of the camera-relative `points` (with normals facing the viewer)
    /// can be shadowed by the object it lies on, so a shadow test of them may leave it out.
    pub(super) fn left_out(
        self,
        object: usize,
        points: &[Vec3],
        normals: &[Vec3],
    ) -> Option<usize> {
        let outside_seen = |centre: Vec3| {
            let mut seen = points.iter().zip(normals);
            seen.all(|(&p, &n)| n.dot(p - centre) >= 0.0)
        };
        match self {
            SelfShadowing::Possible => None,
            SelfShadowing::Never => Some(object),
            SelfShadowing::WhereOutsideSeen(centre) => outside_seen(centre).then_some(object),
        }
    }
}

/// The objects that may cast a shadow from `light` onto any object, by index, given each
/// object's box. A flat object casts only onto what reaches past its plane on the side away
/// from the light; a curved one onto itself or anything else.
pub fn casters(prepared: &PreparedScene, boxes: &[Option<Bounds>], light: &Light) -> Vec<usize> {
    let others = |index: usize| {
        boxes
            .iter()
            .enumerate()
            .filter(move |(other, b)| *other != index && b.is_some())
            .filter_map(|(_, b)| *b)
    };
    (0..prepared.objects.len())
        .filter(|&index| {
            let surface = &prepared.objects[index].surface;
            match flat_plane(surface) {
                Some((point, normal)) => {
                    let lit_side = match *light {
                        Light::Point { position, .. } => normal.dot(position - point),
                        Light::Directional { towards, .. } => normal.dot(towards.as_dvec3()),
                    };
                    // Past the plane by more than the box's own rounding (a sphere resting on a
                    // floor touches it, its box grown by its chord error).
                    let beyond = |b: Bounds| {
                        let tolerance = 1e-3 * b.min.distance(b.max);
                        let side = lit_side.signum();
                        b.corners()
                            .iter()
                            .any(|c| normal.dot(*c - point) * side < -tolerance)
                    };
                    others(index).any(beyond)
                }
                None => {
                    can_shadow_itself(surface)
                        || seen_from_within(surface, &prepared.scene)
                        || others(index).next().is_some()
                }
            }
        })
        .collect()
}

/// A point on a flat surface's plane and its normal.
fn flat_plane(surface: &Surface) -> Option<(DVec3, DVec3)> {
    match surface {
        Surface::Plane(s) => Some((s.origin, s.normal.as_dvec3())),
        Surface::Triangle(s) => Some((s.a, s.normal.as_dvec3())),
        _ => None,
    }
}
