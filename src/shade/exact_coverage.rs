//! Exact coverage: which true surface a pixel's ray meets first, where the mesh cannot say.
//! Curved surfaces are tessellated as hulls around their true surfaces, so every pixel a true
//! surface covers is covered by its mesh; shading then settles each fragment on the true
//! surfaces: one whose ray misses its own is cast against every object (and may show what lies
//! behind, or the background), and one whose ray meets a neighbouring object's true surface
//! first (where two objects touch or cut each other) becomes that neighbour's.

use super::exact_hits::{ExactScratch, true_hits_along};
use super::frame_object::FrameObject;
use crate::raster::{Fragment, SampleRays};
use crate::surface::{Hit, Ray, Surface, TrueHit, intersect};
use glam::{DVec3, Vec3};
use std::ops::{Range, RangeInclusive};

/// For each object, the others whose true surface may pass in front of its own within the
/// error of its mesh: those whose boxes (grown by their meshes' chord errors) overlap its box.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Neighbours {
    of: Vec<Vec<u32>>,
    /// Per object, what bounds where its true surface can pass in front of another's fragment.
    reaches: Vec<Reach>,
}

/// Where an object's true surface can pass in front of another object's fragment, relative to
/// its anchor. f32: the margins are the chord error or a relative 1e-5, far above f32 rounding
/// at camera distances.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Reach {
    /// A ball around the true surface (centre, radius): a fragment outside it is not passed.
    pub ball: (Vec3, f32),
    pub shape: ReachShape,
}

impl Reach {
    /// Whether the near plane may pass through the hull of the object whose anchor is at
    /// `origin` (camera-relative), which lies within half again the true surface's ball.
    fn near_clips_hull(&self, origin: Vec3, rays: &SampleRays) -> bool {
        let (centre, radius) = self.ball;
        rays.forward.dot(origin + centre) - 1.5 * radius < rays.near
    }
}

/// What an object's shape adds to its ball.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum ReachShape {
    /// Nothing: the ball is all that is known.
    #[default]
    Open,
    /// A closed surface whose hull holds it (a sphere): its true surface meets a ray only
    /// behind its hull, so it passes in front of no fragment that beat its hull in depth
    /// (a flat surface's, which never moves off its mesh), unless the near plane clips the hull.
    Closed,
    /// Flat, in the plane through the anchor with this unit normal: a ray passes it only where
    /// the eye and the fragment lie on opposite sides.
    Flat(Vec3),
}

/// How far a fragment may lie on the eye's side of a flat neighbour and still be tested against
/// it, relative to the distances involved: room for the f32 rounding of its point.
const FLAT_ROUNDING: f32 = 1e-5;

/// Whether a neighbour's true surface may pass in front of a fragment (`Neighbours::reach_test`).
#[derive(Clone, Copy, Debug)]
enum ReachTest {
    Everywhere,
    /// Within the neighbour's ball (centre relative to its camera-relative anchor `origin`,
    /// squared radius), and, for a flat neighbour, past its plane.
    Within {
        origin: Vec3,
        ball: (Vec3, f32),
        plane: Option<FlatSide>,
    },
}

/// A flat neighbour's plane through its anchor, with unit `normal`, as the eye sees it: on which
/// side the eye lies, and how far it is from the anchor.
#[derive(Clone, Copy, Debug)]
struct FlatSide {
    normal: Vec3,
    eye_side: f32,
    eye_distance: f32,
}

impl FlatSide {
    /// Whether `point` (relative to the anchor) lies on the far side of the plane from the eye,
    /// or within rounding of it.
    #[inline(always)]
    fn passed(&self, point: Vec3) -> bool {
        let point_side = self.normal.dot(point);
        let rounding = FLAT_ROUNDING * (self.eye_distance + point.length());
        self.eye_side * point_side <= 0.0 || point_side.abs() <= rounding
    }
}

impl ReachTest {
    /// Whether the surface may pass in front of the fragment point `depth·direction`.
    #[inline(always)]
    fn may_reach(&self, direction: Vec3, depth: f32) -> bool {
        match *self {
            ReachTest::Everywhere => true,
            ReachTest::Within {
                origin,
                ball: (centre, radius_squared),
                plane,
            } => {
                // The fragment relative to the anchor.
                let point = direction * depth - origin;
                let outside = point.distance_squared(centre) > radius_squared;
                !outside && plane.is_none_or(|plane| plane.passed(point))
            }
        }
    }
}

