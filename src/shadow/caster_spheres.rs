//! A sphere around each caster of a light, to tell without a map or a ray that a point is in no
//! caster's shadow: when its segment to the light (its ray, for a directional light) passes no
//! sphere. Most of a floor under a sphere is told so. Where the caster is itself a sphere, a
//! segment passing well inside it is as surely in its shadow. A batch whose bounding ball passes
//! every sphere is told clear at once; other points are screened a lane of them at a time
//! (structure-of-arrays loops, compiled to SIMD over points).

use super::bounds::Bounds;
use crate::scene::Light;
use crate::scene::PreparedScene;
use crate::surface::Surface;
use glam::{DVec3, Vec3};

/// The most casters whose spheres a point is tested against: past that, testing each would cost
/// more per fragment than the lookup it saves.
pub const MOST_SPHERES: usize = 16;

/// Points screened at once.
pub const SCREEN_LANES: usize = 64;

/// The casters' spheres and the light, relative to the camera's eye (f32, subtracted in f64).
pub struct CasterSpheres {
    /// `None` for more casters than `MOST_SPHERES`: no point is told clear.
    spheres: Option<Vec<CasterSphere>>,
    light: LightAt,
}

#[derive(Clone, Copy)]
struct CasterSphere {
    /// The caster's index among the scene's objects.
    object: usize,
    centre: Vec3,
    radius: f32,
    /// Within this distance of the centre a point's way to the light surely meets the caster: a
    /// sphere caster's own radius less the margin, where the light is outside it (a way between
    /// two points inside a sphere meets none of it); zero for any other caster.
    solid: f32,
}

enum LightAt {
    Point(Vec3),
    /// The unit direction towards the light.
    Directional(Vec3),
}

/// What the spheres tell of a lane of points (the first `len` lanes).
pub struct Screened {
    pub len: usize,
    /// The cosine between each point's normal and its way to the light (NaN at a point light).
    pub facing: [f32; SCREEN_LANES],
    /// Whether the point's way to the light passes every sphere left in.
    pub clear: [bool; SCREEN_LANES],
    /// Whether its way passes well inside a sphere caster left in: surely in shadow.
    pub blocked: [bool; SCREEN_LANES],
}

impl Default for Screened {
    fn default() -> Self {
        Screened {
            len: 0,
            facing: [0.0; SCREEN_LANES],
            clear: [false; SCREEN_LANES],
            blocked: [false; SCREEN_LANES],
        }
    }
}

impl CasterSpheres {
    /// Spheres around `casters`, grown by `margin` world units (what a lookup's taps and lift
    /// may reach past a caster's outline, and f32's rounding).
    pub fn new(
        prepared: &PreparedScene,
        casters: &[usize],
        boxes: &[Option<Bounds>],
        light: &Light,
        eye: DVec3,
        margin: f32,
    ) -> CasterSpheres {
        let spheres = (casters.len() <= MOST_SPHERES).then(|| {
            casters
                .iter()
                .filter_map(|&index| {
                    let (centre, radius, solid) = match &prepared.objects[index].surface {
                        Surface::Sphere(s) => {
                            let solid = if light_outside(light, s.center, s.radius + margin) {
                                (s.radius - margin).max(0.0)
                            } else {
                                0.0
                            };
                            (s.center, f64::from(s.radius), solid)
                        }
                        _ => {
                            let b = boxes[index]?;
                            (b.centre(), b.min.distance(b.max) / 2.0, 0.0)
                        }
                    };
                    Some(CasterSphere {
                        object: index,
                        centre: (centre - eye).as_vec3(),
                        radius: radius as f32 + margin,
                        solid,
                    })
                })
                .collect()
        });
        let light = match *light {
            Light::Point { position, .. } => LightAt::Point((position - eye).as_vec3()),
            Light::Directional { towards, .. } => {
                LightAt::Directional(crate::surface::normalize_or(towards, Vec3::Y))
            }
        };
        CasterSpheres { spheres, light }
    }

