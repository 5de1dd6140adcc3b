//! Cellular (Worley) noise: the distance from a point to the nearest of the feature points, one
//! at a hashed place in each unit cell of the lattice, with its exact gradient (the unit vector
//! from that feature point; zero on it). The search is exact, not the usual 3×3 approximation:
//! every cell that could hold a nearer point is visited. In f64, as the lattice needs.

use super::noise::{lattice_hash, split};
use super::perlin::Graded;

/// Which of the lattice's hash streams places the feature points.
const FEATURE_STREAM: u64 = 0x63_656C_6C73;

/// Distance to the nearest feature point at (x, y), with its partials.
pub fn cells2(x: f64, y: f64) -> Graded<2> {
    nearest([x, y])
}

/// Distance to the nearest feature point at (x, y, z), with its partials.
pub fn cells3(x: f64, y: f64, z: f64) -> Graded<3> {
    nearest([x, y, z])
}

/// The feature point of the cell whose lowest corner is `cell`, in lattice units.
pub fn feature_point<const D: usize>(cell: [i64; D]) -> [f64; D] {
    let at = |k: usize| cell.get(k).copied().unwrap_or(0);
    let bits = 64 / D as u32;
    let hash = lattice_hash(at(0), at(1), at(2), FEATURE_STREAM + D as u64);
    std::array::from_fn(|k| {
        let chunk = (hash >> (k as u32 * bits)) & ((1u64 << bits) - 1);
        cell[k] as f64 + chunk as f64 / (1u64 << bits) as f64
    })
}

fn nearest<const D: usize>(point: [f64; D]) -> Graded<D> {
    if point.iter().any(|p| p.is_nan()) {
        return Graded {
            value: f64::NAN,
            gradient: [f64::NAN; D],
        };
    }
    let split: [(i64, f64); D] = point.map(split);
    let own: [i64; D] = split.map(|(cell, _)| cell);
    let fraction: [f64; D] = split.map(|(_, fraction)| fraction);
    let mut best = Nearest {
        distance2: f64::INFINITY,
        cell: own,
    };
    // The point's own cell holds a feature point within √D < 2 of it, so no cell three or more
    // away can be nearer; the cells two away only where the nearest of the 3ⁿ around is
    // farther than their wall.
    search(&mut best, point, own, fraction, 1);
    let wall = 1.0 + fraction.iter().map(|f| f.min(1.0 - f)).fold(1.0, f64::min);
    if best.distance2 > wall * wall {
        search(&mut best, point, own, fraction, 2);
    }
    let feature = feature_point(best.cell);
    let value = best.distance2.sqrt();
    let gradient = std::array::from_fn(|k| match value > 0.0 {
        true => (point[k] - feature[k]) / value,
        false => 0.0,
    });
    Graded { value, gradient }
}

/// The nearest feature point found so far: its squared distance and its cell.
struct Nearest<const D: usize> {
    distance2: f64,
    cell: [i64; D],
}

/// Visits every cell up to `reach` cells from `own` along each axis whose nearest possible
/// point could beat `best` (a cell already visited cannot).
fn search<const D: usize>(
    best: &mut Nearest<D>,
    point: [f64; D],
    own: [i64; D],
    fraction: [f64; D],
    reach: i64,
) {
    let mut offset = [-reach; D];
    loop {
        let bound: f64 = (0..D).map(|k| gap(offset[k], fraction[k]).powi(2)).sum();
        if bound < best.distance2 {
            let cell: [i64; D] = std::array::from_fn(|k| own[k].saturating_add(offset[k]));
            let distance2 = squared_distance(point, feature_point(cell));
            if distance2 < best.distance2 {
                *best = Nearest { distance2, cell };
            }
        }
        // The next offset, odometer fashion; done after the last.
        let mut k = 0;
        loop {
            if k == D {
                return;
            }
            offset[k] += 1;
            if offset[k] <= reach {
                break;
            }
            offset[k] = -reach;
            k += 1;
        }
    }
}

