//! Every knob that trades speed for accuracy, settable one by one, and the named presets.
//!
//! A `Quality` turns a scene into what the renderer needs: the prepared meshes (tessellation,
//! fixed or adaptive to the view; texture filter override), the render target (interpolation)
//! and the fragment program (normal form, gradient method, exact frame or vertex normals).
//! Samples per pixel are carried here for the supersampled renderer to read.

mod adaptive;
mod displaced_grid;
mod knob_settings;
mod preset;

pub use adaptive::{MAX_ADAPTIVE_DENSITY, adaptive_density, projected_chord_error};
pub use displaced_grid::{DisplacedGrid, displaced_grid};
pub use knob_settings::{
    MAX_DENSITY, MAX_SAMPLES, MAX_SHADOW_BIAS, SHADOW_MAP_SIZES, SHADOW_TAPS, check_quality,
    knob_names,
};
pub use preset::Preset;

use crate::memory_budget::{BYTES_PER_TRIANGLE, MemoryUse, OverBudget};
use crate::pattern::Precision;
use crate::raster::{Interpolation, RenderTarget, Viewport};
use crate::scene::Camera;
use crate::scene::{Material, Object, Scene, Texturing};
use crate::scene::{PreparedObject, PreparedScene};
use crate::shade::{
    BumpHeights, GradientMethod, LitShader, Neighbours, NormalForm, Reach, ReachShape, Shadowing,
    Showing, SurfacePointSource, VertexNormals,
};
use crate::shadow::{ShadowMaps, ShadowSettings};
use crate::surface::{Surface, Tessellation, push_out_to_hull};
use crate::texture::Filter;
use glam::DVec3;
use rayon::prelude::*;
use std::sync::Arc;

/// The normal the shader starts from before the bump perturbs it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum NormalSource {
    /// The surface's exact frame at the fragment's (u,v).
    #[default]
    ExactFrame,
    /// Position and normal interpolated across each triangle from its vertices (Phong shading).
    InterpolatedVertex,
}

/// Which pixels a curved surface covers, and which surface is in front where two meet.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Coverage {
    /// The mesh's: its chords cut inside the true outline, by up to their chord error.
    #[default]
    Mesh,
    /// The true surfaces': curved meshes are tessellated as hulls around their surfaces, and
    /// each fragment is settled on the true surface its ray meets first (or the background).
    Exact,
}

/// One setting of every speed/accuracy knob (a still's recipe records it as a TOML table).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case", deny_unknown_fields)]
pub struct Quality {
    /// Cells per half turn of curved surfaces, for every object (where refinement starts when
    /// `adaptive_tolerance_px` is set).
    pub tessellation: u32,
    /// Screen-space adaptive tessellation: each object's density is refined from `tessellation`
    /// until its chords deviate from the surface by at most this many pixels in this view.
    pub adaptive_tolerance_px: Option<f32>,
    /// Samples per pixel (1, 4, 16, …), averaged in linear light by the supersampled renderer.
    pub samples: u32,
    /// Adaptive supersampling: one pass at pixel centres, then `samples` only where a pixel and
    /// a neighbour differ in coverage or by more than this contrast (in √linear units per
    /// channel, roughly perceptual); `None` supersamples every pixel.
    #[serde(default)]
    pub adaptive_samples: Option<f32>,
    /// Texture filter for every image texture; `None` keeps each scene's own.
    pub filter: Option<Filter>,
    pub gradient: GradientMethod,
    /// The float patterns are evaluated in (recipes from before this knob read as the default).
    #[serde(default)]
    pub pattern_precision: Precision,
    pub normal_form: NormalForm,
    pub normals: NormalSource,
    /// Where fragments of curved surfaces are shaded: at the (u,v) interpolated across their
    /// triangle, or where each fragment's own ray meets the true surface (recipes from before
    /// this knob read as interpolated, as they were drawn).
    #[serde(default)]
    pub surface_point: SurfacePointSource,
    /// Whose outline and depth decide coverage: the mesh's, or the true surfaces' (which also
    /// shades at the true surface point). Recipes from before this knob read as the mesh's.
    #[serde(default)]
    pub coverage: Coverage,
    pub interpolation: Interpolation,
    /// Texels on a side of each light's shadow map (and of each of a point light's six cube
    /// faces, when it needs a cube, up to 2048).
    #[serde(default = "interactive_shadow_map")]
    pub shadow_map: u32,
    /// Depth comparisons per shadow lookup: 1 (the nearest texel, a hard stair-stepped edge),
    /// 4 (bilinear), 9 or 16 (wider, softer filters).
    #[serde(default = "interactive_shadow_taps")]
    pub shadow_taps: u32,
    /// How far a shadow lookup moves off its surface along the normal before comparing, in
    /// texels, past what the mesh's chord error needs: room for a surface bending towards its
    /// light between the filter's taps. Too little and such surfaces shadow themselves in
    /// specks (acne); too much and shadows come loose from their casters, and lookups near a
    /// contact move into the other object.
    #[serde(default = "interactive_shadow_bias")]
    pub shadow_bias: f32,
    /// How a lookup the filter finds partly lit (on a shadow's edge) is settled: `filtered`
    /// keeps the filter's fraction (a soft edge a few texels wide), `exact` casts a shadow ray
    /// against the true surfaces (the reference's hard edge). Recipes from before this knob
    /// read as filtered, as they were drawn.
    #[serde(default)]
    pub shadow_edges: ShadowEdges,
    /// How far, in pixels of the view, a displaced surface's triangles may stray from it: its
    /// grid is refined until they do not (within the memory budget).
    #[serde(default = "interactive_displace_tolerance")]
    pub displace_tolerance_px: f32,
}

