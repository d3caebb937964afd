// Shadow rays through filtering surfaces: listing the surfaces past the first in one pass (plain spheres,
// planes and boxes) gives the light, and the query count, of POV's one query per surface.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "render/geometry.hpp"
#include "render/geometry_test_util.hpp"
#include "render/shadows.hpp"
#include "render/texture_layers.hpp"

namespace lumen::render {
namespace {

using namespace testing;

// Geometry as an Intersector that lists surfaces when `when` says.
class Stepping final : public Intersector {
public:
    Stepping(const Geometry& g, Listing when) : g_(g), when_(when) {}
    Listing shadow_listing() const override { return when_; }
    bool intersect(const Ray& ray, double t_min, double t_max, Hit& hit, bool shadow) const override {
        return g_.intersect(ray, t_min, t_max, hit, shadow);
    }
    int visit_shadow_hits(const Ray& ray, double t_min, double t_max, HitVisitor visit,
                          void* context) const override {
        return when_ != Listing::Never ? g_.visit_shadow_hits(ray, t_min, t_max, visit, context) : -1;
    }

private:
    const Geometry& g_;
    Listing when_;
};

scene::TexturePtr texture_of(scene::PigmentPtr pigment) {
    auto texture = std::make_shared<scene::Texture>();
    texture->pigment = std::move(pigment);
    return texture;
}

scene::TexturePtr plain(scene::Colour c) {
    auto pigment = std::make_shared<scene::Pigment>();
    pigment->colour = c;
    return texture_of(pigment);
}

scene::LayeredTexture filtering(std::mt19937& rng) {
    std::uniform_real_distribution<double> u(0.3, 1);
    return {plain({u(rng), u(rng), u(rng), u(rng) * 0.8, u(rng) * 0.2})};
}

std::shared_ptr<scene::Object> glassy(scene::Shape shape, std::mt19937& rng) {
    auto o = make(std::move(shape));
    o->texture = filtering(rng);
    scene::Interior in;
    in.fade_distance = 2;
    in.fade_power = 1001;  // exponential fade: depends on the depth inside
    in.fade_colour = {0.5, 0.8, 0.9};
    o->interior = in;
    return o;
}

TEST(ShadowFilter, ListingEveryCrossingAgreesWithOneQueryPerSurface) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-3, 3), r(0.3, 1.2);
    std::vector<scene::ObjectPtr> objects;
    for (int i = 0; i < 10; ++i)  // more than the direct-test limit: the BVH path lists too
        objects.push_back(glassy(scene::Sphere{{u(rng), u(rng), u(rng)}, r(rng)}, rng));
    for (int i = 0; i < 4; ++i) {
        const glm::dvec3 c{u(rng), u(rng), u(rng)};
        objects.push_back(glassy(scene::Box{c - r(rng), c + r(rng)}, rng));
    }
    objects.push_back(glassy(scene::Plane{{0, 1, 0}, -2}, rng));
    // Coincident surfaces: a box face on the plane and a sphere twice.
    objects.push_back(glassy(scene::Box{{-1, -2, -1}, {1, -1.5, 1}}, rng));
    objects.push_back(glassy(scene::Sphere{{0.5, 0.5, 0.5}, 0.7}, rng));
    objects.push_back(glassy(scene::Sphere{{0.5, 0.5, 0.5}, 0.7}, rng));
    const Geometry geometry(scene_of(objects));
    EXPECT_TRUE(geometry.lists_shadow_hits());
    EXPECT_TRUE(geometry.mostly_passes_light());
    using L = Intersector::Listing;
    const Stepping from_start(geometry, L::FromStart), after_first(geometry, L::AfterFirstSurface),
        stepping(geometry, L::Never);

    int crossed = 0;
    for (int i = 0; i < 3000; ++i) {
        const glm::dvec3 from{u(rng) * 1.5, u(rng) * 1.5, u(rng) * 1.5};
        glm::dvec3 to{u(rng) * 3, 6, u(rng) * 3};
        if (i % 3 == 0) to = {u(rng) * 3, -6, u(rng) * 3};  // through the plane
        const glm::dvec3 dir = glm::normalize(to - from);
        const double distance = glm::length(to - from);
        TraceCounters b;
        const glm::dvec3 fb = shadow_filter(stepping, from, dir, distance, {}, b);
        for (const Stepping* listing : {&from_start, &after_first}) {
            TraceCounters a;
            const glm::dvec3 fa = shadow_filter(*listing, from, dir, distance, {}, a);
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(fa[c], fb[c], 1e-12 + 1e-9 * fb[c]) << i;
            EXPECT_EQ(a.shadow_rays, b.shadow_rays) << i;
        }
        crossed += b.shadow_rays > 2;
    }
    EXPECT_GT(crossed, 500);  // the rays do cross several surfaces
}

