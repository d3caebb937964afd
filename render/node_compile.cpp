// Turns scene objects into nodes: composes transforms, resolves inheritance (texture,
// interior, no_shadow, inverse parity) and computes the boxes used for culling.
#include <cmath>

#include "base/diagnostics.hpp"
#include "render/node.hpp"
#include "render/texture_layers.hpp"

namespace lumen::render {

namespace {

// A hair wider than exact, so rounding in the corner transforms never culls a real hit.
Aabb padded(Aabb b) {
    if (b.empty() || !b.finite()) return b;
    glm::dvec3 pad = 1e-9 * (1.0 + glm::max(glm::abs(b.lo), glm::abs(b.hi)));
    return {b.lo - pad, b.hi + pad};
}

// A member of an intersection shows only where it lies inside every other member, so its box
// is cut to the box of their insides (for a plane along an axis, its half-space); a quadric
// without its transform gets the box of its own inside there. The rook's body, a cylinder
// between two planes, is then a box the BVH can cull rather than a surface every ray meets.
void fit_members(NodeStore& store, const std::vector<uint32_t>& kids) {
    std::vector<Aabb> after(kids.size() + 1, Aabb::everything());  // members i.. together
    for (size_t i = kids.size(); i-- > 0;)
        after[i] = intersect(after[i + 1], store.nodes[kids[i]].solid);
    Aabb before = Aabb::everything();  // members ..i-1 together
    for (size_t i = 0; i < kids.size(); ++i) {
        Node& member = store.nodes[kids[i]];
        const Aabb others = intersect(before, after[i + 1]);
        before = intersect(before, member.solid);
        member.surface = intersect(member.surface, padded(others));
        if (member.kind == NodeKind::Shape && member.identity && !member.inverse)
            member.surface = intersect(
                member.surface, padded(shape_bounds_within(store.shapes[member.shape], others)));
    }
}

// A member's solid box in the frame of the intersection it belongs to, where only its own
// transform applies: a plane along that frame's axes bounds a half-space there, though the
// intersection's rotation leaves it unbounded in world space.
Aabb solid_in_frame(const NodeStore& store, const Node& m, const scene::Transform& from_world) {
    if (m.solid.empty()) return m.solid;
    const scene::Object& o = *m.object;
    if (m.kind == NodeKind::Shape)
        if (const auto* p = std::get_if<scene::Plane>(&o.shape)) {
            PlaneShape plane = make_plane(*p);
            if (!plane.valid || !ShapeTraits<scene::Plane>::bake(*p, o.transform, plane))
                return Aabb::everything();
            return m.inverse ? complement_solid_bounds(plane) : solid_bounds(plane);
        }
    if (m.kind == NodeKind::Shape && !m.identity && !m.inverse)
        return transformed(shape_solid_bounds(store.shapes[m.shape]), o.transform);
    return transformed(m.solid, from_world);
}

// POV-Ray bounds an intersection in its own frame, by the overlap of its members' boxes
// there, and then transforms that box: the quarter of a rotated blob that three planes
// along its axes cut out is boxed as that quarter, not as the whole blob.
Aabb framed_bounds(const NodeStore& store, const std::vector<uint32_t>& kids,
                   const scene::Transform& world) {
    const scene::Transform from_world{world.inv, world.m};
    Aabb frame = Aabb::everything();
    for (uint32_t k : kids)
        frame = intersect(frame, solid_in_frame(store, store.nodes[k], from_world));
    if (frame.empty() || !frame.finite()) return Aabb::everything();
    return padded(transformed(frame, world));
}

bool transform_is_finite(const scene::Transform& xf) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(xf.m[c][r]) || !std::isfinite(xf.inv[c][r])) return false;
    return true;
}

// Flags a CSG hands down to everything inside it.
template <class To>
void inherit_flags(To& to, const NodeContext& ctx, const scene::Object& o) {
    to.no_shadow = ctx.no_shadow || o.no_shadow;
    to.no_image = ctx.no_image || o.no_image;
    to.no_reflection = ctx.no_reflection || o.no_reflection;
    to.double_illuminate = ctx.double_illuminate || o.double_illuminate;
    to.no_radiosity = ctx.no_radiosity || o.no_radiosity;
    to.hollow = ctx.hollow || o.hollow;
}

