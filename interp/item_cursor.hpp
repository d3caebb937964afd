// Reads the flattened items of a block the way POV-Ray's parser reads a block body: one item
// at a time, with typed expectations ("expected a vector after 'translate'") and optional
// commas between arguments.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "interp/builders.hpp"
#include "interp/value.hpp"

namespace lumen::interp {

// "a float", "an object", "'translate'", "','" ... for error messages.
std::string describe_item(const Item& item);
std::string describe_value(const Value& value);

class ItemCursor {
public:
    // `what` names the block in messages ("sphere", "finish", "color_map entry").
    ItemCursor(BuildContext& ctx, const std::vector<Item>& items, std::string what,
               SourceLoc block_loc);
    ItemCursor(BuildContext& ctx, const BlockValue& block);

    BuildContext& ctx() const { return ctx_; }
    const std::string& what() const { return what_; }
    SourceLoc block_loc() const { return block_loc_; }

    // Commas are optional separators almost everywhere: every peek/next skips them.
    bool at_end();
    const Item& peek();  // precondition: !at_end()
    const Item& next();  // precondition: !at_end()
    // Location of the last item consumed (or the block) for errors about missing items.
    SourceLoc here() const;
    // Where the next argument is written (the last item's place at the end), for its errors.
    SourceLoc next_loc() { return at_end() ? here() : peek().loc; }

    // Type tests on the next item (false at the end).
    bool next_is_keyword(std::string_view word = {});
    bool next_is_float();
    bool next_is_vector_like();  // float or vector
    bool next_is_colour_like();  // float, vector or colour
    // A colour value, or a colour keyword (`color`, `rgb`, `red`, ...) that starts one.
    bool next_is_colour_start();
    template <class T> bool next_is() {
        return !at_end() && peek().kind == Item::Kind::Value && peek().value.is<T>();
    }

    // Consumes keyword `word` if it comes next.
    bool accept_keyword(std::string_view word);

    // Typed reads. `after` names the keyword being read for ("translate") or is empty for
    // positional arguments (then `role` describes it, e.g. "the sphere's radius").
    double expect_float(std::string_view after);
    int expect_int(std::string_view after);
    glm::dvec3 expect_vector(std::string_view after);       // float promoted to <f,f,f>
    std::vector<double> expect_vecn(std::string_view after);  // raw components (float -> 1)
    scene::Colour expect_colour(std::string_view after);    // float -> all 5 channels
    std::string expect_string(std::string_view after);
    std::optional<double> optional_float();  // next float, if any
    bool optional_bool();                    // `hollow [on|off]`: true unless a float says 0

    template <class T> const T& expect(std::string_view after, const char* type_desc) {
        if (!next_is<T>()) fail_expected(type_desc, after);
        return next().value.as<T>();
    }

    [[noreturn]] void fail_expected(std::string_view what_expected, std::string_view after);
    // "'phong_siz' is not a finish keyword" (+ did you mean) or "unexpected a string in ...".
    [[noreturn]] void fail_unexpected(const Item& item, const std::vector<std::string>& keywords);
    [[noreturn]] void fail(SourceLoc loc, const std::string& message, std::string hint = {});
    void warn(SourceLoc loc, const std::string& message);

private:
    void skip_commas();
    // Folds trailing `filter 0.5`, `transmit 0.2`, `red 1` ... keyword items into `c`.
    void read_colour_components(scene::Colour& c);

    // The item at the cursor (after commas), expanded from a literal run if it is in one;
    // null at the end.
    const Item* current();

    BuildContext& ctx_;
    const std::vector<Item>& items_;
    std::string what_;
    SourceLoc block_loc_;
    size_t pos_ = 0;
    // Inside a Literals item: the element and where its values start.
    size_t element_ = 0, offset_ = 0;
    // Elements read from runs, the latest at ring_[ring_at_] (valid when expanded_): a
    // reference peek() or next() returned stays good for the next kRing - 1 reads.
    static constexpr size_t kRing = 8;
    std::array<Item, kRing> ring_;
    size_t ring_at_ = 0;
    bool expanded_ = false;
    std::optional<SourceLoc> last_loc_;
};

}  // namespace lumen::interp
