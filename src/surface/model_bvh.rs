//! A bounding volume hierarchy over a model's triangles, for exact rays: the reference's view
//! rays, exact coverage and the true hits. Built by splitting at the median centroid along the
//! longest axis; leaves hold up to `LEAF` triangles. Rays are f64 relative to the anchor and
//! meet the triangles by Möller–Trumbore in f64.

use super::corner::Corner;
use glam::{DVec3, Vec3};
use std::ops::RangeInclusive;

const LEAF: usize = 4;

/// Where a ray meets the model: its parameter, triangle and the barycentric weights (a, b) of
/// the triangle's second and third corners.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ModelHit {
    pub t: f64,
    pub triangle: usize,
    pub a: f64,
    pub b: f64,
}

#[derive(Clone, Copy, Debug)]
struct Node {
    min: Vec3,
    max: Vec3,
    /// A leaf's first entry in `order`, or an inner node's second child (its first follows it).
    start: u32,
    /// Triangles in a leaf; 0 for an inner node.
    count: u32,
}

pub struct Bvh {
    nodes: Vec<Node>,
    /// Triangle indices, each leaf's a contiguous run.
    order: Vec<u32>,
}

impl Bvh {
    pub fn new(corners: &[Corner]) -> Bvh {
        let triangles = corners.len() / 3;
        let centroids: Vec<Vec3> = (0..triangles)
            .map(|t| (corners[3 * t].p + corners[3 * t + 1].p + corners[3 * t + 2].p) / 3.0)
            .collect();
        let mut bvh = Bvh {
            nodes: Vec::with_capacity(2 * triangles.div_ceil(LEAF)),
            order: (0..triangles as u32).collect(),
        };
        if triangles > 0 {
            bvh.build(corners, &centroids, 0, triangles);
        }
        bvh
    }

    /// Adds the node over `order[start..end]` and its subtree; returns its index.
    fn build(&mut self, corners: &[Corner], centroids: &[Vec3], start: usize, end: usize) -> usize {
        let (mut min, mut max) = (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY));
        for &t in &self.order[start..end] {
            for corner in &corners[3 * t as usize..3 * t as usize + 3] {
                min = min.min(corner.p);
                max = max.max(corner.p);
            }
        }
        let index = self.nodes.len();
        self.nodes.push(Node {
            min,
            max,
            start: start as u32,
            count: (end - start) as u32,
        });
        if end - start <= LEAF {
            return index;
        }
        let extent = max - min;
        let axis = if extent.x >= extent.y && extent.x >= extent.z {
            0
        } else if extent.y >= extent.z {
            1
        } else {
            2
        };
        let middle = (start + end) / 2;
        self.order[start..end].select_nth_unstable_by(middle - start, |&a, &b| {
            centroids[a as usize][axis].total_cmp(&centroids[b as usize][axis])
        });
        self.build(corners, centroids, start, middle);
        let second = self.build(corners, centroids, middle, end);
        self.nodes[index].start = second as u32;
        self.nodes[index].count = 0;
        index
    }

    /// The nearest hit of the ray `origin + t·direction` with t in `range`.
    pub fn intersect(
        &self,
        corners: &[Corner],
        origin: DVec3,
        direction: DVec3,
        range: &RangeInclusive<f64>,
    ) -> Option<ModelHit> {
        if self.nodes.is_empty() {
            return None;
        }
        let inverse = direction.recip();
        let mut best: Option<ModelHit> = None;
        let mut far = *range.end();
        let mut stack = [0u32; 64];
        let mut depth = 1;
        while depth > 0 {
            depth -= 1;
            let index = stack[depth];
            let node = self.nodes[index as usize];
            if !box_hit(node.min, node.max, origin, inverse, *range.start(), far) {
                continue;
            }
            if node.count > 0 {
                let run = node.start as usize..(node.start + node.count) as usize;
                for &t in &self.order[run] {
                    let t = t as usize;
                    let hit = triangle_hit(&corners[3 * t..3 * t + 3], origin, direction);
                    if let Some((distance, a, b)) = hit
                        && range.contains(&distance)
                        && distance <= far
                    {
                        far = distance;
                        best = Some(ModelHit {
                            t: distance,
                            triangle: t,
                            a,
                            b,
                        });
                    }
                }
            } else if depth + 2 <= stack.len() {
                // The first child was built right after its parent, the second is recorded.
                stack[depth] = node.start;
                stack[depth + 1] = index + 1;
                depth += 2;
            }
        }
        best
    }
}

impl Bvh {
    /// How many triangles the ray from `origin` along `direction` crosses, for t > 0.
    pub fn crossings(&self, corners: &[Corner], origin: DVec3, direction: DVec3) -> usize {
        if self.nodes.is_empty() {
            return 0;
        }
        let inverse = direction.recip();
        let (mut count, mut stack, mut depth) = (0, [0u32; 64], 1);
        while depth > 0 {
            depth -= 1;
            let index = stack[depth];
            let node = self.nodes[index as usize];
            if !box_hit(node.min, node.max, origin, inverse, 0.0, f64::INFINITY) {
                continue;
            }
            if node.count > 0 {
                let run = node.start as usize..(node.start + node.count) as usize;
                count += self.order[run]
                    .iter()
                    .filter_map(|&t| {
                        let t = t as usize;
                        triangle_hit(&corners[3 * t..3 * t + 3], origin, direction)
                    })
                    .filter(|&(distance, _, _)| distance > 0.0)
                    .count();
            } else if depth + 2 <= stack.len() {
                stack[depth] = node.start;
                stack[depth + 1] = index + 1;
                depth += 2;
            }
        }
        count
    }
}

/// Whether the ray meets the box for some t in `near..=far` (slabs, in f64).
fn box_hit(min: Vec3, max: Vec3, origin: DVec3, inverse: DVec3, near: f64, far: f64) -> bool {
    let a = (min.as_dvec3() - origin) * inverse;
    let b = (max.as_dvec3() - origin) * inverse;
    let entry = a.min(b).max_element().max(near);
    let exit = a.max(b).min_element().min(far);
    // NaN (a ray in a box's face plane) keeps the box: the triangles decide.
    entry <= exit || entry.is_nan() || exit.is_nan()
}

/// Möller–Trumbore in f64: the ray parameter and the weights of corners 1 and 2.
fn triangle_hit(corners: &[Corner], origin: DVec3, direction: DVec3) -> Option<(f64, f64, f64)> {
    let p0 = corners[0].p.as_dvec3();
    let (e1, e2) = (corners[1].p.as_dvec3() - p0, corners[2].p.as_dvec3() - p0);
    let h = direction.cross(e2);
    let det = e1.dot(h);
    if det.abs() < 1e-300 || !det.is_finite() {
        return None;
    }
    let s = origin - p0;
    let a = s.dot(h) / det;
    if !(0.0..=1.0).contains(&a) {
        return None;
    }
    let q = s.cross(e1);
    let b = direction.dot(q) / det;
    if b < 0.0 || a + b > 1.0 {
        return None;
    }
    Some((e2.dot(q) / det, a, b))
}
