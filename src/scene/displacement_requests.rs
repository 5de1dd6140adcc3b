//! What a scene's requests for true displacement come to: an object asks with `displace`,
//! and is displaced when its bump gives a height and its surface is one displacement moves
//! (a plane or a sphere). Each request that is not met for a bump is told in one line, and the
//! object is drawn with Blinn's bump instead.

use super::{Object, Scene};
use crate::surface::DisplacedBase;

impl Object {
    /// Why the object's `displace` cannot be met, if it asks and cannot.
    pub fn displacement_refused(&self) -> Option<String> {
        if !self.displace {
            return None;
        }
        let kind = self.surface.kind_name();
        // Without a bump there is nothing to move it by, and nothing drawn differently.
        let bump = self.material.bump.as_ref()?;
        if !bump.has_height() {
            return Some(format!(
                "the {kind}'s bump gives only a slope, no height to displace it by; it keeps \
                 Blinn's bump"
            ));
        }
        if DisplacedBase::of(&self.surface).is_none() {
            return Some(format!(
                "displacement moves planes and spheres; the {kind} keeps Blinn's bump"
            ));
        }
        None
    }
}

impl Scene {
    /// One line for each object whose request for displacement is not met, naming it.
    pub fn displacement_warnings(&self) -> Vec<String> {
        let refused = self.objects.iter().enumerate();
        refused
            .filter_map(|(index, o)| Some((index, o.displacement_refused()?)))
            .map(|(index, why)| format!("object {}: {why}", index + 1))
            .collect()
    }
}
