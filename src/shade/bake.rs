//! A material sampled over a (u,v) rectangle of its surface on a grid: colours, bump heights and
//! tangent-space normals as images, for renderers that take image maps (`bumpwork bake`, the
//! POV-Ray scene export). Row 0 is the top of the image, v = max; column 0 is u = min; samples
//! sit at cell centres.

use super::pattern_batch::{PatternBatch, Sites};
use crate::raster::Fragment;
use crate::scene::{Bump, BumpSource, Material, Texturing};
use crate::surface::{Frame, Frames, Surface};
use crate::texture::{Footprint, SurfacePoint, TextureMapping};
use glam::{Vec2, Vec3};

/// The (u,v) rectangle a bake covers and its grid of samples (at cell centres).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BakeGrid {
    /// (u,v) at the left of the first column and the bottom of the last row.
    pub min: Vec2,
    /// (u,v) at the right of the last column and the top of the first row.
    pub max: Vec2,
    pub width: u32,
    pub height: u32,
}

impl BakeGrid {
    /// The whole domain of `surface`, `side` samples square.
    pub fn whole(surface: &Surface, side: u32) -> BakeGrid {
        let domain = surface.domain();
        BakeGrid {
            min: domain.min,
            max: domain.max,
            width: side,
            height: side,
        }
    }

    /// (u,v) of sample (`column`, `row`).
    pub fn uv(&self, column: u32, row: u32) -> Vec2 {
        let extent = self.max - self.min;
        Vec2::new(
            self.min.x + (column as f32 + 0.5) / self.width as f32 * extent.x,
            self.max.y - (row as f32 + 0.5) / self.height as f32 * extent.y,
        )
    }

    fn samples(&self) -> usize {
        self.width as usize * self.height as usize
    }
}

/// The (u,v) at each cell of one grid row, and the surface frames there.
fn grid_row(surface: &Surface, grid: &BakeGrid, row: u32) -> (Vec<Fragment>, Frames) {
    let fragments: Vec<Fragment> = (0..grid.width)
        .map(|column| Fragment {
            object: 0,
            uv: grid.uv(column, row),
            duv_dx: Vec2::ZERO,
            duv_dy: Vec2::ZERO,
            depth: 1.0,
            x: column,
            y: row,
        })
        .collect();
    let frames = fragments
        .iter()
        .map(|f| surface.frame(f.uv.x, f.uv.y))
        .collect();
    (fragments, frames)
}

fn surface_point(frame: &Frame, uv: Vec2, time: f64) -> SurfacePoint {
    SurfacePoint {
        p: frame.p,
        pu: frame.pu,
        pv: frame.pv,
        uv,
        time: time as f32,
    }
}

/// The material's colour (linear RGB) over the whole domain, `side` samples square.
pub fn bake_color(surface: &Surface, material: &Material, time: f64, side: u32) -> Vec<Vec3> {
    bake_color_on(surface, material, time, &BakeGrid::whole(surface, side))
}

/// The material's colour (linear RGB) over `grid`: its texture where it has one.
pub fn bake_color_on(
    surface: &Surface,
    material: &Material,
    time: f64,
    grid: &BakeGrid,
) -> Vec<Vec3> {
    let mut batch = PatternBatch::default();
    let mut out = Vec::with_capacity(grid.samples());
    let group: Vec<u32> = (0..grid.width).collect();
    let mut colors = vec![Vec3::ZERO; grid.width as usize];
    for row in 0..grid.height {
        let (fragments, frames) = grid_row(surface, grid, row);
        match &material.texture {
            None => colors.fill(material.color),
            Some(Texturing::Pattern(binding)) => {
                let at = Sites {
                    fragments: &fragments,
                    group: &group,
                    frames: &frames,
                };
                batch.colors(binding, at, time, &mut colors);
            }
            Some(Texturing::Image(image)) => {
                for ((color, fragment), frame) in
                    colors.iter_mut().zip(&fragments).zip(frames.iter())
                {
                    let st = image
                        .mapping
                        .map(&surface_point(&frame, fragment.uv, time))
                        .st;
                    *color = image
                        .texture
                        .sample(&image.sampler, st, Footprint::POINT)
                        .truncate();
                }
            }
        }
        out.extend_from_slice(&colors);
    }
    out
}

/// The bump height B (times strength, sign applied) over the whole domain; `None` for slope
/// patterns, which define no height.
pub fn bake_height(surface: &Surface, bump: &Bump, time: f64, side: u32) -> Option<Vec<f32>> {
    bake_bump_on(surface, bump, time, &BakeGrid::whole(surface, side)).heights
}

