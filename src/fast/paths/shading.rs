//! The work at four paths' hits, written once for any type of four lanes: their hit
//! records on spheres, their direct light (a point light with its shadow rays, or a
//! sample of a sphere light), and their cosine-weighted bounces.
//!
//! Every step is the course function's, in its order, so every number is the same
//! to the last bit: [`Sphere::hit_at`], [`Hit::facing_the_ray`],
//! [`PointLight::lambert`], [`Hit::spawn_towards`], `Tracer::light_sample` (session
//! 4), [`sample_cosine_hemisphere`], [`Frame::new`] and [`Frame::to_world`],
//! [`Hit::spawn`], the last float of a new ray's origin included
//! ([`one_ulp_towards`]: its bits plus or minus one, on the lanes, but for its rare
//! cases). One step stays one number at a time, before these functions: the cosine
//! and sine of an angle, the C library's, which has no lane version that rounds as
//! it does. One number may differ in the sign of a zero: a cosine of `-0` in
//! `lambert`'s `.max(0.0)`, which Rust leaves free to give either zero, and which
//! the lanes give as `+0`; the light it scales is zero either way, and the image
//! is the same.
//!
//! [`Sphere::hit_at`]: crate::geometry::Sphere::hit_at
//! [`Hit::facing_the_ray`]: crate::geometry::Hit::facing_the_ray
//! [`PointLight::lambert`]: crate::lights::PointLight::lambert
//! [`Hit::spawn_towards`]: crate::geometry::Hit::spawn_towards
//! [`Hit::spawn`]: crate::geometry::Hit::spawn
//! [`sample_cosine_hemisphere`]: crate::maths::sampling::sample_cosine_hemisphere
//! [`Frame::new`]: crate::maths::frame::Frame::new
//! [`Frame::to_world`]: crate::maths::frame::Frame::to_world
//! [`one_ulp_towards`]: crate::geometry::spawn::one_ulp_towards

use crate::geometry::Ray;
use crate::maths::{Real, Vec3};

/// Four vectors by coordinate: `v[axis][k]` is coordinate `axis` of vector `k`.
pub type FourVectors = [[Real; 4]; 3];

/// Vector `k` of `v`.
#[inline(always)]
pub fn vector(v: &FourVectors, k: usize) -> Vec3 {
    Vec3::new(v[0][k], v[1][k], v[2][k])
}

/// Ray `k` of four whose origins are `origin` and directions `direction`.
#[inline(always)]
pub fn ray(origin: &FourVectors, direction: &FourVectors, k: usize) -> Ray {
    Ray {
        origin: vector(origin, k),
        direction: vector(direction, k),
    }
}

/// What [`Sphere::hit_at`](crate::geometry::Sphere::hit_at) finds for four rays,
/// their normals already facing the rays.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SphereHits {
    /// The hit points, projected onto their spheres.
    pub point: FourVectors,
    /// The unit normals, facing the rays.
    pub normal: FourVectors,
    /// The bounds on the points' rounding errors, per coordinate.
    pub error: FourVectors,
    /// The offsets that clear the errors, along the outward normals.
    pub offset: FourVectors,
    /// Per ray, not zero where it started outside its sphere.
    pub outside: [Real; 4],
}

/// The direct light at four hits from a point light: what
/// [`PointLight::lambert`](crate::lights::PointLight::lambert) and
/// [`Hit::spawn_towards`](crate::geometry::Hit::spawn_towards) give.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointLit {
    /// The light that arrives if nothing is in the way.
    pub lit: FourVectors,
    /// The shadow rays' origins.
    pub origin: FourVectors,
    /// The shadow rays' directions.
    pub direction: FourVectors,
    /// The distances from the origins to the light.
    pub distance: [Real; 4],
}

/// One direction sampled towards a sphere light from each of four hits: what
/// `Tracer::light_sample` gives (from session 4).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightSamples {
    /// The light each direction brings if nothing is in the way.
    pub lit: FourVectors,
    /// The rays' origins.
    pub origin: FourVectors,
    /// The rays' directions.
    pub direction: FourVectors,
    /// Per hit, not zero where it has a ray: outside the light, the direction above
    /// the surface.
    pub kept: [Real; 4],
}

