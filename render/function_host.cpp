#include "render/function_host.hpp"

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
        // POV-Ray's colours are single precision: 0.3 comes back as 0.30000001192092896.
        const scene::Colour c = evaluate_pigment(pigment, p);
        const float channels[5] = {float(c.r), float(c.g), float(c.b), float(c.f), float(c.t)};
        for (int i = 0; i < 5; ++i) out[i] = channels[i];
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
