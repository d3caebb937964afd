// Shadow rays through filtering surfaces: listing the surfaces past the first in one pass (plain spheres,
// planes and boxes) gives the light, and the query count, of POV's one query per surface;
// skipping clear objects gives the same light; in scenes of opaque objects an occlusion test
// (any surface, not the nearest) gives the light of the walk.
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

// Geometry as an Intersector that lists surfaces when `when` says, and lets shadow rays skip
// clear objects when `clear` says (Sabotaged: without ever giving up near one).
enum class Clear { Seen, Skipped, Sabotaged };
class Stepping final : public Intersector {
public:
    Stepping(const Geometry& g, Listing when, Clear clear = Clear::Seen)
        : g_(g), when_(when), clear_(clear) {}
    Listing shadow_listing(Query) const override { return when_; }
    bool intersect(const Ray& ray, double t_min, double t_max, Hit& hit, Query query) const override {
        return g_.intersect(ray, t_min, t_max, hit, query);
    }
    int visit_shadow_hits(const Ray& ray, double t_min, double t_max, Query query,
                          HitVisitor visit, void* context) const override {
        return when_ != Listing::Never
                   ? g_.visit_shadow_hits(ray, t_min, t_max, query, visit, context)
                   : -1;
    }
    bool has_clear_objects() const override {
        return clear_ != Clear::Seen && g_.has_clear_objects();
    }
    bool near_clear_object(const glm::dvec3& p) const override {
        return clear_ == Clear::Skipped && g_.near_clear_object(p);
    }

private:
    const Geometry& g_;
    Listing when_;
    Clear clear_;
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

std::shared_ptr<scene::Object> with(scene::Shape shape, scene::LayeredTexture texture,
                                    const scene::Interior& interior) {
    auto o = make(std::move(shape));
    o->texture = std::move(texture);
    o->interior = interior;
    return o;
}

std::shared_ptr<scene::Object> glassy(scene::Shape shape, std::mt19937& rng) {
    scene::Interior in;
    in.fade_distance = 2;
    in.fade_power = 1001;  // exponential fade: depends on the depth inside
    in.fade_colour = {0.5, 0.8, 0.9};
    return with(std::move(shape), filtering(rng), in);
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
    using L = Intersector::Listing;
    EXPECT_EQ(geometry.shadow_listing(Query::Shadow), L::FromStart);
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

// A glass that lets all light through (rgbf 1), with an interior that does not fade.
std::shared_ptr<scene::Object> clear_glass(scene::Shape shape) {
    scene::Interior in;
    in.ior = 1.5;
    return with(std::move(shape), {plain({1, 1, 1, 1, 0})}, in);
}

TEST(ShadowFilter, SkippingClearObjectsAgreesWithSteppingThroughThem) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-3, 3), r(0.3, 1.2);
    std::vector<scene::ObjectPtr> objects;
    for (int i = 0; i < 6; ++i) {
        objects.push_back(clear_glass(scene::Sphere{{u(rng), u(rng), u(rng)}, r(rng)}));
        objects.push_back(glassy(scene::Sphere{{u(rng), u(rng), u(rng)}, r(rng)}, rng));
    }
    objects.push_back(clear_glass(scene::Box{{-2, -1, -2}, {-1, 1, -1}}));
    objects.push_back(glassy(scene::Plane{{0, 1, 0}, -2}, rng));
    // Filtering surfaces within the tolerance past clear ones, where POV steps over them: a
    // sphere just inside a clear one, a box face just above a clear box.
    objects.push_back(clear_glass(scene::Sphere{{0, 0, 0}, 1}));
    objects.push_back(glassy(scene::Sphere{{0, 0, 0}, 0.9995}, rng));
    objects.push_back(clear_glass(scene::Box{{1.5, -1, 1.5}, {2.5, 0, 2.5}}));
    objects.push_back(glassy(scene::Box{{1.5, 0.0004, 1.5}, {2.5, 1, 2.5}}, rng));
    const Geometry geometry(scene_of(objects));
    ASSERT_TRUE(geometry.has_clear_objects());
    using L = Intersector::Listing;
    const Stepping reference(geometry, L::Never, Clear::Seen);
    const Stepping skipping[] = {{geometry, L::Never, Clear::Skipped},
                                 {geometry, L::FromStart, Clear::Skipped},
                                 {geometry, L::AfterFirstSurface, Clear::Skipped}};
    const Stepping sabotaged(geometry, L::Never, Clear::Sabotaged);

