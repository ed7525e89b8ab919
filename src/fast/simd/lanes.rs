//! The four-ray sphere test, written once for any type of four lanes.
//!
//! A processor can do one operation on four numbers at once (SIMD: single
//! instruction, multiple data) when they lie side by side in one register, each in
//! its own lane. Four paths followed at once put one ray in each lane and test each
//! sphere against the four rays in one go. The test is written here once, as a
//! macro, with the lane operations as functions (`add`, `mul`, `sqrt`, `lt`,
//! `select`, ...) that the module using it defines for its own type of lanes: the
//! `wide` crate's, which works on any processor ([`portable`](crate::fast::simd::portable)), and
//! AVX's, four `f64` per instruction (`avx`). Its steps are those of
//! [`Sphere::intersect`](crate::geometry::Sphere::intersect), in the same order, so
//! every distance is the same number to the last bit.

use crate::maths::Real;

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
            use $crate::maths::Real;
            // Each coordinate gathered lane by lane, with no closure (see `found`).
            let [r0, r1, r2, r3] = rays;
            let o = [r0.origin, r1.origin, r2.origin, r3.origin];
            let d = [r0.direction, r1.direction, r2.direction, r3.direction];
            let origin = [
                gather([o[0].x, o[1].x, o[2].x, o[3].x]),
                gather([o[0].y, o[1].y, o[2].y, o[3].y]),
                gather([o[0].z, o[1].z, o[2].z, o[3].z]),
            ];
            let direction = [
                gather([d[0].x, d[1].x, d[2].x, d[3].x]),
                gather([d[0].y, d[1].y, d[2].y, d[3].y]),
                gather([d[0].z, d[1].z, d[2].z, d[3].z]),
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
            let (t, which) = (lanes(nearest), lanes(which));
            let found = $crate::fast::simd::lanes::found;
            [
                found(t[0], which[0]),
                found(t[1], which[1]),
                found(t[2], which[2]),
                found(t[3], which[3]),
            ]
        }
    };
}

pub(crate) use four_ray_sphere_test;

/// A lane's answer: the distance `t` and the sphere whose index has the bits of
/// `which`, or `None` where `t` is infinite (no sphere met). It is called lane by
/// lane, with no closure: a closure inside a function compiled with AVX is compiled
/// without it, and called rather than inlined (written with closures, `indirect`
/// with `--fast` ran 7% more instructions and took 10% longer).
#[inline(always)]
pub(crate) fn found(t: Real, which: Real) -> Option<(Real, usize)> {
    (t < Real::INFINITY).then_some((t, which.to_bits() as usize))
}
