//! Shadows on the rasterizer. Each light's shadow maps are depth maps, drawn by the frames' own
//! scan converter (`raster::render_depth`), of the objects that can cast from it (`casting`),
//! fitted to them where they lie between the light and the view (`light_views`). A lookup moves
//! off its surface only by its mesh's chord error and the bias, and each filter tap compares the
//! map with the receiver's tangent plane along that tap's ray (`filter`); points no caster's
//! sphere can shade (`caster_spheres`) and taps the depth blocks settle (`depth_blocks`) skip
//! the taps. A receiver that cannot shadow itself (a sphere, anything flat) leaves its own caster
//! out. Where every object is such a surface and exact edges are asked for, no map is drawn:
//! exact rays (`exact_rays`) cost less than lookups there. Bumps shade but do not move geometry,
//! so they cast no shadows. Numerics: f32 in each map's own light-relative space, whose origin is
//! subtracted from the camera's in f64; exact rays in f64.

mod bounds;
mod cache;
mod caster_spheres;
mod casting;
mod depth_blocks;
mod exact_rays;
mod filter;
mod light_views;

pub use bounds::{Bounds, object_bounds, seen_bounds, union_of};
pub use cache::ShadowCache;
use casting::SelfShadowing;
pub use casting::{can_shadow, casters};
use exact_rays::GRAZING;
pub use exact_rays::{ShadowRays, rays_cheaper_than_maps};
pub use filter::DepthFilter;

use crate::raster::{DepthMap, Viewport, render_depth};
use crate::scene::PreparedScene;
use crate::scene::{Camera, Light, Scene};
use crate::shade::Shadowing;
use caster_spheres::{CasterSpheres, SCREEN_LANES, Screened};
use depth_blocks::DepthBlocks;
use glam::Vec3;
use light_views::{MapView, cube_face_of, cube_face_size, directional_view, point_views};
use rayon::prelude::*;

/// The texels on a side a shadow map may have.
pub const MAP_SIZES: std::ops::RangeInclusive<u32> = 16..=8192;

/// The shadow knobs of a quality.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShadowSettings {
    /// Texels on a side of a light's map (a cube's faces get half).
    pub map_size: u32,
    /// Depth comparisons per lookup: 1, 4, 9 or 16.
    pub taps: u32,
    /// Normal offset past the filter's reach, in texels.
    pub bias_texels: f32,
    /// Whether a lookup the filter finds partly lit is settled by an exact shadow ray.
    pub exact_edges: bool,
    /// With exact edges, whether lights are shadowed by exact rays alone, drawing no map, where
    /// those cost less (`rays_cheaper_than_maps`).
    pub rays_where_cheaper: bool,
}

impl ShadowSettings {
    /// Whether these settings shadow `scene` by exact rays alone.
    fn by_rays(&self, scene: &Scene) -> bool {
        self.exact_edges && self.rays_where_cheaper && rays_cheaper_than_maps(scene)
    }
}

/// Every light's shadow maps for one view of a prepared scene.
pub struct ShadowMaps {
    /// Per light of the scene, its maps or rays; `None` where it shadows nothing the camera sees.
    lights: Vec<Option<LightShadows>>,
    /// Per object, where it cannot shadow itself, so its lookups leave it out.
    self_shadowing: Vec<SelfShadowing>,
    /// Per object, how far a lookup on it moves off the surface along its normal before the
    /// bias: twice its mesh's chord error, as the true surface may lie that far behind the
    /// chords the maps were drawn from (inside a bowl), and bend towards the light between taps.
    lifts: Vec<f32>,
    /// Per object, its largest curvature: how far a receiver's tangent plane stays true to it.
    curvatures: Vec<f32>,
    filter: DepthFilter,
    /// Texels a lookup moves off its surface along its normal, besides its lift.
    offset_texels: f32,
    /// Where set, lookups the filter finds partly lit are settled by exact shadow rays (and
    /// `LightShadows::Rays` settle every point by them).
    edges: Option<ShadowRays>,
}

