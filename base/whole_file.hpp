// Files written whole or not at all: the content goes to a temporary name beside the file,
// renamed over it at the end, so a reader (another process of a farm sharing the file) sees
// a whole file or none, and a failed write leaves nothing behind.
#pragma once
#include <functional>
#include <ostream>
#include <string>

namespace lumen {

// Writes `path` through `write` (a binary stream). Returns "" on success, else why it failed:
// "cannot be written" (not opened, or not renamed) or "write failed".
std::string write_whole_file(const std::string& path, const std::function<void(std::ostream&)>& write);

}  // namespace lumen
