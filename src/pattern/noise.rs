//! Value noise on the integer lattice: hashed corner values in [-1, 1], blended with the quintic
//! fade 6t⁵−15t⁴+10t³ (C2, so the bump normals it makes are continuous). Deterministic; returns the
//! exact gradient along with the value.

/// Noise value and its partials (∂/∂x, ∂/∂y).
pub fn noise2(x: f64, y: f64) -> (f64, f64, f64) {
    let (ix, fx) = split(x);
    let (iy, fy) = split(y);
    let (u, du) = fade(fx);
    let (v, dv) = fade(fy);
    let a = corner(ix, iy, 0);
    let b = corner(ix + 1, iy, 0);
    let c = corner(ix, iy + 1, 0);
    let d = corner(ix + 1, iy + 1, 0);
    let k = a - b - c + d;
    let value = a + (b - a) * u + (c - a) * v + k * u * v;
    (value, du * ((b - a) + k * v), dv * ((c - a) + k * u))
}

/// Noise value and its partials (∂/∂x, ∂/∂y, ∂/∂z).
pub fn noise3(x: f64, y: f64, z: f64) -> (f64, [f64; 3]) {
    let (ix, fx) = split(x);
    let (iy, fy) = split(y);
    let (iz, fz) = split(z);
    let (u, du) = fade(fx);
    let (v, dv) = fade(fy);
    let (w, dw) = fade(fz);
    let h = |dx: i64, dy: i64, dz: i64| corner(ix + dx, iy + dy, iz + dz);
    let (a, b, c, d) = (h(0, 0, 0), h(1, 0, 0), h(0, 1, 0), h(1, 1, 0));
    let (e, f, g, k) = (h(0, 0, 1), h(1, 0, 1), h(0, 1, 1), h(1, 1, 1));
    // Trilinear blend written as a polynomial in (u, v, w), so its partials are direct.
    let k1 = b - a;
    let k2 = c - a;
    let k3 = e - a;
    let k4 = a - b - c + d;
    let k5 = a - c - e + g;
    let k6 = a - b - e + f;
    let k7 = -a + b + c - d + e - f - g + k;
    let value =
        a + k1 * u + k2 * v + k3 * w + k4 * u * v + k5 * v * w + k6 * w * u + k7 * u * v * w;
    let gradient = [
        du * (k1 + k4 * v + k6 * w + k7 * v * w),
        dv * (k2 + k4 * u + k5 * w + k7 * u * w),
        dw * (k3 + k5 * v + k6 * u + k7 * u * v),
    ];
    (value, gradient)
}

/// Beyond this the lattice stops: every coordinate past ±2⁶² falls in the last cell, so `cell + 1`
/// cannot overflow (found by fuzzing: a plain `as i64` saturates at 2⁶³ − 1 and the next corner
/// overflowed).
const LAST_CELL: f64 = (1u64 << 62) as f64;

/// Lattice cell and position inside it. Coordinates beyond ±2⁶² share cells; noise there is
/// still finite.
pub(super) fn split(x: f64) -> (i64, f64) {
    let cell = x.floor();
    (cell.clamp(-LAST_CELL, LAST_CELL) as i64, x - cell)
}

fn fade(t: f64) -> (f64, f64) {
    let value = t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
    let slope = 30.0 * t * t * (t - 1.0) * (t - 1.0);
    (value, slope)
}

/// Pseudo-random value in [-1, 1] for a lattice corner.
fn corner(x: i64, y: i64, z: i64) -> f64 {
    (lattice_hash(x, y, z, 0) >> 11) as f64 / (1u64 << 52) as f64 - 1.0
}

/// 64 pseudo-random bits for a lattice point; `stream` gives each user of the lattice bits
/// of its own.
pub(super) fn lattice_hash(x: i64, y: i64, z: i64, stream: u64) -> u64 {
    let mut h = (x as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15)
        ^ (y as u64).wrapping_mul(0xC2B2_AE3D_27D4_EB4F)
        ^ (z as u64).wrapping_mul(0x1656_67B1_9E37_79F9)
        ^ stream.wrapping_mul(0xD6E8_FEB8_6659_FD93);
    // splitmix64 finaliser: every input bit affects every output bit.
    h = (h ^ (h >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    h = (h ^ (h >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    h ^ (h >> 31)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_stay_in_range_and_are_deterministic() {
        for i in 0..1000 {
            let (x, y) = (i as f64 * 0.37 - 100.0, i as f64 * 0.11);
            let (n, _, _) = noise2(x, y);
            assert!((-1.0..=1.0).contains(&n));
            assert_eq!(noise2(x, y).0, n);
        }
    }

    #[test]
    fn finite_past_the_end_of_the_lattice() {
        for x in [9.3e18, -9.3e18, 1.0e19, 3.0e38, f64::MAX, -f64::MAX] {
            let (value, du, dv) = noise2(x, -x);
            assert!((-1.0..=1.0).contains(&value) && du.is_finite() && dv.is_finite());
            let (value, gradient) = noise3(x, x, -x);
            assert!((-1.0..=1.0).contains(&value) && gradient.iter().all(|g| g.is_finite()));
        }
    }

    #[test]
    fn gradient_matches_central_difference() {
        let h = 1e-6;
        for i in 0..200 {
            let (x, y, z) = (
                i as f64 * 0.173 - 7.0,
                i as f64 * 0.291,
                3.0 - i as f64 * 0.07,
            );
            let (_, gx, gy) = noise2(x, y);
            assert!((gx - (noise2(x + h, y).0 - noise2(x - h, y).0) / (2.0 * h)).abs() < 1e-5);
            assert!((gy - (noise2(x, y + h).0 - noise2(x, y - h).0) / (2.0 * h)).abs() < 1e-5);
            let (_, g) = noise3(x, y, z);
            let fd = (noise3(x, y, z + h).0 - noise3(x, y, z - h).0) / (2.0 * h);
            assert!((g[2] - fd).abs() < 1e-5);
        }
    }

    #[test]
    fn continuous_across_cell_boundaries() {
        let e = 1e-9;
        for i in -5..5 {
            let x = i as f64;
            assert!((noise2(x - e, 0.3).0 - noise2(x + e, 0.3).0).abs() < 1e-6);
            assert!((noise3(0.2, x - e, 0.7).0 - noise3(0.2, x + e, 0.7).0).abs() < 1e-6);
        }
    }
}
