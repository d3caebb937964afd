// POV-Ray's image storage rules (see pov_storage.hpp).
#include "image/pov_storage.hpp"

#include <cmath>

namespace lumen::image {

namespace {

float decoded(Decode::Kind kind, double gamma, float v) {
    switch (kind) {
        case Decode::Kind::Raw: return v;
        case Decode::Kind::Power: return v > 0 ? float(std::pow(double(v), gamma)) : v;
        case Decode::Kind::SRGB: {
            const double d = v;
            return float(d <= 0.04045 ? d / 12.92 : std::pow((d + 0.055) / 1.055, 2.4));
        }
    }
    return v;
}

}  // namespace

float Decode::apply(float v) const {
    const float d = decoded(kind, gamma, v);
    if (working_gamma == 1 || !(d > 0)) return d;
    return float(std::pow(double(d), 1.0 / working_gamma));
}

std::optional<Decode> file_decode(const ImageFile& file) {
    switch (file.gamma.kind) {
        case FileGamma::Kind::SRGB: return Decode{Decode::Kind::SRGB, 1};
        case FileGamma::Kind::Power: return Decode{Decode::Kind::Power, 1.0 / file.gamma.gamma};
        case FileGamma::Kind::Unspecified: return std::nullopt;
    }
    return std::nullopt;
}

Decode default_decode(const ImageFile& file, Format format) {
    switch (format) {
        case Format::Png: return file_decode(file).value_or(Decode{Decode::Kind::SRGB, 1});
        case Format::Gif:
        case Format::Tga:
        case Format::Bmp:
        case Format::Jpeg: return {Decode::Kind::SRGB, 1};
        default: return {};
    }
}

PovImage store_as_pov(const ImageFile& file, Format format, const Decode& decode) {
    PovImage out;
    out.width = file.width;
    out.height = file.height;
    out.alpha = file.has_alpha();
    out.high_precision = file.floating || file.bit_depth > 8;
    // Alpha is never gamma-decoded.
    auto colour = [&](float r, float g, float b, float a) {
        return std::array<float, 4>{decode.apply(r), decode.apply(g), decode.apply(b), a};
    };
    if (file.has_palette()) {
        out.palette = true;
        out.high_precision = false;
        for (const auto& e : file.palette) out.colours.push_back(colour(e[0], e[1], e[2], e[3]));
        out.indices = file.indices;
        return out;
    }
    out.grey = file.grey();
    const bool requantise = out.grey && !out.high_precision && format == Format::Png;
    const size_t n = file.pixels();
    const int c = file.channels;
    out.colours.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const float* v = file.values.data() + i * size_t(c);
        if (out.grey) {
            float d = decode.apply(v[0]);
            if (requantise) d = std::trunc(pov_grey(d, d, d) * 255.0f) / 255.0f;
            out.colours[i] = {d, d, d, c == 2 ? v[1] : 1.0f};
        } else {
            out.colours[i] = colour(v[0], v[1], v[2], c == 4 ? v[3] : 1.0f);
        }
    }
    return out;
}

}  // namespace lumen::image
