// mesh { triangle{} smooth_triangle{} ... inside_vector } and
// mesh2 { vertex_vectors normal_vectors uv_vectors texture_list face_indices normal_indices }
#include "interp/build_common.hpp"

namespace lumen::interp {

namespace {

// Reads `{ N, item, item, ... }` calling `read(cursor)` N times.
template <class Read>
void read_counted(BuildContext& ctx, const BlockValue& block, const Read& read) {
    ItemCursor cur(ctx, block);
    int n = cur.expect_int("");
    if (n < 0) cur.fail(cur.here(), block.keyword + " count is negative");
    for (int i = 0; i < n; ++i) {
        if (cur.at_end())
            cur.fail(cur.here(), block.keyword + ": expected " + std::to_string(n) +
                                     " entries, found " + std::to_string(i));
        read(cur);
    }
    if (!cur.at_end())
        cur.fail(cur.peek().loc, block.keyword + ": more entries than the count " +
                                     std::to_string(n));
}

std::array<int, 3> index_triple(ItemCursor& cur) {
    SourceLoc loc = cur.next_is_vector_like() ? cur.peek().loc : cur.here();
    glm::dvec3 v = cur.expect_vector("");
    std::array<int, 3> out{};
    for (int i = 0; i < 3; ++i) {
        if (!(v[i] >= 0 && v[i] < 2147483647.0)) cur.fail(loc, "bad index in " + cur.what());
        out[i] = static_cast<int>(v[i]);
    }
    return out;
}

void check_range(ItemCursor& cur, const std::array<int, 3>& idx, size_t size, const char* what,
                 SourceLoc loc) {
    for (int i : idx)
        if (i >= 0 && size_t(i) >= size)
            cur.fail(loc, std::string(what) + " index " + std::to_string(i) +
                              " out of range (there are " + std::to_string(size) + ")");
}

// mesh2's uv indices per face (POV-Ray 3.7): uv_indices when given (one triple per face);
// without them, uv_vectors indexed like the vertices, or one uv for every corner. Any other
// uv count is refused, as POV-Ray refuses it.
void index_uvs(ItemCursor& cur, scene::Mesh& mesh, const std::vector<std::array<int, 3>>* uv_indices,
               const std::vector<SourceLoc>& face_locs) {
    if (uv_indices) {
        if (uv_indices->size() != mesh.faces.size())
            cur.fail(cur.block_loc(), "uv_indices count differs from face_indices count");
        for (size_t i = 0; i < mesh.faces.size(); ++i) {
            check_range(cur, (*uv_indices)[i], mesh.uvs.size(), "uv", face_locs[i]);
            mesh.faces.edit()[i].uv = (*uv_indices)[i];
        }
        return;
    }
    if (mesh.uvs.empty()) return;
    if (mesh.uvs.size() != 1 && mesh.uvs.size() != mesh.vertices.size())
        cur.fail(cur.block_loc(), "mesh2 needs uv_indices: its uv_vectors count (" +
                                      std::to_string(mesh.uvs.size()) +
                                      ") is neither 1 nor the vertex count");
    for (scene::Mesh::Face& f : mesh.faces.edit()) f.uv = mesh.uvs.size() == 1 ? std::array<int, 3>{} : f.v;
}

bool read_inside_vector(ItemCursor& cur, const Item& item, scene::Mesh& mesh) {
    if (item.kind != Item::Kind::Keyword || item.keyword != "inside_vector") return false;
    mesh.inside_vector = cur.expect_vector("inside_vector");
    return true;
}

}  // namespace

glm::dvec2 read_vector2(ItemCursor& cur, const std::string& after) {
    const std::vector<double> v = cur.expect_vecn(after);
    if (v.size() == 1) return {v[0], v[0]};
    if (v.size() != 2) cur.fail(cur.here(), "'" + after + "' takes a 2-component vector");
    return {v[0], v[1]};
}

scene::ObjectPtr build_mesh(ItemCursor& cur) {
    // `mesh { Mesh_Ident modifiers }` copies a declared mesh (mesh_camera scenes do).
    if (cur.next_is<scene::ObjectPtr>() &&
        std::holds_alternative<scene::Mesh>(cur.peek().value.as<scene::ObjectPtr>()->shape))
        return read_object_copy(cur);
    scene::Object obj;
    obj.loc = cur.block_loc();
    // Filled in place, so transforms met among the items also move per-triangle textures.
    scene::Mesh& mesh = obj.shape.emplace<scene::Mesh>();
    auto extra = [&](const Item& item) {
        if (read_inside_vector(cur, item, mesh)) return true;
        if (item.kind != Item::Kind::Value || !item.value.is<scene::ObjectPtr>()) return false;
        const scene::Object& tri_obj = *item.value.as<scene::ObjectPtr>();
        const auto* tri = std::get_if<scene::Triangle>(&tri_obj.shape);
        if (!tri) cur.fail(item.loc, "a mesh may only contain triangles and smooth_triangles");
        scene::Mesh::Face face;
        int base = int(mesh.vertices.size());
        for (int i = 0; i < 3; ++i) {
            mesh.vertices.push_back(tri->p[i]);
            mesh.uvs.push_back(tri->uv[i]);
            face.v[i] = face.uv[i] = base + i;
            if (tri->smooth) {
                face.n[i] = int(mesh.normals.size());
                mesh.normals.push_back(tri->n[i]);
            }
        }
        if (!tri_obj.texture.empty()) {
            mesh.textures.push_back(tri_obj.texture);
            face.tex.fill(int(mesh.textures.size()) - 1);
        }
        mesh.faces.push_back(face);
        return true;
    };
    read_object_modifiers(cur, obj, extra, {"triangle", "smooth_triangle", "inside_vector"});
    if (mesh.faces.empty()) cur.fail(cur.block_loc(), "mesh has no triangles");
    return std::make_shared<scene::Object>(std::move(obj));
}

scene::ObjectPtr build_mesh2(ItemCursor& cur) {
    scene::Object obj;
    obj.loc = cur.block_loc();
    // Filled in place, so transforms met among the items also move per-triangle textures.
    scene::Mesh& mesh = obj.shape.emplace<scene::Mesh>();
    std::vector<std::array<int, 3>> normal_indices, uv_indices;
    std::vector<SourceLoc> face_locs;
    bool have_normal_indices = false, have_uv_indices = false;
    BuildContext& ctx = cur.ctx();
    auto extra = [&](const Item& item) {
        if (read_inside_vector(cur, item, mesh)) return true;
        const BlockValue* b = block_of(item);
        if (!b) return false;
        const std::string& k = b->keyword;
        if (k == "vertex_vectors") {
            read_counted(ctx, *b, [&](ItemCursor& c) { mesh.vertices.push_back(c.expect_vector("")); });
        } else if (k == "normal_vectors") {
            read_counted(ctx, *b, [&](ItemCursor& c) { mesh.normals.push_back(c.expect_vector("")); });
        } else if (k == "uv_vectors") {
            read_counted(ctx, *b,
                         [&](ItemCursor& c) { mesh.uvs.push_back(read_vector2(c, "uv_vectors")); });
        } else if (k == "texture_list") {
            read_counted(ctx, *b, [&](ItemCursor& c) {
                mesh.textures.push_back(
                    c.expect<std::shared_ptr<const TextureValue>>("", "a texture")->layers);
            });
        } else if (k == "face_indices") {
            read_counted(ctx, *b, [&](ItemCursor& c) {
                scene::Mesh::Face f;
                face_locs.push_back(c.next_is_vector_like() ? c.peek().loc : c.here());
                f.v = index_triple(c);
                if (c.next_is_float()) {  // one texture, or one per vertex
                    f.tex.fill(c.expect_int(""));
                    if (c.next_is_float()) {
                        f.tex[1] = c.expect_int("");
                        f.tex[2] = c.expect_int("");
                    }
                }
                mesh.faces.push_back(f);
            });
        } else if (k == "normal_indices") {
            have_normal_indices = true;
            read_counted(ctx, *b, [&](ItemCursor& c) { normal_indices.push_back(index_triple(c)); });
        } else if (k == "uv_indices") {
            have_uv_indices = true;
            read_counted(ctx, *b, [&](ItemCursor& c) { uv_indices.push_back(index_triple(c)); });
        } else {
            return false;
        }
        return true;
    };
    read_object_modifiers(cur, obj, extra,
                          {"vertex_vectors", "normal_vectors", "uv_vectors", "texture_list",
                           "face_indices", "normal_indices", "uv_indices", "inside_vector"});
    if (mesh.faces.empty()) cur.fail(cur.block_loc(), "mesh2 has no face_indices");
    if (have_normal_indices && normal_indices.size() != mesh.faces.size())
        cur.fail(cur.block_loc(), "normal_indices count differs from face_indices count");
    for (size_t i = 0; i < mesh.faces.size(); ++i) {
        scene::Mesh::Face& f = mesh.faces.edit()[i];
        check_range(cur, f.v, mesh.vertices.size(), "vertex", face_locs[i]);
        check_range(cur, f.tex, mesh.textures.size(), "texture", face_locs[i]);
        // Without normal_indices, normal_vectors are indexed like the vertices.
        if (have_normal_indices) f.n = normal_indices[i];
        else if (!mesh.normals.empty()) f.n = f.v;
        check_range(cur, f.n, mesh.normals.size(), "normal", face_locs[i]);
    }
    index_uvs(cur, mesh, have_uv_indices ? &uv_indices : nullptr, face_locs);
    return std::make_shared<scene::Object>(std::move(obj));
}

}  // namespace lumen::interp