    /// Whether every one of `points` (camera-relative) has a way to the light that passes every
    /// sphere but `except`'s: tested once for a ball around them all. A way from a point of
    /// the ball stays within its radius of the way from its centre (the two meet at the light,
    /// or run parallel), so the ball is clear where the centre's way passes each sphere by more
    /// than that radius. `false` when no spheres are kept, for no points or a non-finite one.
    pub fn all_clear(&self, points: &[Vec3], except: Option<usize>) -> bool {
        let Some(spheres) = &self.spheres else {
            return false;
        };
        let Some((centre, radius)) = ball_around(points) else {
            return false;
        };
        let way = self.way_from(centre);
        let point_light = matches!(self.light, LightAt::Point(_));
        spheres
            .iter()
            .filter(|s| Some(s.object) != except)
            .all(|sphere| {
                let apart = past_way(sphere.centre - centre, way, point_light).length();
                apart > sphere.radius + radius
            })
    }

    /// The way from camera-relative `point` towards the light: to a point light, or the
    /// direction of a directional one.
    #[inline(always)]
    fn way_from(&self, point: Vec3) -> Vec3 {
        match self.light {
            LightAt::Point(light) => light - point,
            LightAt::Directional(towards) => towards,
        }
    }

    /// The cosine between unit `normal` and the way from camera-relative `point` to the light,
    /// as `screen` gives it.
    #[inline(always)]
    pub fn facing(&self, point: Vec3, normal: Vec3) -> f32 {
        let way = self.way_from(point);
        normal.dot(way) / way.length()
    }

    /// Screens up to `SCREEN_LANES` camera-relative points with unit `normals` into `out`,
    /// leaving object `except`'s sphere out.
    pub fn screen(
        &self,
        points: &[Vec3],
        normals: &[Vec3],
        except: Option<usize>,
        out: &mut Screened,
    ) {
        crate::simd::widest(
            #[inline(always)]
            || self.screen_lanes(points, normals, except, out),
        );
    }

    /// `screen`'s loops, inlined into its call so they are compiled for the widest SIMD.
    #[inline(always)]
    fn screen_lanes(
        &self,
        points: &[Vec3],
        normals: &[Vec3],
        except: Option<usize>,
        out: &mut Screened,
    ) {
        let len = points.len().min(normals.len()).min(SCREEN_LANES);
        out.len = len;
        let (mut p, mut n) = ([[0.0f32; SCREEN_LANES]; 3], [[0.0f32; SCREEN_LANES]; 3]);
        for (k, (point, normal)) in points.iter().zip(normals).take(len).enumerate() {
            (p[0][k], p[1][k], p[2][k]) = (point.x, point.y, point.z);
            (n[0][k], n[1][k], n[2][k]) = (normal.x, normal.y, normal.z);
        }
        let to_light = match self.light {
            LightAt::Point(light) => {
                let towards = |axis: usize| p[axis].map(|p| light[axis] - p);
                [towards(0), towards(1), towards(2)]
            }
            LightAt::Directional(towards) => towards.to_array().map(|t| [t; SCREEN_LANES]),
        };
        let at = |lanes: &[[f32; SCREEN_LANES]; 3], k: usize| {
            Vec3::new(lanes[0][k], lanes[1][k], lanes[2][k])
        };
        for k in 0..SCREEN_LANES {
            let way = at(&to_light, k);
            out.facing[k] = at(&n, k).dot(way) / way.length();
        }
        let Some(spheres) = &self.spheres else {
            out.clear = [false; SCREEN_LANES];
            out.blocked = [false; SCREEN_LANES];
            return;
        };
        out.clear = [true; SCREEN_LANES];
        out.blocked = [false; SCREEN_LANES];
        let point_light = matches!(self.light, LightAt::Point(_));
        for sphere in spheres.iter().filter(|s| Some(s.object) != except) {
            for k in 0..SCREEN_LANES {
                let to_centre = sphere.centre - at(&p, k);
                let apart = past_way(to_centre, at(&to_light, k), point_light).length_squared();
                out.clear[k] &= apart > sphere.radius * sphere.radius;
                out.blocked[k] |= apart < sphere.solid * sphere.solid;
            }
        }
    }
}