/// How one light's shadows are found.
enum LightShadows {
    Maps(LightMaps),
    /// By exact rays alone (`rays_cheaper_than_maps`), cast only where a point's way to the
    /// light passes a caster's sphere.
    Rays(CasterSpheres),
}

/// One light's maps: one, or a cube's six faces.
struct LightMaps {
    faces: Vec<ShadowFace>,
    /// Around the casters the faces hold: a point clear of them all is lit without a lookup.
    casters: CasterSpheres,
}

struct ShadowFace {
    view: MapView,
    map: DepthMap,
    blocks: DepthBlocks,
    /// The camera's eye relative to the map's origin, so camera-relative points become
    /// map-relative by one f32 addition.
    from_camera: Vec3,
}

/// How much nearer than the map a receiver must be to count as behind it, relative to its
/// distance: room for the f32 rounding of the map's depths and the receiver's.
const DEPTH_ROUNDING: f32 = 5e-5;

/// The bytes the maps of `scene` take with `settings`, counted before any is drawn: a point
/// light's cube of six faces or single map, whichever is larger; none when nothing can shadow or
/// exact rays shadow it all.
pub fn map_bytes(scene: &Scene, settings: &ShadowSettings) -> u64 {
    if !scene.shadows || !can_shadow(scene) || settings.by_rays(scene) {
        return 0;
    }
    let map_size = settings.map_size;
    let texels = u64::from(map_size).pow(2);
    let per_light = |light: &Light| match light {
        Light::Directional { .. } => texels,
        Light::Point { .. } => texels.max(6 * u64::from(cube_face_size(map_size)).pow(2)),
    };
    let texels: u64 = scene.lights.iter().map(per_light).sum();
    texels.saturating_mul(DepthMap::BYTES_PER_TEXEL)
}

impl ShadowMaps {
    /// The maps for the camera's view of a full image of `viewport`'s shape; `None` when the
    /// scene has shadows off or nothing in it can shadow anything.
    pub fn build(
        prepared: &PreparedScene,
        camera: &Camera,
        viewport: Viewport,
        settings: ShadowSettings,
    ) -> Option<ShadowMaps> {
        let scene = &prepared.scene;
        if !scene.shadows || !can_shadow(scene) {
            return None;
        }
        let boxes = object_bounds(prepared);
        let whole = union_of(boxes.iter().copied())?;
        let seen = seen_bounds(camera, viewport.aspect(), &whole);
        let filter = DepthFilter::new(settings.taps);
        let offset_texels = settings.bias_texels;
        let lifts: Vec<f32> = prepared
            .objects
            .iter()
            .map(|o| 2.0 * o.mesh.chord_error)
            .collect();
        let largest_lift = lifts.iter().copied().fold(0.0, f32::max);
        let casting: Vec<Vec<usize>> = (scene.lights.iter())
            .map(|light| casters(prepared, &boxes, light))
            .collect();
        let by_rays = settings.by_rays(scene);
        let lights = (scene.lights.par_iter().zip(&casting))
            .map(|(light, casters)| {
                let region = shadowing_region(light, &seen?, &whole, casters, &boxes)?;
                if by_rays {
                    let margin = f32_rounding(camera, light, &whole);
                    let spheres =
                        CasterSpheres::new(prepared, casters, &boxes, light, camera.eye, margin);
                    return Some(LightShadows::Rays(spheres));
                }
                let views = match *light {
                    Light::Directional { towards, .. } => {
                        vec![directional_view(towards, &region, settings.map_size)]
                    }
                    Light::Point { position, .. } => {
                        point_views(position, &region, settings.map_size, filter.reach() + 1.0)
                    }
                };
                // A lookup reaches past a caster's outline by its taps, and its lift and its
                // neighbours' rounding, at most a few texels: the widest texel of the views.
                let widest = views.iter().map(|v| v.texel(v.deepest)).fold(0.0, f32::max);
                let texels = filter.reach() + 2.0 + offset_texels;
                let margin = texels * widest + 2.0 * largest_lift;
                let spheres =
                    CasterSpheres::new(prepared, casters, &boxes, light, camera.eye, margin);
                let maps = LightMaps::draw(prepared, camera, casters, views, spheres);
                Some(LightShadows::Maps(maps))
            })
            .collect();
        Some(ShadowMaps {
            lights,
            self_shadowing: (prepared.objects.iter())
                .map(|o| SelfShadowing::of(&o.surface, camera.eye))
                .collect(),
            lifts,
            curvatures: prepared
                .objects
                .iter()
                .map(|o| o.surface.max_curvature())
                .collect(),
            filter,
            offset_texels,
            edges: settings
                .exact_edges
                .then(|| ShadowRays::against(prepared, camera, casting))
                .flatten(),
        })
    }
}

