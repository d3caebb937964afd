// Warnings printed once per location: a warning given again at the same place with the same
// text (a #while loop calling the same macro, a mesh of a million degenerate triangles) is
// counted, and one note at the end says how often it came. Errors and notes (#debug) pass
// straight through.
#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <tuple>

#include "base/diagnostics.hpp"

namespace lumen {

class WarningLog {
public:
    using Printer = std::function<void(const Diagnostic&)>;
    explicit WarningLog(Printer print) : print_(std::move(print)) {}

    // Prints `d` unless it is a warning already printed from the same location.
    void report(const Diagnostic& d);
    // One note per warning that came more than once ("... given N times"), in source order;
    // then forgets them.
    void flush();

    // Times the warning at `loc` with `message` was reported (0 if never).
    uint64_t count(const SourceLoc& loc, const std::string& message) const;

private:
    using Key = std::tuple<const SourceFile*, uint32_t, uint32_t, std::string>;
    struct Seen {
        Diagnostic first;
        uint64_t count = 0;
    };
    Printer print_;
    std::map<Key, Seen> seen_;
};

}  // namespace lumen
