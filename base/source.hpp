// Source files and locations. Every syntax-tree node, scene entity and diagnostic carries a
// SourceLoc so errors can point at file:line:col (pbrt's FileLoc idea).
#pragma once
#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <string_view>

namespace lumen {

struct SourceFile {
    std::string name;  // path as shown in messages
    std::string text;  // whole file contents
    // The text of 1-based line `line`, without its newline (empty if out of range).
    std::string_view line_text(uint32_t line) const;
};

struct SourceLoc {
    const SourceFile* file = nullptr;  // null for built-ins / command line
    uint32_t line = 0;                 // 1-based; 0 = unknown
    uint32_t column = 0;               // 1-based, in bytes
    uint32_t byte = 0;                 // 0-based offset into file->text
    std::string str() const;           // "file:line:col" (or "<command line>")
};

// Owns every SourceFile loaded during a run; files are never freed before the run ends,
// so SourceLoc can hold plain pointers.
class SourceManager {
public:
    const SourceFile* add(std::string name, std::string text);
    // Reads a file from disk; returns nullptr if it cannot be read.
    const SourceFile* load(const std::string& path);

private:
    std::deque<std::unique_ptr<SourceFile>> files_;
};

}  // namespace lumen
