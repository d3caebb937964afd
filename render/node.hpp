// The scene's objects compiled for tracing: a flat array of nodes (primitives and CSG
// operations) with transforms composed down to world space, inherited textures, interiors and
// no_shadow resolved per node, and surface/solid bounds for culling.
#pragma once
#include <cstdint>
#include <memory>
#include <variant>
#include <vector>

#include "render/bounds.hpp"
#include "render/ray.hpp"
#include "render/shapes/shape_data.hpp"
#include "scene/object.hpp"

namespace lumen::render {

// Difference {A B C} compiles to Intersection {A, inverse B, inverse C}.
enum class NodeKind : uint8_t { Shape, Union, Merge, Intersection };

struct Node {
    NodeKind kind = NodeKind::Shape;
    bool identity = true;    // no transform left (baked into the shape, or none)
    bool inverse = false;    // inside/outside swapped (own `inverse` or subtracted)
    bool flip = false;       // normal flipped: odd number of inverses from the root down
    bool no_shadow = false;  // own or inherited from a CSG ancestor
    bool no_image = false, no_reflection = false, double_illuminate = false,
         no_radiosity = false, hollow = false;  // likewise (reported in Hit)
    bool needs_uv = false;   // its texture uses uv_mapping: hits get their (u, v); not baked
    // Its hits depend on the range a search is given, not only on which of them lie in it
    // (a julia fractal marches from its start to its end), here or in a member: a CSG
    // narrows that range by its other members' finite boxes alone (csg.cpp), as it always did.
    bool range_sensitive = false;
    double min_depth = kDepthDefault;
    uint32_t xf = 0;         // NodeStore::transforms: object -> world (when !identity)
    Aabb surface;            // world box of the points a hit can be at
    Aabb solid;              // world box of the points that can be inside
    uint32_t shape = 0;      // index into NodeStore::shapes (Shape nodes)
    uint32_t children = 0, child_count = 0;  // ranges in NodeStore::links
    uint32_t clips = 0, clip_count = 0;
    uint32_t bounds = 0, bound_count = 0;
    const scene::Object* object = nullptr;   // the source object
    const scene::LayeredTexture* texture = nullptr;  // after inheritance; null = default
    const scene::LayeredTexture* interior_texture = nullptr;  // after inheritance; null = none
    const scene::Interior* interior = nullptr;       // after inheritance; null = default
    // Photon flags after inheritance (the outermost CSG block wins; null = defaults), and the
    // outermost photon target among the node and its CSG ancestors (shot as a whole; null:
    // none).
    const scene::ObjectPhotons* photons = nullptr;
    const scene::Object* photon_target = nullptr;
    uint32_t light_group = 0;  // the innermost light_group it lies in (0: none)
    bool global_lights = true; // the scene's lights reach it (node_compile: group_inside)
};

struct NodeStore {
    std::vector<Node> nodes;
    std::vector<uint32_t> links;
    std::vector<ShapeData> shapes;
    std::vector<scene::Transform> transforms;
};

// CSG nesting deeper than this is refused (keeps every recursion bounded).
constexpr int kMaxNesting = 1000;

// What the compiler inherits from enclosing objects.
struct NodeContext {
    scene::Transform to_world;                  // the parent's object -> world
    const scene::LayeredTexture* texture = nullptr;
    const scene::LayeredTexture* interior_texture = nullptr;
    const scene::Interior* interior = nullptr;
    const scene::ObjectPhotons* photons = nullptr;  // an enclosing object's photons { }
    const scene::Object* photon_target = nullptr;   // an enclosing photon target
    bool target_splits = false;  // it is a union whose members are photon targets themselves
    uint32_t light_group = 0;    // the innermost enclosing light_group, and whether
    bool global_lights = true;   // the scene's lights reach inside
    bool no_shadow = false, no_image = false, no_reflection = false, double_illuminate = false,
         no_radiosity = false, hollow = false;
    bool invert = false, flip = false;
    std::vector<uint32_t> clips;                // clip nodes pushed down from flattened unions
    std::vector<uint32_t> bounds;               // bounded_by nodes pushed down likewise
    int depth = 0;
};

// Compiles `object` (and its children, clips and bounds) into `store`; returns its node.
// `accelerate` = false skips building mesh BVHs. Throws LumenError for unsupported shapes.
uint32_t compile_object(NodeStore& store, const scene::Object& object, const NodeContext& ctx,
                        bool accelerate = true);

// Top-level form: unions (not merges) are flattened into their children, with inverse, clips,
// bounds and inherited attributes pushed down, so the BVH sees every primitive. Appends roots
// and, to `to_world`, each root's object -> world transform (what the radiosity mesher places
// the source object with).
void compile_top_level(NodeStore& store, const scene::Object& object,
                       std::vector<uint32_t>& roots, std::vector<scene::Transform>& to_world);

// The nearest accepted hit of a node: which leaf, and the shape's own report.
struct NodeHit {
    ShapeHit shape;
    uint32_t leaf = 0;
};

// Nearest hit of node `index` with tmin < t < tmax on the world ray. `any`: some hit in that
// range, not necessarily the nearest (an occlusion test: a CSG stops at its first member with
// an accepted hit).
bool intersect_node(const NodeStore& store, uint32_t index, const Ray& ray, double tmin,
                    double tmax, bool shadow, NodeHit& hit, bool any = false);
// Whether world point p is inside node `index` (inverse, CSG and clipped_by applied).
bool inside_node(const NodeStore& store, uint32_t index, const glm::dvec3& p);

// Number of primitive shapes under a node (meshes count their triangles).
size_t count_primitives(const NodeStore& store, uint32_t index);

}  // namespace lumen::render
