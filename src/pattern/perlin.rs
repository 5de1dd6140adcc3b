//! Gradient noise: Ken Perlin's improved noise (SIGGRAPH 2002), with his permutation and his
//! twelve cube-edge gradients, so `perlin(x, y, z)` gives the values of his reference code. The
//! value and its exact gradient are worked out together. Two-dimensional noise is the
//! three-dimensional one at z = 0. All in f64: the lattice position needs its fraction exact.

/// Perlin's permutation of 0..=255; lattice corners hash through it, wrapping every 256 cells.
pub(super) const PERMUTATION: [u8; 256] = [
    151, 160, 137, 91, 90, 15, 131, 13, 201, 95, 96, 53, 194, 233, 7, 225, 140, 36, 103, 30, 69,
    142, 8, 99, 37, 240, 21, 10, 23, 190, 6, 148, 247, 120, 234, 75, 0, 26, 197, 62, 94, 252, 219,
    203, 117, 35, 11, 32, 57, 177, 33, 88, 237, 149, 56, 87, 174, 20, 125, 136, 171, 168, 68, 175,
    74, 165, 71, 134, 139, 48, 27, 166, 77, 146, 158, 231, 83, 111, 229, 122, 60, 211, 133, 230,
    220, 105, 92, 41, 55, 46, 245, 40, 244, 102, 143, 54, 65, 25, 63, 161, 1, 216, 80, 73, 209, 76,
    132, 187, 208, 89, 18, 169, 200, 196, 135, 130, 116, 188, 159, 86, 164, 100, 109, 198, 173,
    186, 3, 64, 52, 217, 226, 250, 124, 123, 5, 202, 38, 147, 118, 126, 255, 82, 85, 212, 207, 206,
    59, 227, 47, 16, 58, 17, 182, 189, 28, 42, 223, 183, 170, 213, 119, 248, 152, 2, 44, 154, 163,
    70, 221, 153, 101, 155, 167, 43, 172, 9, 129, 22, 39, 253, 19, 98, 108, 110, 79, 113, 224, 232,
    178, 185, 112, 104, 218, 246, 97, 228, 251, 34, 242, 193, 238, 210, 144, 12, 191, 179, 162,
    241, 81, 51, 145, 235, 249, 14, 239, 107, 49, 192, 214, 31, 181, 199, 106, 157, 184, 84, 204,
    176, 115, 121, 50, 45, 127, 4, 150, 254, 138, 236, 205, 93, 222, 114, 67, 29, 24, 72, 243, 141,
    128, 195, 78, 66, 215, 61, 156, 180,
];

/// A value and its gradient.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Graded<const D: usize> {
    pub value: f64,
    pub gradient: [f64; D],
}

/// Noise at (x, y, z), in about −1..1, with its partials.
pub fn perlin3(x: f64, y: f64, z: f64) -> Graded<3> {
    let lattice = [cell(x), cell(y), cell(z)];
    let near = layer(lattice, 0);
    let far = layer(lattice, 1);
    lerp(fade(lattice[2].1), 2, near, far)
}

/// Noise at (x, y), with its partials: that at z = 0, where the far layer's weight and slope
/// are both 0, so only the near layer's four corners are needed.
pub fn perlin2(x: f64, y: f64) -> Graded<2> {
    let Graded { value, gradient } = layer([cell(x), cell(y), (0, 0.0)], 0);
    Graded {
        value,
        gradient: [gradient[0], gradient[1]],
    }
}