/// How the edges of shadows are drawn (see `Quality::shadow_edges`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ShadowEdges {
    #[default]
    Filtered,
    Exact,
}

fn interactive_shadow_map() -> u32 {
    Quality::interactive().shadow_map
}

fn interactive_shadow_taps() -> u32 {
    Quality::interactive().shadow_taps
}

fn interactive_shadow_bias() -> f32 {
    Quality::interactive().shadow_bias
}

fn interactive_displace_tolerance() -> f32 {
    Quality::interactive().displace_tolerance_px
}

/// The most triangles one displaced surface is cut into, whatever the budget: past this a
/// still takes seconds to cut and the workbench stops being immediate.
pub const MOST_DISPLACED_TRIANGLES: u64 = 1 << 20;

impl Default for Quality {
    fn default() -> Self {
        Quality::interactive()
    }
}

impl Quality {
    /// Coarse meshes shaded as they are (their outline, their interpolated (u,v)), Blinn's
    /// normal, filtered shadow edges and nearest texels, for slow machines and huge terminals.
    /// It keeps
    /// perspective-correct (u,v): affine saves no measurable time and is off by whole pattern
    /// periods on the two-triangle planes (`bumpwork bench` shows both); and the exact frame:
    /// interpolated vertex normals are slower, a point location per fragment against two
    /// `sincos`.
    pub fn draft() -> Quality {
        Quality {
            tessellation: 16,
            filter: Some(Filter::Nearest),
            shadow_map: 512,
            shadow_taps: 1,
            shadow_edges: ShadowEdges::Filtered,
            normal_form: NormalForm::Blinn,
            surface_point: SurfacePointSource::Interpolated,
            coverage: Coverage::Mesh,
            displace_tolerance_px: 1.0,
            ..Quality::interactive()
        }
    }

    /// What the renderer does by default: density 64 meshes settled on the true surfaces (exact
    /// coverage and surface points), one sample, each scene's filter, exact frame and
    /// derivatives, the full normal of the bumped surface, exact shadow edges.
    pub fn interactive() -> Quality {
        Quality {
            tessellation: Tessellation::default().density,
            adaptive_tolerance_px: None,
            samples: 1,
            adaptive_samples: None,
            filter: None,
            gradient: GradientMethod::Exact,
            pattern_precision: Precision::Fastest,
            normal_form: NormalForm::Full,
            normals: NormalSource::ExactFrame,
            surface_point: SurfacePointSource::Exact,
            coverage: Coverage::Exact,
            interpolation: Interpolation::PerspectiveCorrect,
            shadow_map: 1024,
            shadow_taps: 4,
            shadow_bias: 0.0,
            shadow_edges: ShadowEdges::Exact,
            displace_tolerance_px: 0.5,
        }
    }

