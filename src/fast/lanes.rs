//! The four-ray sphere test, written once for any type of four lanes.
//!
//! A processor can do one operation on four numbers at once (SIMD: single
//! instruction, multiple data) when they lie side by side in one register, each in
//! its own lane. Four paths followed at once put one ray in each lane and test each
//! sphere against the four rays in one go. The test is written here once, as a
//! macro, with the lane operations as functions (`add`, `mul`, `sqrt`, `lt`,
//! `select`, ...) that the module using it defines for its own type of lanes: the
//! `wide` crate's, which works on any processor ([`portable`](super::portable)), and
//! AVX's, four `f64` per instruction (`avx`). Its steps are those of
//! [`Sphere::intersect`](crate::geometry::Sphere::intersect), in the same order, so
//! every distance is the same number to the last bit.

/// Defines `meet` and `nearest_of_four` in the module that invokes it, for its lane
/// type `L` and its lane operations, each function with the attributes given (such
/// as `#[target_feature(enable = "avx")]`).
macro_rules! four_ray_sphere_test {
    ($(#[$attribute:meta])*) => {
        // ANCHOR: meet
        /// For each of four lanes, the smallest `t > 0` at which the ray from
        /// `origin` along the unit vector `direction` meets the sphere of `centre`
        /// and `radius`, or infinity: `Sphere::intersect` on four pairs at once.
        /// Every lane computes every step, whether or not its sphere is missed early
        /// (a negative discriminant gives a NaN root, a zero `mu` an infinite root);
        /// the misses are picked out at the end.
        $(#[$attribute])*
        #[inline]
        fn meet(origin: [L; 3], direction: [L; 3], centre: [L; 3], radius: L) -> L {
            let [dx, dy, dz] = direction;
            let zero = splat(0.0);
            // s = O - C, s.d, and c = |s|^2 - R^2.
            let sx = sub(origin[0], centre[0]);
            let sy = sub(origin[1], centre[1]);
            let sz = sub(origin[2], centre[2]);
            let sd = add(add(mul(sx, dx), mul(sy, dy)), mul(sz, dz));
            let r2 = mul(radius, radius);
            let c = sub(add(add(mul(sx, sx), mul(sy, sy)), mul(sz, sz)), r2);
            // The discriminant R^2 - |s - (s.d) d|^2, without cancellation.
            let (mx, my, mz) = (sub(sx, mul(sd, dx)), sub(sy, mul(sd, dy)), sub(sz, mul(sd, dz)));
            let discriminant = sub(r2, add(add(mul(mx, mx), mul(my, my)), mul(mz, mz)));
            // mu = -(s.d + copysign(sqrt(discriminant), s.d)); the roots mu and c / mu.
            let root = or(sqrt(discriminant), and(sd, splat(-0.0)));
            let mu = neg(add(sd, root));
            let t0 = div(c, mu);
            let before = lt(t0, mu);
            let near = select(before, t0, mu);
            let far = select(before, mu, t0);
            let t = select(gt(near, zero), near, far);
            let away = and(gt(c, zero), gt(sd, zero));
            let valid = and(ge(discriminant, zero), and(ne(mu, zero), gt(far, zero)));
            select(and_not(away, valid), t, splat($crate::maths::Real::INFINITY))
        }
        // ANCHOR_END: meet

        /// For each of four `rays`, the distance to the nearest of `spheres` (each
        /// its centre, radius and index, the index held as the bits of a `Real`) that
        /// it hits, and that sphere's index: each sphere is tested against the four
        /// rays at once ([`meet`]). A strict `<` keeps the first sphere on a tie, as
        /// the course's loop does.
        $(#[$attribute])*
        pub(crate) fn nearest_of_four(
            spheres: &[[$crate::maths::Real; 5]],
            rays: [&$crate::geometry::Ray; 4],
        ) -> [Option<($crate::maths::Real, usize)>; 4] {
            use $crate::geometry::Ray;
            use $crate::maths::Real;
            let four = |f: fn(&Ray) -> Real| gather(rays.map(f));
            let origin = [four(|r| r.origin.x), four(|r| r.origin.y), four(|r| r.origin.z)];
            let direction = [
                four(|r| r.direction.x),
                four(|r| r.direction.y),
                four(|r| r.direction.z),
            ];
            let mut nearest = splat(Real::INFINITY);
            let mut which = splat(0.0);
            for &[x, y, z, radius, index] in spheres {
                let centre = [splat(x), splat(y), splat(z)];
                let t = meet(origin, direction, centre, splat(radius));
                let closer = lt(t, nearest);
                nearest = select(closer, t, nearest);
                which = select(closer, splat(index), which);
            }
            let (nearest, which) = (lanes(nearest), lanes(which));
            std::array::from_fn(|k| {
                (nearest[k] < Real::INFINITY).then(|| (nearest[k], which[k].to_bits() as usize))
            })
        }
    };
}

pub(crate) use four_ray_sphere_test;
