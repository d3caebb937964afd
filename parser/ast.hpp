// The syntax tree of an SDL file. The grammar is deliberately generic: a block is any
// `word { items }`, and a block body is a flat sequence of items (keywords, expressions,
// nested blocks, `[...]` map entries, commas and directives). What a keyword means, and which
// values it consumes, is decided by the interpreter, exactly as POV-Ray's own stream parser
// does. This keeps unsupported features parseable (tolerant loading) and lets a macro body mean
// the same thing wherever it is called.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "base/source.hpp"
#include "parser/node_pool.hpp"

namespace lumen::ast {

enum class Kind {
    // ---- expressions -----------------------------------------------------------------
    Number,     // `number`
    String,     // `text` = the unescaped string
    Ident,      // `text` = identifier or built-in constant name (x, pi, clock, true, ...)
    Vector,     // <a, b, ...>: children = components (1..N; the interpreter checks the count)
    Unary,      // `text` = "-", "+" or "!"; children[0] = operand
    Binary,     // left-associative chain at one precedence level, kept flat so long chains
                // never recurse: children = operands (n >= 2), `ops` = n-1 operators, each one
                // of "*" "/" "+" "-" "<" "<=" "=" "!=" ">=" ">" "&" "|"
    Ternary,    // cond ? a : b: children = {cond, a, b}
    Call,       // name(args): `text` = name (built-in function, macro, or user function);
                // children = arguments (a macro argument may be any item-like expression)
    Member,     // expr.name: `text` = x y z t u v red green blue filter transmit gray hf ...;
                // children[0] = expr
    Index,      // expr[i][j]...: children[0] = base, children[1..] = index expressions
    Colour,     // colour expression: [color|colour] then parts in written order;
                // children = ColourPart nodes
    ColourPart, // `text` = "rgb" "rgbf" "rgbt" "rgbft" "srgb" "srgbf" "srgbt" "srgbft" "red"
                // "green" "blue" "filter" "transmit" "gray" "grey", or "" for a bare
                // expression (e.g. `color Red`); children[0] = the expression
    ArrayDecl,  // array[d1][d2]... [{ init }]: children = dimension exprs, then optionally
                // one ArrayInit as the last child (`flag` = true when the initialiser is present)
    ArrayInit,  // { a, b, {c, d} }: children = expressions or nested ArrayInit

    // ---- block items ------------------------------------------------------------------
    Keyword,    // a reserved word used as a modifier, e.g. `translate`, `hollow`, `phong`;
                // `text` = the word. Its arguments are the following items.
    Block,      // `text` = keyword (or an unknown word, which the interpreter reports);
                // `params` = names in `function(x, y) { }` style parameter lists;
                // children = body items
    MapEntry,   // [ items ] inside a map block: children = items
    Comma,      // ',' between items (kept: POV uses commas to separate some arguments)
    Semicolon,  // ';' outside a directive (accepted and ignored)
    PolyTerm,   // xyz(i, j, k): c in a polynomial block; children = i, j, k, c
    PwrTerm,    // pwr(a, b) in a julia_fractal block: children = a, b
    Literals,   // a run of literal items (numbers, vectors of literal numbers, commas) kept
                // as arrays: `literals` (LiteralRun), no children. The lists of big meshes.