/// The four corners of the lattice cell at z offset `dz` (0 or 1), blended along x and y.
fn layer(lattice: [(usize, f64); 3], dz: usize) -> Graded<3> {
    let [(ix, fx), (iy, fy), (iz, fz)] = lattice;
    let (a, b) = (hash(ix) + iy, hash(ix + 1) + iy);
    let (aa, ab) = (hash(a) + iz + dz, hash(a + 1) + iz + dz);
    let (ba, bb) = (hash(b) + iz + dz, hash(b + 1) + iz + dz);
    let z = fz - dz as f64;
    let corner = |h: usize, dx: f64, dy: f64| dot(hash(h), [fx - dx, fy - dy, z]);
    let along_x =
        |h0: usize, h1: usize, dy: f64| lerp(fade(fx), 0, corner(h0, 0.0, dy), corner(h1, 1.0, dy));
    lerp(fade(fy), 1, along_x(aa, ba, 0.0), along_x(ab, bb, 1.0))
}

/// The lattice cell, wrapped to the permutation's 256, and the position inside it. Java's
/// `(int)` saturates where `as i64` does not, so the two agree for |x| < 2³¹ (and both give a
/// finite value everywhere else).
fn cell(x: f64) -> (usize, f64) {
    let floor = x.floor();
    ((floor as i64 & 255) as usize, x - floor)
}

fn hash(i: usize) -> usize {
    usize::from(PERMUTATION[i & 255])
}

/// Perlin's sixteen gradients, by the low four bits of a hash: the axes of his `u` and `v`
/// and their signs (`grad` in his code), as a table so no branch depends on the hash.
const GRADIENTS: [(usize, usize, f64, f64); 16] = {
    let mut table = [(0, 0, 0.0, 0.0); 16];
    let mut h = 0;
    while h < 16 {
        let u_axis = if h < 8 { 0 } else { 1 };
        let v_axis = if h < 4 {
            1
        } else if h == 12 || h == 14 {
            0
        } else {
            2
        };
        let u_sign = if h & 1 == 0 { 1.0 } else { -1.0 };
        let v_sign = if h & 2 == 0 { 1.0 } else { -1.0 };
        table[h] = (u_axis, v_axis, u_sign, v_sign);
        h += 1;
    }
    table
};

/// Perlin's `grad`: the dot product of the hashed gradient with the offset from the corner,
/// with that gradient as its own.
fn dot(hash: usize, offset: [f64; 3]) -> Graded<3> {
    let (u_axis, v_axis, u_sign, v_sign) = GRADIENTS[hash & 15];
    let mut gradient = [0.0; 3];
    gradient[u_axis] = u_sign;
    gradient[v_axis] = v_sign;
    Graded {
        value: u_sign * offset[u_axis] + v_sign * offset[v_axis],
        gradient,
    }
}

/// `a + t·(b − a)` where `t = (weight, its slope along axis)`.
fn lerp(t: (f64, f64), axis: usize, a: Graded<3>, b: Graded<3>) -> Graded<3> {
    let (weight, slope) = t;
    let mut gradient = [0.0; 3];
    for (k, g) in gradient.iter_mut().enumerate() {
        *g = a.gradient[k] + weight * (b.gradient[k] - a.gradient[k]);
    }
    gradient[axis] += slope * (b.value - a.value);
    Graded {
        value: a.value + weight * (b.value - a.value),
        gradient,
    }
}

