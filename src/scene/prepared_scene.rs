//! A scene's objects tessellated once, reused for every frame until the scene or the density
//! changes.

use super::{Material, Scene};
use crate::surface::{Mesh, Surface, Tessellation};
use rayon::prelude::*;

/// A scene's objects tessellated once, reused for every frame until the scene or density changes.
pub struct PreparedScene {
    pub scene: Scene,
    pub objects: Vec<PreparedObject>,
    /// What preparing could not do as the scene asked, one line each (a displacement refused).
    pub notices: Vec<String>,
}

pub struct PreparedObject {
    pub surface: Surface,
    pub material: Material,
    pub mesh: Mesh,
}

impl PreparedScene {
    pub fn new(scene: Scene, tessellation: Tessellation) -> PreparedScene {
        let objects = scene
            .objects
            .par_iter()
            .map(|o| PreparedObject {
                surface: o.surface.clone(),
                material: o.material.clone(),
                mesh: o.surface.tessellate(tessellation),
            })
            .collect();
        PreparedScene {
            scene,
            objects,
            notices: Vec::new(),
        }
    }

    pub fn triangle_count(&self) -> usize {
        self.objects.iter().map(|o| o.mesh.indices.len()).sum()
    }
}
