// The C interface through which the peers benchmark (benches/peers.rs) builds
// tinybvh's hierarchies over a triangle list and traces a ray set through them, the
// loop over the rays in C++ so that no call crosses the language boundary per ray.
// tiny_bvh.h is tinybvh 1.6.8 (MIT licence, Jacco Bikker), unchanged.
#define TINYBVH_IMPLEMENTATION
#include "tiny_bvh.h"

#include <cstdint>

using namespace tinybvh;

namespace {

// Counts the rays of `rays` (origin, direction, t_max: 7 floats each) that hit
// (closest hit) or are blocked (any hit) in `bvh`.
template <class B>
uint32_t trace(const B& bvh, const float* rays, uint32_t count, int occlusion) {
    uint32_t found = 0;
    for (uint32_t i = 0; i < count; i++) {
        const float* r = rays + 7 * i;
        Ray ray(bvhvec3(r[0], r[1], r[2]), bvhvec3(r[3], r[4], r[5]), r[6]);
        if (occlusion) {
            found += bvh.IsOccluded(ray) ? 1 : 0;
        } else {
            bvh.Intersect(ray);
            found += ray.hit.t < r[6] ? 1 : 0;
        }
    }
    return found;
}

}  // namespace

extern "C" {

// Layouts: 2 the binary BVH, 4 BVH4_CPU, 8 BVH8_CPU (null where this build has no
// AVX2). `vertices` holds three (x, y, z, 0) corners per triangle.
void* tinybvh_build(int layout, const float* vertices, uint32_t triangles) {
    const bvhvec4* v = reinterpret_cast<const bvhvec4*>(vertices);
    switch (layout) {
    case 2: { auto* b = new BVH(); b->BuildHQ(v, triangles); return b; }
    case 4: { auto* b = new BVH4_CPU(); b->BuildHQ(v, triangles); return b; }
#ifdef BVH_USEAVX2
    case 8: { auto* b = new BVH8_CPU(); b->BuildHQ(v, triangles); return b; }
#endif
    default: return nullptr;
    }
}

uint32_t tinybvh_trace(int layout, const void* bvh, const float* rays, uint32_t count,
                       int occlusion) {
    switch (layout) {
    case 2: return trace(*static_cast<const BVH*>(bvh), rays, count, occlusion);
    case 4: return trace(*static_cast<const BVH4_CPU*>(bvh), rays, count, occlusion);
#ifdef BVH_USEAVX2
    case 8: return trace(*static_cast<const BVH8_CPU*>(bvh), rays, count, occlusion);
#endif
    default: return 0;
    }
}

void tinybvh_free(int layout, void* bvh) {
    switch (layout) {
    case 2: delete static_cast<BVH*>(bvh); break;
    case 4: delete static_cast<BVH4_CPU*>(bvh); break;
#ifdef BVH_USEAVX2
    case 8: delete static_cast<BVH8_CPU*>(bvh); break;
#endif
    default: break;
    }
}

}
