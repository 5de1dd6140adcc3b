//! Percentage-closer filtering: the fraction of a square of depth comparisons around a lookup
//! that find the receiver in front of the map, weighted so the fraction varies smoothly as the
//! lookup moves (a box of the given width convolved with the bilinear tent). Each tap compares
//! the map with the receiver's own depth along that tap's ray (its tangent plane's), not with
//! the lookup's: a sloped receiver then matches the map at every tap, so no bias is needed for
//! its slope, and no normal offset lifts the lookup into a neighbouring object.

use crate::raster::DepthMap;

/// A square of `side` × `side` depth comparisons per lookup.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DepthFilter {
    side: u32,
}

impl DepthFilter {
    /// `taps` is a square: 1, 4, 9 or 16.
    pub fn new(taps: u32) -> DepthFilter {
        DepthFilter {
            side: (taps.max(1) as f32).sqrt().round() as u32,
        }
    }

    /// How far from the lookup, in texels, the farthest comparison with any weight lies.
    pub fn reach(&self) -> f32 {
        self.side as f32 / 2.0
    }

    /// The weighted fraction of comparisons at map position (x, y) in texels (texel (i, j)
    /// centred at (i, j)) in which the receiver's depth along the tap's ray, `depth(i, j)`, is at
    /// most the map's there. Taps past the map's edge read its edge texels.
    pub fn fraction(&self, map: &DepthMap, x: f32, y: f32, depth: impl Fn(u32, u32) -> f32) -> f32 {
        let (first_x, weights_x) = self.axis(x);
        let (first_y, weights_y) = self.axis(y);
        let last = map.size as i64 - 1;
        let side = self.side as usize;
        let (mut lit, mut taps, mut lit_taps) = (0.0, 0, 0);
        for (j, weight_y) in weights_y[..side].iter().enumerate() {
            if *weight_y == 0.0 {
                continue;
            }
            let row = (first_y + j as i64).clamp(0, last) as u32;
            for (i, weight_x) in weights_x[..side].iter().enumerate() {
                let column = (first_x + i as i64).clamp(0, last) as u32;
                taps += 1;
                if depth(column, row) <= map.at(column, row) {
                    lit += weight_y * weight_x;
                    lit_taps += 1;
                }
            }
        }
        // All lit is exactly 1 (the weights' sum may round below it): a surface no shadow
        // touches is lit to the bit as without shadows.
        if lit_taps == taps { 1.0 } else { lit }
    }

    /// The first texel along an axis and the weights of it and the next `side − 1`.
    fn axis(&self, x: f32) -> (i64, [f32; 4]) {
        let mut weights = [0.0; 4];
        match self.side {
            1 => {
                weights[0] = 1.0;
                ((x + 0.5).floor() as i64, weights)
            }
            2 => {
                let first = x.floor();
                let f = x - first;
                weights[0] = 1.0 - f;
                weights[1] = f;
                (first as i64, weights)
            }
            side => {
                // The tent averaged over a box of width side − 2 centred on x.
                let half = (side - 2) as f32 / 2.0;
                let first = (x - side as f32 / 2.0).floor() + 1.0;
                for (i, weight) in weights[..side as usize].iter_mut().enumerate() {
                    let c = first + i as f32;
                    *weight =
                        (tent_integral(x + half - c) - tent_integral(x - half - c)) / (2.0 * half);
                }
                (first as i64, weights)
            }
        }
    }
}

/// ∫ from −∞ to t of the tent max(0, 1 − |s|).
fn tent_integral(t: f32) -> f32 {
    if t <= -1.0 {
        0.0
    } else if t <= 0.0 {
        (t + 1.0) * (t + 1.0) / 2.0
    } else if t <= 1.0 {
        1.0 - (1.0 - t) * (1.0 - t) / 2.0
    } else {
        1.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A map whose left `edge` columns are near (depth 1) and the rest far (depth 10).
    fn step_map(size: u32, edge: u32) -> DepthMap {
        let depth = (0..size * size)
            .map(|i| if i % size < edge { 1.0 } else { 10.0 })
            .collect();
        DepthMap { size, depth }
    }

    #[test]
    fn weights_sum_to_one_and_never_go_negative() {
        for taps in [1, 4, 9, 16] {
            let filter = DepthFilter::new(taps);
            for k in 0..100 {
                let x = 3.0 + k as f32 * 0.0137;
                let (_, weights) = filter.axis(x);
                let sum: f32 = weights.iter().sum();
                assert!((sum - 1.0).abs() < 1e-5, "{taps} taps at {x}: {weights:?}");
                assert!(weights.iter().all(|&w| w >= 0.0));
            }
        }
    }

    #[test]
    fn the_fraction_falls_from_lit_to_shadowed_across_an_edge_monotonically() {
        // Depth 5 is behind the near columns (shadowed there) and in front of the far ones.
        let map = step_map(32, 16);
        for taps in [1, 4, 9, 16] {
            let filter = DepthFilter::new(taps);
            let mut last = 0.0;
            for k in 0..=200 {
                let x = 10.0 + k as f32 * 0.06;
                let lit = filter.fraction(&map, x, 8.0, |_, _| 5.0);
                assert!(lit >= last - 1e-6, "{taps} taps: {lit} after {last} at {x}");
                last = lit;
            }
            assert_eq!(
                filter.fraction(&map, 10.0, 8.0, |_, _| 5.0),
                0.0,
                "{taps} taps"
            );
            assert_eq!(
                filter.fraction(&map, 22.0, 8.0, |_, _| 5.0),
                1.0,
                "{taps} taps"
            );
            // Half way across the edge (between texels 15 and 16), half lit.
            let middle = filter.fraction(&map, 15.5, 8.0, |_, _| 5.0);
            assert!(
                (middle - 0.5).abs() < 1e-5 || taps == 1,
                "{taps} taps: {middle}"
            );
            // No weight past the reach.
            let reach = filter.reach();
            assert_eq!(
                filter.fraction(&map, 15.5 - reach - 0.01, 8.0, |_, _| 5.0),
                0.0
            );
        }
    }

    #[test]
    fn a_sloped_receiver_compared_tap_by_tap_matches_a_map_of_itself() {
        // The map holds a plane rising one unit a texel; the receiver lies on that plane.
        let size = 16;
        let plane = |i: u32, j: u32| 100.0 + i as f32 + 0.5 * j as f32;
        let depth = (0..size * size)
            .map(|k| plane(k % size, k / size))
            .collect();
        let map = DepthMap { size, depth };
        for taps in [1, 4, 9, 16] {
            let lit = DepthFilter::new(taps).fraction(&map, 7.3, 6.8, plane);
            assert_eq!(lit, 1.0, "{taps} taps");
            let behind = DepthFilter::new(taps).fraction(&map, 7.3, 6.8, |i, j| plane(i, j) + 0.01);
            assert_eq!(behind, 0.0, "{taps} taps");
        }
    }

    #[test]
    fn taps_past_the_edge_read_the_edge() {
        let map = step_map(8, 8);
        let filter = DepthFilter::new(16);
        assert_eq!(filter.fraction(&map, -0.5, -0.5, |_, _| 0.5), 1.0);
        assert_eq!(filter.fraction(&map, 7.9, 7.9, |_, _| 5.0), 0.0);
    }
}
