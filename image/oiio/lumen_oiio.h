/* The C interface of liblumen_oiio.so, the OpenImageIO module that lumen loads with dlopen
   only for OpenEXR, Radiance HDR and TIFF output (see render/image_files.hpp) and for reading
   the image files lumen has no reader of its own for (see image/image_file.hpp). */
#ifndef LUMEN_OIIO_H
#define LUMEN_OIIO_H
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

enum LumenOiioStored { LUMEN_OIIO_UINT8, LUMEN_OIIO_UINT16, LUMEN_OIIO_HALF, LUMEN_OIIO_FLOAT };

struct LumenOiioImage {
    const char* format;       /* OpenImageIO format name: "openexr", "hdr", "tiff" */
    const char* path;
    int width, height, channels;
    int stored;               /* enum LumenOiioStored */
    const char* colour_space; /* "oiio:ColorSpace" of integer files; NULL for float files */
    const char* software;
    const float* pixels;      /* integer files: in [0,1]; float files: linear light */
};

/* Writes the image; returns 0, or non-zero with a message in error[error_size]. */
typedef int (*LumenOiioWrite)(const struct LumenOiioImage* image, char* error, size_t error_size);
#define LUMEN_OIIO_WRITE_SYMBOL "lumen_oiio_write_v1"

/* An image read as floats: integer files as level / maxval, float files as stored. */
struct LumenOiioPixels {
    int width, height, channels;
    int bits;     /* bits per sample in the file */
    int floating; /* non-zero for half/float files */
};
/* Returns room for `count` floats (the module fills them), or NULL to refuse. */
typedef float* (*LumenOiioAlloc)(void* context, size_t count);
/* Reads the image at `path` unless a side exceeds max_side or the pixels max_pixels; returns
   0, or non-zero with a message in error[error_size]. */
typedef int (*LumenOiioRead)(const char* path, int max_side, size_t max_pixels,
                             struct LumenOiioPixels* out, LumenOiioAlloc alloc, void* context,
                             char* error, size_t error_size);
#define LUMEN_OIIO_READ_SYMBOL "lumen_oiio_read_v1"

#ifdef __cplusplus
}
#endif
#endif
