//! A material sampled over its surface's (u,v) domain on a square grid: colours and bump heights
//! as images, for renderers that take image maps (the POV-Ray scene export). Row 0 is the top
//! of the image, v = max; column 0 is u = min; samples sit at cell centres.

use super::pattern_batch::{PatternBatch, Sites};
use crate::pattern::OutputKind;
use crate::raster::Fragment;
use crate::scene::{Bump, BumpSource, Material, Texturing};
use crate::surface::{Frame, Surface};
use crate::texture::{Footprint, SurfacePoint, TextureMapping};
use glam::{Vec2, Vec3};

/// The (u,v) at each cell of one grid row, and the surface frames there.
fn grid_row(surface: &Surface, side: u32, row: u32) -> (Vec<Fragment>, Vec<Frame>) {
    let domain = surface.domain();
    let extent = domain.max - domain.min;
    let v = domain.max.y - (row as f32 + 0.5) / side as f32 * extent.y;
    let fragments: Vec<Fragment> = (0..side)
        .map(|column| Fragment {
            object: 0,
            uv: Vec2::new(
                domain.min.x + (column as f32 + 0.5) / side as f32 * extent.x,
                v,
            ),
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

/// The material's colour (linear RGB) over the grid: its texture where it has one.
pub fn bake_color(surface: &Surface, material: &Material, time: f64, side: u32) -> Vec<Vec3> {
    let mut batch = PatternBatch::default();
    let mut out = Vec::with_capacity((side * side) as usize);
    let group: Vec<u32> = (0..side).collect();
    let mut colors = vec![Vec3::ZERO; side as usize];
    for row in 0..side {
        let (fragments, frames) = grid_row(surface, side, row);
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
                for ((color, fragment), frame) in colors.iter_mut().zip(&fragments).zip(&frames) {
                    let st = image
                        .mapping
                        .map(&surface_point(frame, fragment.uv, time))
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

/// The bump height B (times strength, sign applied) over the grid; `None` for slope patterns,
/// which define no height.
pub fn bake_height(surface: &Surface, bump: &Bump, time: f64, side: u32) -> Option<Vec<f32>> {
    let mut batch = PatternBatch::default();
    let mut out = Vec::with_capacity((side * side) as usize);
    let group: Vec<u32> = (0..side).collect();
    let mut heights = vec![0.0; side as usize];
    let mut gradients = vec![Vec2::ZERO; side as usize];
    for row in 0..side {
        let (fragments, frames) = grid_row(surface, side, row);
        match &bump.source {
            BumpSource::Pattern(binding) if binding.pattern.output() == OutputKind::Height => {
                let at = Sites {
                    fragments: &fragments,
                    group: &group,
                    frames: &frames,
                };
                batch.bump(binding, at, time, &mut heights, &mut gradients);
            }
            BumpSource::Pattern(_) => return None,
            BumpSource::Image(image) => {
                for ((h, fragment), frame) in heights.iter_mut().zip(&fragments).zip(&frames) {
                    let st = image
                        .mapping
                        .map(&surface_point(frame, fragment.uv, time))
                        .st;
                    let sample =
                        image
                            .map
                            .sample_gradient(st, image.wrap_s, image.wrap_t, Footprint::POINT);
                    *h = sample.height;
                }
            }
        }
        out.extend(heights.iter().map(|h| h * bump.scale()));
    }
    Some(out)
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
