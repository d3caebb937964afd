// Expression evaluation with POV-Ray's promotion rules (conversions.hpp).
#include <algorithm>
#include <cmath>

#include "interp/conversions.hpp"
#include "interp/evaluator.hpp"
#include "parser/keywords.hpp"
#include "parser/parser.hpp"

namespace lumen::interp {

using ast::Kind;

namespace {

// Numeric "shape" of a value for promotion: float < vector < colour.
enum class Shape { Float, Vector, Colour };

Shape shape_of(const Value& v) {
    if (v.is<double>()) return Shape::Float;
    if (v.is<VecN>()) return Shape::Vector;
    if (v.is<scene::Colour>()) return Shape::Colour;
    type_error(v, "a float, vector or colour");
}

// Components of `v` widened to `n`: a float fills every component, others pad with zeros.
std::vector<double> widened(const Value& v, size_t n) {
    if (v.is<double>()) return std::vector<double>(n, v.as<double>());
    std::vector<double> c = components(v);
    c.resize(n, 0.0);
    return c;
}

Value make_numeric(Shape s, std::vector<double> c, SourceLoc loc) {
    switch (s) {
        case Shape::Float: return Value{c[0], loc};
        case Shape::Vector: return Value{VecN{std::move(c)}, loc};
        case Shape::Colour: return Value{colour_from(c), loc};
    }
    return {};
}

bool is_comparison(const std::string& op) {
    return op == "<" || op == "<=" || op == "=" || op == "!=" || op == ">=" || op == ">";
}

double compare(const std::string& op, double a, double b) {
    if (op == "<") return a < b;
    if (op == "<=") return a <= b;
    if (op == ">") return a > b;
    if (op == ">=") return a >= b;
    bool equal = std::fabs(a - b) < kEpsilon;  // POV compares within EPSILON
    return op == "=" ? equal : !equal;
}

}  // namespace

// One binary operation, with the arithmetic ones applied per component after promotion.
static Value apply_binary(Evaluator& ev, const std::string& op, const Value& a, const Value& b,
                          SourceLoc loc) {
    if (is_comparison(op)) {
        if (a.is<std::string>() && b.is<std::string>()) {  // POV-Ray 3.7 compares strings too
            int c = a.as<std::string>().compare(b.as<std::string>());
            return Value{compare(op, c < 0 ? -1 : c > 0 ? 1 : 0, 0), loc};
        }
        return Value{compare(op, to_float(a), to_float(b)), loc};
    }
    if (op == "&") return Value{double(to_bool(a) && to_bool(b)), loc};
    if (op == "|") return Value{double(to_bool(a) || to_bool(b)), loc};

    Shape sa = shape_of(a), sb = shape_of(b);
    Shape s = std::max(sa, sb);
    size_t n = 1;
    if (s == Shape::Colour) n = 5;
    else if (s == Shape::Vector)
        n = std::max(a.is<VecN>() ? a.as<VecN>().c.size() : 0, b.is<VecN>() ? b.as<VecN>().c.size() : 0);
    std::vector<double> x = widened(a, n), y = widened(b, n);
    char o = op[0];
    bool divided_by_zero = false;
    // POV-Ray's parser makes x / 0 +inf whatever x is (1/0, -1/0, 0/0; math_builtins.cpp),
    // its function VM the IEEE quotient.
    const bool pov_parser = !ev.in_function_body();
    for (size_t i = 0; i < n; ++i) {
        switch (o) {
            case '+': x[i] += y[i]; break;
            case '-': x[i] -= y[i]; break;
            case '*': x[i] *= y[i]; break;
            case '/':
                if (y[i] == 0.0) divided_by_zero = true;
                x[i] = y[i] == 0.0 && pov_parser ? HUGE_VAL : x[i] / y[i];
                break;
            default: throw LumenError(loc, "unknown operator '" + op + "'");
        }
    }
    Value result = make_numeric(s, std::move(x), loc);
    if (divided_by_zero)
        ev.warn(b.loc, "division by zero gives " + non_finite_text(result));
    else if (!all_finite(result) && all_finite(a) && all_finite(b))
        ev.warn(loc, "'" + op + "' overflows to " + non_finite_text(result) + " here");
    return result;
}

Value Evaluator::fold_binary(const ast::Node& e, size_t from, Value acc) {
    for (size_t i = from; i < e.children.size(); ++i) {
        Value rhs = eval(*e.children[i]);
        acc = apply_binary(*this, e.more().ops.at(i - 1), acc, rhs, e.loc);
    }
    return acc;
}

void Evaluator::eval_argument(const ast::Node& a, std::vector<Value>& args) {
    const bool additive = a.kind == Kind::Binary &&
                          std::all_of(a.more().ops.begin(), a.more().ops.end(),
                                      [](const std::string& op) { return op == "+" || op == "-"; });
    if (!additive) {
        args.push_back(eval(a));
        return;
    }
    Value head = eval(*a.children.at(0));
    if (is_numeric(head)) {
        args.push_back(fold_binary(a, 1, std::move(head)));
        return;
    }
    // POV-Ray ends an argument where its object (texture, ...) ends, so `F(Obj -y, 0)` passes
    // Obj and -y (shapes.inc callers rely on it); the sign starts the next argument.
    Value sign = apply_binary(*this, a.more().ops[0], Value{0.0, a.loc}, eval(*a.children.at(1)), a.loc);
    args.push_back(std::move(head));
    args.push_back(fold_binary(a, 2, std::move(sign)));
}

Value Evaluator::eval(const ast::Node& e) {
    switch (e.kind) {
        case Kind::Number:
            if (!std::isfinite(e.number)) warn(e.loc, "number too large for a double: it is inf");
            return Value{e.number, e.loc};
        case Kind::String: return Value{e.text, e.loc};
        case Kind::Ident: return lookup(e);
        case Kind::Vector: {
            size_t n = e.children.size();
            // poly, cubic and quartic read their coefficients as one long vector literal.
            const bool coefficients =
                !open_blocks_.empty() && (open_blocks_.back() == "poly" ||
                                          open_blocks_.back() == "cubic" ||
                                          open_blocks_.back() == "quartic");
            if (n < 2 || (n > 5 && n != 12 && !coefficients))
                throw LumenError(e.loc, "a vector needs 2 to 5 components, found " + std::to_string(n));
            VecN v;
            for (const auto& c : e.children) v.c.push_back(eval_float(*c));
            return Value{std::move(v), e.loc};
        }
        case Kind::Unary: {
            Value v = eval(*e.children.at(0));
            if (e.text == "!") return Value{double(!to_bool(v)), e.loc};
            Shape s = shape_of(v);
            std::vector<double> c = components(v);
            if (e.text == "-")
                for (double& x : c) x = -x;
            return make_numeric(s, std::move(c), e.loc);
        }
        case Kind::Binary:
            return fold_binary(e, 1, eval(*e.children.at(0)));
        case Kind::Ternary:
            return eval_condition(*e.children.at(0)) ? eval(*e.children.at(1)) : eval(*e.children.at(2));
        case Kind::Call: {
            if (const ast::Node* m = macro_named(e.text)) return call_macro_value(*m, e);
            if (Value* f = symbols.find(e.text)) {
                if (f->is<std::shared_ptr<const FunctionValue>>()) {
                    auto fn = f->as<std::shared_ptr<const FunctionValue>>();  // keeps it alive
                    return call_function(*fn, e);
                }
                throw LumenError(e.loc, "'" + e.text + "' is a " + f->type_name() +
                                            ", not a macro or function");
            }
            return call_builtin(e);
        }
        case Kind::Member: return member(e);
        case Kind::Index: {
            ArraySlot slot = array_slot(e);
            const std::optional<Value>& el = slot.array->elems[slot.index];
            if (!el) throw LumenError(e.loc, "array element used before it was initialised");
            Value v = *el;
            v.loc = e.loc;
            return v;
        }
        case Kind::Colour: return colour(e);
        case Kind::ArrayDecl: return array_decl(e);
        case Kind::Block: return eval_block(e);
        default:
            throw LumenError(e.loc, std::string("expected an expression, found ") + ast::kind_name(e.kind));
    }
}

double Evaluator::eval_float(const ast::Node& e) { return to_float(eval(e)); }

bool Evaluator::eval_condition(const ast::Node& e) { return to_bool(eval(e)); }

Value Evaluator::lookup(const ast::Node& ident) {
    if (Value* v = symbols.find(ident.text)) {
        if (v->is<std::shared_ptr<const MacroValue>>())
            throw LumenError(ident.loc, "macro '" + ident.text + "' must be called with an argument list: " +
                                            ident.text + "(...)");
        Value copy = *v;
        copy.loc = ident.loc;
        return copy;
    }
    if (auto c = builtin_constant(ident.text, ident.loc)) return *c;
    throw LumenError(ident.loc, "undeclared identifier '" + ident.text + "'",
                     did_you_mean(ident.text, suggestion_words()));
}

std::vector<std::string> Evaluator::suggestion_words() const {
    std::vector<std::string> names = symbols.visible_names();
    const auto& reserved = parser::reserved_words();
    names.insert(names.end(), reserved.begin(), reserved.end());
    return names;
}

Value Evaluator::member(const ast::Node& e) {
    Value base = eval(*e.children.at(0));
    const std::string& m = e.text;
    if (!base.is<VecN>() && !base.is<scene::Colour>()) type_error(base, "a vector or colour");
    std::vector<double> c = components(base);
    if (m == "gray" || m == "grey" || m == "hf") return Value{grey(colour_from(c)), e.loc};
    int index = -1;
    if (m == "x" || m == "u" || m == "red") index = 0;
    else if (m == "y" || m == "v" || m == "green") index = 1;
    else if (m == "z" || m == "blue") index = 2;
    else if (m == "t" || m == "filter") index = 3;
    else if (m == "transmit") index = 4;
    else throw LumenError(e.loc, "unknown member '." + m + "'");
    if (static_cast<size_t>(index) >= c.size())
        throw LumenError(e.loc, std::string("a ") + std::to_string(c.size()) + "-component " +
                                    base.type_name() + " has no component '." + m + "'");
    return Value{c[index], e.loc};
}

Evaluator::ArraySlot Evaluator::array_slot(const ast::Node& e) {
    Value base = eval(*e.children.at(0));
    if (!base.is<std::shared_ptr<ArrayValue>>()) type_error(base, "an array");
    ArraySlot slot{base.as<std::shared_ptr<ArrayValue>>(), 0};
    const ArrayValue& a = *slot.array;
    size_t given = e.children.size() - 1;
    if (given != a.dims.size())
        throw LumenError(e.loc, "array has " + std::to_string(a.dims.size()) + " dimension(s) but " +
                                    std::to_string(given) + " index(es) were given");
    for (size_t d = 0; d < given; ++d) {
        const ast::Node& ix = *e.children[d + 1];
        double f = eval_float(ix);
        if (!(f > -1.0 && std::trunc(f) < static_cast<double>(a.dims[d])))
            throw LumenError(ix.loc, "array index " + number_text(std::trunc(f)) + " is out of range 0.." +
                                         std::to_string(a.dims[d] - 1));
        slot.index = slot.index * a.dims[d] + static_cast<size_t>(f);
    }
    return slot;
}

// Array declarations: `array[2][3] { {1,2,3}, {4,5,6} }`.
Value Evaluator::array_decl(const ast::Node& e) {
    const size_t max_elements = options_.max_array_elements;
    auto arr = std::make_shared<ArrayValue>();
    size_t ndims = e.children.size() - (e.flag ? 1 : 0);
    size_t total = 1;
    for (size_t d = 0; d < ndims; ++d) {
        double f = eval_float(*e.children[d]);
        if (!(f >= 1.0)) throw LumenError(e.children[d]->loc, "invalid array size " + number_text(f));
        if (f * double(total) > double(max_elements))
            throw LumenError(e.children[d]->loc, "array of " + number_text(std::floor(f) * double(total)) +
                                                     " elements exceeds the limit of " + std::to_string(max_elements) +
                                                     " per array (Max_Array_Elements)");
        arr->dims.push_back(static_cast<size_t>(f));
        total *= arr->dims.back();
    }
    if (e.flag && ndims == 0) {
        // Sizes taken from the initialiser's shape.
        for (const ast::Node* n = e.children.back().get(); n && n->kind == Kind::ArrayInit;
             n = n->children.empty() ? nullptr : n->children[0].get()) {
            arr->dims.push_back(n->children.size());
            total *= n->children.size();
        }
    }
    if (arr->dims.empty()) throw LumenError(e.loc, "an array needs at least one dimension");
    budget.allocating(total * sizeof(arr->elems[0]), e.loc);
    arr->elems.resize(total);
    if (e.flag) {
        size_t next = 0;
        fill_array(*arr, *e.children.back(), 0, next);
    }
    return Value{std::move(arr), e.loc};
}

void Evaluator::fill_array(ArrayValue& arr, const ast::Node& init, size_t level, size_t& next) {
    if (init.kind != Kind::ArrayInit)
        throw LumenError(init.loc, "expected '{' for array dimension " + std::to_string(level + 1));
    if (init.children.size() != arr.dims[level])
        throw LumenError(init.loc, "array initialiser has " + std::to_string(init.children.size()) +
                                       " elements, expected " + std::to_string(arr.dims[level]));
    for (const auto& c : init.children) {
        if (level + 1 < arr.dims.size()) {
            fill_array(arr, *c, level + 1, next);
        } else {
            if (c->kind == Kind::ArrayInit)
                throw LumenError(c->loc, "too many nested '{' in array initialiser");
            arr.elems[next++] = eval(*c);
        }
    }
}

// Colour expressions: parts apply in written order (POV-Ray 3.7's rules).
Value Evaluator::colour(const ast::Node& e) {
    scene::Colour c{};
    for (const auto& part_ptr : e.children) {
        const ast::Node& part = *part_ptr;
        const std::string& p = part.text;
        Value v = eval(*part.children.at(0));
        if (p.empty()) {
            c = to_colour(v);
        } else if (p == "red") c.r = to_float(v);
        else if (p == "green") c.g = to_float(v);
        else if (p == "blue") c.b = to_float(v);
        else if (p == "filter") c.f = to_float(v);
        else if (p == "transmit") c.t = to_float(v);
        else if (p == "gray" || p == "grey") c.r = c.g = c.b = to_float(v);
        else {
            bool srgb = p.rfind("srgb", 0) == 0;
            std::string channels = p.substr(srgb ? 4 : 3);  // "", "f", "t", "ft"
            if (p.compare(srgb ? 1 : 0, 3, "rgb") != 0) throw LumenError(part.loc, "unknown colour keyword '" + p + "'");
            if (v.is<scene::Colour>()) {
                c = v.as<scene::Colour>();  // POV takes the whole colour (with a warning)
            } else {
                size_t n = 3 + channels.size();
                std::vector<double> x = to_vector(v, n).c;
                c = {x[0], x[1], x[2], 0, 0};
                if (channels == "f") c.f = x[3];
                if (channels == "t") c.t = x[3];
                if (channels == "ft") c.f = x[3], c.t = x[4];
            }
            if (srgb) {
                auto decode = [](double s) {
                    return s < 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4);
                };
                c.r = decode(c.r), c.g = decode(c.g), c.b = decode(c.b);
            }
        }
    }
    return Value{c, e.loc};
}

}  // namespace lumen::interp