    // ---- directives (may appear wherever an item may) ---------------------------------
    Body,       // a sequence of items: the whole file, a directive branch, a macro body
    Version,    // #version expr; children[0] = expr ("unofficial ..." forms: text kept)
    Include,    // #include expr; children[0] = expr
    Declare,    // #declare / #local: `text` = "declare" | "local"; children[0] = target
                // (Ident or Index); children[1..] = right-hand side items: usually one
                // expression, Block or ArrayDecl; several `texture {}` Blocks for a layered
                // texture
    Undef,      // #undef name: `text` = name
    If,         // children = Branch nodes in order; the last may be an else branch
    Ifdef,      // #ifdef (name) / #ifndef: `text` = "ifdef" | "ifndef";
                // children[0] = Ident or Index tested; children[1] = Branch (then),
                // optional children[2] = Branch (else)
    Branch,     // children[0] = condition (Null for #else), children[1] = Body
    Switch,     // children[0] = selector expression, then Case/Range/Branch(else) nodes
    Case,       // #case (expr) body: children = {expr, Body}
    Range,      // #range (lo, hi) body: children = {lo, hi, Body}
    Break,      // #break
    While,      // #while (cond) body #end: children = {cond, Body}
    For,        // #for (ident, start, end [, step]) body #end: `text` = ident;
                // children = {start, end, step-or-Null, Body}
    Macro,      // #macro name(params) ... #end: `text` = name, `params` = parameter names,
                // `optional_params[i]` true when written `optional name`;
                // the body is NOT parsed here: `raw_begin`..`raw_end` are byte offsets into
                // loc.file->text, `raw_loc` is the location of raw_begin. The interpreter parses
                // it with parse_fragment() when the macro is first called.
    Default,    // #default { texture{} | pigment{} | finish{} | normal{} }: children = items
    Message,    // #debug / #warning / #error expr: `text` = "debug" | "warning" | "error"
                // (also "render", "statistics"); children[0] = expr
    FileIO,     // #fopen #fclose #read #write: `text` = directive name; refused when evaluated
    Null,       // placeholder for an absent optional child
};

struct Node;
using NodePtr = std::unique_ptr<Node>;

// What only a few kinds of node have, kept apart so that the many small nodes (numbers,
// vectors, identifiers) stay small.
// A run of at least kMinLiteralRun literal floats and vectors (with the commas between them)
// in a block body, as the grammar's literal_run reads it: what would be one Number or Vector
// node per value is a few bytes per value here. The interpreter hands the run on as one item
// and expands it one element at a time (interp/literal_items.hpp), with each element's own
// location, so nothing downstream can tell the difference.
struct LiteralRun {
    std::vector<double> values;   // every element's components, in order
    std::vector<uint32_t> bytes;  // each element's offset into the file
    std::vector<uint8_t> sizes;   // each element: 0 a comma, 1 a float, 2..5 a vector
    struct Line {
        uint32_t start;   // offset of the line's first byte
        uint32_t number;  // 1-based
    };
    std::vector<Line> lines;      // each line elements start on, in order
    size_t value_elements = 0;    // floats and vectors

    // Element i's location in `file`.
    SourceLoc loc(const SourceFile* file, size_t i) const;
};
inline constexpr size_t kMinLiteralRun = 8;

struct NodeExtra {
    std::vector<std::string> ops;      // Binary operators
    std::vector<std::string> params;   // Block function params, Macro params
    std::vector<bool> optional_params; // Macro
    uint32_t raw_begin = 0, raw_end = 0;  // Macro body byte range
    SourceLoc raw_loc;                     // Macro body start
    std::shared_ptr<LiteralRun> literals;  // Literals (immutable once parsed)
};

struct Node {
    Kind kind = Kind::Null;
    bool flag = false;                 // ArrayDecl: has initialiser; Block: written
                                       // `function W, H { }` (height_field), W and H are
                                       // children[0] and [1], the body follows
    SourceLoc loc;                     // where the node starts
    std::string text;                  // meaning depends on kind (see above)
    double number = 0.0;               // Number
    std::vector<NodePtr> children;
    std::unique_ptr<NodeExtra> extra;  // see more()

    Node() = default;
    Node(Kind k, SourceLoc l) : kind(k), loc(l) {}
    // Nodes come from the node pool (parser/node_pool.hpp).
    static void* operator new(std::size_t size) { return allocate_node_slot(size); }
    static void operator delete(void* p, std::size_t size) noexcept { free_node_slot(p, size); }
    // The operators, parameters and macro body range (made on first write).
    NodeExtra& more() {
        if (!extra) extra = std::make_unique<NodeExtra>();
        return *extra;
    }
    const NodeExtra& more() const {
        static const NodeExtra kNone;
        return extra ? *extra : kNone;
    }
};

// Kind name for dumps and messages ("Number", "Block", ...).
const char* kind_name(Kind k);

}  // namespace lumen::ast