/// A bump baked over a grid, strength and sign applied.
pub struct BakedBump {
    /// B at each sample; `None` for slope patterns and normal maps, which define no height.
    pub heights: Option<Vec<f32>>,
    /// The tangent-space unit normal at each sample: x along +u, y along +v, z out of the
    /// surface. From the bump's exact gradient, as the renderer's Blinn normal has it.
    pub normals: Vec<Vec3>,
}

/// The bump over `grid`: its heights and its tangent-space normals.
pub fn bake_bump_on(surface: &Surface, bump: &Bump, time: f64, grid: &BakeGrid) -> BakedBump {
    let mut batch = PatternBatch::default();
    let has_height = bump.has_height();
    let mut heights_out = Vec::with_capacity(if has_height { grid.samples() } else { 0 });
    let mut normals = Vec::with_capacity(grid.samples());
    let group: Vec<u32> = (0..grid.width).collect();
    let mut heights = vec![0.0; grid.width as usize];
    let mut gradients = vec![Vec2::ZERO; grid.width as usize];
    let scale = bump.scale();
    for row in 0..grid.height {
        let (fragments, frames) = grid_row(surface, grid, row);
        let at = Sites {
            fragments: &fragments,
            group: &group,
            frames: &frames,
        };
        sample_bump(bump, at, time, &mut batch, (&mut heights, &mut gradients));
        if has_height {
            heights_out.extend(heights.iter().map(|h| h * scale));
        }
        let each = gradients.iter().zip(frames.iter());
        normals.extend(each.map(|(g, frame)| tangent_normal(*g * scale, &frame)));
    }
    BakedBump {
        heights: has_height.then_some(heights_out),
        normals,
    }
}

/// The bump's B and (Bu, Bv) at the sites (strength not applied), into `out` (the sites'
/// length): a normal map's heights are zero.
pub(super) fn sample_bump(
    bump: &Bump,
    at: Sites,
    time: f64,
    batch: &mut PatternBatch,
    out: (&mut [f32], &mut [Vec2]),
) {
    let (heights, gradients) = out;
    let sites = at.fragments.iter().zip(at.frames.iter());
    match &bump.source {
        BumpSource::Pattern(binding) => {
            batch.bump(binding, at, time, heights, gradients);
        }
        BumpSource::Image(image) => {
            let each = heights.iter_mut().zip(gradients.iter_mut());
            for ((h, g), (fragment, frame)) in each.zip(sites) {
                let mapped = image.mapping.map(&surface_point(&frame, fragment.uv, time));
                let sample = (image.map).sample_gradient(
                    mapped.st,
                    image.wrap_s,
                    image.wrap_t,
                    Footprint::POINT,
                );
                *h = sample.height;
                *g = sample.surface_gradient(mapped.jacobian);
            }
        }
        BumpSource::NormalMap(map) => {
            for ((g, h), (fragment, frame)) in gradients.iter_mut().zip(heights).zip(sites) {
                *g = map.gradient(&surface_point(&frame, fragment.uv, time));
                *h = 0.0;
            }
        }
    }
}

/// The unit normal of P + B·n in the tangent frame (unit Pu, unit Pv, n) for the gradient
/// (Bu, Bv) of B: (−Bu/|Pu|, −Bv/|Pv|, 1) normalised, which is Blinn's normal where Pu ⟂ Pv
/// (flat surfaces, and every surface here but the cone's apex, which has no frame).
pub fn tangent_normal(gradient: Vec2, frame: &Frame) -> Vec3 {
    let (a, b) = (frame.pu.length(), frame.pv.length());
    if !(a > 0.0 && b > 0.0) {
        return Vec3::Z;
    }
    let tilted = Vec3::new(-gradient.x / a, -gradient.y / b, 1.0);
    let n = tilted.normalize_or(Vec3::Z);
    if n.is_finite() { n } else { Vec3::Z }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::preset;

    #[test]
    fn a_height_pattern_bakes_to_its_values_and_a_plain_material_to_its_colour() {
        let scene = preset("plane-waffle").unwrap();
        let object = &scene.objects[0];
        let bump = object.material.bump.as_ref().unwrap();
        let heights = bake_height(&object.surface, bump, 0.0, 64).unwrap();
        assert_eq!(heights.len(), 64 * 64);
        assert!(heights.iter().all(|h| h.is_finite()));
        let (lo, hi) = heights
            .iter()
            .fold((f32::MAX, f32::MIN), |(a, b), &h| (a.min(h), b.max(h)));
        assert!(hi - lo > 1e-3, "the waffle varies: {lo}..{hi}");
        let colors = bake_color(&object.surface, &object.material, 0.0, 8);
        assert!(colors.iter().all(|&c| c == object.material.color));
    }
}
