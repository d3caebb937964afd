// A four-wide BVH collapsed from a binary one (bvh.hpp): each node holds the boxes of up to four
// children side by side, so one ray meets four boxes in one pass of vector arithmetic and half
// as many levels. The slab test is the binary one's (SlabRay::hits), lane by lane in double
// precision, so a box is hit here exactly when it is hit there; only the order in which leaves
// are visited differs. Meshes trace through it (render/shapes/mesh.cpp).
#pragma once
#include <cstdint>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "render/bvh.hpp"

namespace lumen::render {

class WideBvh {
public:
    struct Node {
        // Per axis and slot, the children's bounds (empty slots: lo +inf, hi -inf).
        alignas(16) double lo[3][4], hi[3][4];
        int32_t child[4];   // an inner child's node, or a leaf's first position; -1: empty
        uint16_t count[4];  // a leaf's primitives; 0 for an inner child
        uint8_t used = 0;   // bit k: slot k holds a child
    };

    // Collapses `bvh` (its positions stay those of bvh.order()).
    explicit WideBvh(const Bvh& bvh);
    WideBvh() = default;
    bool empty() const { return nodes_.empty(); }
    size_t node_count() const { return nodes_.size(); }

    // As Bvh::traverse: leaf(position) for the primitives of every leaf whose box the ray meets
    // within [tmin, tmax], nearer boxes first; the visitor may lower tmax to prune the rest.
    template <class Leaf>
    void traverse(const SlabRay& ray, double tmin, double& tmax, Leaf&& leaf) const {
        if (nodes_.empty()) return;
        struct Pending {
            int32_t index;   // node, or leaf's first position
            uint16_t count;  // leaf primitives (0: a node)
            double enter;
        };
        Pending stack[4 * (Bvh::kMaxDepth + 2)];
        int sp = 0;
        stack[sp++] = {0, 0, tmin};
        while (sp > 0) {
            const Pending p = stack[--sp];
            if (p.enter > tmax) continue;
            if (p.count) {
                for (uint32_t i = uint32_t(p.index), e = i + p.count; i < e; ++i) leaf(i);
                continue;
            }
            const Node& n = nodes_[size_t(p.index)];
            double enter[4];
            const unsigned hit = slab4(n, ray, tmin, tmax, enter) & n.used;
            // The children met, nearest last on the stack (popped first).
            int met[4], m = 0;
            for (int k = 0; k < 4; ++k)
                if (hit & (1u << k)) {
                    int j = m++;
                    for (; j > 0 && enter[met[j - 1]] < enter[k]; --j) met[j] = met[j - 1];
                    met[j] = k;
                }
            for (int j = 0; j < m; ++j) stack[sp++] = {n.child[met[j]], n.count[met[j]], enter[met[j]]};
        }
    }

private:
    // SlabRay::hits for the four slots at once: bit k set when slot k is met, enter[k] its
    // entry distance. Its comparisons are minimum and maximum operations with the same
    // operand order, so the lanes agree with it bit for bit, NaN included.
    static unsigned slab4(const Node& n, const SlabRay& ray, double tmin, double tmax,
                          double enter[4]) {
#if defined(__SSE2__)
        __m128d t0a = _mm_set1_pd(tmin), t0b = t0a, t1a = _mm_set1_pd(tmax), t1b = t1a;
        for (int a = 0; a < 3; ++a) {
            const __m128d o = _mm_set1_pd(ray.origin[a]), inv = _mm_set1_pd(ray.inv_dir[a]);
            const __m128d loa = _mm_mul_pd(_mm_sub_pd(_mm_load_pd(n.lo[a]), o), inv);
            const __m128d lob = _mm_mul_pd(_mm_sub_pd(_mm_load_pd(n.lo[a] + 2), o), inv);
            const __m128d hia = _mm_mul_pd(_mm_sub_pd(_mm_load_pd(n.hi[a]), o), inv);
            const __m128d hib = _mm_mul_pd(_mm_sub_pd(_mm_load_pd(n.hi[a] + 2), o), inv);
            // near = lo < hi ? lo : hi; far = lo < hi ? hi : lo; t0 = near > t0 ? near : t0;
            // t1 = far < t1 ? far : t1 (minpd(x, y) is x < y ? x : y, maxpd x > y ? x : y).
            t0a = _mm_max_pd(_mm_min_pd(loa, hia), t0a);
            t0b = _mm_max_pd(_mm_min_pd(lob, hib), t0b);
            t1a = _mm_min_pd(_mm_max_pd(hia, loa), t1a);
            t1b = _mm_min_pd(_mm_max_pd(hib, lob), t1b);
        }
        _mm_storeu_pd(enter, t0a);
        _mm_storeu_pd(enter + 2, t0b);
        return unsigned(_mm_movemask_pd(_mm_cmple_pd(t0a, t1a))) |
               unsigned(_mm_movemask_pd(_mm_cmple_pd(t0b, t1b))) << 2;
#else
        unsigned hit = 0;
        for (int k = 0; k < 4; ++k) {
            Aabb b;
            for (int a = 0; a < 3; ++a) b.lo[a] = n.lo[a][k], b.hi[a] = n.hi[a][k];
            double exit;
            if (ray.hits(b, tmin, tmax, enter[k], exit)) hit |= 1u << k;
        }
        return hit;
#endif
    }

    int32_t collapse(const Bvh& bvh, uint32_t binary);
    std::vector<Node> nodes_;
};

}  // namespace lumen::render