/// Distance along one axis from a point at `fraction` of its cell to the cell `offset` away.
fn gap(offset: i64, fraction: f64) -> f64 {
    match offset {
        0 => 0.0,
        o if o < 0 => fraction + (-o - 1) as f64,
        o => (o - 1) as f64 + 1.0 - fraction,
    }
}

fn squared_distance<const D: usize>(a: [f64; D], b: [f64; D]) -> f64 {
    (0..D).map(|k| (a[k] - b[k]).powi(2)).sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The nearest feature point by brute force over the 7ⁿ cells around the point.
    fn brute_force<const D: usize>(point: [f64; D]) -> f64 {
        let own: [i64; D] = point.map(|p| p.floor() as i64);
        let mut best = f64::INFINITY;
        for index in 0..7usize.pow(D as u32) {
            let cell: [i64; D] =
                std::array::from_fn(|k| own[k] + (index / 7usize.pow(k as u32) % 7) as i64 - 3);
            best = best.min(squared_distance(point, feature_point(cell)));
        }
        best.sqrt()
    }

    fn points() -> impl Iterator<Item = [f64; 3]> {
        (0..4000).map(|i| {
            let i = i as f64;
            [
                i * 0.0731 - 140.0,
                90.0 - i * 0.0397,
                (i * 0.37).cos() * 9.0,
            ]
        })
    }

    #[test]
    fn the_search_finds_the_nearest_point_as_brute_force_does() {
        for [x, y, z] in points() {
            assert_eq!(cells2(x, y).value, brute_force([x, y]), "at {x}, {y}");
            assert_eq!(
                cells3(x, y, z).value,
                brute_force([x, y, z]),
                "at {x}, {y}, {z}"
            );
        }
    }

    #[test]
    fn feature_points_lie_in_their_cells_and_spread_over_them() {
        let mut mean = [0.0; 3];
        let count = 20_000;
        for i in 0..count {
            let cell = [i % 131 - 65, i / 131 - 76, (i * 7) % 11 - 5];
            let point = feature_point(cell);
            for k in 0..3 {
                let inside = point[k] - cell[k] as f64;
                assert!((0.0..1.0).contains(&inside), "{point:?} in {cell:?}");
                mean[k] += inside / count as f64;
            }
        }
        assert!(mean.iter().all(|m| (m - 0.5).abs() < 0.01), "{mean:?}");
    }

    #[test]
    fn the_gradient_is_the_unit_vector_from_the_nearest_point() {
        let h = 1e-7;
        let mut compared = 0;
        for [x, y, z] in points() {
            let at = cells3(x, y, z);
            let length = at.gradient.iter().map(|g| g * g).sum::<f64>().sqrt();
            assert!((length - 1.0).abs() < 1e-12, "|gradient| {length}");
            let along_x = (cells3(x + h, y, z).value - cells3(x - h, y, z).value) / (2.0 * h);
            // Away from the cells' borders, where the nearest point changes.
            if (along_x - at.gradient[0]).abs() < 1e-2 {
                compared += 1;
                assert!((along_x - at.gradient[0]).abs() < 1e-6);
            }
            let flat = cells2(x, y);
            let along_y = (cells2(x, y + h).value - cells2(x, y - h).value) / (2.0 * h);
            if (along_y - flat.gradient[1]).abs() < 1e-2 {
                compared += 1;
            }
        }
        assert!(compared > 7000, "only {compared} comparisons");
    }

    #[test]
    fn finite_far_out_and_nothing_from_nan() {
        // Up to the largest f32 lanes hold; past 1e154 the squared distance overflows.
        for x in [1e15, -1e18, 9.3e18, 3e38, -1e150] {
            let n = cells3(x, -x, 0.5);
            assert!(
                n.value.is_finite() && n.gradient.iter().all(|g| g.is_finite()),
                "{x}"
            );
            assert!(cells2(x, 7.0).value.is_finite());
        }
        let on_a_point = feature_point([3, -2]);
        let there = cells2(on_a_point[0], on_a_point[1]);
        assert_eq!((there.value, there.gradient), (0.0, [0.0, 0.0]));
        assert!(cells2(f64::NAN, 0.0).value.is_nan());
    }
}
