// Small helpers of the image test drivers (differential, stability) for running programs
// through the shell and reading their logs.
#pragma once
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace lumen::differential {

// `s` as one single-quoted shell word.
inline std::string quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

inline std::string read_text(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

}  // namespace lumen::differential