/// How far, in world units, the f32 camera-relative points and spheres of a light's caster test
/// may be off: a ten-thousandth of the distances involved, far past f32's rounding.
fn f32_rounding(camera: &Camera, light: &Light, whole: &Bounds) -> f32 {
    let light_distance = match *light {
        Light::Point { position, .. } => position.distance(camera.eye),
        Light::Directional { .. } => 0.0,
    };
    let extent = whole.min.distance(whole.max) + whole.centre().distance(camera.eye);
    (1e-4 * (extent + light_distance)) as f32
}

/// The part of the scene a light's map must cover: its casters, as far as they lie between the
/// light and what the camera sees (`seen`). `None` when no caster does.
fn shadowing_region(
    light: &Light,
    seen: &Bounds,
    whole: &Bounds,
    casters: &[usize],
    boxes: &[Option<Bounds>],
) -> Option<Bounds> {
    let casting = union_of(casters.iter().map(|&index| boxes[index]))?;
    let towards_light = match *light {
        Light::Point { position, .. } => Bounds {
            min: position,
            max: position,
        },
        Light::Directional { towards, .. } => {
            let reach = whole.min.distance(whole.max);
            let away = crate::surface::normalize_or(towards, Vec3::Y).as_dvec3() * reach;
            Bounds {
                min: seen.min + away,
                max: seen.max + away,
            }
        }
    };
    casting.intersection(seen.union(towards_light))
}

impl LightMaps {
    fn draw(
        prepared: &PreparedScene,
        camera: &Camera,
        casters: &[usize],
        views: Vec<MapView>,
        spheres: CasterSpheres,
    ) -> LightMaps {
        let meshes: Vec<_> = casters
            .iter()
            .map(|&index| &prepared.objects[index])
            .map(|object| (object.surface.origin(), &object.mesh))
            .collect();
        let faces = views
            .into_par_iter()
            .map(|view| {
                let map = distances(render_depth(&meshes, &view.view), &view);
                ShadowFace {
                    blocks: DepthBlocks::new(&map),
                    map,
                    from_camera: (camera.eye - view.view.origin).as_vec3(),
                    view,
                }
            })
            .collect();
        LightMaps {
            faces,
            casters: spheres,
        }
    }

    /// The face a camera-relative point falls in.
    fn face_for(&self, p: Vec3) -> &ShadowFace {
        match self.faces.as_slice() {
            [only] => only,
            faces => &faces[cube_face_of(p + faces[0].from_camera)],
        }
    }
}

/// A perspective map's depths turned into distances from the light, texel by texel (depth over
/// the cosine of the texel's ray to the axis, exact). Compared by distance, a surface square to
/// the light's ray keeps one value across texels wherever it is in the map, as in an orthographic
/// map, so the normal offset that suffices at the map's centre suffices at its edges.
fn distances(mut map: DepthMap, view: &MapView) -> DepthMap {
    if !view.is_perspective() {
        return map;
    }
    let size = map.size as usize;
    let tan_half = view.texel_per_depth * size as f32 / 2.0;
    let across = |i: usize| ((i as f32 + 0.5) / size as f32 * 2.0 - 1.0) * tan_half;
    map.depth
        .par_chunks_mut(size.max(1))
        .enumerate()
        .for_each(|(j, row)| {
            let y = across(j);
            for (i, depth) in row.iter_mut().enumerate() {
                let x = across(i);
                *depth *= (x * x + y * y + 1.0).sqrt();
            }
        });
    map
}

