#include "render/interior_list.hpp"

namespace lumen::render {

double cross_interface(const InteriorList& before, const void* id, const scene::Interior* in,
                       bool hollow, InteriorList& after) {
    auto ior_of = [](const scene::Interior* i) { return i ? i->ior : 1.0; };
    after = before;
    const double ior = ior_of(in);
    const int at = after.find(id);
    if (after.empty()) {
        after.push(id, in, hollow);
        return 1.0 / ior;
    }
    if (at == after.size() - 1) {
        after.remove_at(at);
        return ior / (after.empty() ? 1.0 : ior_of(after.last().interior));
    }
    if (at >= 0) {
        after.remove_at(at);
        return 1.0;
    }
    const double eta = ior_of(after.last().interior) / ior;
    after.push(id, in, hollow);
    return eta;
}

}  // namespace lumen::render
