#include "cli/ini_file.hpp"

#include <filesystem>

#include "cli/command_line.hpp"
#include "cli/text.hpp"
#include "base/diagnostics.hpp"

namespace lumen::cli {
namespace {

constexpr int kMaxIniDepth = 16;

// Drops a ';' or '#' comment that is not inside quotes.
std::string strip_comment(std::string_view line) {
    bool quoted = false;
    for (size_t i = 0; i < line.size(); ++i) {
        if (line[i] == '"') quoted = !quoted;
        if (!quoted && (line[i] == ';' || line[i] == '#')) return std::string(line.substr(0, i));
    }
    return std::string(line);
}

SourceLoc loc_at(const SourceFile& file, uint32_t line, size_t line_start, size_t column0) {
    return SourceLoc{&file, line, uint32_t(column0 + 1), uint32_t(line_start + column0)};
}

// POV looks for INI files in the current folder, then along the library paths.
std::string find_ini(const std::string& name, const Options& o) {
    namespace fs = std::filesystem;
    if (fs::exists(name) || fs::path(name).is_absolute()) return name;
    for (const std::string& dir : o.scene.library_paths) {
        const fs::path p = fs::path(dir) / name;
        if (fs::exists(p)) return p.string();
    }
    return name;
}

}  // namespace

std::pair<std::string, std::string> split_ini_spec(const std::string& spec) {
    const std::string s = unquote(trim(spec));
    const size_t open = s.rfind('[');
    if (!s.empty() && s.back() == ']' && open != std::string::npos && open > 0)
        return {s.substr(0, open), trim(s.substr(open + 1, s.size() - open - 2))};
    return {s, {}};
}

void apply_ini_text(Options& o, SourceManager& sources, const SourceFile& file,
                    const std::string& section, int depth) {
    // Lines before the first header always apply; later ones only under the named section.
    bool active = true;
    uint32_t line_no = 0;
    size_t start = 0;
    while (start <= file.text.size()) {
        size_t end = file.text.find('\n', start);
        if (end == std::string::npos) end = file.text.size();
        ++line_no;
        const std::string raw = strip_comment(std::string_view(file.text).substr(start, end - start));
        const std::string line = trim(raw);
        const size_t indent = raw.find_first_not_of(" \t");
        const SourceLoc loc = loc_at(file, line_no, start, indent == std::string::npos ? 0 : indent);
        if (line.empty()) {
            // nothing
        } else if (line.front() == '[') {
            if (line.back() != ']') throw LumenError(loc, "unterminated section header");
            active = !section.empty() && iequals(trim(line.substr(1, line.size() - 2)), section);
        } else if (active) {
            const size_t eq = line.find('=');
            if (eq != std::string::npos && line.front() != '+' && line.front() != '-' &&
                line.front() != '"') {
                apply_ini_option(o, line.substr(0, eq), line.substr(eq + 1), loc, sources, depth);
            } else {
                // A line of switches and/or file names, exactly as on the command line.
                for (const std::string& word : split_words(line))
                    apply_argument(o, sources, word, loc, depth);
            }
        }
        start = end + 1;
    }
}

void read_ini_file(Options& o, SourceManager& sources, const std::string& spec,
                   const SourceLoc& from, int depth) {
    if (depth > kMaxIniDepth)
        throw LumenError(from, "INI files nested more than " + std::to_string(kMaxIniDepth) +
                                   " deep (an Include_Ini loop?)");
    const auto [name, section] = split_ini_spec(spec);
    const SourceFile* file = sources.load(find_ini(name, o));
    if (!file) throw LumenError(from, "cannot read INI file '" + name + "'");
    apply_ini_text(o, sources, *file, section, depth);
}

}  // namespace lumen::cli