/// What a lookup needs of the object it is on.
#[derive(Clone, Copy)]
struct Receiver {
    /// See `ShadowMaps::lifts`.
    lift: f32,
    /// How far the receiver's tangent plane is trusted, over the square root of a texel's
    /// width: a curved receiver departs from its tangent plane, and where the light grazes it
    /// the plane met by a tap's ray a texel away may lie far along the surface, past an
    /// occluder the surface itself never reaches. So the plane is trusted only as far as the
    /// surface keeps within the filter's reach of it, √(2·reach·texel/κ), twice over
    /// (infinite for a flat receiver).
    trust: f32,
}

impl ShadowFace {
    /// The fraction of the light reaching camera-relative point `p` with facing geometric
    /// normal `n` on `receiver`, and whether the light grazes the surface there.
    fn reach(&self, p: Vec3, n: Vec3, maps: &ShadowMaps, receiver: Receiver) -> MapAnswer {
        let relative = p + self.from_camera;
        if self.view.clearly_misses(relative) {
            // No caster the map holds lies between this point and the light.
            return MapAnswer::LIT;
        }
        let facing = n.dot(self.towards_light(relative));
        if facing.is_nan() || facing <= 0.0 {
            // The light is behind the side of the surface that is seen: the surface itself
            // blocks it (the shader's terminator, which no map lookup can undo).
            return MapAnswer::DARK;
        }
        let lit = self.lit_fraction(relative, n, maps, receiver, facing);
        MapAnswer {
            lit,
            grazing: facing < GRAZING,
        }
    }

    /// `reach`'s fraction where the surface faces the light (`facing`, the cosine, positive).
    #[inline(always)]
    fn lit_fraction(
        &self,
        relative: Vec3,
        n: Vec3,
        maps: &ShadowMaps,
        receiver: Receiver,
        facing: f32,
    ) -> f32 {
        let texel = self.view.texel(self.view.view.forward.dot(relative));
        let lifted = relative + n * (maps.offset_texels * texel + receiver.lift);
        let Some((x, y)) = self.texel_position(lifted) else {
            return 1.0;
        };
        let lookup = Lookup {
            x,
            y,
            centre: self.measured(lifted),
            // Rounding grows with the distances compared and with the map's extent there (an
            // orthographic map's depths are relative to its middle, so they pass through zero).
            rounding: DEPTH_ROUNDING * (texel * self.view.view.size as f32),
            trusted: receiver.trust * texel.sqrt(),
        };
        if let Some(all_taps) = self.settled_by_blocks(&lookup, maps, texel, facing) {
            return all_taps;
        }
        let plane = self.view.tap_plane(lifted, n);
        let (centre, trusted) = (lookup.centre, lookup.trusted);
        let receiver = |i, j| {
            let along = plane.at(i, j).clamp(centre - trusted, centre + trusted);
            along - DEPTH_ROUNDING * along.abs() - lookup.rounding
        };
        maps.filter.fraction(&self.map, x, y, receiver)
    }

    /// The unit direction from a map-relative point to the light.
    fn towards_light(&self, relative: Vec3) -> Vec3 {
        if self.view.is_perspective() {
            -relative.normalize_or_zero()
        } else {
            -self.view.view.forward
        }
    }

    /// Where a map-relative point falls on the map, in texels (texel (i, j) centred at
    /// (i, j)); `None` behind the light, or past a fitted map's edge, where no point the camera
    /// sees lies and nothing shadows it.
    fn texel_position(&self, q: Vec3) -> Option<(f32, f32)> {
        let view = &self.view.view;
        let clip = view.view_projection * q.extend(1.0);
        if clip.w.is_nan() || clip.w <= 0.0 {
            return None;
        }
        let size = view.size as f32;
        let x = (clip.x / clip.w * 0.5 + 0.5) * size - 0.5;
        let y = (0.5 - clip.y / clip.w * 0.5) * size - 0.5;
        let outside = -1.0..=size;
        let on_map = outside.contains(&x) && outside.contains(&y);
        (self.view.cube_face || on_map).then_some((x, y))
    }