// POV-Ray hands a CSG's photons { } flags down to its members: the outermost block counts.
const scene::ObjectPhotons* inherited_photons(const NodeContext& ctx, const scene::Object& o) {
    if (ctx.photons) return ctx.photons;
    return o.photons ? &*o.photons : nullptr;
}

// The photon target a node belongs to: the outermost target around it, except that a target
// union (split_union, the default) makes each of its members a target of its own.
const scene::Object* outer_target(const NodeContext& ctx, const scene::Object& o) {
    if (ctx.photon_target && !ctx.target_splits) return ctx.photon_target;
    return ctx.photon_target || (o.photons && o.photons->target) ? &o : nullptr;
}

// The light_group of what lies inside `o`: o's own where o is a placed group, else the one
// around o. The scene's lights reach it only where every group around it says global_lights
// on (POV-Ray, probed: an outer group's default `off` holds inside an inner group's `on`).
void group_inside(NodeContext& inner, const NodeContext& outer, const scene::Object& o) {
    const auto* csg = std::get_if<scene::Csg>(&o.shape);
    const bool own = csg && csg->light_group != 0;
    inner.light_group = own ? csg->light_group : outer.light_group;
    inner.global_lights = outer.global_lights && (!own || csg->global_lights);
}

bool splits_for_photons(const scene::Object& o) {
    const auto* csg = std::get_if<scene::Csg>(&o.shape);
    return csg && csg->op == scene::CsgOp::Union && o.split_union;
}

void pass_flags(NodeContext& to, const Node& from) {
    to.no_shadow = from.no_shadow;
    to.no_image = from.no_image;
    to.no_reflection = from.no_reflection;
    to.double_illuminate = from.double_illuminate;
    to.no_radiosity = from.no_radiosity;
    to.hollow = from.hollow;
}

// Whether a hit on the primitive is shaded with a uv_mapping texture: its own or inherited
// textures, or a mesh's or blob's per-part ones.
bool shades_with_uv(const scene::Object& object, const Node& node) {
    if (uses_uv_mapping(node.texture) || uses_uv_mapping(node.interior_texture)) return true;
    if (const auto* mesh = std::get_if<scene::Mesh>(&object.shape))
        for (const auto& t : mesh->textures)
            if (uses_uv_mapping(&t)) return true;
    if (const auto* blob = std::get_if<scene::Blob>(&object.shape))
        for (const auto& c : blob->components)
            if (uses_uv_mapping(&c.texture)) return true;
    return false;
}

uint32_t append_links(NodeStore& store, const std::vector<uint32_t>& items) {
    auto first = uint32_t(store.links.size());
    store.links.insert(store.links.end(), items.begin(), items.end());
    return first;
}

// Compiles clipped_by / bounded_by objects. The interpreter keeps them complete, in world
// space, even on CSG children (transforming an object transforms its descendants' clips).
std::vector<uint32_t> compile_helpers(NodeStore& store, const std::vector<scene::ObjectPtr>& objs,
                                      const NodeContext& ctx, bool accelerate,
                                      std::vector<uint32_t> inherited) {
    NodeContext plain;  // identity: world space
    plain.depth = ctx.depth + 1;
    for (const auto& o : objs)
        if (o) inherited.push_back(compile_object(store, *o, plain, accelerate));
    return inherited;
}

}  // namespace

