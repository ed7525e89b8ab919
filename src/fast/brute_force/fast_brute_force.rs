//! Beyond the course: session 5's searches, every triangle for every ray (and, with
//! the bounding box, for every ray that meets the mesh's box), tested [`LANES`] at a
//! time by one ray ([`TriangleLanes`]). Still every triangle: the same search as the
//! course's, in fewer instructions, finding the same hit to the last bit.

use crate::fast::brute_force::triangle_lanes::TriangleLanes;
use crate::fast::lanes::{LaneKind, Lanes, OnLanes};
use crate::fast::simd::real_lanes::LANES;
use crate::geometry::{Ray, TriangleHit, TriangleTest};
use crate::maths::Real;
use crate::meshes::{Mesh, MeshHit, Search};

/// Every triangle of a mesh in groups of [`LANES`], in the order of the mesh's
/// triangles: group `g` holds triangles `LANES g` to `LANES g + LANES - 1`.
#[derive(Clone, Debug, PartialEq)]
pub struct FastBruteForce {
    /// The groups.
    groups: Vec<TriangleLanes>,
    /// How many triangles the mesh has.
    count: usize,
    /// Whether a ray must first meet the mesh's bounding box, as in the stage
    /// `mesh-bbox`.
    boxed: bool,
    /// The lanes the groups are tested on.
    lanes: Lanes,
}

impl FastBruteForce {
    /// The search of `mesh`, which must use the course's Moller-Trumbore test
    /// (`None` otherwise), behind its bounding box if `boxed`, on the fastest lanes
    /// this processor has.
    pub fn build(mesh: &Mesh, boxed: bool) -> Option<FastBruteForce> {
        if mesh.triangle_test != TriangleTest::MollerTrumbore {
            return None;
        }
        let count = mesh.triangles.len();
        let corners: Vec<_> = (0..count as u32).map(|t| mesh.corners(t)).collect();
        Some(FastBruteForce {
            groups: corners.chunks(LANES).map(TriangleLanes::new).collect(),
            count,
            boxed,
            lanes: Lanes::fastest(),
        })
    }

    /// The same search with its tests made in `lanes`.
    pub fn with_lanes(self, lanes: Lanes) -> FastBruteForce {
        FastBruteForce { lanes, ..self }
    }

    /// The lanes of group `g` that hold a triangle.
    fn filled(&self, g: usize) -> u32 {
        (1 << (self.count - LANES * g).min(LANES)) - 1
    }

    /// Whether `ray` is turned away by the mesh's box before `t_max`, where the
    /// search has one.
    fn turned_away(&self, mesh: &Mesh, ray: &Ray, t_max: Real) -> bool {
        self.boxed
            && mesh
                .bounds
                .entry(ray, ray.direction.recip(), t_max)
                .is_none()
    }

    // ANCHOR: fast_brute_force
    /// The nearest triangle that `ray` meets closer than `t_max`, as the course's
    /// [`Mesh::nearest_among`] finds it over every triangle: the least distance,
    /// and on equal distances the lower triangle number. Each group is tested
    /// below the best distance so far (its next float up, so that an equal distance
    /// with a lower number can still win).
    #[inline(always)]
    fn nearest_with<L: LaneKind>(&self, lanes: L, ray: &Ray, t_max: Real) -> Option<MeshHit> {
        let mut best: Option<MeshHit> = None;
        let mut limit = t_max;
        for (g, group) in self.groups.iter().enumerate() {
            let found = group.hits(lanes, ray, limit);
            let mut hits = found.hits & self.filled(g);
            while hits != 0 {
                let k = hits.trailing_zeros() as usize;
                hits &= hits - 1;
                let triangle = (LANES * g + k) as u32;
                let at = TriangleHit {
                    t: found.t[k],
                    beta: found.beta[k],
                    gamma: found.gamma[k],
                };
                if best.is_none_or(|b| (at.t, triangle) < (b.at.t, b.triangle)) {
                    best = Some(MeshHit { triangle, at });
                    limit = at.t.next_up();
                }
            }
        }
        best
    }
    // ANCHOR_END: fast_brute_force

    /// Whether `ray` meets any triangle closer than `t_max`; stops at the first
    /// group that holds one.
    #[inline(always)]
    fn occluded_with<L: LaneKind>(&self, lanes: L, ray: &Ray, t_max: Real) -> bool {
        for (g, group) in self.groups.iter().enumerate() {
            if group.hits(lanes, ray, t_max).hits & self.filled(g) != 0 {
                return true;
            }
        }
        false
    }
}

impl Search for FastBruteForce {
    fn name(&self) -> &'static str {
        if self.boxed {
            "bounding box, fast"
        } else {
            "brute force, fast"
        }
    }

    fn nearest(&self, mesh: &Mesh, ray: &Ray, t_max: Real) -> Option<MeshHit> {
        if self.turned_away(mesh, ray, t_max) {
            return None;
        }
        self.lanes.run(Nearest(self, ray, t_max))
    }

    fn occluded(&self, mesh: &Mesh, ray: &Ray, t_max: Real) -> bool {
        !self.turned_away(mesh, ray, t_max) && self.lanes.run(Occluded(self, ray, t_max))
    }
}

/// The nearest hit of a ray below a distance, on any lanes.
struct Nearest<'a>(&'a FastBruteForce, &'a Ray, Real);

impl OnLanes for Nearest<'_> {
    type Output = Option<MeshHit>;

    #[inline(always)]
    fn on<L: LaneKind>(self, lanes: L) -> Option<MeshHit> {
        self.0.nearest_with(lanes, self.1, self.2)
    }
}

/// Whether a ray meets a triangle below a distance, on any lanes.
struct Occluded<'a>(&'a FastBruteForce, &'a Ray, Real);

impl OnLanes for Occluded<'_> {
    type Output = bool;

    #[inline(always)]
    fn on<L: LaneKind>(self, lanes: L) -> bool {
        self.0.occluded_with(lanes, self.1, self.2)
    }
}
