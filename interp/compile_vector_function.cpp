// `function { pigment | pattern | transform | spline { ... } }`: vector functions (and the
// pattern function, a float one) compiled into one instruction on x, y, z (t for a spline):
// an external the renderer evaluates (pigment, pattern), a 3 x 4 matrix (transform) or the
// spline itself.
#include "interp/evaluator.hpp"
#include "scene/content_hash.hpp"

namespace lumen::interp {

using fn::Op;

fn::ProgramPtr Evaluator::compile_vector_function(const ast::Node& block) {
    if (!block.more().params.empty())
        throw LumenError(block.loc, "a " + block.children.back()->text +
                                        " function takes no parameter list (it has x, y, z)");
    const ast::Node& body = *block.children.back();
    auto p = std::make_shared<fn::Program>();
    for (uint32_t i = 0; i < 3; ++i) p->code.push_back({Op::Arg, 0, 0, i});
    if (body.text == "spline") {  // one parameter, t
        const Value v = eval(body);
        const auto* f = v.is<std::shared_ptr<const FunctionValue>>()
                            ? v.as<std::shared_ptr<const FunctionValue>>().get() : nullptr;
        if (!f || !f->spline) throw LumenError(body.loc, "expected a spline");
        p->code.resize(1);
        p->params = 1;
        p->splines.push_back(f->spline);
        p->code.push_back({Op::Spline, fn::kMemberAsked, 1, 0});
        p->components = f->spline->terms;
        return p;
    }
    if (body.text == "transform") {
        const Value v = eval(body);
        if (!v.is<std::shared_ptr<const scene::Transform>>())
            throw LumenError(body.loc, "expected a transform");
        const glm::dmat4& m = v.as<std::shared_ptr<const scene::Transform>>()->m;
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 4; ++c) p->consts.push_back(m[c][r]);
        p->code.push_back({Op::Transform, fn::kMemberAsked, 3, 0});
        p->components = 3;
        return p;
    }
    // A pattern function is its pattern block read as a pigment: the pattern and its
    // modifiers, whose value (before any colour map) the renderer returns.
    const bool pattern = body.text == "pattern";
    const Value v = pattern ? eval_block_as(body, "pigment") : eval(body);
    if (!v.is<scene::PigmentPtr>()) throw LumenError(body.loc, "expected a pigment");
    fn::External e;
    e.kind = pattern ? fn::External::Kind::Pattern : fn::External::Kind::Pigment;
    const scene::PigmentPtr& pigment = v.as<scene::PigmentPtr>();
    scene::ContentHash h;
    h.add(pigment);
    e.content = h.value();
    e.payload = pigment;
    p->externals.push_back(std::move(e));
    p->code.push_back({Op::External, pattern ? uint8_t(0) : fn::kMemberAsked, 3, 0});
    p->components = pattern ? 1 : 5;
    p->needs_host = true;
    return p;
}

}  // namespace lumen::interp