uint32_t compile_object(NodeStore& store, const scene::Object& object, const NodeContext& ctx,
                        bool accelerate) {
    if (ctx.depth > kMaxNesting)
        throw LumenError(object.loc, "objects are nested too deeply (more than " +
                                         std::to_string(kMaxNesting) + " levels)");
    if (auto* u = std::get_if<scene::UnsupportedShape>(&object.shape))
        throw LumenError(u->what.loc.line ? u->what.loc : object.loc,
                         "'" + u->what.feature + "' is not supported yet");

    Node node;
    node.object = &object;
    const scene::Transform world = object.transform.then(ctx.to_world);
    node.inverse = object.inverse != ctx.invert;
    node.flip = ctx.flip != node.inverse;
    inherit_flags(node, ctx, object);
    node.texture = object.texture.empty() ? ctx.texture : &object.texture;
    node.interior_texture =
        object.interior_texture.empty() ? ctx.interior_texture : &object.interior_texture;
    node.interior = object.interior ? &*object.interior : ctx.interior;
    node.photons = inherited_photons(ctx, object);
    node.photon_target = outer_target(ctx, object);
    node.light_group = ctx.light_group;
    node.global_lights = ctx.global_lights;

    std::vector<uint32_t> clips = compile_helpers(store, object.clipped_by, ctx, accelerate, ctx.clips);
    std::vector<uint32_t> bounds = compile_helpers(store, object.bounded_by, ctx, accelerate, ctx.bounds);

    if (auto* csg = std::get_if<scene::Csg>(&object.shape)) {
        // POV-Ray inverts a union into the intersection of its inverted members (De Morgan):
        // an inverted union keeps only its outer surface, as a merge does (measured on a
        // box with inverted unions of cylinders cut out of it).
        const bool merged = csg->op == scene::CsgOp::Merge ||
                            (csg->op == scene::CsgOp::Union && node.inverse);
        node.kind = merged                              ? NodeKind::Merge
                    : csg->op == scene::CsgOp::Union ? NodeKind::Union
                                                     : NodeKind::Intersection;
        NodeContext inner;
        inner.to_world = world;
        inner.texture = node.texture;
        inner.interior_texture = node.interior_texture;
        inner.interior = node.interior;
        inner.photons = node.photons;
        inner.photon_target = node.photon_target;
        inner.target_splits = node.photon_target == &object && splits_for_photons(object);
        group_inside(inner, ctx, object);
        pass_flags(inner, node);
        inner.flip = node.flip;
        inner.depth = ctx.depth + 1;
        std::vector<uint32_t> kids;
        std::vector<bool> bounds_overlap;  // counts in POV-Ray's overlap of member boxes
        for (size_t i = 0; i < csg->children.size(); ++i) {
            if (!csg->children[i]) continue;
            inner.invert = csg->op == scene::CsgOp::Difference && i > 0;
            kids.push_back(compile_object(store, *csg->children[i], inner, accelerate));
            node.range_sensitive = node.range_sensitive || store.nodes[kids.back()].range_sensitive;
            bounds_overlap.push_back(
                !store.nodes[kids.back()].inverse &&
                !std::holds_alternative<scene::HeightField>(csg->children[i]->shape));
        }
        if (node.kind == NodeKind::Intersection) fit_members(store, kids);
        // POV-Ray bounds an intersection by the overlap of its members' bounding boxes (the
        // subtracted ones and height fields left out): a ray that misses it misses the object,
        // one that meets it finds every crossing. A disc's box is flat though its inside is a
        // half-space.
        Aabb surface, solid = node.kind == NodeKind::Intersection ? Aabb::everything() : Aabb{};
        Aabb overlap = Aabb::everything();
        for (size_t i = 0; i < kids.size(); ++i) {
            const Node& child = store.nodes[kids[i]];
            surface.expand(child.surface);
            if (node.kind == NodeKind::Intersection) solid = intersect(solid, child.solid);
            else solid.expand(child.solid);
            if (bounds_overlap[i]) overlap = intersect(overlap, child.surface);
        }
        if (node.kind == NodeKind::Intersection) {
            if (!world.is_identity() && transform_is_finite(world))
                solid = intersect(solid, framed_bounds(store, kids, world));
            surface = intersect(intersect(surface, solid), overlap);
        }
        if (kids.empty()) solid = surface = Aabb{};
        node.surface = surface;
        node.solid = solid;
        node.children = append_links(store, kids);
        node.child_count = uint32_t(kids.size());
    } else {
        ShapeData data;
        bool finite = transform_is_finite(world);
        // uv is measured in the shape's own space: a baked shape has lost it.
        node.needs_uv = shades_with_uv(object, node);
        if (world.is_identity()) {
            prepare_shape(object.shape, accelerate, data);
        } else if (!finite || node.needs_uv || !bake_transform(object.shape, world, data)) {
            prepare_shape(object.shape, accelerate, data);
            node.identity = false;
            node.xf = uint32_t(store.transforms.size());
            store.transforms.push_back(world);
        }
        node.min_depth = min_depth_of(object.shape);
        node.range_sensitive = std::holds_alternative<JuliaFractalShape>(data);
        // Object-space boxes: where the shape can be hit, and where it can be inside.
        Aabb surface = shape_bounds(data), solid = shape_solid_bounds(data);
        if (!finite) surface = solid = Aabb{};  // singular transform: never hit
        if (!node.identity) {
            surface = transformed(surface, world);
            solid = transformed(solid, world);
        }
        node.surface = padded(surface);
        node.solid = padded(solid);
        node.shape = uint32_t(store.shapes.size());
        store.shapes.push_back(std::move(data));
    }
    if (node.inverse) {
        // Inverted, a shape may be inside anywhere, but for a plane along an axis: the other
        // half-space, which bounds the members of a difference that subtracts it.
        const PlaneShape* plane = node.kind == NodeKind::Shape && node.identity
                                      ? std::get_if<PlaneShape>(&store.shapes[node.shape])
                                      : nullptr;
        node.solid = plane ? complement_solid_bounds(*plane) : Aabb::everything();
    }
    for (uint32_t c : clips) {
        node.surface = intersect(node.surface, store.nodes[c].solid);
        node.solid = intersect(node.solid, store.nodes[c].solid);
    }
    node.clips = append_links(store, clips);
    node.clip_count = uint32_t(clips.size());
    node.bounds = append_links(store, bounds);
    node.bound_count = uint32_t(bounds.size());
    store.nodes.push_back(std::move(node));
    return uint32_t(store.nodes.size() - 1);
}