    int differs_without_giving_up = 0, fewer_queries = 0;
    for (int i = 0; i < 3000; ++i) {
        glm::dvec3 from{u(rng) * 1.5, u(rng) * 1.5, u(rng) * 1.5};
        if (i % 4 == 0) from = {u(rng) * 0.1, -0.5, u(rng) * 0.1};   // inside the nested pair
        if (i % 4 == 1) from = {2 + u(rng) * 0.1, -0.5, 2 + u(rng) * 0.1};  // in the clear box
        const glm::dvec3 to{u(rng) * 3, 6, u(rng) * 3};
        const glm::dvec3 dir = glm::normalize(to - from);
        const double distance = glm::length(to - from);
        TraceCounters b;
        const glm::dvec3 fb = shadow_filter(reference, from, dir, distance, {}, b);
        for (const Stepping& skip : skipping) {
            TraceCounters a;
            const glm::dvec3 fa = shadow_filter(skip, from, dir, distance, {}, a);
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(fa[c], fb[c], 1e-12 + 1e-9 * fb[c]) << i;
            fewer_queries += a.shadow_rays < b.shadow_rays;
        }
        TraceCounters s;
        const glm::dvec3 fs = shadow_filter(sabotaged, from, dir, distance, {}, s);
        differs_without_giving_up += glm::length(fs - fb) > 1e-6;
    }
    EXPECT_GT(fewer_queries, 1000);             // clear objects were skipped
    EXPECT_GT(differs_without_giving_up, 100);  // and the near ones do matter
}

TEST(ShadowFilter, WhichObjectsShadowRaysMaySkip) {
    std::mt19937 rng(3);
    auto fading = clear_glass(scene::Sphere{{0, 6, 0}, 1});
    fading->interior->fade_distance = 1;
    fading->interior->fade_power = 2;
    auto caustic = clear_glass(scene::Sphere{{0, 9, 0}, 1});
    caustic->interior->caustics = 0.5;
    auto tinted_inside = clear_glass(scene::Sphere{{0, 12, 0}, 1});
    tinted_inside->interior_texture = filtering(rng);
    auto fade_for_eye_rays_only = clear_glass(scene::Sphere{{0, 15, 0}, 1});
    fade_for_eye_rays_only->interior->fade_distance = 1;  // fade_power 0: shadow rays ignore it
    const Geometry geometry(scene_of(
        {clear_glass(scene::Sphere{{0, 0, 0}, 1}),
         csg(scene::CsgOp::Union, {clear_glass(scene::Sphere{{0, 3, 0}, 1}),
                                   clear_glass(scene::Box{{-1, 2.5, -1}, {1, 3.5, 1}})}),
         fading, caustic, tinted_inside, fade_for_eye_rays_only,
         clear_glass(scene::Plane{{0, 0, 1}, 5})}));
    ASSERT_TRUE(geometry.has_clear_objects());
    auto first_hit_y = [&](double y, Query query) {
        Hit h;
        return geometry.intersect(ray({0, y, -10}, {0, 0, 1}), 1e-3, 100, h, query) ? h.point.z
                                                                                   : 1e9;
    };
    for (double y : {0.0, 3.0, 15.0}) {  // skipped: clear sphere, clear union, eye-only fade
        EXPECT_DOUBLE_EQ(first_hit_y(y, Query::Shadow), -1) << y;
        EXPECT_DOUBLE_EQ(first_hit_y(y, Query::ShadowSkipClear), 5) << y;  // the plane: unbounded
    }
    for (double y : {6.0, 9.0, 12.0})  // fade, caustics, a filtering interior_texture: seen
        EXPECT_DOUBLE_EQ(first_hit_y(y, Query::ShadowSkipClear), -1) << y;
    // Near: within twice the tolerance of a skippable object's box.
    EXPECT_TRUE(geometry.near_clear_object({0, 0, 0}));
    EXPECT_TRUE(geometry.near_clear_object({1.0015, 0, 0}));
    EXPECT_FALSE(geometry.near_clear_object({1.003, 0, 0}));
    EXPECT_FALSE(geometry.near_clear_object({0, 6, 0}));
    EXPECT_FALSE(geometry.near_clear_object({0, 0, 5}));
}

