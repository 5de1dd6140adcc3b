//! The memory one render may take. Decoded images, tessellated triangles, lights and output
//! buffers share one budget, each estimated before it is allocated, so a scene too large for the
//! machine is one message naming what to reduce instead of an abort halfway through.

use std::fmt;

/// The environment variable that sets the budget, in MiB.
pub const MEMORY_BUDGET_VAR: &str = "BUMPWORK_MEMORY_MIB";
/// Leaves room on an 8 GB laptop for the desktop, an editor and a browser.
pub const DEFAULT_MEMORY_MIB: u64 = 4096;
const MAX_MEMORY_MIB: u64 = 1 << 20;

/// What a tessellated triangle holds while a frame renders, rounded up: its three indices, its
/// share of the mesh's vertices (position and (u,v)) and of the per-frame clip-space vertices.
pub const BYTES_PER_TRIANGLE: u64 = 32;
/// A light and what shading keeps for it per frame.
const BYTES_PER_LIGHT: u64 = 64;

/// The budget in bytes: `BUMPWORK_MEMORY_MIB` MiB, or `DEFAULT_MEMORY_MIB` when unset. An
/// invalid value is reported by [`check_budget_var`] at start-up.
pub fn budget_bytes() -> u64 {
    check_budget_var()
        .ok()
        .flatten()
        .unwrap_or(DEFAULT_MEMORY_MIB)
        << 20
}

/// `Ok(None)` when `BUMPWORK_MEMORY_MIB` is unset, `Ok(Some(mib))` when it holds a whole number
/// of MiB from 1 to 1048576, and a message otherwise.
pub fn check_budget_var() -> Result<Option<u64>, String> {
    let Some(value) = std::env::var_os(MEMORY_BUDGET_VAR) else {
        return Ok(None);
    };
    value
        .to_str()
        .and_then(|v| v.trim().parse::<u64>().ok())
        .filter(|mib| (1..=MAX_MEMORY_MIB).contains(mib))
        .map(Some)
        .ok_or_else(|| {
            format!(
                "{MEMORY_BUDGET_VAR} must be a whole number of MiB from 1 to {MAX_MEMORY_MIB}, not '{}'",
                crate::diagnostic::shown_input(&value.to_string_lossy())
            )
        })
}

/// What a render will hold at its peak, estimated before the large parts are allocated.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MemoryUse {
    /// Bytes of decoded images (texels and mip chains), each shared image counted once.
    pub image_bytes: u64,
    /// Triangles of the tessellated scene.
    pub triangles: u64,
    pub lights: u64,
    /// Bytes of framebuffers and encoder buffers.
    pub output_bytes: u64,
    /// Bytes of the lights' shadow maps.
    pub shadow_map_bytes: u64,
}

impl MemoryUse {
    pub fn geometry_bytes(&self) -> u64 {
        self.triangles.saturating_mul(BYTES_PER_TRIANGLE)
    }

    pub fn light_bytes(&self) -> u64 {
        self.lights.saturating_mul(BYTES_PER_LIGHT)
    }

    pub fn total(&self) -> u64 {
        self.image_bytes
            .saturating_add(self.geometry_bytes())
            .saturating_add(self.light_bytes())
            .saturating_add(self.output_bytes)
            .saturating_add(self.shadow_map_bytes)
    }

    /// `Ok` when the whole fits `budget` bytes, else what it needs and what to reduce.
    pub fn check(&self, budget: u64) -> Result<(), OverBudget> {
        if self.total() <= budget {
            Ok(())
        } else {
            Err(OverBudget {
                needed: *self,
                budget,
            })
        }
    }
}

/// A render that does not fit: displays as one line naming the largest part and what reduces it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct OverBudget {
    pub needed: MemoryUse,
    pub budget: u64,
}

impl fmt::Display for OverBudget {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let needed = &self.needed;
        let parts = [
            (
                needed.geometry_bytes(),
                format!("{} triangles", count_words(needed.triangles)),
                "fewer objects or a lower tessellation",
            ),
            (
                needed.image_bytes,
                "images".to_string(),
                "smaller or fewer images",
            ),
            (
                needed.output_bytes,
                "output buffers".to_string(),
                "a smaller size",
            ),
            (
                needed.light_bytes(),
                format!("{} lights", count_words(needed.lights)),
                "fewer lights",
            ),
            (
                needed.shadow_map_bytes,
                "shadow maps".to_string(),
                "a smaller quality.shadow-map, or shadows=false",
            ),
        ];
        let largest = parts
            .iter()
            .max_by_key(|(bytes, ..)| *bytes)
            .expect("five parts");
        write!(
            f,
            "this render needs about {} of memory, over the {} budget; {} take {} (try {}), ",
            size_words(needed.total()),
            size_words(self.budget),
            largest.1,
            size_words(largest.0),
            largest.2
        )?;
        write!(f, "or raise {MEMORY_BUDGET_VAR}")
    }
}

