#include "render/function_host.hpp"

#include <algorithm>
#include <cstdint>

#include "render/pattern.hpp"
#include "render/pigment.hpp"

namespace lumen::render {

namespace {

class RenderHost final : public fn::Host {
public:
    void evaluate(const fn::External& e, const double* xyz, double* out) const override {
        const auto* pigment = static_cast<const scene::Pigment*>(e.payload.get());
        const glm::dvec3 p(xyz[0], xyz[1], xyz[2]);
        if (e.kind == fn::External::Kind::Pattern) {
            out[0] = pigment ? pattern_value(pigment->pattern, p) : 0;
            return;
        }
        // A colour's channels are asked for one by one at the same point (a height_field's
        // pigment function, `.red`, `.green` and `.blue` side by side): the last colour is
        // kept, per thread, for its pigment (by content: an address may be reused) and point.
        thread_local struct {
            const void* pigment = nullptr;
            uint64_t content = 0;
            glm::dvec3 p{0};
            float channels[5] = {};
        } last;
        if (!(last.pigment == pigment && last.content == e.content && last.p == p)) {
            // POV-Ray's colours are single precision: 0.3 comes back as 0.30000001192092896.
            const scene::Colour c = evaluate_pigment(pigment, p);
            const float channels[5] = {float(c.r), float(c.g), float(c.b), float(c.f), float(c.t)};
            std::copy(channels, channels + 5, last.channels);
            last.pigment = pigment, last.content = e.content, last.p = p;
        }
        for (int i = 0; i < 5; ++i) out[i] = last.channels[i];
    }
};

}  // namespace

const fn::Host& function_host() {
    static const RenderHost host;
    return host;
}

std::shared_ptr<const fn::Host> shared_function_host() {
    return std::shared_ptr<const fn::Host>(&function_host(), [](const fn::Host*) {});
}

}  // namespace lumen::render