impl Neighbours {
    /// Objects i and j ≠ i are neighbours where `overlap(i, j)`; `reaches` bounds where each
    /// object's true surface lies, relative to its anchor.
    pub fn new(
        count: usize,
        overlap: impl Fn(usize, usize) -> bool,
        reaches: Vec<Reach>,
    ) -> Neighbours {
        let of = (0..count)
            .map(|i| {
                let others = (0..count).filter(|&j| j != i && overlap(i, j));
                others.map(|j| j as u32).collect()
            })
            .collect();
        Neighbours { of, reaches }
    }

    /// Whether the true surface of the object whose anchor is at `origin` (camera-relative)
    /// lies behind its hull along every ray, so that it passes in front of no fragment that beat
    /// the hull in depth: a closed surface wholly past the near plane (its hull lies within half
    /// again its ball; the near plane could clip the hull where the true surface is not).
    fn hidden_by_hull(&self, object: usize, origin: Vec3, rays: &SampleRays) -> bool {
        self.reaches.get(object).is_some_and(|reach| {
            reach.shape == ReachShape::Closed && !reach.near_clips_hull(origin, rays)
        })
    }

    /// Whether the true surface of the object whose anchor is at `origin` (camera-relative) may
    /// pass in front of a fragment: the test, its parts that do not depend on the fragment
    /// worked out once.
    fn reach_test(&self, object: usize, origin: Vec3, rays: &SampleRays) -> ReachTest {
        let Some(reach) = self.reaches.get(object) else {
            return ReachTest::Everywhere;
        };
        let (centre, radius) = reach.ball;
        let ball = (centre, radius * radius);
        match reach.shape {
            // Where the near plane clips its hull, a curved surface may pass in front of
            // fragments far behind it, where its hull would have covered them.
            ReachShape::Open | ReachShape::Closed if reach.near_clips_hull(origin, rays) => {
                ReachTest::Everywhere
            }
            ReachShape::Open | ReachShape::Closed => ReachTest::Within {
                origin,
                ball,
                plane: None,
            },
            ReachShape::Flat(normal) => {
                let eye = -origin;
                let plane = FlatSide {
                    normal,
                    eye_side: normal.dot(eye),
                    eye_distance: eye.length(),
                };
                ReachTest::Within {
                    origin,
                    ball,
                    plane: Some(plane),
                }
            }
        }
    }

    pub fn of(&self, object: usize) -> &[u32] {
        self.of.get(object).map_or(&[], Vec::as_slice)
    }
}

/// The fragments of `run` (all of object `index`, not pending a full cast) whose ray meets a
/// neighbour's true surface in front of where they are, moved to that neighbour; how many.
pub(super) fn nearer_neighbours(
    objects: &[FrameObject],
    neighbours: &Neighbours,
    index: u32,
    rays: &SampleRays,
    fragments: &mut [Fragment],
    run: Range<usize>,
    scratch: &mut ExactScratch,
) -> usize {
    let mut count = 0;
    // A flat surface's fragments are where its mesh put them, so they beat every hull in depth.
    let settled = objects[index as usize].prepared.surface.is_its_own_mesh();
    for &other in neighbours.of(index as usize) {
        let object = &objects[other as usize];
        if settled && neighbours.hidden_by_hull(other as usize, object.origin, rays) {
            continue;
        }
        let surface = &object.prepared.surface;
        // Only the fragments within the neighbour's reach are cast against it.
        let test = neighbours.reach_test(other as usize, object.origin, rays);
        let mut candidates = std::mem::take(&mut scratch.candidates);
        candidates.clear();
        candidates.extend(run.clone().filter(|&k| {
            let f = &fragments[k];
            !scratch.pending[k] && test.may_reach(rays.through(f.x, f.y), f.depth)
        }));
        let near = candidates.iter().map(|&k| &fragments[k]);
        match surface {
            // Its Newton steps find the root near a point, not the first along the ray.
            Surface::Wave(_) => first_hits_before(object, rays, near, scratch),
            _ => true_hits_along(surface, object.eye, rays, near, scratch),
        }
        let hits = scratch.hits.iter().zip(&scratch.found);
        for (&k, (hit, &found)) in candidates.iter().zip(hits) {
            let fragment = &mut fragments[k];
            if found && hit.depth < fragment.depth && hit.depth >= rays.near {
                fragment.object = other;
                fragment.uv = hit.uv;
                fragment.depth = hit.depth;
                scratch.moved[k] = true;
                count += 1;
            }
        }
        scratch.candidates = candidates;
    }
    count
}

