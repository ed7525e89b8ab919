//! tinybvh's hierarchies, built and traced through the C interface of
//! `tiny_bvh/shim.cpp` (compiled by `build.rs`).

use std::ffi::c_void;
use std::ptr::NonNull;

unsafe extern "C" {
    fn tinybvh_build(layout: i32, vertices: *const f32, triangles: u32) -> *mut c_void;
    fn tinybvh_trace(
        layout: i32,
        bvh: *const c_void,
        rays: *const f32,
        count: u32,
        occlusion: i32,
    ) -> u32;
    fn tinybvh_free(layout: i32, bvh: *mut c_void);
}

/// One of tinybvh's layouts, each built with its high-quality builder (`BuildHQ`,
/// spatial splits).
#[derive(Clone, Copy, Debug)]
pub enum Layout {
    /// The binary BVH (`BVH`), traced one box at a time.
    Binary = 2,
    /// Four boxes a node, in SSE (`BVH4_CPU`).
    Four = 4,
    /// Eight boxes a node, in AVX2 (`BVH8_CPU`), over leaves of four triangles.
    Eight = 8,
}

/// A tinybvh hierarchy over a triangle list, freed when dropped.
pub struct TinyBvh {
    layout: Layout,
    bvh: NonNull<c_void>,
}

/// A ray set as tinybvh takes it: per ray its origin, direction and `t_max`, in
/// single precision.
pub struct TinyRays {
    values: Vec<f32>,
    occlusion: bool,
}

impl TinyRays {
    /// `rays` (origin, direction, `t_max` each), any-hit rays if `occlusion`.
    pub fn new(rays: impl Iterator<Item = [f32; 7]>, occlusion: bool) -> TinyRays {
        TinyRays {
            values: rays.flatten().collect(),
            occlusion,
        }
    }
}

impl TinyBvh {
    /// The `layout` hierarchy over `corners`, three `(x, y, z, 0)` a triangle;
    /// `None` where this build has no such layout (`BVH8_CPU` needs AVX2).
    pub fn build(layout: Layout, corners: &[[f32; 4]]) -> Option<TinyBvh> {
        let triangles = u32::try_from(corners.len() / 3).expect("fewer than 2^32 triangles");
        // SAFETY: `corners` holds `3 * triangles` corners of four floats, which
        // tinybvh reads during the build only.
        let bvh = unsafe { tinybvh_build(layout as i32, corners.as_ptr().cast(), triangles) };
        NonNull::new(bvh).map(|bvh| TinyBvh { layout, bvh })
    }

    /// How many of `rays` hit a triangle (closest hit) or are blocked (any hit).
    pub fn trace(&self, rays: &TinyRays) -> usize {
        let count = u32::try_from(rays.values.len() / 7).expect("fewer than 2^32 rays");
        // SAFETY: `self.bvh` is a live hierarchy of `self.layout`, and `rays` holds
        // `count` rays of seven floats.
        let found = unsafe {
            tinybvh_trace(
                self.layout as i32,
                self.bvh.as_ptr(),
                rays.values.as_ptr(),
                count,
                i32::from(rays.occlusion),
            )
        };
        found as usize
    }
}

impl Drop for TinyBvh {
    fn drop(&mut self) {
        // SAFETY: `self.bvh` was made by `tinybvh_build` for `self.layout` and is
        // freed once, here.
        unsafe { tinybvh_free(self.layout as i32, self.bvh.as_ptr()) }
    }
}
