//! The orthonormal basis around the axis of a surface of revolution.

use glam::{DVec3, Vec3};

/// An orthonormal basis around a symmetry axis, for the surfaces of revolution.
/// `e1` is where the azimuth starts (u = 0 points along −e1 after the seed's quarter-turn offset).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AxisBasis {
    pub e1: Vec3,
    pub axis: Vec3,
    pub e2: Vec3,
}

impl AxisBasis {
    /// A right-handed basis with `axis` as the second vector. With axis = +Y this is the world basis.
    pub fn from_axis(axis: Vec3) -> AxisBasis {
        let axis = super::normalize_or(axis, Vec3::Y);
        // Start from world X unless the axis is close to it: keeps the world basis for axis = ±Y.
        let reference = if axis.x.abs() < 0.9 { Vec3::X } else { Vec3::Z };
        let e2 = reference.cross(axis).normalize();
        let e1 = axis.cross(e2);
        AxisBasis { e1, axis, e2 }
    }

    /// Point with coordinates (a along e1, b along axis, c along e2).
    #[inline]
    pub fn to_world(&self, a: f32, b: f32, c: f32) -> Vec3 {
        self.e1 * a + self.axis * b + self.e2 * c
    }

    /// A point or direction's coordinates along (e1, axis, e2), in f64.
    #[inline(always)]
    pub fn local(&self, p: DVec3) -> DVec3 {
        DVec3::new(
            p.dot(self.e1.as_dvec3()),
            p.dot(self.axis.as_dvec3()),
            p.dot(self.e2.as_dvec3()),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn y_axis_gives_world_basis() {
        let b = AxisBasis::from_axis(Vec3::Y);
        assert!((b.e1 - Vec3::X).length() < 1e-6, "{:?}", b.e1);
        assert!((b.e2 - Vec3::Z).length() < 1e-6, "{:?}", b.e2);
    }

    #[test]
    fn any_axis_gives_orthonormal_right_handed_basis() {
        for axis in [
            Vec3::X,
            -Vec3::Y,
            Vec3::new(1.0, 2.0, -3.0),
            Vec3::new(0.0, 0.0, 0.0),
        ] {
            let b = AxisBasis::from_axis(axis);
            for v in [b.e1, b.axis, b.e2] {
                assert!((v.length() - 1.0).abs() < 1e-5);
            }
            assert!(b.e1.dot(b.axis).abs() < 1e-5);
            assert!(b.e1.dot(b.e2).abs() < 1e-5);
            assert!((b.e1.cross(b.axis) - b.e2).length() < 1e-5);
        }
    }
}
