#include "cli/merge.hpp"

#include <cmath>
#include <cstdio>
#include <optional>

#include "base/diagnostics.hpp"
#include "image/image_file.hpp"
#include "render/image_output.hpp"

namespace lumen::cli {
namespace {

// The file types lumen writes, as the image reader names them.
std::optional<render::FileType> written_type(const std::string& path) {
    switch (image::format_from_extension(path).value_or(image::Format::Sys)) {
        case image::Format::Png: return render::FileType::PNG;
        case image::Format::Ppm: return render::FileType::PPM;
        case image::Format::Tiff: return render::FileType::TIFF;
        case image::Format::Exr: return render::FileType::EXR;
        case image::Format::Hdr: return render::FileType::HDR;
        default: return std::nullopt;
    }
}

render::FileType type_of(const std::string& path) {
    if (const auto t = written_type(path)) return *t;
    throw LumenError({}, "'" + path + "' is not an image type lumen writes",
                     "lumen merge reads and writes .png, .ppm, .tif, .exr and .hdr files");
}

// The file's size and format as lumen's writers take them (no samples).
render::EncodedImage header_of(const image::ImageFile& f, const std::string& path) {
    if (f.has_palette() || (f.channels != 3 && f.channels != 4))
        throw LumenError({}, "'" + path + "' is not an RGB or RGBA image as lumen writes them");
    render::EncodedImage e;
    e.width = f.width;
    e.height = f.height;
    e.channels = f.channels;
    e.maxval = f.floating ? 0 : (1 << f.bit_depth) - 1;
    switch (f.gamma.kind) {
        case image::FileGamma::Kind::Unspecified: e.curve = render::EncodedImage::Curve::Unlabelled; break;
        case image::FileGamma::Kind::SRGB: e.curve = render::EncodedImage::Curve::SRGB; break;
        case image::FileGamma::Kind::Power:
            e.curve = render::EncodedImage::Curve::Power;
            e.file_gamma = 1.0 / f.gamma.gamma;  // the file holds 1 / File_Gamma
            break;
    }
    return e;
}

// The same samples and colour labels (sizes may differ: cropped parts).
bool same_format(const render::EncodedImage& a, const render::EncodedImage& b) {
    return a.channels == b.channels &&
           a.maxval == b.maxval && a.curve == b.curve &&
           (a.curve != render::EncodedImage::Curve::Power || a.file_gamma == b.file_gamma);
}

std::string describe(const render::EncodedImage& e) {
    return std::to_string(e.width) + "x" + std::to_string(e.height) + ", " +
           std::to_string(e.channels) + " channels, " +
           (e.maxval ? std::to_string(e.maxval == 255 ? 8 : 16) + " bits" : std::string("float"));
}

}  // namespace

MergeResult merge_parts(const std::vector<MergePart>& parts, const std::string& output,
                        int width, int height) {
    if (parts.empty()) throw LumenError({}, "lumen merge: no parts to merge");
    const render::FileType type = type_of(output);
    render::EncodedImage whole;
    std::vector<int> owner;  // the part each pixel came from, -1 for none yet
    for (size_t p = 0; p < parts.size(); ++p) {
        const std::string& path = parts[p].path;
        if (type_of(path) != type)
            throw LumenError({}, "'" + path + "' is not of the output's type",
                             "merge parts into a file of their own type");
        image::ImageFile file;
        try {
            file = image::read_image(path, *image::format_from_extension(path));
        } catch (const image::ImageError& e) {
            throw LumenError({}, "cannot read '" + path + "': " + e.what());
        }
        const render::EncodedImage part = header_of(file, path);
        if (p == 0) {
            whole = part;
            whole.width = width > 0 ? width : part.width;
            whole.height = height > 0 ? height : part.height;
            owner.assign(size_t(whole.width) * whole.height, -1);
            whole.values.assign(owner.size() * size_t(whole.channels), 0.0f);
        }
        const int x0 = parts[p].x, y0 = parts[p].y;
        if (!same_format(part, whole) || x0 < 0 || y0 < 0 || x0 + part.width > whole.width ||
            y0 + part.height > whole.height) {
            throw LumenError({}, "'" + path + "' (" + describe(part) + " at " +
                                     std::to_string(x0) + ", " + std::to_string(y0) +
                                     ") does not fit '" + output + "' (" + describe(whole) + ")",
                             "merge the parts of one render, made with the same options");
        }
        // Samples are read as level / maxval: back to levels, as the writers take them.
        const size_t c = size_t(whole.channels);
        const float levels = whole.maxval ? float(whole.maxval) : 0.0f;
        float value[4];
        for (int y = 0; y < part.height; ++y) {
            for (int x = 0; x < part.width; ++x) {
                const float* s = file.values.data() + (size_t(y) * part.width + x) * c;
                bool rendered = false;
                for (size_t k = 0; k < c; ++k) rendered |= s[k] != 0.0f;
                if (!rendered) continue;
                for (size_t k = 0; k < c; ++k) value[k] = levels > 0 ? std::round(s[k] * levels) : s[k];
                const size_t i = size_t(y + y0) * whole.width + size_t(x + x0);
                float* d = whole.values.data() + i * c;
                if (owner[i] < 0) {
                    std::copy(value, value + c, d);
                    owner[i] = int(p);
                } else if (!std::equal(value, value + c, d)) {
                    throw LumenError({}, "'" + path + "' and '" + parts[size_t(owner[i])].path +
                                             "' differ at pixel " + std::to_string(x + x0) +
                                             ", " + std::to_string(y + y0),
                                     "overlapping parts must come from the same render");
                }
            }
        }
    }
    render::write_encoded(whole, type, output);
    MergeResult r{whole.width, whole.height, 0};
    for (const int o : owner) r.blank += o < 0;
    return r;
}

namespace {

// "W,H" or "X,Y": two whole numbers.
bool read_pair(const std::string& text, int& a, int& b) {
    char* end = nullptr;
    const long x = std::strtol(text.c_str(), &end, 10);
    if (end == text.c_str() || *end != ',') return false;
    const char* second = end + 1;
    const long y = std::strtol(second, &end, 10);
    if (end == second || *end || x < 0 || y < 0 || x > 1 << 20 || y > 1 << 20) return false;
    a = int(x);
    b = int(y);
    return true;
}

constexpr const char* kMergeUsage =
    "usage: lumen merge OUTPUT [--size=W,H] [--at=X,Y] PART ...\n"
    "Joins partial renders of one image (+SR/+ER/+SC/+EC) into OUTPUT: each pixel comes\n"
    "from the part that rendered it (a partial render's margins are zero samples). A part\n"
    "after --at=X,Y holds only its area (Output_Crop=on), its top-left at pixel X,Y of an\n"
    "image --size=W,H (default: the first part's size). Parts and OUTPUT share a file type.\n";

}  // namespace

int run_merge(const std::vector<std::string>& args) {
    if (args.size() == 1 && args[0] == "--help") {
        std::fputs(kMergeUsage, stdout);
        return 0;
    }
    try {
        if (args.size() < 2) throw LumenError({}, "lumen merge needs an output and parts", kMergeUsage);
        std::vector<MergePart> parts;
        int width = 0, height = 0, x = 0, y = 0;
        for (size_t i = 1; i < args.size(); ++i) {
            const std::string& a = args[i];
            if (a.rfind("--size=", 0) == 0) {
                if (!read_pair(a.substr(7), width, height) || width == 0 || height == 0)
                    throw LumenError({}, "lumen merge: bad size '" + a + "'", "--size=3840,2160");
            } else if (a.rfind("--at=", 0) == 0) {
                if (!read_pair(a.substr(5), x, y))
                    throw LumenError({}, "lumen merge: bad position '" + a + "'", "--at=960,540");
            } else {
                parts.push_back({a, x, y});
                x = y = 0;
            }
        }
        const MergeResult r = merge_parts(parts, args[0], width, height);
        std::fprintf(stderr, "lumen merge: %zu parts -> %s (%dx%d)%s\n", parts.size(),
                     args[0].c_str(), r.width, r.height,
                     r.blank ? (", " + std::to_string(r.blank) + " pixels black in every part").c_str() : "");
        return 0;
    } catch (const LumenError& e) {
        std::fputs(format_diagnostic(e.diag).c_str(), stderr);
        return 1;
    }
}

}  // namespace lumen::cli
