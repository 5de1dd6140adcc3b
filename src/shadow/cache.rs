//! The last shadow maps kept for the next frame: the workbench renders a view in many passes
//! (progressive refinement, then supersampling), all with the same maps, and redraws a still
//! view without any change to what casts or receives a shadow.

use super::{ShadowMaps, ShadowSettings};
use crate::raster::Viewport;
use crate::scene::PreparedScene;
use crate::scene::{Camera, Light};
use crate::surface::Surface;
use std::sync::{Arc, Mutex};

/// Maps reused while nothing they depend on changes.
#[derive(Default)]
pub struct ShadowCache {
    last: Mutex<Option<(MapsKey, Option<Arc<ShadowMaps>>)>>,
}

/// Everything the maps are made from.
#[derive(Clone, PartialEq)]
struct MapsKey {
    surfaces: Vec<Surface>,
    /// Per object, its mesh's size and chord error: the tessellation.
    meshes: Vec<(usize, u32)>,
    lights: Vec<Light>,
    shadows: bool,
    camera: Camera,
    aspect: u32,
    settings: ShadowSettings,
}

impl ShadowCache {
    /// `ShadowMaps::build`'s maps, drawn again only when the scene's geometry, lights, the
    /// camera, the view's size or the settings differ from the last call's.
    pub fn maps(
        &self,
        prepared: &PreparedScene,
        camera: &Camera,
        viewport: Viewport,
        settings: ShadowSettings,
    ) -> Option<Arc<ShadowMaps>> {
        let key = MapsKey {
            surfaces: prepared.objects.iter().map(|o| o.surface.clone()).collect(),
            meshes: prepared
                .objects
                .iter()
                .map(|o| (o.mesh.indices.len(), o.mesh.chord_error.to_bits()))
                .collect(),
            lights: prepared.scene.lights.clone(),
            shadows: prepared.scene.shadows,
            camera: camera.clone(),
            aspect: viewport.aspect().to_bits(),
            settings,
        };
        let mut last = self
            .last
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner());
        if let Some((kept, maps)) = last.as_ref()
            && *kept == key
        {
            return maps.clone();
        }
        let maps = ShadowMaps::build(prepared, camera, viewport, settings).map(Arc::new);
        *last = Some((key, maps.clone()));
        maps
    }
}
