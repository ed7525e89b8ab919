//! A scene made larger or smaller and moved: the same picture, in other numbers.

use crate::lights::light::Light;
use crate::maths::numbers::{Real, Vec3};
use crate::scene::objects::Scene;

impl Scene {
    /// The same scene made `factor` times larger about the origin, then moved by
    /// `shift`: every point `p` becomes `factor p + shift`, every length `factor`
    /// times longer. Its image is the same: a point light's intensity grows with
    /// `factor^2`, so that the irradiance `I cos / d^2` it gives is unchanged, and
    /// a sphere light keeps its radiance, seen under the same solid angle. The
    /// renderer has no length of its own, so any difference between the two images
    /// is rounding: how the scale sweep of the tests and the book measures it.
    pub fn scaled(&self, factor: Real, shift: Vec3) -> Scene {
        let place = |p: Vec3| p * factor + shift;
        let mut out = self.clone();
        out.camera.position = place(out.camera.position);
        #[cfg(feature = "s4")]
        if let crate::camera::pinhole::Lens::Thin(lens) = &mut out.camera.lens {
            lens.aperture *= factor;
            lens.focus *= factor;
        }
        for sphere in &mut out.spheres {
            sphere.centre = place(sphere.centre);
            sphere.radius *= factor;
        }
        match &mut out.light {
            Some(Light::Point(light)) => {
                light.position = place(light.position);
                light.intensity *= factor * factor;
            }
            #[cfg(feature = "s4")]
            Some(Light::Sphere(light)) => {
                light.centre = place(light.centre);
                light.radius *= factor;
            }
            None => {}
        }
        #[cfg(feature = "s5")]
        for mesh in &mut out.meshes {
            for p in &mut mesh.positions {
                *p = place(*p);
            }
            mesh.bounds = mesh
                .positions
                .iter()
                .fold(crate::geometry::aabb::Aabb::EMPTY, |b, &p| b.grow(p));
            #[cfg(feature = "s6")]
            if let crate::meshes::mesh::Search::Bvh(_) = mesh.search {
                mesh.search =
                    crate::meshes::mesh::Search::Bvh(crate::acceleration::bvh::Bvh::build(mesh));
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene_file::load::Overrides;
    use crate::scene_file::stages::find_stage;

    #[test]
    fn every_length_scales_and_every_point_moves() {
        let room = find_stage(1, "spheres")
            .unwrap()
            .scene(&Overrides::default())
            .unwrap();
        let shift = Vec3::new(1.0, 2.0, 3.0);
        let big = room.scaled(10.0, shift);
        assert_eq!(big.camera.position, room.camera.position * 10.0 + shift);
        for (a, b) in room.spheres.iter().zip(&big.spheres) {
            assert_eq!(b.centre, a.centre * 10.0 + shift);
            assert_eq!(b.radius, a.radius * 10.0);
        }
        let (Some(Light::Point(a)), Some(Light::Point(b))) = (room.light, big.light) else {
            panic!("the room has a point light");
        };
        assert_eq!(b.intensity, 100.0 * a.intensity);
    }
}
