// Symbol tables with POV-Ray's scoping rules.
//
// POV keeps a stack of tables: the global one, then one per include file being read and one per
// macro call in progress. Lookup is dynamic (innermost table first), so a macro sees its
// caller's locals. `#local` writes into the innermost table; `#declare` overwrites the innermost
// existing binding of the name, or creates a global one when there is none (checked against
// POV-Ray 3.7: a #declare inside a macro modifies the caller's #local of the same name).
#pragma once
#include <string>
#include <unordered_map>
#include <vector>

#include "interp/value.hpp"

namespace lumen::interp {

class SymbolTable {
public:
    SymbolTable();

    // Entering/leaving an include file or a macro call.
    void push();
    void pop();
    size_t depth() const { return frames_.size(); }

    // Innermost binding, or null.
    Value* find(const std::string& name);
    // Index of the frame holding the innermost binding, or npos.
    size_t frame_of(const std::string& name) const;

    void declare(const std::string& name, Value v);  // #declare
    void local(const std::string& name, Value v);    // #local
    void set_in_frame(size_t frame, const std::string& name, Value v);
    // #undef: removes the innermost binding; false if there was none.
    bool undef(const std::string& name);

    // Every visible name (for "did you mean" suggestions).
    std::vector<std::string> visible_names() const;

    static constexpr size_t npos = static_cast<size_t>(-1);

private:
    std::vector<std::unordered_map<std::string, Value>> frames_;  // [0] = global
};

}  // namespace lumen::interp
