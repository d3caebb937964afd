// liblumen_oiio.so (image/oiio/lumen_oiio.h), the OpenImageIO module, loaded with dlopen on
// first use: OIIO pulls in some 260 shared libraries whose start-up would dominate a small
// render, so lumen loads them only for the formats it has no reader of its own for.
#pragma once
#include <string>

namespace lumen::image {

// The module's exported function `symbol`, or null with `why` set. The module is looked for
// beside the running executable, then where the build put it; it is loaded once per process.
void* oiio_module_function(const char* symbol, std::string& why);

}  // namespace lumen::image
