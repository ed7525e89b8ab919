//! An orthonormal frame around a normal, to turn a direction sampled around the
//! `z` axis into one around the normal.

use crate::maths::{Real, Vec3};

/// Three orthonormal axes `(t1, t2, n)`: the local frame `(T1, T2, N)` of the course.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    /// First tangent.
    pub t1: Vec3,
    /// Second tangent.
    pub t2: Vec3,
    /// The unit normal, the frame's `z` axis.
    pub n: Vec3,
}

impl Frame {
    // ANCHOR: frame
    /// A frame whose `z` axis is the unit vector `n`, built without branches on the
    /// normal's direction (Duff et al., "Building an Orthonormal Basis, Revisited",
    /// JCGT 2017), so it is continuous and exact to rounding for every `n`.
    ///
    /// Exercise s3.2, the frame around the normal: book session 3, "Indirect lighting".
    pub fn new(n: Vec3) -> Self {
        let sign = (1.0 as Real).copysign(n.z);
        let a = -1.0 / (sign + n.z);
        let b = n.x * n.y * a;
        Self {
            t1: Vec3::new(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x),
            t2: Vec3::new(b, sign + n.y * n.y * a, -n.y),
            n,
        }
    }
    // ANCHOR_END: frame

    /// The world direction of local coordinates `(x, y, z)`: `x T1 + y T2 + z N`.
    pub fn to_world(&self, local: Vec3) -> Vec3 {
        local.x * self.t1 + local.y * self.t2 + local.z * self.n
    }

    /// The local coordinates of a world direction.
    pub fn to_local(&self, world: Vec3) -> Vec3 {
        Vec3::new(world.dot(self.t1), world.dot(self.t2), world.dot(self.n))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frames_are_orthonormal_for_every_normal() {
        let normals = [
            Vec3::Z,
            -Vec3::Z,
            Vec3::X,
            Vec3::new(1.0, 2.0, 3.0).normalize(),
            Vec3::new(1e-9, -1e-9, -1.0).normalize(),
            Vec3::new(-0.3, 0.9, -1e-12).normalize(),
        ];
        for n in normals {
            let f = Frame::new(n);
            for (a, b) in [(f.t1, f.t2), (f.t1, f.n), (f.t2, f.n)] {
                assert!(a.dot(b).abs() < 4.0 * Real::EPSILON, "{n}: not orthogonal");
            }
            for v in [f.t1, f.t2] {
                assert!(
                    (v.length() - 1.0).abs() < 4.0 * Real::EPSILON,
                    "{n}: not unit"
                );
            }
            assert!(
                (f.t1.cross(f.t2) - n).length() < 4.0 * Real::EPSILON,
                "{n}: right-handed"
            );
            let w = Vec3::new(0.2, -0.5, 0.7);
            assert!((f.to_local(f.to_world(w)) - w).length() < 4.0 * Real::EPSILON);
        }
    }
}