/// Defines `sphere_hits`, `point_light`, `sphere_light` and `bounces` in the module
/// that invokes it, for its lane type `L` and its lane operations (those of the
/// sphere test, and `abs`, `max`, `all`, `step_towards`), each function with the
/// attributes given. No closure is used: one inside a function compiled with AVX is
/// compiled without it, and called.
macro_rules! four_hit_shading {
    ($(#[$attribute:meta])*) => {
        /// The three coordinates of four vectors, one vector per lane.
        $(#[$attribute])*
        #[inline]
        fn gather3(v: [$crate::maths::Vec3; 4]) -> [L; 3] {
            [
                gather([v[0].x, v[1].x, v[2].x, v[3].x]),
                gather([v[0].y, v[1].y, v[2].y, v[3].y]),
                gather([v[0].z, v[1].z, v[2].z, v[3].z]),
            ]
        }

        /// The lanes of three coordinates.
        $(#[$attribute])*
        #[inline]
        fn scatter3(v: [L; 3]) -> $crate::fast::paths::shading::FourVectors {
            [lanes(v[0]), lanes(v[1]), lanes(v[2])]
        }

        /// `a . b`, glam's order: `(a_x b_x + a_y b_y) + a_z b_z`.
        $(#[$attribute])*
        #[inline]
        fn dot(a: [L; 3], b: [L; 3]) -> L {
            add(add(mul(a[0], b[0]), mul(a[1], b[1])), mul(a[2], b[2]))
        }

        /// `s v`, lane by lane.
        $(#[$attribute])*
        #[inline]
        fn scale(s: L, v: [L; 3]) -> [L; 3] {
            [mul(s, v[0]), mul(s, v[1]), mul(s, v[2])]
        }

        /// `a + b`, lane by lane.
        $(#[$attribute])*
        #[inline]
        fn plus(a: [L; 3], b: [L; 3]) -> [L; 3] {
            [add(a[0], b[0]), add(a[1], b[1]), add(a[2], b[2])]
        }

        /// `a - b`, lane by lane.
        $(#[$attribute])*
        #[inline]
        fn minus(a: [L; 3], b: [L; 3]) -> [L; 3] {
            [sub(a[0], b[0]), sub(a[1], b[1]), sub(a[2], b[2])]
        }

        // ANCHOR: to_world
        /// `Frame::new(n).to_world(local)`: the local coordinates `local` in the
        /// frame around the unit vectors `n`.
        $(#[$attribute])*
        #[inline]
        fn to_world(n: [L; 3], local: [L; 3]) -> [L; 3] {
            let [nx, ny, nz] = n;
            let sign = or(and(nz, splat(-0.0)), splat(1.0));
            let a = div(splat(-1.0), add(sign, nz));
            let b = mul(mul(nx, ny), a);
            let t1 = [
                add(splat(1.0), mul(mul(mul(sign, nx), nx), a)),
                mul(sign, b),
                mul(neg(sign), nx),
            ];
            let t2 = [b, add(sign, mul(mul(ny, ny), a)), neg(ny)];
            let [x, y, z] = local;
            plus(plus(scale(x, t1), scale(y, t2)), scale(z, n))
        }
        // ANCHOR_END: to_world

        /// The lanes where `one_ulp_towards(p, o)` takes its usual case: `p` finite
        /// and not zero, `o` not zero (a NaN `o` makes `p` NaN, so such a lane is
        /// never usual).
        $(#[$attribute])*
        #[inline]
        fn usual(p: L, o: L) -> L {
            let finite = lt(abs(p), splat($crate::maths::Real::INFINITY));
            and(and(ne(p, splat(0.0)), finite), ne(o, splat(0.0)))
        }

        /// The origins of rays leaving four hits (`point`, `offset`) along
        /// `direction`: `Hit::spawn` on the lanes, the last float of each coordinate
        /// too where every lane takes `one_ulp_towards`'s usual case (nearly
        /// always), one number at a time otherwise.
        $(#[$attribute])*
        #[inline]
        fn spawn(
            point: [L; 3],
            offset: [L; 3],
            direction: [L; 3],
        ) -> $crate::fast::paths::shading::FourVectors {
            let away = lt(dot(direction, offset), splat(0.0));
            let [x, y, z] = offset;
            let offset = [
                select(away, neg(x), x),
                select(away, neg(y), y),
                select(away, neg(z), z),
            ];
            let pushed = plus(point, offset);
            let [px, py, pz] = pushed;
            let [ox, oy, oz] = offset;
            if all(and(usual(px, ox), and(usual(py, oy), usual(pz, oz)))) {
                return scatter3([step_towards(px, ox), step_towards(py, oy), step_towards(pz, oz)]);
            }
            let (mut origin, offset) = (scatter3(pushed), scatter3(offset));
            for axis in 0..3 {
                for k in 0..4 {
                    let p = origin[axis][k];
                    origin[axis][k] = $crate::geometry::spawn::one_ulp_towards(p, offset[axis][k]);
                }
            }
            origin
        }

        /// `Sphere::hit_at` then `Hit::facing_the_ray` for four rays, ray `k` meeting
        /// sphere `spheres[k]` (centre and radius first) at `t[k]`.
        $(#[$attribute])*
        pub(crate) fn sphere_hits(
            rays: [&$crate::geometry::Ray; 4],
            t: [$crate::maths::Real; 4],
            spheres: [&[$crate::maths::Real; 5]; 4],
        ) -> $crate::fast::paths::shading::SphereHits {
            let [r0, r1, r2, r3] = rays;
            let origin = gather3([r0.origin, r1.origin, r2.origin, r3.origin]);
            let direction = gather3([r0.direction, r1.direction, r2.direction, r3.direction]);
            let [s0, s1, s2, s3] = spheres;
            let centre = [
                gather([s0[0], s1[0], s2[0], s3[0]]),
                gather([s0[1], s1[1], s2[1], s3[1]]),
                gather([s0[2], s1[2], s2[2], s3[2]]),
            ];
            let radius = gather([s0[3], s1[3], s2[3], s3[3]]);
            let radial = minus(plus(origin, scale(gather(t), direction)), centre);
            let length = sqrt(dot(radial, radial));
            let normal = [div(radial[0], length), div(radial[1], length), div(radial[2], length)];
            let on_sphere = scale(radius, normal);
            let point = plus(centre, on_sphere);
            let bound = splat($crate::maths::error_bound(7));
            let error = scale(bound, plus(
                [abs(centre[0]), abs(centre[1]), abs(centre[2])],
                [abs(on_sphere[0]), abs(on_sphere[1]), abs(on_sphere[2])],
            ));
            let along = dot([abs(normal[0]), abs(normal[1]), abs(normal[2])], error);
            let offset = scale(along, normal);
            let from_centre = minus(origin, centre);
            let outside = gt(dot(from_centre, from_centre), mul(radius, radius));
            let facing = scale(select(outside, splat(1.0), splat(-1.0)), normal);
            $crate::fast::paths::shading::SphereHits {
                point: scatter3(point),
                normal: scatter3(facing),
                error: scatter3(error),
                offset: scatter3(offset),
                outside: lanes(outside),
            }
        }

        /// `PointLight::lambert` and `Hit::spawn_towards` (towards the light) at four
        /// hits (normals facing their rays) of surfaces of `albedo`.
        $(#[$attribute])*
        pub(crate) fn point_light(
            hits: [&$crate::geometry::Hit; 4],
            albedo: [$crate::maths::Colour; 4],
            light: &$crate::lights::PointLight,
        ) -> $crate::fast::paths::shading::PointLit {
            use $crate::maths::PI;
            let [h0, h1, h2, h3] = hits;
            let point = gather3([h0.point, h1.point, h2.point, h3.point]);
            let normal = gather3([h0.normal, h1.normal, h2.normal, h3.normal]);
            let p = light.position;
            let position = [splat(p.x), splat(p.y), splat(p.z)];
            let to_light = minus(position, point);
            let d2 = dot(to_light, to_light);
            let length = sqrt(d2);
            let [lx, ly, lz] = to_light;
            let unit = [div(lx, length), div(ly, length), div(lz, length)];
            let cos = max(dot(normal, unit), splat(0.0));
            let power = mul(div(splat(light.intensity), mul(splat(4.0 * PI), d2)), cos);
            let [ax, ay, az] = gather3(albedo);
            let pi = splat(PI);
            let lit = [div(mul(power, ax), pi), div(mul(power, ay), pi), div(mul(power, az), pi)];
            let direction = scale(div(splat(1.0), length), to_light);
            let offset = gather3([h0.offset, h1.offset, h2.offset, h3.offset]);
            let origin = spawn(point, offset, direction);
            let [ox, oy, oz] = origin;
            let to_target = minus([gather(ox), gather(oy), gather(oz)], position);
            $crate::fast::paths::shading::PointLit {
                lit: scatter3(lit),
                origin,
                direction: scatter3(direction),
                distance: lanes(sqrt(dot(to_target, to_target))),
            }
        }

        /// `Tracer::light_sample` at four hits (normals facing their rays) of
        /// surfaces of `albedo`, from each hit's `[u1, cos phi, sin phi]`, towards
        /// the sphere light of `centre`, `radius` and `emission`: the cone under
        /// which the light is seen (`SphereLight::cone`), its frame, a direction in
        /// it (`Cone::sample`), its density, and the ray.
        $(#[$attribute])*
        pub(crate) fn sphere_light(
            hits: [&$crate::geometry::Hit; 4],
            albedo: [$crate::maths::Colour; 4],
            samples: [[$crate::maths::Real; 3]; 4],
            light: ($crate::maths::Vec3, $crate::maths::Real, $crate::maths::Colour),
        ) -> $crate::fast::paths::shading::LightSamples {
            use $crate::maths::PI;
            let (centre, radius, emission) = light;
            let [h0, h1, h2, h3] = hits;
            let point = gather3([h0.point, h1.point, h2.point, h3.point]);
            let to_centre = minus([splat(centre.x), splat(centre.y), splat(centre.z)], point);
            let r2 = dot(to_centre, to_centre);
            let sin2 = div(splat(radius * radius), r2);
            let outside = lt(sin2, splat(1.0));
            let cos_max = sqrt(sub(splat(1.0), sin2));
            let one_minus_cos_max = div(sin2, add(splat(1.0), cos_max));
            let [cx, cy, cz] = to_centre;
            let inverse = div(splat(1.0), sqrt(r2));
            let axis = [mul(cx, inverse), mul(cy, inverse), mul(cz, inverse)];
            let [s0, s1, s2, s3] = samples;
            let u1 = gather([s0[0], s1[0], s2[0], s3[0]]);
            let cos_phi = gather([s0[1], s1[1], s2[1], s3[1]]);
            let sin_phi = gather([s0[2], s1[2], s2[2], s3[2]]);
            let one_minus_cos = mul(u1, one_minus_cos_max);
            let squared = mul(one_minus_cos, sub(splat(2.0), one_minus_cos));
            let sin_theta = sqrt(max(squared, splat(0.0)));
            let local = [
                mul(cos_phi, sin_theta),
                mul(sin_phi, sin_theta),
                sub(splat(1.0), one_minus_cos),
            ];
            let direction = to_world(axis, local);
            let inside_cone = ge(local[2], cos_max);
            let pdf = and(inside_cone, div(splat(1.0), mul(splat(2.0 * PI), one_minus_cos_max)));
            let normal = gather3([h0.normal, h1.normal, h2.normal, h3.normal]);
            let cos = dot(direction, normal);
            let kept = and(outside, gt(cos, splat(0.0)));
            let [ax, ay, az] = gather3(albedo);
            let pi = splat(PI);
            let lit = [
                div(mul(div(mul(splat(emission.x), ax), pi), cos), pdf),
                div(mul(div(mul(splat(emission.y), ay), pi), cos), pdf),
                div(mul(div(mul(splat(emission.z), az), pi), cos), pdf),
            ];
            let offset = gather3([h0.offset, h1.offset, h2.offset, h3.offset]);
            $crate::fast::paths::shading::LightSamples {
                lit: scatter3(lit),
                origin: spawn(point, offset, direction),
                direction: scatter3(direction),
                kept: lanes(kept),
            }
        }

        /// The cosine-weighted bounces of four hits (normals facing their rays):
        /// `sample_cosine_hemisphere` from each sample's `[cos phi, sin phi, u2]`,
        /// turned into the frame of the normal and spawned from the hit; the rays'
        /// origins and directions.
        $(#[$attribute])*
        pub(crate) fn bounces(
            hits: [&$crate::geometry::Hit; 4],
            samples: [[$crate::maths::Real; 3]; 4],
        ) -> ($crate::fast::paths::shading::FourVectors, $crate::fast::paths::shading::FourVectors) {
            let [s0, s1, s2, s3] = samples;
            let cos_phi = gather([s0[0], s1[0], s2[0], s3[0]]);
            let sin_phi = gather([s0[1], s1[1], s2[1], s3[1]]);
            let u2 = gather([s0[2], s1[2], s2[2], s3[2]]);
            let r = sqrt(sub(splat(1.0), u2));
            let local = [mul(cos_phi, r), mul(sin_phi, r), sqrt(u2)];
            let [h0, h1, h2, h3] = hits;
            let direction = to_world(gather3([h0.normal, h1.normal, h2.normal, h3.normal]), local);
            let point = gather3([h0.point, h1.point, h2.point, h3.point]);
            let offset = gather3([h0.offset, h1.offset, h2.offset, h3.offset]);
            (spawn(point, offset, direction), scatter3(direction))
        }
    };
}

pub(crate) use four_hit_shading;
