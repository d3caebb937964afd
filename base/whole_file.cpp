#include "base/whole_file.hpp"

#include <cstdio>
#include <fstream>
#include <random>

namespace lumen {

std::string write_whole_file(const std::string& path, const std::function<void(std::ostream&)>& write) {
    const std::string tmp = path + ".tmp" + std::to_string(std::random_device{}());
    {
        std::ofstream out(tmp, std::ios::binary);
        if (!out) return "cannot be written";
        write(out);
        out.close();
        if (!out) {
            std::remove(tmp.c_str());
            return "write failed";
        }
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        std::remove(tmp.c_str());
        return "cannot be written";
    }
    return "";
}

}  // namespace lumen