    /// `interactive` with 16 samples, density 128 refined where chords would stray more than
    /// half a pixel, and twice the shadow map.
    pub fn high() -> Quality {
        Quality {
            tessellation: 128,
            adaptive_tolerance_px: Some(0.5),
            samples: 16,
            shadow_map: 2048,
            displace_tolerance_px: 0.25,
            ..Quality::interactive()
        }
    }

    /// Density 256, refined until chords are within a tenth of a pixel; 64 samples and the
    /// reference's shading (patterns in f64): the closest the rasterizer gets to the ray-cast
    /// reference.
    pub fn exact() -> Quality {
        Quality {
            tessellation: 256,
            adaptive_tolerance_px: Some(0.1),
            samples: 64,
            pattern_precision: Precision::Double,
            shadow_map: 4096,
            displace_tolerance_px: 0.1,
            ..Quality::high()
        }
    }

    /// A preset by name, or a message listing the names (a command-line value parser).
    pub fn named(name: &str) -> Result<Quality, String> {
        Preset::named(name).map(Preset::quality)
    }

    /// Tessellates the scene for this view (after applying the filter override), once the
    /// meshes, the scene's images and lights and `output_bytes` of buffers are known to fit the
    /// memory budget together.
    pub fn prepare(
        &self,
        mut scene: Scene,
        camera: &Camera,
        viewport: Viewport,
        output_bytes: u64,
    ) -> Result<PreparedScene, OverBudget> {
        if let Some(filter) = self.filter {
            override_filter(&mut scene, filter);
        }
        let tessellations: Vec<Tessellation> = scene
            .objects
            .par_iter()
            .map(|o| Tessellation {
                density: self.density_for(&o.surface, camera, viewport),
            })
            .collect();
        let memory = |triangles| MemoryUse {
            image_bytes: scene.image_bytes(),
            triangles,
            lights: scene.lights.len() as u64,
            output_bytes,
            shadow_map_bytes: crate::shadow::map_bytes(&scene, &self.shadow_settings()),
        };
        let budget = crate::memory_budget::budget_bytes();
        let undisplaced = |(o, &tessellation): (&Object, &Tessellation)| match o.displace {
            true => 0,
            false => o.surface.triangle_count(tessellation),
        };
        let fixed = memory(
            scene
                .objects
                .iter()
                .zip(&tessellations)
                .map(undisplaced)
                .sum(),
        );
        fixed.check(budget)?;
        let displaced_count = scene.objects.iter().filter(|o| o.displace).count().max(1) as u64;
        let spare = budget.saturating_sub(fixed.total()) / BYTES_PER_TRIANGLE / displaced_count;
        let most_triangles = spare.min(MOST_DISPLACED_TRIANGLES);
        let (grids, notices) = self.displaced_grids(&scene, (camera, viewport), most_triangles);
        let triangles = scene
            .objects
            .iter()
            .zip(&tessellations)
            .zip(&grids)
            .map(|((o, &tessellation), grid)| match grid {
                Some(grid) => grid.mesh.indices.len() as u64,
                None => o.surface.triangle_count(tessellation),
            })
            .fold(0, u64::saturating_add);
        memory(triangles).check(budget)?;
        let objects = (scene.objects.par_iter().zip(tessellations).zip(grids))
            .map(|((o, tessellation), grid)| self.prepared_object(o, tessellation, grid))
            .collect();
        Ok(PreparedScene {
            scene,
            objects,
            notices,
        })
    }

    /// Each object's displaced surface, where it asks for one and can have it, and a notice for
    /// each that cannot for its heights.
    fn displaced_grids(
        &self,
        scene: &Scene,
        view: (&Camera, Viewport),
        most_triangles: u64,
    ) -> (Vec<Option<DisplacedGrid>>, Vec<String>) {
        let attempts: Vec<Result<Option<DisplacedGrid>, String>> = (scene.objects.par_iter())
            .map(|o| self.displaced(o, scene.time, view, most_triangles))
            .collect();
        let mut notices = Vec::new();
        let grids = (attempts.into_iter().enumerate())
            .map(|(index, attempt)| {
                attempt.unwrap_or_else(|why| {
                    notices.push(format!("object {}: {why}", index + 1));
                    None
                })
            })
            .collect();
        (grids, notices)
    }

