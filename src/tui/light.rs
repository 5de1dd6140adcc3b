//! Moving the scene's lights: each turns about the vertical axis through the orbit target and
//! rises or sinks towards the pole, keeping its distance.

use crate::scene::Light;
use glam::DVec3;

const MAX_ELEVATION: f64 = 89.0_f64.to_radians();

/// Turns every light by `azimuth_degrees` about +y and raises it by `elevation_degrees`.
pub fn move_lights(
    lights: &mut [Light],
    center: DVec3,
    azimuth_degrees: f64,
    elevation_degrees: f64,
) {
    for light in lights {
        match light {
            Light::Point { position, .. } => {
                *position = center + turn(*position - center, azimuth_degrees, elevation_degrees);
            }
            Light::Directional { towards, .. } => {
                let turned = turn(towards.as_dvec3(), azimuth_degrees, elevation_degrees);
                *towards = turned.as_vec3();
            }
        }
    }
}

fn turn(offset: DVec3, azimuth_degrees: f64, elevation_degrees: f64) -> DVec3 {
    let radius = offset.length();
    if radius == 0.0 || !radius.is_finite() {
        return offset;
    }
    let azimuth = offset.x.atan2(offset.z) + azimuth_degrees.to_radians();
    let elevation = ((offset.y / radius).clamp(-1.0, 1.0).asin() + elevation_degrees.to_radians())
        .clamp(-MAX_ELEVATION, MAX_ELEVATION);
    let (sin_a, cos_a) = azimuth.sin_cos();
    let (sin_e, cos_e) = elevation.sin_cos();
    DVec3::new(sin_a * cos_e, sin_e, cos_a * cos_e) * radius
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    #[test]
    fn turning_keeps_distance_and_a_full_turn_returns() {
        let start = DVec3::new(-400.0, 600.0, 500.0);
        let mut lights = [Light::Point {
            position: start,
            color: Vec3::ONE,
        }];
        for _ in 0..24 {
            move_lights(&mut lights, DVec3::ZERO, 15.0, 0.0);
        }
        let Light::Point { position, .. } = lights[0] else {
            unreachable!()
        };
        assert!((position - start).length() < 1e-6, "{position}");
    }
}