/// Perlin's quintic 6t⁵ − 15t⁴ + 10t³ and its slope.
fn fade(t: f64) -> (f64, f64) {
    (
        t * t * t * (t * (t * 6.0 - 15.0) + 10.0),
        30.0 * t * t * (t - 1.0) * (t - 1.0),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Perlin's published reference `ImprovedNoise.noise`, transcribed line for line (value
    /// only), with his doubled table.
    fn reference(mut x: f64, mut y: f64, mut z: f64) -> f64 {
        let p: Vec<usize> = (0..512)
            .map(|i| usize::from(PERMUTATION[i % 256]))
            .collect();
        let fade = |t: f64| t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
        let lerp = |t: f64, a: f64, b: f64| a + t * (b - a);
        let grad = |hash: usize, x: f64, y: f64, z: f64| {
            let h = hash & 15;
            let u = if h < 8 { x } else { y };
            let v = if h < 4 {
                y
            } else if h == 12 || h == 14 {
                x
            } else {
                z
            };
            (if h & 1 == 0 { u } else { -u }) + (if h & 2 == 0 { v } else { -v })
        };
        let big_x = (x.floor() as i32 & 255) as usize;
        let big_y = (y.floor() as i32 & 255) as usize;
        let big_z = (z.floor() as i32 & 255) as usize;
        x -= x.floor();
        y -= y.floor();
        z -= z.floor();
        let (u, v, w) = (fade(x), fade(y), fade(z));
        let a = p[big_x] + big_y;
        let aa = p[a] + big_z;
        let ab = p[a + 1] + big_z;
        let b = p[big_x + 1] + big_y;
        let ba = p[b] + big_z;
        let bb = p[b + 1] + big_z;
        lerp(
            w,
            lerp(
                v,
                lerp(u, grad(p[aa], x, y, z), grad(p[ba], x - 1.0, y, z)),
                lerp(
                    u,
                    grad(p[ab], x, y - 1.0, z),
                    grad(p[bb], x - 1.0, y - 1.0, z),
                ),
            ),
            lerp(
                v,
                lerp(
                    u,
                    grad(p[aa + 1], x, y, z - 1.0),
                    grad(p[ba + 1], x - 1.0, y, z - 1.0),
                ),
                lerp(
                    u,
                    grad(p[ab + 1], x, y - 1.0, z - 1.0),
                    grad(p[bb + 1], x - 1.0, y - 1.0, z - 1.0),
                ),
            ),
        )
    }

    fn points() -> impl Iterator<Item = [f64; 3]> {
        (0..3000).map(|i| {
            let i = i as f64;
            [i * 0.173 - 260.0, 300.0 - i * 0.291, (i * 0.7).sin() * 40.0]
        })
    }

    #[test]
    fn the_table_is_a_permutation() {
        let mut seen = [false; 256];
        PERMUTATION
            .iter()
            .for_each(|&p| seen[usize::from(p)] = true);
        assert!(seen.iter().all(|&s| s));
    }

    #[test]
    fn values_are_perlins_reference_bit_for_bit() {
        let lattice = (-3..4).map(|i| [f64::from(i), 0.5, f64::from(-i)]);
        for [x, y, z] in points().chain(lattice) {
            let ours = perlin3(x, y, z).value;
            assert_eq!(
                ours.to_bits(),
                reference(x, y, z).to_bits(),
                "at {x}, {y}, {z}"
            );
            assert!(ours.abs() <= 1.1, "{ours} at {x}, {y}, {z}");
        }
    }

    #[test]
    fn gradients_match_central_differences() {
        let h = 1e-6;
        for point in points() {
            let exact = perlin3(point[0], point[1], point[2]).gradient;
            for axis in 0..3 {
                let at = |d: f64| {
                    let mut p = point;
                    p[axis] += d;
                    perlin3(p[0], p[1], p[2]).value
                };
                let difference = (at(h) - at(-h)) / (2.0 * h);
                assert!(
                    (exact[axis] - difference).abs() < 1e-6,
                    "axis {axis} at {point:?}: {} vs {difference}",
                    exact[axis]
                );
            }
        }
    }

    #[test]
    fn the_plane_noise_is_the_volume_noise_at_z_zero_and_zero_on_the_lattice() {
        for [x, y, _] in points() {
            let (flat, volume) = (perlin2(x, y), perlin3(x, y, 0.0));
            assert_eq!(flat.value, volume.value);
            assert_eq!(flat.gradient, [volume.gradient[0], volume.gradient[1]]);
            assert_eq!(flat.value, reference(x, y, 0.0));
        }
        assert_eq!(perlin2(3.0, -7.0).value, 0.0);
        for x in [1e12, -1e15, 3e38, f64::MAX] {
            let n = perlin3(x, -x, x * 0.5);
            assert!(n.value.is_finite() && n.gradient.iter().all(|g| g.is_finite()));
        }
        assert!(perlin2(f64::NAN, 1.0).value.is_nan());
    }
}
