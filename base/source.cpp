#include "base/source.hpp"

#include <fstream>
#include <sstream>

namespace lumen {

std::string_view SourceFile::line_text(uint32_t line) const {
    if (line == 0) return {};
    size_t pos = 0;
    for (uint32_t l = 1; l < line; ++l) {
        pos = text.find('\n', pos);
        if (pos == std::string::npos) return {};
        ++pos;
    }
    size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    std::string_view sv(text.data() + pos, end - pos);
    if (!sv.empty() && sv.back() == '\r') sv.remove_suffix(1);
    return sv;
}

std::string SourceLoc::str() const {
    if (!file) return "<command line>";
    return file->name + ":" + std::to_string(line) + ":" + std::to_string(column);
}

const SourceFile* SourceManager::add(std::string name, std::string text) {
    auto f = std::make_unique<SourceFile>();
    f->name = std::move(name);
    f->text = std::move(text);
    files_.push_back(std::move(f));
    return files_.back().get();
}

const SourceFile* SourceManager::load(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return nullptr;
    std::ostringstream ss;
    ss << in.rdbuf();
    return add(path, ss.str());
}

}  // namespace lumen
