// libpng's error callbacks for the reader and the writer: the message is kept for the
// caller's exception and control returns through png_longjmp (libpng's own unwinding).
#pragma once
#include <cstdio>

#include <png.h>

namespace lumen::image {

struct PngErrorText {
    char text[256] = "libpng error";
};

[[noreturn]] inline void png_error_to_text(png_structp png, png_const_charp message) {
    auto* e = static_cast<PngErrorText*>(png_get_error_ptr(png));
    std::snprintf(e->text, sizeof e->text, "%s", message);
    png_longjmp(png, 1);
}
inline void png_ignore_warning(png_structp, png_const_charp) {}

}  // namespace lumen::image