/// From the nearest point of the way `way` from a point (a segment to a point light, else a
/// ray) to a centre `to_centre` away from that point.
#[inline(always)]
fn past_way(to_centre: Vec3, way: Vec3, point_light: bool) -> Vec3 {
    let along = to_centre.dot(way);
    let t = if point_light {
        (along / way.length_squared()).clamp(0.0, 1.0)
    } else {
        along.max(0.0)
    };
    to_centre - way * t
}

/// The centre and radius of a ball holding `points` (around their bounding box); `None` for no
/// points or a non-finite one.
fn ball_around(points: &[Vec3]) -> Option<(Vec3, f32)> {
    if points.is_empty() {
        return None;
    }
    let [min, max, sum] = crate::simd::widest(
        #[inline(always)]
        || extents(bytemuck::cast_slice(points)),
    );
    let centre = (min + max) * 0.5;
    // Rounded up by what rounding the centre and the length may have lost.
    let rounding = 4.0 * f32::EPSILON;
    let radius = (max - min).length() * 0.5 * (1.0 + rounding)
        + rounding * min.abs().max(max.abs()).length();
    (sum.is_finite() && radius.is_finite()).then_some((centre, radius))
}

/// The least and greatest x, y and z of points laid out as x, y, z, x, y, z…, and their sum
/// (which only tells whether one is not finite: the comparisons pass NaN by). Eight points a
/// step, each lane keeping one coordinate, so the loop compiles to vector compares.
#[inline(always)]
fn extents(coordinates: &[f32]) -> [Vec3; 3] {
    const LANES: usize = 24;
    let (mut least, mut most, mut sum) = (
        [f32::INFINITY; LANES],
        [f32::NEG_INFINITY; LANES],
        [0.0; LANES],
    );
    let mut take = |lane: usize, x: f32| {
        least[lane] = if x < least[lane] { x } else { least[lane] };
        most[lane] = if x > most[lane] { x } else { most[lane] };
        sum[lane] += x;
    };
    let steps = coordinates.chunks_exact(LANES);
    let rest = steps.remainder();
    for step in steps {
        for (lane, &x) in step.iter().enumerate() {
            take(lane, x);
        }
    }
    // The rest is whole points too, so lane k still holds axis k mod 3.
    for (lane, &x) in rest.iter().enumerate() {
        take(lane, x);
    }
    let axes = |lanes: &[f32; LANES], pick: fn(f32, f32) -> f32| {
        let mut axes = [lanes[0], lanes[1], lanes[2]];
        for (lane, &x) in lanes.iter().enumerate().skip(3) {
            axes[lane % 3] = pick(axes[lane % 3], x);
        }
        Vec3::from_array(axes)
    };
    [
        axes(&least, f32::min),
        axes(&most, f32::max),
        axes(&sum, |a, b| a + b),
    ]
}

