#include "parser/ast.hpp"

#include <algorithm>

namespace lumen::ast {

SourceLoc LiteralRun::loc(const SourceFile* file, size_t i) const {
    const uint32_t byte = bytes[i];
    // The last line starting at or before the element (elements and lines are in order).
    auto it = std::upper_bound(lines.begin(), lines.end(), byte,
                               [](uint32_t b, const Line& l) { return b < l.start; });
    const Line& line = *(it - 1);
    return SourceLoc{file, line.number, byte - line.start + 1, byte};
}

const char* kind_name(Kind k) {
    switch (k) {
        case Kind::Number: return "Number";
        case Kind::String: return "String";
        case Kind::Ident: return "Ident";
        case Kind::Vector: return "Vector";
        case Kind::Unary: return "Unary";
        case Kind::Binary: return "Binary";
        case Kind::Ternary: return "Ternary";
        case Kind::Call: return "Call";
        case Kind::Member: return "Member";
        case Kind::Index: return "Index";
        case Kind::Colour: return "Colour";
        case Kind::ColourPart: return "ColourPart";
        case Kind::ArrayDecl: return "ArrayDecl";
        case Kind::ArrayInit: return "ArrayInit";
        case Kind::Keyword: return "Keyword";
        case Kind::Block: return "Block";
        case Kind::MapEntry: return "MapEntry";
        case Kind::Comma: return "Comma";
        case Kind::Semicolon: return "Semicolon";
        case Kind::PolyTerm: return "PolyTerm";
        case Kind::PwrTerm: return "PwrTerm";
        case Kind::Literals: return "Literals";
        case Kind::Body: return "Body";
        case Kind::Version: return "Version";
        case Kind::Include: return "Include";
        case Kind::Declare: return "Declare";
        case Kind::Undef: return "Undef";
        case Kind::If: return "If";
        case Kind::Ifdef: return "Ifdef";
        case Kind::Branch: return "Branch";
        case Kind::Switch: return "Switch";
        case Kind::Case: return "Case";
        case Kind::Range: return "Range";
        case Kind::Break: return "Break";
        case Kind::While: return "While";
        case Kind::For: return "For";
        case Kind::Macro: return "Macro";
        case Kind::Default: return "Default";
        case Kind::Message: return "Message";
        case Kind::FileIO: return "FileIO";
        case Kind::Null: return "Null";
    }
    return "?";
}

}  // namespace lumen::ast
