// #fopen / #read / #write / #fclose: the files a scene opens, with POV-Ray 3.7's formats and
// a safe default for where they may be (see README, "File I/O").
#pragma once
#include <cstdio>
#include <memory>
#include <string>

namespace lumen::interp {

struct FileValue {
    std::string name;   // as the scene wrote it (messages)
    std::string path;   // as opened
    bool writing = false;
    std::string text;   // read: the whole file
    size_t pos = 0;     // read: the next byte
    std::FILE* out = nullptr;  // write / append
    size_t written = 0;
    ~FileValue() {
        if (out) std::fclose(out);
    }
};

}  // namespace lumen::interp