    /// A map-relative point's depth as the map measures it.
    fn measured(&self, q: Vec3) -> f32 {
        if self.view.is_perspective() {
            q.length()
        } else {
            self.view.view.forward.dot(q)
        }
    }

    /// Every tap's answer at once, where the receiver's depth over the taps lies wholly in
    /// front of or behind every caster around them. Its plane rises at most tan θ a unit
    /// across (half again for a perspective map's spreading rays).
    fn settled_by_blocks(
        &self,
        lookup: &Lookup,
        maps: &ShadowMaps,
        texel: f32,
        facing: f32,
    ) -> Option<f32> {
        let reach = maps.filter.reach() + 1.0;
        let sine = (1.0 - facing * facing).max(0.0).sqrt();
        let spreading = if self.view.is_perspective() { 1.5 } else { 1.0 };
        let rounding = 2.0 * (DEPTH_ROUNDING * lookup.centre.abs() + lookup.rounding);
        let spread = (reach * texel * spreading * sine / facing).min(lookup.trusted) + rounding;
        let last = self.map.size - 1;
        let texel_at = |v: f32| (v.max(0.0) as u32).min(last);
        let (least, greatest) = self.blocks.range(
            (texel_at(lookup.x - reach), texel_at(lookup.y - reach)),
            (texel_at(lookup.x + reach), texel_at(lookup.y + reach)),
        );
        if lookup.centre + spread <= least {
            Some(1.0)
        } else if lookup.centre - spread > greatest {
            Some(0.0)
        } else {
            None
        }
    }
}

/// What a map says of a point: the fraction of the light reaching it, and whether the light
/// grazes its surface (its cosine below `GRAZING`).
#[derive(Clone, Copy)]
struct MapAnswer {
    lit: f32,
    grazing: bool,
}

impl MapAnswer {
    /// Lit, settled without the light's direction: no caster lies between point and light.
    const LIT: MapAnswer = MapAnswer {
        lit: 1.0,
        grazing: false,
    };
    /// In shadow, settled without a map: the way to the light passes well inside a sphere.
    const DARK: MapAnswer = MapAnswer {
        lit: 0.0,
        grazing: false,
    };

    /// Settled by the receiver alone, its way passing every other caster: lit where the light
    /// is in front of it (its cosine `facing`).
    fn facing(facing: f32) -> MapAnswer {
        match facing > 0.0 {
            true => MapAnswer {
                lit: 1.0,
                grazing: facing < GRAZING,
            },
            false => MapAnswer::DARK,
        }
    }
}

/// One lookup on a map: where it falls, the receiver's depth there, how much rounding to allow
/// and how far the receiver's plane is trusted.
struct Lookup {
    x: f32,
    y: f32,
    centre: f32,
    /// The rounding allowed for the map's extent (see `DEPTH_ROUNDING`).
    rounding: f32,
    trusted: f32,
}

impl Shadowing for ShadowMaps {
    fn casts(&self, light: usize) -> bool {
        self.lights.get(light).is_some_and(Option::is_some)
    }

    fn reaching(
        &self,
        light: usize,
        object: usize,
        points: &[Vec3],
        normals: &[Vec3],
        out: &mut [f32],
    ) {
        let Some(Some(shadows)) = self.lights.get(light) else {
            out.fill(1.0);
            return;
        };
        let own = self.own_caster(object, points, normals);
        match shadows {
            LightShadows::Rays(spheres) if spheres.all_clear(points, own) => {
                // The way passes every caster but the receiver, which blocks it only past its
                // terminator, where the shader stops the light.
                out.fill(1.0);
            }
            LightShadows::Rays(spheres) => {
                let rays = (self.edges.as_ref()).expect("rays are drawn with exact edges");
                let mut screened = Screened::default();
                for (first, out) in (0..)
                    .step_by(SCREEN_LANES)
                    .zip(out.chunks_mut(SCREEN_LANES))
                {
                    let (points, normals) = (&points[first..], &normals[first..]);
                    spheres.screen(points, normals, own, &mut screened);
                    for (k, out) in out.iter_mut().enumerate() {
                        let (p, n, facing) = (points[k], normals[k], screened.facing[k]);
                        // Past the terminator the receiver itself blocks the light.
                        let lit = facing > 0.0
                            && (screened.clear[k]
                                || !(screened.blocked[k] || rays.blocked_at(light, p, n, own)));
                        *out = if lit { 1.0 } else { 0.0 };
                    }
                }
            }
            LightShadows::Maps(maps) => {
                self.reaching_by_maps(maps, (light, object, own), (points, normals), out)
            }
        }
    }
}