/// Whether `light` lies outside the sphere of `radius` around `centre` (a directional light
/// always does).
fn light_outside(light: &Light, centre: DVec3, radius: f32) -> bool {
    match *light {
        Light::Point { position, .. } => position.distance(centre) > f64::from(radius),
        Light::Directional { .. } => true,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spheres(light: LightAt) -> CasterSpheres {
        CasterSpheres {
            spheres: Some(vec![CasterSphere {
                object: 0,
                centre: Vec3::new(0.0, 1.0, 0.0),
                radius: 1.0,
                solid: 0.9,
            }]),
            light,
        }
    }

    /// What `spheres` tell of one point on a floor (normal +y), leaving `except` out.
    fn screened(spheres: &CasterSpheres, p: Vec3, except: Option<usize>) -> (bool, bool, f32) {
        let mut out = Screened::default();
        spheres.screen(&[p], &[Vec3::Y], except, &mut out);
        assert_eq!(out.len, 1);
        (out.clear[0], out.blocked[0], out.facing[0])
    }

    #[test]
    fn only_points_whose_way_to_the_light_passes_a_sphere_are_not_clear() {
        let above = spheres(LightAt::Point(Vec3::new(0.0, 10.0, 0.0)));
        let (clear, blocked, _) = screened(&above, Vec3::new(0.3, 0.0, 0.0), None);
        assert!(!clear && blocked, "under the sphere");
        let (clear, blocked, facing) = screened(&above, Vec3::new(3.0, 0.0, 0.0), None);
        assert!(clear && !blocked, "beside it");
        assert!((facing - 10.0 / 109f32.sqrt()).abs() < 1e-6, "{facing}");
        let (clear, _, _) = screened(&above, Vec3::new(0.3, 0.0, 0.0), Some(0));
        assert!(clear, "under the sphere, with the sphere left out");
        // Passing 0.95 from the centre: inside the sphere but not surely.
        let (clear, blocked, _) = screened(&above, Vec3::new(1.056, 0.0, 0.0), None);
        assert!(!clear && !blocked, "at the edge");
        // Between the sphere and the light: the segment stops before the sphere.
        assert!(screened(&above, Vec3::new(0.0, 5.0, 0.0), None).0);
        let sun = spheres(LightAt::Directional(Vec3::new(1.0, 1.0, 0.0).normalize()));
        let (clear, blocked, _) = screened(&sun, Vec3::new(-1.0, 0.0, 0.0), None);
        assert!(!clear && blocked, "in the shadow's path");
        assert!(
            screened(&sun, Vec3::new(2.5, 0.0, 0.0), None).0,
            "on the lit side"
        );
    }

    /// Clusters of floor points from under the sphere to well beside it: a cluster is told
    /// clear only where `screen` finds every one of its points clear, and the test is not
    /// idle (some clusters are told clear, some not).
    #[test]
    fn a_batch_is_told_clear_only_where_every_point_is() {
        let lights = [
            LightAt::Point(Vec3::new(2.0, 10.0, 1.0)),
            LightAt::Directional(Vec3::new(1.0, 1.0, 0.5).normalize()),
        ];
        let mut told = [0, 0];
        for light in lights {
            let spheres = spheres(light);
            for step in 0..400 {
                let centre = Vec3::new(
                    step as f32 * 0.05 - 10.0,
                    0.0,
                    (step % 17) as f32 * 0.4 - 3.0,
                );
                let spread = 0.05 + (step % 5) as f32 * 0.3;
                let points: Vec<Vec3> = (0..37)
                    .map(|k| {
                        let k = k as f32;
                        centre + spread * Vec3::new((k * 1.7).sin(), 0.0, (k * 2.3).cos())
                    })
                    .collect();
                let clear = spheres.all_clear(&points, None);
                told[usize::from(clear)] += 1;
                if clear {
                    for &p in &points {
                        assert!(screened(&spheres, p, None).0, "{p} of a clear cluster");
                    }
                }
                assert!(
                    spheres.all_clear(&points, Some(0)),
                    "with the sphere left out"
                );
            }
        }
        assert!(told[0] > 100 && told[1] > 100, "{told:?}");
    }

    #[test]
    fn extents_are_those_of_the_points_and_a_non_finite_one_shows_in_the_sum() {
        for count in [1, 2, 7, 8, 9, 23, 50] {
            let mut points: Vec<Vec3> = (0..count)
                .map(|k| {
                    let k = k as f32;
                    Vec3::new((k * 0.9).sin() * 5.0, k - 3.0, (k * 1.3).cos() * -2.0)
                })
                .collect();
            let [min, max, sum] = extents(bytemuck::cast_slice(&points));
            let fold = |pick: fn(Vec3, Vec3) -> Vec3| points.iter().copied().reduce(pick).unwrap();
            assert_eq!(
                (min, max),
                (fold(Vec3::min), fold(Vec3::max)),
                "{count} points"
            );
            assert!(sum.is_finite());
            points[count / 2].y = f32::NAN;
            assert!(
                !extents(bytemuck::cast_slice(&points))[2].is_finite(),
                "{count} points"
            );
            assert!(ball_around(&points).is_none());
        }
        assert!(ball_around(&[]).is_none());
    }
}
