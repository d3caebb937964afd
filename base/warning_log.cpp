#include "base/warning_log.hpp"

#include <algorithm>
#include <vector>

namespace lumen {

void WarningLog::report(const Diagnostic& d) {
    if (d.severity != Severity::Warning) {
        print_(d);
        return;
    }
    Seen& s = seen_[Key{d.loc.file, d.loc.line, d.loc.column, d.message}];
    if (s.count++ == 0) {
        s.first = d;
        print_(d);
    }
}

void WarningLog::flush() {
    std::vector<const Seen*> repeated;
    for (const auto& [key, s] : seen_)
        if (s.count > 1) repeated.push_back(&s);
    std::stable_sort(repeated.begin(), repeated.end(), [](const Seen* a, const Seen* b) {
        return a->first.loc.byte < b->first.loc.byte;
    });
    for (const Seen* s : repeated) {
        Diagnostic note{Severity::Note, s->first.loc,
                        "warning '" + s->first.message + "' given " + std::to_string(s->count) +
                            " times here (printed once)",
                        {}, s->first.include_chain};
        print_(note);
    }
    seen_.clear();
}

uint64_t WarningLog::count(const SourceLoc& loc, const std::string& message) const {
    auto it = seen_.find(Key{loc.file, loc.line, loc.column, message});
    return it == seen_.end() ? 0 : it->second.count;
}

}  // namespace lumen
