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

// The file's samples as lumen's writers take them: levels 0..maxval, or linear floats.
render::EncodedImage encoded(const image::ImageFile& f, const std::string& path) {
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
    e.values.resize(f.values.size());
    for (size_t i = 0; i < f.values.size(); ++i)
        e.values[i] = f.floating ? f.values[i] : std::round(f.values[i] * float(e.maxval));
    return e;
}

bool same_format(const render::EncodedImage& a, const render::EncodedImage& b) {
    return a.width == b.width && a.height == b.height && a.channels == b.channels &&
           a.maxval == b.maxval && a.curve == b.curve &&
           (a.curve != render::EncodedImage::Curve::Power || a.file_gamma == b.file_gamma);
}

std::string describe(const render::EncodedImage& e) {
    return std::to_string(e.width) + "x" + std::to_string(e.height) + ", " +
           std::to_string(e.channels) + " channels, " +
           (e.maxval ? std::to_string(e.maxval == 255 ? 8 : 16) + " bits" : std::string("float"));
}

}  // namespace

MergeResult merge_parts(const std::vector<std::string>& parts, const std::string& output) {
    if (parts.empty()) throw LumenError({}, "lumen merge: no parts to merge");
    const render::FileType type = type_of(output);
    render::EncodedImage whole;
    std::vector<int> owner;  // the part each pixel came from, -1 for none yet
    for (size_t p = 0; p < parts.size(); ++p) {
        const std::string& path = parts[p];
        if (type_of(path) != type)
            throw LumenError({}, "'" + path + "' is not of the output's type",
                             "merge parts into a file of their own type");
        render::EncodedImage part;
        try {
            part = encoded(image::read_image(path, *image::format_from_extension(path)), path);
        } catch (const image::ImageError& e) {
            throw LumenError({}, "cannot read '" + path + "': " + e.what());
        }
        if (p == 0) {
            whole = part;
            std::fill(whole.values.begin(), whole.values.end(), 0.0f);
            owner.assign(size_t(whole.width) * whole.height, -1);
        } else if (!same_format(part, whole)) {
            throw LumenError({}, "'" + path + "' (" + describe(part) + ") does not match '" +
                                     parts[0] + "' (" + describe(whole) + ")",
                             "merge the parts of one render, made with the same options");
        }
        const int c = whole.channels;
        for (size_t i = 0; i < owner.size(); ++i) {
            const float* s = part.values.data() + i * c;
            bool rendered = false;
            for (int k = 0; k < c; ++k) rendered |= s[k] != 0.0f;
            if (!rendered) continue;
            float* d = whole.values.data() + i * c;
            if (owner[i] < 0) {
                std::copy(s, s + c, d);
                owner[i] = int(p);
            } else if (!std::equal(s, s + c, d)) {
                throw LumenError({}, "'" + path + "' and '" + parts[size_t(owner[i])] +
                                         "' differ at pixel " + std::to_string(i % whole.width) +
                                         ", " + std::to_string(i / whole.width),
                                 "overlapping parts must come from the same render");
            }
        }
    }
    render::write_encoded(whole, type, output);
    MergeResult r{whole.width, whole.height, 0};
    for (const int o : owner) r.blank += o < 0;
    return r;
}

int run_merge(const std::vector<std::string>& args) {
    if (args.size() < 2 || args[0] == "--help") {
        std::fputs("usage: lumen merge OUTPUT PART...\n"
                   "Joins partial renders of one image (+SR/+ER/+SC/+EC) into OUTPUT: each\n"
                   "pixel comes from the part that rendered it (a partial render's margins are\n"
                   "zero). The parts and OUTPUT share one file type.\n",
                   args.empty() || args[0] != "--help" ? stderr : stdout);
        return args.empty() || args[0] != "--help" ? 1 : 0;
    }
    try {
        const std::vector<std::string> parts(args.begin() + 1, args.end());
        const MergeResult r = merge_parts(parts, args[0]);
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