    /// `object` as the rasterizer draws it: its displaced surface and mesh where it has one,
    /// else its surface tessellated (as a hull around it, with exact coverage).
    fn prepared_object(
        &self,
        object: &Object,
        tessellation: Tessellation,
        grid: Option<DisplacedGrid>,
    ) -> PreparedObject {
        if let Some(grid) = grid {
            return PreparedObject {
                surface: Surface::Displaced(grid.surface),
                // The bump is the geometry now: its normal is the displaced frame's.
                material: Material {
                    bump: None,
                    ..object.material.clone()
                },
                mesh: grid.mesh,
            };
        }
        let mut mesh = object.surface.tessellate(tessellation);
        if self.coverage == Coverage::Exact {
            push_out_to_hull(&object.surface, &mut mesh);
        }
        PreparedObject {
            surface: object.surface.clone(),
            material: object.material.clone(),
            mesh,
        }
    }

    /// The displaced surface `object` asks for, cut for this view in at most `most_triangles`
    /// triangles; `None` where it does not ask, or cannot be displaced (see
    /// `Object::displacement_refused`), and why not where its heights are out of bounds.
    fn displaced(
        &self,
        object: &Object,
        time: f64,
        view: (&Camera, Viewport),
        most_triangles: u64,
    ) -> Result<Option<DisplacedGrid>, String> {
        let bump = object.material.bump.as_ref().filter(|_| object.displace);
        let Some(field) = bump.and_then(|bump| BumpHeights::new(bump, time)) else {
            return Ok(None);
        };
        let tolerance = self.displace_tolerance_px;
        let field = Arc::new(field);
        displaced_grid(&object.surface, field, view, tolerance, most_triangles).transpose()
    }

    /// The tessellation density this quality gives a surface in this view.
    pub fn density_for(
        &self,
        surface: &crate::surface::Surface,
        camera: &Camera,
        viewport: Viewport,
    ) -> u32 {
        match self.adaptive_tolerance_px {
            Some(tolerance) => {
                let start = self.tessellation;
                adaptive_density(surface, camera, viewport, tolerance, start)
            }
            None => self.tessellation,
        }
    }