void compile_top_level(NodeStore& store, const scene::Object& object,
                       std::vector<uint32_t>& roots, std::vector<scene::Transform>& to_world) {
    // Explicit stack: unions nested thousands deep (loops building unions) stay flat. The
    // children of one union share its context, stored once.
    std::vector<NodeContext> contexts(1);
    std::vector<std::pair<const scene::Object*, size_t>> stack{{&object, 0}};
    while (!stack.empty()) {
        auto [obj, at] = stack.back();
        stack.pop_back();
        const scene::Object& o = *obj;
        auto* csg = std::get_if<scene::Csg>(&o.shape);
        // An inverted union is not flattened: it is a merge (compile_object).
        if (!csg || csg->op != scene::CsgOp::Union || o.inverse != contexts[at].invert) {
            roots.push_back(compile_object(store, o, contexts[at]));
            to_world.push_back(o.transform.then(contexts[at].to_world));
            continue;
        }
        NodeContext inner;
        const NodeContext& ctx = contexts[at];
        inner.to_world = o.transform.then(ctx.to_world);
        inner.invert = o.inverse != ctx.invert;  // reaches the leaves' `inverse` (and flip)
        inner.flip = ctx.flip;
        inherit_flags(inner, ctx, o);
        inner.texture = o.texture.empty() ? ctx.texture : &o.texture;
        inner.interior_texture =
            o.interior_texture.empty() ? ctx.interior_texture : &o.interior_texture;
        inner.interior = o.interior ? &*o.interior : ctx.interior;
        inner.photons = inherited_photons(ctx, o);
        inner.photon_target = outer_target(ctx, o);
        inner.target_splits = inner.photon_target == &o && splits_for_photons(o);
        group_inside(inner, ctx, o);
        inner.clips = compile_helpers(store, o.clipped_by, ctx, true, ctx.clips);
        inner.bounds = compile_helpers(store, o.bounded_by, ctx, true, ctx.bounds);
        contexts.push_back(std::move(inner));
        for (auto it = csg->children.rbegin(); it != csg->children.rend(); ++it)
            if (*it) stack.emplace_back(it->get(), contexts.size() - 1);
    }
}

size_t count_primitives(const NodeStore& store, uint32_t index) {
    const Node& n = store.nodes[index];
    if (n.kind != NodeKind::Shape) {
        size_t total = 0;
        for (uint32_t i = 0; i < n.child_count; ++i)
            total += count_primitives(store, store.links[n.children + i]);
        return total;
    }
    if (auto* mesh = std::get_if<MeshPtr>(&store.shapes[n.shape]))
        return (*mesh)->face.size();
    return 1;
}

}  // namespace lumen::render
