//! Whether anything in a scene can shadow anything: not where the scene is one convex surface.

use crate::scene::Scene;
use crate::surface::Surface;

/// Whether a shadow can fall anywhere in the scene. One sphere, plane or triangle alone cannot
/// shadow itself (its own back side is already turned from the light); a bowl, a cone's inside
/// or a wave can, and any two objects can shadow each other.
pub fn can_shadow(scene: &Scene) -> bool {
    if scene.lights.is_empty() {
        return false;
    }
    match scene.objects.as_slice() {
        [] => false,
        [only] => !matches!(
            only.surface,
            Surface::Sphere(_) | Surface::Plane(_) | Surface::Triangle(_)
        ),
        _ => true,
    }
}