TEST(ShadowFilter, SceneWithCsgStepsFromSurfaceToSurface) {
    std::mt19937 rng(2);
    std::vector<scene::ObjectPtr> objects{
        glassy(scene::Sphere{{0, 0, 0}, 1}, rng),
        csg(scene::CsgOp::Difference, {glassy(scene::Sphere{{0, 3, 0}, 1}, rng),
                                       glassy(scene::Sphere{{0, 3.5, 0}, 0.5}, rng)})};
    const Geometry geometry(scene_of(objects));
    int visited = 0;
    EXPECT_EQ(geometry.visit_shadow_hits(
                  ray({0, -5, 0}, {0, 1, 0}), 1e-3, 100,
                  [](void* n, const Hit&) { return ++*static_cast<int*>(n) > 0; }, &visited),
              -1);
    EXPECT_EQ(visited, 0);
    EXPECT_FALSE(geometry.lists_shadow_hits());
    // Plain objects list every crossing, nearest first, and stop when told.
    const Geometry plain(scene_of({glassy(scene::Sphere{{0, 0, 0}, 1}, rng),
                                   glassy(scene::Box{{-1, 2, -1}, {1, 4, 1}}, rng)}));
    std::vector<double> ts;
    auto record = [](void* v, const Hit& h) {
        static_cast<std::vector<double>*>(v)->push_back(h.t);
        return true;
    };
    EXPECT_EQ(plain.visit_shadow_hits(ray({0, -5, 0}, {0, 1, 0}), 1e-3, 100, record, &ts), 4);
    ASSERT_EQ(ts.size(), 4u);
    EXPECT_DOUBLE_EQ(ts[0], 4);
    EXPECT_DOUBLE_EQ(ts[1], 6);
    EXPECT_DOUBLE_EQ(ts[2], 7);
    EXPECT_DOUBLE_EQ(ts[3], 9);
    EXPECT_EQ(plain.visit_shadow_hits(ray({0, -5, 0}, {0, 1, 0}), 1e-3, 100,
                                      [](void*, const Hit&) { return false; }, nullptr),
              1);
}

TEST(ShadowFilter, WhichTexturesMayPassLight) {
    const scene::Colour opaque{0.5, 0.5, 0.5, 0, 0}, glass{1, 1, 1, 0.9, 0};
    const scene::LayeredTexture solid{plain(opaque)}, clear{plain(glass)};
    EXPECT_FALSE(may_pass_light(nullptr));
    EXPECT_FALSE(may_pass_light(&solid));
    EXPECT_TRUE(may_pass_light(&clear));
    // Layers multiply: one opaque layer stops the light.
    const scene::LayeredTexture layered{plain(glass), plain(opaque)};
    EXPECT_FALSE(may_pass_light(&layered));
    // A colour_map entry with transmit, a pigment_map entry that filters.
    auto mapped = std::make_shared<scene::Pigment>();
    mapped->pattern.type = scene::PatternType::Gradient;
    mapped->colour_map = {{0, opaque}, {1, {0, 0, 0, 0, 0.5}}};
    const scene::LayeredTexture gradient{texture_of(mapped)};
    EXPECT_TRUE(may_pass_light(&gradient));
    auto nested = std::make_shared<scene::Pigment>();
    nested->pattern.type = scene::PatternType::Checker;
    nested->pigment_map = {{0, std::make_shared<scene::Pigment>()}, {1, mapped}};
    const scene::LayeredTexture checker{texture_of(nested)};
    EXPECT_TRUE(may_pass_light(&checker));
    // texture_map entries are resolved through one of their layers: any may count.
    auto map_texture = std::make_shared<scene::Texture>();
    map_texture->pattern.type = scene::PatternType::Checker;
    map_texture->texture_map = {{0, solid}, {1, layered}};
    const scene::LayeredTexture by_map{map_texture};
    EXPECT_TRUE(may_pass_light(&by_map));
    map_texture->texture_map = {{0, solid}, {1, solid}};
    EXPECT_FALSE(may_pass_light(&by_map));
}

}  // namespace
}  // namespace lumen::render