/// The first hit of `object`'s true surface along each fragment's ray between the near plane
/// and the fragment, into `scratch.hits` and `scratch.found`.
fn first_hits_before<'f>(
    object: &FrameObject,
    rays: &SampleRays,
    run: impl Iterator<Item = &'f Fragment>,
    scratch: &mut ExactScratch,
) {
    let origin = object.eye;
    scratch.hits.clear();
    scratch.found.clear();
    for fragment in run {
        let direction = rays.exact_through(fragment.x, fragment.y);
        let range = rays.near as f64..=fragment.depth as f64;
        let hit = intersect(&object.prepared.surface, &Ray { origin, direction }, range);
        scratch.found.push(hit.is_some());
        scratch
            .hits
            .push(hit.map_or(TrueHit::default(), |hit| TrueHit {
                uv: hit.uv,
                depth: hit.t as f32,
            }));
    }
}

/// Casts each pending fragment's ray against every object's true surface: it becomes the
/// nearest hit's, or background (object `objects.len()`, infinite depth). How many became
/// another object's, and how many background.
pub(super) fn cast_dropped(
    objects: &[FrameObject],
    rays: &SampleRays,
    fragments: &mut [Fragment],
    scratch: &mut ExactScratch,
) -> (usize, usize) {
    let (mut reassigned, mut background) = (0, 0);
    let range = rays.near as f64..=rays.far as f64;
    let each = fragments
        .iter_mut()
        .zip(&scratch.pending)
        .zip(&mut scratch.moved);
    for ((fragment, &pending), moved) in each {
        if !pending {
            continue;
        }
        let direction = rays.exact_through(fragment.x, fragment.y);
        let eye = |object: &FrameObject| object.eye;
        match nearest_true_hit(objects, eye, direction, range.clone()) {
            Some((index, hit)) => {
                reassigned += usize::from(index as u32 != fragment.object);
                fragment.object = index as u32;
                fragment.uv = hit.uv;
                fragment.depth = hit.t as f32;
                *moved = true;
            }
            None => {
                fragment.object = objects.len() as u32;
                fragment.depth = f32::INFINITY;
                background += 1;
            }
        }
    }
    (reassigned, background)
}

/// The nearest true surface along the ray from the eye (`eye(object)`: the eye relative to the
/// object's anchor) in `direction`, for t in `range`: which object, and the hit. The first
/// object wins an exact tie, and back faces of a sphere seen from outside are culled, as the
/// rasterizer culls them.
pub fn nearest_true_hit(
    objects: &[FrameObject],
    eye: impl Fn(&FrameObject) -> DVec3,
    direction: DVec3,
    range: RangeInclusive<f64>,
) -> Option<(usize, Hit)> {
    let mut nearest: Option<(usize, Hit)> = None;
    for (index, object) in objects.iter().enumerate() {
        let surface = &object.prepared.surface;
        let origin = eye(object);
        let ray = Ray { origin, direction };
        let Some(hit) = intersect(surface, &ray, range.clone()) else {
            continue;
        };
        if culled(surface, origin, &hit, direction) {
            continue;
        }
        if nearest.is_none_or(|(_, best)| hit.t < best.t) {
            nearest = Some((index, hit));
        }
    }
    nearest
}

fn culled(surface: &Surface, eye: DVec3, hit: &Hit, direction: DVec3) -> bool {
    // A ray's first hit on a closed model seen from outside faces it already; its interpolated
    // normal may not, near the outline, and the crossing count costs a ray of its own.
    if let Surface::Model(_) = surface {
        return false;
    }
    let normal = || surface.frame(hit.uv.x, hit.uv.y).n.as_dvec3();
    surface.encloses_eye_at(eye) == Some(true) && normal().dot(direction) >= 0.0
}
