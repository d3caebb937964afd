// Frame bookkeeping and the finishers that shape each node (see build_ast.hpp).
#include "parser/build_ast.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>

namespace lumen::parser {

using ast::Kind;
using ast::Node;
using ast::NodePtr;

BuildState::BuildState(const SourceFile& file) : file_(&file) {
    frames_.push_back({std::make_unique<Node>(Kind::Body, SourceLoc{&file, 1, 1, 0}), nullptr});
    top_ = &frames_.back().node->children;
}

SourceLoc BuildState::loc(const InputIterator& it) const {
    return SourceLoc{file_, uint32_t(it.line), uint32_t(it.column), uint32_t(it.byte)};
}

void BuildState::open(Kind kind, const InputIterator& at) {
    NodePtr node;
    if (spare_nodes_.empty()) {
        node = std::make_unique<Node>(kind, loc(at));
    } else {
        node = std::move(spare_nodes_.back());
        spare_nodes_.pop_back();
        node->kind = kind;
        node->flag = false;
        node->loc = loc(at);
        node->number = 0.0;
    }
    frames_.push_back({std::move(node), at.data});
    top_ = &frames_.back().node->children;
}

void BuildState::open_literals() {
    if (!spare_run_) spare_run_ = std::make_shared<ast::LiteralRun>();
    run_ = spare_run_.get();
}

void BuildState::close_literals(bool ok, const InputIterator& at) {
    ast::LiteralRun& run = *run_;
    run_ = nullptr;
    if (!ok) {  // cleared for the next try, keeping its capacity
        run.values.clear(), run.bytes.clear(), run.sizes.clear(), run.lines.clear();
        run.value_elements = 0;
        return;
    }
    // Exact sizes: the run stays as long as the tree.
    run.values.shrink_to_fit();
    run.bytes.shrink_to_fit();
    run.sizes.shrink_to_fit();
    run.lines.shrink_to_fit();
    auto node = std::make_unique<Node>(Kind::Literals, loc(at));
    node->more().literals = std::move(spare_run_);
    top_->push_back(std::move(node));
}

bool BuildState::literal_value(const char* begin, const char* end) {
    double v;
    if (std::from_chars(begin, end, v).ec != std::errc() || !std::isfinite(v)) return false;
    run_->values.push_back(v);
    return true;
}

bool BuildState::literal_element(const InputIterator& at, std::size_t mark) {
    const std::size_t size = run_->values.size() - mark;
    if (size > 5 || (size == 1 && *at.data == '<')) return false;  // <1> is not a vector
    run_->bytes.push_back(uint32_t(at.byte));
    run_->sizes.push_back(uint8_t(size));
    if (run_->lines.empty() || run_->lines.back().number != at.line)
        run_->lines.push_back({uint32_t(at.byte - (at.column - 1)), uint32_t(at.line)});
    if (size > 0) ++run_->value_elements;
    return true;
}

namespace {

// The value of a literal arithmetic expression as the interpreter computes it, if it is one
// and every step is finite (else the interpreter's warnings must still be given).
bool fold_step(const std::string& op, double a, double b, double& r) {
    if (op == "+") r = a + b;
    else if (op == "-") r = a - b;
    else if (op == "*") r = a * b;
    else if (op == "/" && b != 0) r = a / b;
    else return false;
    return std::isfinite(r);
}

bool literal_number(const Node& n, double& v) {
    switch (n.kind) {
        case Kind::Number: v = n.number; return std::isfinite(v);
        case Kind::Unary:
            if (n.text != "-" && n.text != "+") return false;
            if (!literal_number(*n.children.at(0), v)) return false;
            if (n.text == "-") v = -v;
            return true;
        case Kind::Binary: {
            if (!literal_number(*n.children.at(0), v)) return false;
            const std::vector<std::string>& ops = n.more().ops;
            for (std::size_t i = 0; i < ops.size(); ++i) {
                double b;
                if (!literal_number(*n.children.at(i + 1), b) || !fold_step(ops[i], v, b, v))
                    return false;
            }
            return true;
        }
        default: return false;
    }
}

}  // namespace

void BuildState::chain_operator_added() {
    if (chains_.empty()) return;
    Chain& c = chains_.back();
    auto& kids = *top_;  // from c.mark: operand, operator, operand, ..., operand, operator
    if (!c.foldable || (!c.folding && kids.size() - c.mark < 2 * kFoldedChain)) return;
    c.folding = true;
    double acc;
    if (!literal_number(*kids[c.mark], acc)) {
        c.foldable = false;
        return;
    }
    std::size_t j = c.mark + 1;  // the operator before the next operand to fold
    for (double v, r; j + 2 < kids.size(); j += 2, acc = r) {
        if (!literal_number(*kids[j + 1], v) || !fold_step(kids[j]->text, acc, v, r)) {
            c.foldable = false;
            break;
        }
    }
    if (j == c.mark + 1 && kids[c.mark]->kind == Kind::Number) return;
    auto head = std::make_unique<Node>(Kind::Number, kids[c.mark]->loc);
    head->number = acc;
    kids[c.mark] = std::move(head);
    kids.erase(kids.begin() + std::ptrdiff_t(c.mark + 1), kids.begin() + std::ptrdiff_t(j));
}

void BuildState::close(Finisher finish, const char* end) {
    Frame f = std::move(frames_.back());
    frames_.pop_back();
    top_ = &frames_.back().node->children;
    NodePtr n = finish(std::move(f.node), std::string_view(f.begin, std::size_t(end - f.begin)), *this);
    if (n) frames_.back().node->children.push_back(std::move(n));
}

void BuildState::wrap(Kind kind, const InputIterator& at, std::size_t mark, Finisher finish,
                      const char* end) {
    auto n = std::make_unique<Node>(kind, loc(at));
    auto& kids = frames_.back().node->children;
    n->children.assign(std::make_move_iterator(kids.begin() + std::ptrdiff_t(mark)),
                       std::make_move_iterator(kids.end()));
    kids.resize(mark);
    NodePtr r = finish(std::move(n), std::string_view(at.data, std::size_t(end - at.data)), *this);
    if (r) frames_.back().node->children.push_back(std::move(r));
}

void BuildState::enter(const InputIterator& at) {
    if (++depth_ > kMaxNesting)
        throw LumenError(loc(at), "nesting deeper than " + std::to_string(kMaxNesting) + " levels");
}

void BuildState::macro_body(const InputIterator& begin, const InputIterator& end) {
    Node& m = *frames_.back().node;
    m.more().raw_begin = uint32_t(begin.byte);
    m.more().raw_end = uint32_t(end.byte);
    m.more().raw_loc = loc(begin);
}

NodePtr BuildState::take_result() {
    auto& kids = frames_.front().node->children;
    return kids.empty() ? nullptr : std::move(kids.front());
}

namespace finish {

namespace {

// Removes and returns children[0] (a token) of `n`.
NodePtr pop_front(Node& n) {
    NodePtr first = std::move(n.children.front());
    n.children.erase(n.children.begin());
    return first;
}

bool is_word_char(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

}  // namespace

NodePtr keep(NodePtr n, std::string_view, BuildState&) { return n; }

NodePtr text(NodePtr n, std::string_view t, BuildState&) {
    n->text.assign(t);
    return n;
}

NodePtr number(NodePtr n, std::string_view t, BuildState&) {
    // Correctly rounded, as strtod, without a copy of the text.
    if (std::from_chars(t.data(), t.data() + t.size(), n->number).ec != std::errc())
        n->number = std::strtod(std::string(t).c_str(), nullptr);
    return n;
}

NodePtr string(NodePtr n, std::string_view t, BuildState&) {
    // t includes both quotes. Unknown escapes keep their backslash (Windows paths).
    std::string out;
    out.reserve(t.size());
    for (std::size_t i = 1; i + 1 < t.size(); ++i) {
        char c = t[i];
        if (c != '\\' || i + 2 >= t.size()) {
            out += c;
            continue;
        }
        char e = t[++i];
        switch (e) {
            case 'n': out += '\n'; break;
            case 't': out += '\t'; break;
            case 'r': out += '\r'; break;
            case 'a': out += '\a'; break;
            case 'b': out += '\b'; break;
            case 'f': out += '\f'; break;
            case 'v': out += '\v'; break;
            case '0': out += '\0'; break;
            case '\\': out += '\\'; break;
            case '"': out += '"'; break;
            case '\'': out += '\''; break;
            default: out += '\\'; out += e; break;
        }
    }
    n->text = std::move(out);
    return n;
}

NodePtr member(NodePtr n, std::string_view t, BuildState&) {
    n->text.assign(t.substr(1));  // drop the '.'
    return n;
}

NodePtr fold_one(NodePtr n, std::string_view, BuildState&) {
    if (n->children.size() == 1) return std::move(n->children.front());
    return n;
}

NodePtr binary(NodePtr n, std::string_view, BuildState&) {
    if (n->children.size() == 1) return std::move(n->children.front());
    // children alternate operand, operator token, operand, ...
    std::vector<NodePtr> operands;
    operands.reserve(n->children.size() / 2 + 1);
    for (std::size_t i = 0; i < n->children.size(); ++i) {
        if (i % 2 == 1) n->more().ops.push_back(std::move(n->children[i]->text));
        else operands.push_back(std::move(n->children[i]));
    }
    n->children = std::move(operands);
    return n;
}

NodePtr postfix(NodePtr n, std::string_view, BuildState& st) {
    auto& kids = n->children;
    if (kids.size() == 1) return std::move(kids.front());
    // Each suffix wraps the expression so far; bound the resulting depth.
    if (kids.size() > std::size_t(kMaxNesting))
        throw LumenError(kids[kMaxNesting]->loc,
                         "nesting deeper than " + std::to_string(kMaxNesting) + " levels");
    NodePtr base = std::move(kids.front());
    bool base_is_fresh_index = false;  // consecutive [i][j] extend one Index node
    for (std::size_t i = 1; i < kids.size(); ++i) {
        NodePtr& suffix = kids[i];
        if (suffix->kind == Kind::Index) {
            if (!base_is_fresh_index) {
                auto idx = std::make_unique<Node>(Kind::Index, base->loc);
                idx->children.push_back(std::move(base));
                base = std::move(idx);
                base_is_fresh_index = true;
            }
            base->children.push_back(std::move(suffix->children.front()));
        } else {
            auto mem = std::make_unique<Node>(Kind::Member, base->loc);
            mem->text = std::move(suffix->text);
            mem->children.push_back(std::move(base));
            base = std::move(mem);
            base_is_fresh_index = false;
        }
    }
    (void)st;
    return base;
}

NodePtr named(NodePtr n, std::string_view, BuildState&) {
    n->text = std::move(pop_front(*n)->text);
    return n;
}

NodePtr bare_colour(NodePtr n, std::string_view, BuildState&) { return n; }

NodePtr array_decl(NodePtr n, std::string_view, BuildState&) {
    for (NodePtr& c : n->children) {
        if (c->kind == Kind::ArrayInit) {
            n->flag = true;
        } else if (c->children.empty()) {
            c = std::make_unique<Node>(Kind::Null, c->loc);  // `array[]`: size not given
        } else {
            c = std::move(c->children.front());
        }
    }
    return n;
}

NodePtr params(NodePtr n, std::string_view, BuildState&) {
    for (NodePtr& p : n->children) n->more().params.push_back(std::move(p->text));
    n->children.clear();
    n->text = "(";
    return n;
}

NodePtr resolution(NodePtr n, std::string_view, BuildState&) {
    n->text = "function_resolution";
    return n;
}

NodePtr block(NodePtr n, std::string_view, BuildState&) {
    n->text = std::move(pop_front(*n)->text);
    if (n->children.empty() || n->children.front()->kind != Kind::Null) return n;
    NodePtr head = pop_front(*n);
    if (head->text == "(") {
        n->more().params = std::move(head->more().params);
    } else {  // `function W, H { ... }`: W and H lead the children
        n->flag = true;
        n->children.insert(n->children.begin(), std::make_move_iterator(head->children.begin()),
                           std::make_move_iterator(head->children.end()));
    }
    return n;
}

NodePtr branch(NodePtr n, std::string_view, BuildState&) {
    if (n->children.size() == 1)  // #else / #ifdef branch: no condition
        n->children.insert(n->children.begin(), std::make_unique<Node>(Kind::Null, n->loc));
    return n;
}

namespace {

NodePtr clone(const Node& n) {
    auto c = std::make_unique<Node>(n.kind, n.loc);
    c->text = n.text;
    c->number = n.number;
    c->flag = n.flag;
    if (n.extra) c->extra = std::make_unique<ast::NodeExtra>(*n.extra);
    c->children.reserve(n.children.size());
    for (const NodePtr& k : n.children) c->children.push_back(clone(*k));
    return c;
}

// Branch(cond, Body(Block word items...)).
NodePtr block_branch(NodePtr cond, const Node& word, std::vector<NodePtr> items) {
    auto block = std::make_unique<Node>(Kind::Block, word.loc);
    block->text = word.text;
    block->children = std::move(items);
    auto body = std::make_unique<Node>(Kind::Body, word.loc);
    body->children.push_back(std::move(block));
    auto branch = std::make_unique<Node>(Kind::Branch, cond->loc);
    branch->children.push_back(std::move(cond));
    branch->children.push_back(std::move(body));
    return branch;
}

}  // namespace

NodePtr conditional_block(NodePtr n, std::string_view, BuildState&) {
    // children: condition, then-word, else-word, body items...
    std::vector<NodePtr> kids = std::move(n->children);
    n->children.clear();
    std::vector<NodePtr> items, copies;
    for (std::size_t i = 3; i < kids.size(); ++i) {
        copies.push_back(clone(*kids[i]));
        items.push_back(std::move(kids[i]));
    }
    auto no_condition = std::make_unique<Node>(Kind::Null, kids[2]->loc);
    n->children.push_back(block_branch(std::move(kids[0]), *kids[1], std::move(items)));
    n->children.push_back(block_branch(std::move(no_condition), *kids[2], std::move(copies)));
    return n;
}

NodePtr conditionally_opened(NodePtr n, std::string_view, BuildState&) {
    // children: condition, word, body items..., close token (its condition is not kept)
    std::vector<NodePtr> kids = std::move(n->children);
    n->children.clear();
    kids.pop_back();
    std::vector<NodePtr> items, copies;
    for (std::size_t i = 2; i < kids.size(); ++i) {
        copies.push_back(clone(*kids[i]));
        items.push_back(std::move(kids[i]));
    }
    n->children.push_back(block_branch(std::move(kids[0]), *kids[1], std::move(items)));
    auto bare = std::make_unique<Node>(Kind::Branch, n->loc);
    bare->children.push_back(std::make_unique<Node>(Kind::Null, n->loc));
    auto body = std::make_unique<Node>(Kind::Body, n->loc);
    body->children = std::move(copies);
    bare->children.push_back(std::move(body));
    n->children.push_back(std::move(bare));
    return n;
}

NodePtr directive_word(NodePtr n, std::string_view t, BuildState&) {
    std::size_t i = 1;  // after '#'
    while (i < t.size() && (t[i] == ' ' || t[i] == '\t')) ++i;
    std::size_t j = i;
    while (j < t.size() && is_word_char(t[j])) ++j;
    n->text.assign(t.substr(i, j - i));
    return n;
}

NodePtr declare(NodePtr n, std::string_view t, BuildState& st) {
    // `deprecated ["once"] "message"` has no place in the tree: the interpreter does not
    // warn about deprecated names.
    if (!n->children.empty() && n->children.front()->kind == Kind::Null) pop_front(*n);
    return directive_word(std::move(n), t, st);
}

NodePtr version(NodePtr n, std::string_view, BuildState&) {
    NodePtr& v = n->children.front();
    if (v->kind == Kind::Null) {  // `#version unofficial ...;`
        n->text = v->text;
        v = std::make_unique<Node>(Kind::Null, v->loc);
    }
    return n;
}

NodePtr for_loop(NodePtr n, std::string_view, BuildState&) {
    n->text = std::move(pop_front(*n)->text);
    if (n->children.size() == 3)  // start, end, body: no step
        n->children.insert(n->children.begin() + 2, std::make_unique<Node>(Kind::Null, n->loc));
    return n;
}

NodePtr macro_param(NodePtr n, std::string_view t, BuildState&) {
    // `name` or `optional name` (with any whitespace or comments between).
    std::size_t end = t.size();
    std::size_t begin = end;
    while (begin > 0 && is_word_char(t[begin - 1])) --begin;
    n->text.assign(t.substr(begin, end - begin));
    n->flag = begin != 0;
    return n;
}

NodePtr macro(NodePtr n, std::string_view, BuildState&) {
    n->text = std::move(pop_front(*n)->text);
    for (NodePtr& p : n->children) {
        n->more().params.push_back(std::move(p->text));
        n->more().optional_params.push_back(p->flag);
    }
    n->children.clear();
    return n;
}

}  // namespace finish

}  // namespace lumen::parser
