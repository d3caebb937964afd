#include "interp/item_cursor.hpp"

#include <cmath>

#include "interp/literal_items.hpp"

namespace lumen::interp {

namespace {

struct TypeNamer {
    std::string operator()(std::monostate) const { return "nothing"; }
    std::string operator()(double) const { return "a float"; }
    std::string operator()(const VecN&) const { return "a vector"; }
    std::string operator()(const scene::Colour&) const { return "a colour"; }
    std::string operator()(const std::string&) const { return "a string"; }
    std::string operator()(const std::shared_ptr<ArrayValue>&) const { return "an array"; }
    std::string operator()(const std::shared_ptr<const BlockValue>& b) const {
        return "a '" + b->keyword + "' block";
    }
    std::string operator()(const scene::ObjectPtr&) const { return "an object"; }
    std::string operator()(const std::shared_ptr<const TextureValue>&) const { return "a texture"; }
    std::string operator()(const scene::PigmentPtr&) const { return "a pigment"; }
    std::string operator()(const scene::FinishPtr&) const { return "a finish"; }
    std::string operator()(const scene::NormalPtr&) const { return "a normal"; }
    std::string operator()(const std::shared_ptr<const scene::Interior>&) const {
        return "an interior";
    }
    std::string operator()(const std::shared_ptr<const MaterialValue>&) const {
        return "a material";
    }
    std::string operator()(const std::shared_ptr<const scene::Camera>&) const { return "a camera"; }
    std::string operator()(const std::shared_ptr<const scene::Light>&) const {
        return "a light_source";
    }
    std::string operator()(const std::shared_ptr<const scene::Transform>&) const {
        return "a transform";
    }
    std::string operator()(const std::shared_ptr<const ColourMapValue>&) const {
        return "a color_map";
    }
    std::string operator()(const std::shared_ptr<const PigmentMapValue>&) const {
        return "a pigment_map";
    }
    std::string operator()(const std::shared_ptr<const TextureMapValue>&) const {
        return "a texture_map";
    }
    std::string operator()(const std::shared_ptr<const NormalMapValue>&) const {
        return "a normal_map";
    }
    std::string operator()(const std::shared_ptr<const scene::Fog>&) const { return "a fog"; }
    std::string operator()(const std::shared_ptr<const scene::Rainbow>&) const { return "a rainbow"; }
    std::string operator()(const std::shared_ptr<const scene::Media>&) const { return "a media"; }
    std::string operator()(const std::shared_ptr<const scene::SkySphere>&) const {
        return "a sky_sphere";
    }
    std::string operator()(const std::shared_ptr<const MacroValue>&) const { return "a macro"; }
    std::string operator()(const std::shared_ptr<const FunctionValue>& f) const {
        return "a " + f->keyword;
    }
    std::string operator()(const std::shared_ptr<FileValue>&) const { return "a file identifier"; }
    std::string operator()(const scene::Unsupported& u) const { return "'" + u.feature + "'"; }
};

// Colour component keywords that may trail a colour when the parser leaves them as items.
bool is_component_keyword(const std::string& w) {
    return w == "red" || w == "green" || w == "blue" || w == "filter" || w == "transmit" ||
           w == "gray" || w == "grey" || w == "rgb" || w == "rgbf" || w == "rgbt" ||
           w == "rgbft";
}

}  // namespace

std::string describe_value(const Value& value) { return std::visit(TypeNamer{}, value.v); }

std::string describe_item(const Item& item) {
    switch (item.kind) {
        case Item::Kind::Keyword: return "'" + item.keyword + "'";
        case Item::Kind::Comma: return "','";
        case Item::Kind::MapEntry: return "a map entry '[...]'";
        case Item::Kind::Literals: return "a list of numbers";
        case Item::Kind::Value: return describe_value(item.value);
    }
    return "an item";
}

ItemCursor::ItemCursor(BuildContext& ctx, const std::vector<Item>& items, std::string what,
                       SourceLoc block_loc)
    : ctx_(ctx), items_(items), what_(std::move(what)), block_loc_(block_loc) {}

ItemCursor::ItemCursor(BuildContext& ctx, const BlockValue& block)
    : ItemCursor(ctx, block.items, block.keyword, block.loc) {}

void ItemCursor::skip_commas() {
    while (pos_ < items_.size()) {
        const Item& it = items_[pos_];
        if (it.kind == Item::Kind::Comma) {
            ++pos_;
        } else if (it.kind == Item::Kind::Literals) {
            const ast::LiteralRun& run = *it.literals;
            while (element_ < run.sizes.size() && run.sizes[element_] == 0) ++element_;
            if (element_ < run.sizes.size()) return;
            ++pos_;
            element_ = offset_ = 0;
            expanded_ = false;
        } else {
            return;
        }
    }
}

const Item* ItemCursor::current() {
    skip_commas();
    if (pos_ >= items_.size()) return nullptr;
    const Item& it = items_[pos_];
    if (it.kind != Item::Kind::Literals) return &it;
    if (!expanded_) {
        ring_at_ = (ring_at_ + 1) % kRing;
        ring_[ring_at_] = literal_item(*it.literals, element_, offset_, it.loc.file);
        expanded_ = true;
    }
    return &ring_[ring_at_];
}

bool ItemCursor::at_end() { return current() == nullptr; }

const Item& ItemCursor::peek() { return *current(); }

const Item& ItemCursor::next() {
    const Item& it = *current();
    last_loc_ = it.loc;
    if (items_[pos_].kind == Item::Kind::Literals) {
        offset_ += items_[pos_].literals->sizes[element_++];
        expanded_ = false;
    } else {
        ++pos_;
    }
    return it;
}

SourceLoc ItemCursor::here() const { return last_loc_ ? *last_loc_ : block_loc_; }

bool ItemCursor::next_is_keyword(std::string_view word) {
    if (at_end() || peek().kind != Item::Kind::Keyword) return false;
    return word.empty() || peek().keyword == word;
}

bool ItemCursor::next_is_float() { return next_is<double>(); }

bool ItemCursor::next_is_vector_like() { return next_is<double>() || next_is<VecN>(); }

bool ItemCursor::next_is_colour_like() { return next_is_vector_like() || next_is<scene::Colour>(); }

bool ItemCursor::next_is_colour_start() {
    if (next_is_colour_like()) return true;
    if (!next_is_keyword()) return false;
    const std::string& w = peek().keyword;
    return w == "color" || w == "colour" || is_component_keyword(w);
}

bool ItemCursor::accept_keyword(std::string_view word) {
    if (!next_is_keyword(word)) return false;
    next();
    return true;
}

void ItemCursor::fail(SourceLoc loc, const std::string& message, std::string hint) {
    throw LumenError(loc, message, std::move(hint));
}

void ItemCursor::warn(SourceLoc loc, const std::string& message) {
    if (ctx_.warn) ctx_.warn(Diagnostic{Severity::Warning, loc, message, {}, {}});
}

void ItemCursor::fail_expected(std::string_view what_expected, std::string_view after) {
    std::string msg = "expected " + std::string(what_expected);
    msg += after.empty() ? " in " + what_ : " after '" + std::string(after) + "'";
    if (at_end()) fail(here(), msg + ", found the end of the block");
    fail(peek().loc, msg + ", found " + describe_item(peek()));
}

void ItemCursor::fail_unexpected(const Item& item, const std::vector<std::string>& keywords) {
    if (item.kind == Item::Kind::Keyword)
        fail(item.loc, "'" + item.keyword + "' is not " +
                           (std::string("aeiou").find(what_[0]) != std::string::npos ? "an " : "a ") +
                           what_ + " keyword",
             did_you_mean(item.keyword, keywords));
    fail(item.loc, "unexpected " + describe_item(item) + " in " + what_);
}

double ItemCursor::expect_float(std::string_view after) {
    if (!next_is_float()) fail_expected("a float", after);
    return next().value.as<double>();
}

int ItemCursor::expect_int(std::string_view after) {
    // POV truncates floats used as integers.
    double v = std::trunc(expect_float(after));
    if (!(std::abs(v) < 2147483647.0)) fail(here(), "integer out of range");
    return static_cast<int>(v);
}

std::vector<double> ItemCursor::expect_vecn(std::string_view after) {
    if (next_is<double>()) return {next().value.as<double>()};
    if (!next_is<VecN>()) fail_expected("a vector", after);
    return next().value.as<VecN>().c;
}

glm::dvec3 ItemCursor::expect_vector(std::string_view after) {
    if (next_is<double>()) return glm::dvec3(next().value.as<double>());
    if (!next_is<VecN>()) fail_expected("a vector", after);
    const Item& it = next();
    const VecN& v = it.value.as<VecN>();
    if (v.c.size() > 3) fail(it.loc, "expected a 3-component vector, found " +
                                         std::to_string(v.c.size()) + " components");
    return v.xyz();
}

scene::Colour ItemCursor::expect_colour(std::string_view after) {
    accept_keyword("color") || accept_keyword("colour");
    scene::Colour c;
    if (next_is<scene::Colour>()) {
        c = next().value.as<scene::Colour>();
    } else if (next_is<double>()) {
        double f = next().value.as<double>();
        c = {f, f, f, f, f};
    } else if (next_is<VecN>()) {
        const std::vector<double>& v = next().value.as<VecN>().c;
        double* ch[5] = {&c.r, &c.g, &c.b, &c.f, &c.t};
        for (size_t i = 0; i < v.size() && i < 5; ++i) *ch[i] = v[i];
    } else if (!next_is_keyword() || !is_component_keyword(peek().keyword)) {
        fail_expected("a colour", after);
    }
    read_colour_components(c);
    return c;
}

void ItemCursor::read_colour_components(scene::Colour& c) {
    while (next_is_keyword() && is_component_keyword(peek().keyword)) {
        std::string w = next().keyword;
        if (w == "rgb" || w == "rgbf" || w == "rgbt" || w == "rgbft") {
            std::vector<double> v = expect_vecn(w);
            if (v.size() == 1) v.assign(w.size() == 3 ? 3 : w.size(), v[0]);
            c = {};
            c.r = v.size() > 0 ? v[0] : 0;
            c.g = v.size() > 1 ? v[1] : 0;
            c.b = v.size() > 2 ? v[2] : 0;
            if (w == "rgbf") c.f = v.size() > 3 ? v[3] : 0;
            if (w == "rgbt") c.t = v.size() > 3 ? v[3] : 0;
            if (w == "rgbft") { c.f = v.size() > 3 ? v[3] : 0; c.t = v.size() > 4 ? v[4] : 0; }
            continue;
        }
        double f = expect_float(w);
        if (w == "red") c.r = f;
        else if (w == "green") c.g = f;
        else if (w == "blue") c.b = f;
        else if (w == "filter") c.f = f;
        else if (w == "transmit") c.t = f;
        else c.r = c.g = c.b = f;  // gray / grey
    }
}

std::string ItemCursor::expect_string(std::string_view after) {
    if (!next_is<std::string>()) fail_expected("a string", after);
    return next().value.as<std::string>();
}

std::optional<double> ItemCursor::optional_float() {
    if (!next_is_float()) return std::nullopt;
    return next().value.as<double>();
}

bool ItemCursor::optional_bool() {
    std::optional<double> v = optional_float();
    return !v || *v != 0.0;
}

}  // namespace lumen::interp
