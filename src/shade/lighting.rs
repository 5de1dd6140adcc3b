use crate::scene::{Light, Material};
use glam::{DVec3, Vec3};

/// The scene's lights for one frame, moved into camera-relative space (eye at the origin).
#[derive(Clone, Debug)]
pub struct FrameLights {
    pub ambient: Vec3,
    pub lights: Vec<RelativeLight>,
}

#[derive(Clone, Copy, Debug)]
pub enum RelativeLight {
    Point {
        position: Vec3,
        color: Vec3,
    },
    /// `towards` is the unit vector from the surface to the light.
    Directional {
        towards: Vec3,
        color: Vec3,
    },
}

impl FrameLights {
    pub fn new(ambient: Vec3, lights: &[Light], eye: DVec3) -> FrameLights {
        let lights = lights
            .iter()
            .map(|light| match *light {
                Light::Point { position, color } => RelativeLight::Point {
                    position: (position - eye).as_vec3(),
                    color,
                },
                Light::Directional { towards, color } => RelativeLight::Directional {
                    towards: crate::surface::normalize_or(towards, Vec3::Y),
                    color,
                },
            })
            .collect();
        FrameLights { ambient, lights }
    }
}

/// Turns a normal to the side of the surface the viewer sees: open surfaces are lit on whichever
/// side is seen. Decide with the geometric normal and apply the same flip to a bumped one.
#[inline]
pub fn facing_sign(p: Vec3, geometric_normal: Vec3) -> f32 {
    if geometric_normal.dot(-p) < 0.0 {
        -1.0
    } else {
        1.0
    }
}

/// Blinn-Phong in linear light at camera-relative point `p` with unit normal `n` (already facing
/// the viewer) and diffuse colour `color`.
#[inline]
pub fn blinn_phong(
    lights: &FrameLights,
    material: &Material,
    color: Vec3,
    p: Vec3,
    n: Vec3,
) -> Vec3 {
    let to_eye = crate::surface::normalize_or(-p, n);
    let mut diffuse = lights.ambient;
    let mut specular = Vec3::ZERO;
    for light in &lights.lights {
        let (to_light, color) = match *light {
            RelativeLight::Point { position, color } => {
                (crate::surface::normalize_or(position - p, n), color)
            }
            RelativeLight::Directional { towards, color } => (towards, color),
        };
        let lambert = n.dot(to_light);
        if lambert <= 0.0 {
            continue;
        }
        diffuse += color * lambert;
        let half = crate::surface::normalize_or(to_light + to_eye, n);
        specular += color * power(n.dot(half).max(0.0), material.shininess);
    }
    color * diffuse + specular * material.specular
}

/// x^exponent; whole exponents (the usual case) by repeated squaring inline, several times
/// faster than `powf` (and than the `powi` library call), equal to within rounding.
#[inline]
fn power(x: f32, exponent: f32) -> f32 {
    if !(exponent.fract() == 0.0 && (0.0..=1024.0).contains(&exponent)) {
        return x.powf(exponent);
    }
    let (mut base, mut n, mut result) = (x, exponent as u32, 1.0f32);
    while n > 0 {
        if n & 1 == 1 {
            result *= base;
        }
        base *= base;
        n >>= 1;
    }
    result
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn power_agrees_with_powf() {
        for exponent in [0.0, 1.0, 2.0, 7.0, 32.0, 40.0, 1024.0, 2.5, 1500.0] {
            for x in [0.0f32, 0.3, 0.9, 0.999, 1.0] {
                let (got, want) = (power(x, exponent), x.powf(exponent));
                assert!(
                    (got - want).abs() <= 1e-5 * want.max(1e-30) + 1e-30,
                    "{x}^{exponent}: {got} vs {want}"
                );
            }
        }
    }

    fn material() -> Material {
        Material {
            color: Vec3::new(0.8, 0.4, 0.2),
            specular: 0.5,
            shininess: 20.0,
            ..Material::default()
        }
    }

    #[test]
    fn a_head_on_light_gives_full_diffuse_plus_specular() {
        let lights = FrameLights::new(
            Vec3::ZERO,
            &[Light::Directional {
                towards: Vec3::Z,
                color: Vec3::ONE,
            }],
            DVec3::ZERO,
        );
        let c = blinn_phong(
            &lights,
            &material(),
            material().color,
            Vec3::new(0.0, 0.0, -10.0),
            Vec3::Z,
        );
        assert!(
            (c - (material().color + Vec3::splat(0.5))).length() < 1e-5,
            "{c:?}"
        );
    }

    #[test]
    fn lights_behind_the_surface_add_nothing_and_back_sides_are_lit() {
        let lights = FrameLights::new(
            Vec3::splat(0.1),
            &[Light::Point {
                position: DVec3::new(0.0, 0.0, -20.0),
                color: Vec3::ONE,
            }],
            DVec3::ZERO,
        );
        // The normal points away from the eye: it is flipped, and the light is then behind.
        let p = Vec3::new(0.0, 0.0, -10.0);
        let n = Vec3::Z * facing_sign(p, Vec3::Z);
        let c = blinn_phong(&lights, &material(), material().color, p, n);
        assert!((c - material().color * 0.1).length() < 1e-6, "{c:?}");
    }
}
