//! The seed's angle units: a full turn is 720 units, so its dimple period of 30 looks right on
//! a sphere; and the azimuth (u) of the surfaces of revolution, both ways.

use std::f32::consts::{FRAC_PI_2, PI};

/// Seed units per radian: the seed scales its sphere angles by 360/π, so a full turn of azimuth
/// is 720 units and pole to pole is 360.
pub const SEED_UNITS_PER_RADIAN: f32 = 360.0 / PI;

/// `SEED_UNITS_PER_RADIAN` in f64, for the exact (u,v) of ray hits.
pub const SEED_UNITS_PER_RADIAN_F64: f64 = 360.0 / std::f64::consts::PI;

/// The azimuth φ of the seed's `uu = (π/2 + atan(x/z))·360/π`, so that x = sin φ, z = cos φ.
#[inline(always)]
pub fn azimuth(u: f32) -> f32 {
    u / SEED_UNITS_PER_RADIAN - PI / 2.0
}

/// The seed's u of a direction whose components along the azimuth's sine and cosine axes are
/// (x, z): u = (atan2(x, z) + π/2)·360/π, wrapped into [0, 720). The inverse of `azimuth`.
pub fn azimuth_u(x: f64, z: f64) -> f32 {
    let quarter_turn = std::f64::consts::FRAC_PI_2;
    let u = ((x.atan2(z) + quarter_turn) * SEED_UNITS_PER_RADIAN_F64).rem_euclid(720.0);
    // rem_euclid can round up to exactly 720 for a tiny negative input.
    (u as f32).min(720.0f32.next_down())
}

/// `azimuth_u` in f32 without library calls (`atan2` within 3e-7 rad), branch-free so batches
/// of it vectorise.
#[inline(always)]
pub fn azimuth_u_f32(x: f32, z: f32) -> f32 {
    let u = (super::atan2(x, z) + FRAC_PI_2) * SEED_UNITS_PER_RADIAN;
    let u = if u < 0.0 { u + 720.0 } else { u };
    u.min(720.0f32.next_down())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn both_inverses_undo_the_azimuth() {
        for u in [0.0f32, 0.3, 179.0, 360.0, 541.5, 719.9] {
            let (sin_phi, cos_phi) = super::super::sin_cos(azimuth(u));
            // Either side of the seam is the same azimuth.
            let apart = |back: f32| (back - u).abs().min(720.0 - (back - u).abs());
            let back = azimuth_u_f32(sin_phi, cos_phi);
            assert!(apart(back) < 1e-3, "{u} → {back}");
            let back = azimuth_u(sin_phi as f64, cos_phi as f64);
            assert!(apart(back) < 1e-3, "{u} → {back}");
            assert!((0.0..720.0).contains(&back));
        }
    }
}
