// spline { [SplineId] [linear_spline | quadratic_spline | cubic_spline | natural_spline]
// t0, V0 [,] t1, V1 ... }, read as POV-Ray 3.7 reads it: an identifier first copies that spline
// (then retyped and extended), a type keyword may come anywhere between entries, a value is a
// float (becoming <v, v>) or a vector of 2 to 5 components, and at least one entry is needed.
#include <cmath>

#include "interp/build_common.hpp"
#include "interp/conversions.hpp"

namespace lumen::interp {

std::optional<fn::SplineType> spline_type(std::string_view word) {
    if (word == "linear_spline") return fn::SplineType::Linear;
    if (word == "quadratic_spline") return fn::SplineType::Quadratic;
    if (word == "cubic_spline") return fn::SplineType::Cubic;
    if (word == "natural_spline") return fn::SplineType::Natural;
    return std::nullopt;
}

std::shared_ptr<const fn::Spline> build_spline(ItemCursor& cur) {
    auto spline = std::make_shared<fn::Spline>();
    if (cur.next_is<std::shared_ptr<const FunctionValue>>()) {
        const FunctionValue& f = *cur.peek().value.as<std::shared_ptr<const FunctionValue>>();
        if (!f.spline) cur.fail(cur.peek().loc, "a spline can only copy another spline");
        *spline = *f.spline;
        cur.next();
    }
    while (!cur.at_end()) {
        const Item& item = cur.peek();
        if (item.kind == Item::Kind::Keyword) {
            const auto type = spline_type(item.keyword);
            if (!type) cur.fail_unexpected(item, {"linear_spline", "quadratic_spline", "cubic_spline", "natural_spline"});
            spline->type = *type;
            cur.next();
            continue;
        }
        const double t = cur.expect_float("");
        const SourceLoc at = cur.next_loc();
        if (cur.at_end()) cur.fail(at, "a spline entry needs a value after its t");
        const Item& value = cur.next();
        std::vector<double> c = components(value.value);
        if (c.size() == 1) c.push_back(c[0]);  // a float is <v, v>
        if (c.size() > 5) cur.fail(at, "a spline's values have 2 to 5 components");
        std::array<double, 5> v{};
        for (size_t i = 0; i < c.size(); ++i) v[i] = c[i];
        spline->add(t, v, int(c.size()));
    }
    if (spline->entries.empty()) cur.fail(cur.block_loc(), "a spline needs at least one entry");
    spline->prepare();
    return spline;
}

}  // namespace lumen::interp