TEST(ShadowFilter, WhichTexturesPassAllLight) {
    const scene::LayeredTexture glass{plain({1, 1, 1, 1, 0})}, air{plain({0.3, 0, 1, 0, 1})},
        mixed{plain({1, 1, 1, 0.5, 0.5})}, tinted{plain({1, 0.9, 1, 1, 0})},
        layered{plain({1, 1, 1, 1, 0}), plain({0, 0, 0, 0, 1})},
        half{plain({1, 1, 1, 1, 0}), plain({1, 1, 1, 0.5, 0})};
    EXPECT_TRUE(passes_all_light(&glass));
    EXPECT_TRUE(passes_all_light(&air));
    EXPECT_TRUE(passes_all_light(&mixed));
    EXPECT_TRUE(passes_all_light(&layered));
    EXPECT_FALSE(passes_all_light(&tinted));
    EXPECT_FALSE(passes_all_light(&half));
    EXPECT_FALSE(passes_all_light(nullptr));
    // Patterns are not looked into, even where every colour would pass all light.
    auto checker = std::make_shared<scene::Pigment>();
    checker->pattern.kind = scene::make_pattern_kind(scene::PatternType::Checker);
    checker->colour_map = {{0, {1, 1, 1, 1, 0}}, {1, {1, 1, 1, 1, 0}}};
    const scene::LayeredTexture patterned{texture_of(checker)};
    EXPECT_FALSE(passes_all_light(&patterned));
    // Interiors: fade counts only with fade_power > 0 on shadow rays; caustics count.
    scene::Interior in;
    EXPECT_TRUE(clear_for_shadows(nullptr));
    EXPECT_TRUE(clear_for_shadows(&in));
    in.fade_distance = 2;
    EXPECT_TRUE(clear_for_shadows(&in));
    in.fade_power = 1;
    EXPECT_FALSE(clear_for_shadows(&in));
    in.fade_power = 0;
    in.caustics = 1;
    EXPECT_FALSE(clear_for_shadows(&in));
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
                  ray({0, -5, 0}, {0, 1, 0}), 1e-3, 100, Query::Shadow,
                  [](void* n, const Hit&) { return ++*static_cast<int*>(n) > 0; }, &visited),
              -1);
    EXPECT_EQ(visited, 0);
    EXPECT_EQ(geometry.shadow_listing(Query::Shadow), Intersector::Listing::Never);
    // Plain objects list every crossing, nearest first, and stop when told.
    const Geometry plain(scene_of({glassy(scene::Sphere{{0, 0, 0}, 1}, rng),
                                   glassy(scene::Box{{-1, 2, -1}, {1, 4, 1}}, rng)}));
    std::vector<double> ts;
    auto record = [](void* v, const Hit& h) {
        static_cast<std::vector<double>*>(v)->push_back(h.t);
        return true;
    };
    EXPECT_EQ(plain.visit_shadow_hits(ray({0, -5, 0}, {0, 1, 0}), 1e-3, 100, Query::Shadow, record,
                                      &ts),
              4);
    ASSERT_EQ(ts.size(), 4u);
    EXPECT_DOUBLE_EQ(ts[0], 4);
    EXPECT_DOUBLE_EQ(ts[1], 6);
    EXPECT_DOUBLE_EQ(ts[2], 7);
    EXPECT_DOUBLE_EQ(ts[3], 9);
    EXPECT_EQ(plain.visit_shadow_hits(ray({0, -5, 0}, {0, 1, 0}), 1e-3, 100, Query::Shadow,
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
    mapped->pattern.kind = scene::make_pattern_kind(scene::PatternType::Gradient);
    mapped->colour_map = {{0, opaque}, {1, {0, 0, 0, 0, 0.5}}};
    const scene::LayeredTexture gradient{texture_of(mapped)};
    EXPECT_TRUE(may_pass_light(&gradient));
    auto nested = std::make_shared<scene::Pigment>();
    nested->pattern.kind = scene::make_pattern_kind(scene::PatternType::Checker);
    nested->pigment_map = {{0, std::make_shared<scene::Pigment>()}, {1, mapped}};
    const scene::LayeredTexture checker{texture_of(nested)};
    EXPECT_TRUE(may_pass_light(&checker));
    // texture_map entries are resolved through one of their layers: any may count.
    auto map_texture = std::make_shared<scene::Texture>();
    map_texture->pattern.kind = scene::make_pattern_kind(scene::PatternType::Checker);
    map_texture->texture_map = {{0, solid}, {1, layered}};
    const scene::LayeredTexture by_map{map_texture};
    EXPECT_TRUE(may_pass_light(&by_map));
    map_texture->texture_map = {{0, solid}, {1, solid}};
    EXPECT_FALSE(may_pass_light(&by_map));
}

std::shared_ptr<scene::Object> painted(scene::Shape shape, std::mt19937& rng) {
    std::uniform_real_distribution<double> u(0.1, 1);
    auto o = make(std::move(shape));
    o->texture = {plain({u(rng), u(rng), u(rng), 0, 0})};
    return o;
}

TEST(ShadowFilter, OpaqueScenesTestForAnySurfaceNotTheNearest) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> u(-3, 3), r(0.3, 1.2);
    std::vector<scene::ObjectPtr> objects;
    for (int i = 0; i < 6; ++i)
        objects.push_back(painted(scene::Sphere{{u(rng), u(rng), u(rng)}, r(rng)}, rng));
    objects.push_back(painted(scene::Plane{{0, 1, 0}, -2.5}, rng));
    objects.push_back(painted(scene::Torus{1.5, 0.3, false}, rng));
    // CSG whose members are rejected along the way: a hollowed box with a hole, an
    // intersection, a union of a difference, a clipped sphere, a no_shadow box.
    objects.push_back(csg(scene::CsgOp::Difference,
                          {painted(scene::Box{{-2, -2, -2}, {2, 2, 2}}, rng),
                           painted(scene::Box{{-1.8, -1.8, -1.8}, {1.8, 1.8, 1.8}}, rng),
                           painted(scene::Cylinder{{0, -3, 0}, {0, 3, 0}, 0.8, false}, rng)}));
    objects.push_back(csg(scene::CsgOp::Intersection,
                          {painted(scene::Sphere{{1, 1, 1}, 1}, rng),
                           painted(scene::Box{{0.5, 0.5, 0.5}, {3, 3, 3}}, rng)}));
    objects.push_back(csg(scene::CsgOp::Union,
                          {csg(scene::CsgOp::Difference,
                               {painted(scene::Sphere{{-1, 0, 1}, 0.9}, rng),
                                painted(scene::Sphere{{-1, 0.5, 1}, 0.6}, rng)}),
                           painted(scene::Sphere{{-1, -1, -1}, 0.5}, rng)}));
    auto clipped = painted(scene::Sphere{{0, 1, -1}, 1}, rng);
    clipped->clipped_by = {make(scene::Plane{{0, 1, 0}, 1.2})};
    objects.push_back(clipped);
    auto ghost = painted(scene::Box{{-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}}, rng);
    ghost->no_shadow = true;
    objects.push_back(ghost);
    const Geometry geometry(scene_of(objects));
    ASSERT_TRUE(geometry.opaque_only(Query::Shadow));
    const Stepping walking(geometry, Intersector::Listing::Never);  // never takes the shortcut
    ASSERT_FALSE(walking.opaque_only(Query::Shadow));

    int blocked = 0, open = 0, hinted = 0;
    // Each query keeps its last occluder, as a light does; junk names nothing.
    Occluder last_shadow, last[2], junk{123456};
    for (int i = 0; i < 4000; ++i) {
        const glm::dvec3 from{u(rng), u(rng), u(rng)};
        const glm::dvec3 to{u(rng) * 3, i % 2 ? 8 : -8, u(rng) * 3};
        const glm::dvec3 dir = glm::normalize(to - from);
        const double distance = glm::length(to - from);
        TraceCounters a, b, c;
        const glm::dvec3 fa = shadow_filter(geometry, from, dir, distance, {}, a);
        const glm::dvec3 fb = shadow_filter(walking, from, dir, distance, {}, b);
        const glm::dvec3 fc =
            shadow_filter(geometry, from, dir, distance, {}, c, nullptr, nullptr, &last_shadow);
        ASSERT_EQ(fa, fb) << i;
        ASSERT_EQ(fa, fc) << i;
        EXPECT_EQ(a.shadow_rays, b.shadow_rays) << i;
        EXPECT_EQ(a.shadow_rays, c.shadow_rays) << i;
        (fa == glm::dvec3(0) ? blocked : open) += 1;
        hinted += last_shadow.root != Occluder{}.root;
        // occluded() finds a surface exactly where the nearest-hit query does, whatever
        // object its hint names.
        for (Query q : {Query::All, Query::Shadow}) {
            Hit hit;
            const Ray ray{from, dir};
            const bool nearest = geometry.intersect(ray, 1e-3, distance, hit, q);
            EXPECT_EQ(geometry.occluded(ray, 1e-3, distance, q), nearest) << i;
            EXPECT_EQ(geometry.occluded(ray, 1e-3, distance, q, &last[int(q)]), nearest) << i;
            Occluder stale{uint32_t(i % 16)};  // any root, seen by q or not
            EXPECT_EQ(geometry.occluded(ray, 1e-3, distance, q, &stale), nearest) << i;
            EXPECT_EQ(geometry.occluded(ray, 1e-3, distance, q, &junk), nearest) << i;
        }
    }
    EXPECT_GT(blocked, 1000);
    EXPECT_GT(open, 500);
    EXPECT_GT(hinted, 3000);  // set by the first blocked ray on

    // One surface that may let light through, anywhere in a CSG, ends the shortcut.
    std::vector<scene::ObjectPtr> with_glass = objects;
    auto pane = make(scene::Box{{-1, -1, -1}, {1, 1, 1}});
    pane->texture = {plain({1, 1, 1, 0.5, 0})};
    with_glass.push_back(csg(scene::CsgOp::Union, {painted(scene::Sphere{{0, 0, 0}, 1}, rng), pane}));
    EXPECT_FALSE(Geometry(scene_of(with_glass)).opaque_only(Query::Shadow));
    // A glass object that casts no shadow is not seen by shadow rays.
    pane->no_shadow = true;
    std::vector<scene::ObjectPtr> shadowless = objects;
    shadowless.push_back(pane);
    const Geometry g(scene_of(shadowless));
    EXPECT_TRUE(g.opaque_only(Query::Shadow));
    EXPECT_FALSE(g.opaque_only(Query::All));
}


}  // namespace
}  // namespace lumen::render
