// Renders a radiosity sample scene with lumen at its defaults (the scene's own radiosity block,
// no anti-aliasing) and compares it with POV-Ray's converged render: the mean absolute error
// over all pixels and RGB channels (8-bit values on a 0..1 scale, as `idiff -a`) must not
// exceed the scene's bar in references.txt, and no pixel may be black where the reference is
// lit all around (a surface left without light). MAX_ERROR "none": a scene that does not meet
// its bar yet, held to the black-pixel check alone. Exit 77 (skip) without the scene.
//   radiosity_reference LUMEN SCENE REFERENCE WxH MAX_ERROR OUT
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>

#include "tests/differential/image_compare.hpp"

int main(int argc, char** argv) {
    if (argc != 7) {
        std::fprintf(stderr, "usage: radiosity_reference LUMEN SCENE REFERENCE WxH MAX_ERROR OUT\n");
        return 2;
    }
    const std::string lumen = argv[1], scene = argv[2], reference = argv[3], size = argv[4],
                      out = argv[6];
    const bool dark_only = std::string(argv[5]) == "none";
    const double bar = dark_only ? 0 : std::atof(argv[5]);
    if (!std::filesystem::exists(scene)) {
        std::printf("skipped: %s not installed (package povray-examples)\n", scene.c_str());
        return 77;
    }
    const auto x = size.find('x');
    const std::string w = size.substr(0, x), h = size.substr(x + 1);
    const std::filesystem::path dir = std::filesystem::path(scene).parent_path();
    // As the references were rendered: the first frame of an animation, the scene's folder
    // on the include path.
    const std::string cmd = "cd '" + dir.string() + "' && '" + lumen + "' '" + scene + "' +W" + w +
                            " +H" + h + " -A +KFI1 +KFF1 +V +FN '+L" + dir.string() + "' '+O" +
                            out + "'";
    const auto t0 = std::chrono::steady_clock::now();
    if (std::system(cmd.c_str()) != 0) {
        std::fprintf(stderr, "lumen failed: %s\n", cmd.c_str());
        return 1;
    }
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    try {
        const lumen::differential::Comparison c =
            lumen::differential::compare_images(reference, out, out + ".heat.png");
        std::printf("%s %s: mean absolute error %.5f (bar %.5f), %d pixels black where the "
                    "reference is lit, lumen %.2f s wall\n",
                    std::filesystem::path(scene).filename().c_str(), size.c_str(), c.mean_error,
                    bar, c.dark_where_lit, secs);
        if (dark_only) return c.dark_where_lit == 0 ? 0 : 1;
        return bar > 0 && c.mean_error <= bar && c.dark_where_lit == 0 ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
}