    /// The whole `viewport`, one sample per pixel centre, with this quality's interpolation.
    pub fn target<'a>(&self, camera: &'a Camera, viewport: Viewport) -> RenderTarget<'a> {
        RenderTarget::new(camera, viewport).with_interpolation(self.interpolation)
    }

    /// The scene's lit picture at time 0 (`shader_showing`).
    pub fn shader(
        &self,
        prepared: &PreparedScene,
        camera: &Camera,
        viewport: Viewport,
    ) -> LitShader {
        self.shader_showing(prepared, camera, viewport, Showing::default())
    }

    /// The scene's fragment program with this quality's shading knobs, showing `showing`, and
    /// its shadow maps for the camera's view of a full image of `viewport`'s size.
    pub fn shader_showing(
        &self,
        prepared: &PreparedScene,
        camera: &Camera,
        viewport: Viewport,
        showing: Showing,
    ) -> LitShader {
        let maps = ShadowMaps::build(prepared, camera, viewport, self.shadow_settings());
        self.shader_with_maps(prepared, camera, maps.map(Arc::new), showing)
    }

    /// `shader_showing` with shadow maps already drawn (kept from an earlier frame:
    /// `ShadowCache`).
    pub fn shader_with_maps(
        &self,
        prepared: &PreparedScene,
        camera: &Camera,
        maps: Option<Arc<ShadowMaps>>,
        showing: Showing,
    ) -> LitShader {
        let mut shader = LitShader::new(&prepared.scene, camera);
        (shader.mode, shader.time) = (showing.mode, showing.time);
        self.configure(&mut shader, prepared);
        shader.shadows = maps.map(|maps| maps as Arc<dyn Shadowing>);
        shader
    }

    pub fn shadow_settings(&self) -> ShadowSettings {
        ShadowSettings {
            map_size: self.shadow_map,
            taps: self.shadow_taps,
            bias_texels: self.shadow_bias,
            exact_edges: self.shadow_edges == ShadowEdges::Exact,
            rays_where_cheaper: true,
        }
    }

    /// Sets the shading knobs of an existing program (keeping its mode and time).
    pub fn configure(&self, shader: &mut LitShader, prepared: &PreparedScene) {
        shader.normal_form = self.normal_form;
        shader.gradient = self.gradient;
        shader.pattern_precision = self.pattern_precision;
        shader.surface_point = match self.coverage {
            Coverage::Exact => SurfacePointSource::Exact,
            Coverage::Mesh => self.surface_point,
        };
        shader.exact_coverage = match self.coverage {
            Coverage::Exact => Some(Arc::new(neighbours(prepared))),
            Coverage::Mesh => None,
        };
        shader.vertex_normals = match self.normals {
            NormalSource::ExactFrame => None,
            NormalSource::InterpolatedVertex => Some(vertex_normals(prepared)),
        };
    }

    /// Every knob on one line, for tables and status lines.
    pub fn describe(&self) -> String {
        let tessellation = match self.adaptive_tolerance_px {
            Some(px) => format!("adaptive<{px}px"),
            None => format!("density {}", self.tessellation),
        };
        let filter = self
            .filter
            .map_or("scene".to_string(), |f| format!("{f:?}"));
        format!(
            "{tessellation}, {} spp, filter {}, gradient {}, patterns {}, {:?} normal, {:?}, \
             {:?} surface point, {:?} coverage, {:?}, shadow map {} × {} taps",
            self.samples,
            filter.to_lowercase(),
            self.gradient.name(),
            self.pattern_precision.name(),
            self.normal_form,
            self.normals,
            self.surface_point,
            self.coverage,
            self.interpolation,
            self.shadow_map,
            self.shadow_taps,
        )
    }
}

fn override_filter(scene: &mut Scene, filter: Filter) {
    for object in &mut scene.objects {
        if let Some(Texturing::Image(image)) = &mut object.material.texture {
            image.sampler.filter = filter;
        }
    }
}

/// Objects whose boxes, grown by their chord errors, overlap: where one's true surface may pass
/// in front of the other's mesh.
fn neighbours(prepared: &PreparedScene) -> Neighbours {
    let bounds = crate::shadow::object_bounds(prepared);
    // A displaced surface's mesh is the surface (within its tolerance): the depth buffer
    // settles it against its neighbours, with no ray search.
    let displaced = |i: usize| matches!(prepared.objects[i].surface, Surface::Displaced(_));
    let overlap = |i: usize, j: usize| match (bounds[i], bounds[j]) {
        _ if displaced(i) || displaced(j) => false,
        (Some(a), Some(b)) => a.intersection(b).is_some(),
        _ => false,
    };
    let reaches = prepared
        .objects
        .iter()
        .zip(&bounds)
        .map(|(object, bounds)| {
            let reach = f64::from(object.mesh.chord_error);
            let ball = match (&object.surface, bounds) {
                (Surface::Sphere(s), _) => (DVec3::ZERO, s.radius as f64 + reach),
                (_, Some(b)) => (
                    b.centre() - object.surface.origin(),
                    b.min.distance(b.max) / 2.0,
                ),
                (_, None) => (DVec3::ZERO, f64::INFINITY),
            };
            let shape = match &object.surface {
                Surface::Sphere(_) => ReachShape::Closed,
                Surface::Plane(p) => ReachShape::Flat(p.normal),
                Surface::Triangle(t) => ReachShape::Flat(t.normal),
                _ => ReachShape::Open,
            };
            Reach {
                ball: (ball.0.as_vec3(), ball.1 as f32),
                shape,
            }
        })
        .collect();
    Neighbours::new(bounds.len(), overlap, reaches)
}

fn vertex_normals(prepared: &PreparedScene) -> Arc<[VertexNormals]> {
    prepared
        .objects
        .par_iter()
        .map(|o| VertexNormals::new(&o.surface, &o.mesh))
        .collect::<Vec<_>>()
        .into()
}
