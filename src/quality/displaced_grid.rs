//! The grid a displaced surface is cut into for a view: as fine as the displaced surface's
//! departure from its triangles needs to stay within a pixel tolerance, measured as for
//! adaptive tessellation (the sag at every edge's (u,v) midpoint, projected to pixels), within
//! a triangle budget. One grid for the whole surface, so neighbouring cells always share their
//! edges' vertices and the mesh has no cracks.

use super::adaptive::{edge_midpoint_uvs, worst_projected_sag};
use crate::raster::Viewport;
use crate::scene::Camera;
use crate::surface::{
    Displaced, DisplacedBase, Frames, GridShape, HeightField, Mesh, Parametric, Surface,
};
use std::sync::Arc;

/// A displaced surface cut for a view, and how far its mesh strays from it there.
pub struct DisplacedGrid {
    pub surface: Displaced,
    pub mesh: Mesh,
    /// The largest projected sag, in pixels.
    pub error_px: f32,
}

/// Margin on the 1/d² prediction, so one refinement usually suffices.
const PREDICTION_MARGIN: f32 = 1.1;
/// Triangles whose edges are measured at once.
const MEASURED_TOGETHER: usize = 1 << 14;
/// Refinements tried before the grid is taken as it is.
const MOST_REFINEMENTS: u32 = 6;

/// `base` moved by `field`, cut finely enough that its mesh stays within `tolerance_px` of it in
/// this view, in at most `most_triangles` triangles; `None` when `base` cannot be displaced, and
/// why not when the heights reach past the base's own size (a sphere's radius, a plane's longer
/// side): so far out the surface folds through itself and its triangles swamp every view.
pub fn displaced_grid(
    base: &Surface,
    field: Arc<dyn HeightField>,
    (camera, viewport): (&Camera, Viewport),
    tolerance_px: f32,
    most_triangles: u64,
) -> Option<Result<DisplacedGrid, String>> {
    let base = DisplacedBase::of(base)?;
    let tolerance = tolerance_px.max(1e-3);
    let mut cells = starting_cells(&base);
    let mut grid = cut(&base, &field, cells, (camera, viewport));
    if let Err(why) = within_bounds(&grid.surface) {
        return Some(Err(why));
    }
    for _ in 0..MOST_REFINEMENTS {
        if grid.error_px <= tolerance {
            break;
        }
        let wanted = cells * (grid.error_px / tolerance).sqrt() * PREDICTION_MARGIN;
        let affordable = cells_within(&base, wanted, most_triangles);
        if affordable <= cells * 1.01 {
            break;
        }
        cells = affordable;
        grid = cut(&base, &field, cells, (camera, viewport));
    }
    Some(Ok(grid))
}

/// Whether the heights stay within the base's own size (see `displaced_grid`).
fn within_bounds(surface: &Displaced) -> Result<(), String> {
    let (low, high) = surface.heights;
    let reach = low.abs().max(high.abs());
    let (size, what) = match &surface.base {
        DisplacedBase::Plane(plane) => (plane.size.max_element(), "the plane's size"),
        DisplacedBase::Sphere(sphere) => (sphere.radius, "the sphere's radius"),
    };
    match reach.is_finite() && reach <= size {
        true => Ok(()),
        false => Err(format!(
            "its bump's heights reach {reach}, past {what} ({size}): displaced that far it \
             would fold through itself; it keeps Blinn's bump (lower the strength to displace it)"
        )),
    }
}

/// Cells along the base's longer side (a plane) or per half turn (a sphere), to start from.
fn starting_cells(base: &DisplacedBase) -> f32 {
    match base {
        DisplacedBase::Plane(_) => 32.0,
        DisplacedBase::Sphere(_) => 64.0,
    }
}

/// The grid of `cells` along the longer side (plane) or per half turn (sphere), its cells
/// square on the base.
fn shape(base: &DisplacedBase, cells: f32) -> GridShape {
    let count = |n: f32| (n.ceil() as u32).clamp(1, 1 << 20);
    match base {
        DisplacedBase::Plane(plane) => {
            let cell = plane.size.x.max(plane.size.y) / cells;
            GridShape::flat(count(plane.size.x / cell), count(plane.size.y / cell))
        }
        DisplacedBase::Sphere(_) => GridShape {
            cells_u: 2 * count(cells).max(2),
            cells_v: count(cells).max(2),
            collapsed_v_min: true,
            collapsed_v_max: true,
        },
    }
}

/// The most cells, up to `wanted`, whose grid keeps within `most_triangles`.
fn cells_within(base: &DisplacedBase, wanted: f32, most_triangles: u64) -> f32 {
    let triangles = shape(base, wanted).triangle_count() as f32;
    let most = most_triangles as f32;
    if triangles <= most {
        wanted
    } else {
        // Triangles grow as the square of the cells.
        (wanted * (most / triangles).sqrt()).floor().max(1.0)
    }
}

fn cut(
    base: &DisplacedBase,
    field: &Arc<dyn HeightField>,
    cells: f32,
    (camera, viewport): (&Camera, Viewport),
) -> DisplacedGrid {
    let (surface, mesh) = Displaced::cut(base.clone(), field.clone(), shape(base, cells));
    // A piece of the triangles at a time: every edge's midpoint frame at once would take more
    // memory than the mesh.
    let error_px = (mesh.indices.chunks(MEASURED_TOGETHER))
        .map(|indices| {
            let midpoints = edge_midpoint_uvs(&mesh.uvs, indices);
            let mut on_surface = Frames::default();
            surface.displaced_frames(&midpoints, &mut on_surface);
            let on_surface: Vec<_> = on_surface.iter().map(|f| f.p).collect();
            let triangles = (&mesh.positions[..], indices);
            worst_projected_sag(triangles, &on_surface, surface.origin(), camera, viewport)
        })
        .fold(0.0, f32::max);
    DisplacedGrid {
        surface,
        mesh,
        error_px,
    }
}