impl ShadowMaps {
    /// How many maps are drawn, a cube's faces each counted (none for a light shadowed by rays).
    pub fn maps_drawn(&self) -> usize {
        let maps = |light: &LightShadows| match light {
            LightShadows::Maps(maps) => maps.faces.len(),
            LightShadows::Rays(_) => 0,
        };
        self.lights.iter().flatten().map(maps).sum()
    }

    /// The caster a lookup on `object` leaves out: itself, where it cannot shadow itself (once
    /// the light is seen to reach the side of it that is seen).
    fn own_caster(&self, object: usize, points: &[Vec3], normals: &[Vec3]) -> Option<usize> {
        let self_shadowing = self.self_shadowing.get(object);
        self_shadowing.and_then(|s| s.left_out(object, points, normals))
    }

    /// `reaching` through a light's maps, for fragments of `object` at `points` with facing
    /// `normals`, leaving its own caster `own` out.
    fn reaching_by_maps(
        &self,
        maps: &LightMaps,
        (light, object, own): (usize, usize, Option<usize>),
        (points, normals): (&[Vec3], &[Vec3]),
        out: &mut [f32],
    ) {
        if maps.casters.all_clear(points, own) {
            for ((out, &p), &n) in out.iter_mut().zip(points).zip(normals) {
                let lookup = match own {
                    None => MapAnswer::LIT,
                    Some(_) => MapAnswer::facing(maps.casters.facing(p, n)),
                };
                *out = self.settled_at_edges(lookup, light, p, n);
            }
            return;
        }
        let curvature = self.curvatures.get(object).copied().unwrap_or(0.0);
        let receiver = Receiver {
            lift: self.lifts.get(object).copied().unwrap_or(0.0),
            trust: match curvature {
                0.0 => f32::INFINITY,
                curvature => 2.0 * (2.0 * self.filter.reach() / curvature).sqrt(),
            },
        };
        let mut screened = Screened::default();
        for (first, out) in (0..)
            .step_by(SCREEN_LANES)
            .zip(out.chunks_mut(SCREEN_LANES))
        {
            let (points, normals) = (&points[first..], &normals[first..]);
            maps.casters.screen(points, normals, own, &mut screened);
            for (k, out) in out.iter_mut().enumerate() {
                let (p, n) = (points[k], normals[k]);
                let lookup = match (screened.clear[k], own) {
                    (true, None) => MapAnswer::LIT,
                    (true, Some(_)) => MapAnswer::facing(screened.facing[k]),
                    _ if screened.blocked[k] => MapAnswer::DARK,
                    (false, _) => maps.face_for(p).reach(p, n, self, receiver),
                };
                *out = self.settled_at_edges(lookup, light, p, n);
            }
        }
    }

    /// A map's answer, or where it is uncertain and exact edges are asked for, the exact ray's.
    fn settled_at_edges(&self, lookup: MapAnswer, light: usize, p: Vec3, n: Vec3) -> f32 {
        // The filter's edge band, where a map cannot place an edge closer than its texels, and
        // the band where the light grazes the surface, where a map's depths cannot tell a
        // surface from its own shadow: there an exact shadow ray settles it.
        let uncertain = (lookup.lit > 0.0 && lookup.lit < 1.0) || lookup.grazing;
        match self.edges.as_ref().filter(|_| uncertain) {
            Some(rays) if rays.blocked_at(light, p, n, None) => 0.0,
            Some(_) => 1.0,
            None => lookup.lit,
        }
    }
}