impl std::error::Error for OverBudget {}

/// A byte count as people say it: 512 KiB, 3.1 MiB, 2.0 GiB.
pub fn size_words(bytes: u64) -> String {
    const UNITS: [&str; 4] = ["KiB", "MiB", "GiB", "TiB"];
    let mut value = bytes as f64 / 1024.0;
    let mut unit = 0;
    while value >= 1024.0 && unit + 1 < UNITS.len() {
        value /= 1024.0;
        unit += 1;
    }
    if value >= 100.0 || unit == 0 || value.fract() == 0.0 {
        format!("{value:.0} {}", UNITS[unit])
    } else {
        format!("{value:.1} {}", UNITS[unit])
    }
}

/// A count as people say it: 950, 12 thousand, 4.2 million, 67 million.
fn count_words(n: u64) -> String {
    let (value, unit) = match n {
        0..10_000 => return n.to_string(),
        10_000..1_000_000 => return format!("{} thousand", n / 1000),
        1_000_000..1_000_000_000 => (n as f64 / 1e6, "million"),
        _ => (n as f64 / 1e9, "billion"),
    };
    if value < 10.0 {
        format!("{value:.1} {unit}")
    } else {
        format!("{value:.0} {unit}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_render_within_its_budget_passes_and_one_byte_over_fails() {
        let needed = MemoryUse {
            image_bytes: 100,
            triangles: 10,
            lights: 1,
            output_bytes: 50,
            shadow_map_bytes: 7,
        };
        let total = 100 + 10 * BYTES_PER_TRIANGLE + BYTES_PER_LIGHT + 50 + 7;
        assert_eq!(needed.total(), total);
        assert!(needed.check(total).is_ok());
        assert!(needed.check(total - 1).is_err());
    }

    #[test]
    fn the_message_names_the_largest_part_and_what_reduces_it() {
        let triangles = MemoryUse {
            triangles: 67_108_864,
            output_bytes: 1 << 20,
            ..MemoryUse::default()
        };
        let message = triangles.check(1 << 30).unwrap_err().to_string();
        assert!(
            message.contains("67 million triangles take 2 GiB"),
            "{message}"
        );
        assert!(message.contains("lower tessellation"), "{message}");
        assert!(message.contains("over the 1 GiB budget"), "{message}");
        assert!(message.contains(MEMORY_BUDGET_VAR), "{message}");
        let images = MemoryUse {
            image_bytes: 13 << 30,
            ..triangles
        };
        let message = images.check(4 << 30).unwrap_err().to_string();
        assert!(message.contains("images take 13 GiB"), "{message}");
        assert!(!message.contains('\n'));
        let maps = MemoryUse {
            shadow_map_bytes: 20 << 30,
            ..images
        };
        let message = maps.check(4 << 30).unwrap_err().to_string();
        assert!(message.contains("shadow maps take 20 GiB"), "{message}");
        assert!(message.contains("shadow-map"), "{message}");
    }

    #[test]
    fn totals_saturate_instead_of_wrapping() {
        let huge = MemoryUse {
            image_bytes: u64::MAX,
            triangles: u64::MAX,
            lights: u64::MAX,
            output_bytes: u64::MAX,
            shadow_map_bytes: u64::MAX,
        };
        assert_eq!(huge.total(), u64::MAX);
        assert!(huge.check(u64::MAX).is_ok());
        assert!(huge.check(u64::MAX - 1).is_err());
    }

    #[test]
    fn sizes_read_as_people_say_them() {
        assert_eq!(size_words(512 << 10), "512 KiB");
        assert_eq!(size_words(3 << 20), "3 MiB");
        assert_eq!(size_words(3 << 19), "1.5 MiB");
        assert_eq!(size_words(4096 << 20), "4 GiB");
        assert_eq!(size_words(300 << 30), "300 GiB");
        assert_eq!(count_words(9_999), "9999");
        assert_eq!(count_words(4_190_208), "4.2 million");
        assert_eq!(count_words(217_000_000), "217 million");
    }
}
