// Media photons (global photons { media N, factor }): the photons left along paths through
// scattering media, counted as POV-Ray 3.7 counts them, and the light they give the media.
#include <gtest/gtest.h>

#include <string>

#include "interp/interpret.hpp"
#include "render/frame.hpp"
#include "render/photons/photon_pass.hpp"
#include "render/render.hpp"

namespace lumen::cli {
namespace {

// A glass sphere focusing a spotlight's photons into a clear box of scattering media.
std::string beam_scene(const std::string& media) {
    return "#version 3.7;\n"
           "global_settings { assumed_gamma 1 photons { count 20000 " + media + " } }\n"
           "camera { location <0, 1.2, -6> look_at <0, 0.8, 0> angle 45 }\n"
           "light_source { <0, 8, 0> rgb 1 spotlight radius 8 falloff 10 point_at <0, 0, 0>\n"
           "  photons { refraction on reflection on } }\n"
           "plane { y, 0 pigment { checker rgb 0.7 rgb 0.4 } }\n"
           "box { <-1.5, 0, -1.5>, <1.5, 2.5, 1.5> hollow pigment { rgbf 1 }\n"
           "  interior { media { scattering { 1, rgb 0.3 extinction 0 } method 3 intervals 1 samples 4 } }\n"
           "  photons { target } }\n"
           "sphere { <0, 3.4, 0>, 0.6 pigment { rgbf <0.9, 0.95, 1, 1> } finish { ambient 0 diffuse 0 }\n"
           "  interior { ior 1.5 } photons { target refraction on reflection off collect off } }\n";
}

size_t media_photons(const std::string& text, int threads = 2) {
    SourceManager sources;
    const scene::Scene s = interp::interpret_text(sources, "media_photons.pov", text, {});
    const render::RenderFrame frame(s);
    const auto pass = render::shoot_photons(frame, threads);
    return pass ? pass->media.size() : 0;
}

TEST(MediaPhotons, StoredAlongPathsAsPovRayStoresThem) {
    // povray 3.7 printed "Media photons stored: 72476" for this scene (its jitter is random).
    const double one = double(media_photons(beam_scene("media 60, 1")));
    EXPECT_NEAR(one / 72476, 1.0, 0.01);
    EXPECT_EQ(media_photons(beam_scene("media 60, 1"), 1), size_t(one));  // any thread count
    // The factor scales the spacing along the path: twice the factor, about half the photons.
    EXPECT_NEAR(double(media_photons(beam_scene("media 60, 2"))) / one, 0.5, 0.05);
    EXPECT_EQ(media_photons(beam_scene("media 0")), 0u);
    EXPECT_EQ(media_photons(beam_scene("")), 0u);
}

// A box of scattering media (no extinction) under a parallel light from above, seen from the
// side; its clear top is a photon target. `photons`: the global photons block, or none.
double beam_brightness(const std::string& photons) {
    const std::string text =
        "#version 3.7;\n"
        "global_settings { assumed_gamma 1 " + photons + " }\n"
        "camera { orthographic location <0, 0.5, -5> look_at <0, 0.5, 0> right x * 2 up y * 2 }\n"
        "light_source { <0, 10, 0> rgb 1 parallel point_at 0 photons { refraction on } }\n"
        "box { <-0.5, 0, -0.5>, <0.5, 1, 0.5> hollow pigment { rgbf 1 }\n"
        "  interior { media { scattering { 1, rgb 0.2 extinction 0 } } } photons { target } }\n"
        "plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 0 } }\n";
    SourceManager sources;
    const scene::Scene s = interp::interpret_text(sources, "slab.pov", text, {});
    render::RenderOptions o;
    o.width = o.height = 40;
    o.threads = 2;
    const render::Image im = render::render(s, o);
    double sum = 0;
    for (int y = 15; y < 25; ++y)
        for (int x = 15; x < 25; ++x) sum += im.at(x, y)[1];
    return sum / 100;
}

TEST(MediaPhotons, LightTheMediaAsTheLightWould) {
    const double direct = beam_brightness("");
    EXPECT_NEAR(direct, 0.2, 0.01);  // scattering 0.2 times the light, isotropic
    // The clear target shadows the light in the media where there are photons; the media
    // photons bring it back: POV-Ray measured 0.991 of the direct light here (sRGB 0.4818
    // against 0.4863).
    const double by_photons = beam_brightness("photons { spacing 0.02 media 100, 1 }");
    EXPECT_NEAR(by_photons / direct, 1.0, 0.03);
    const double shadowed = beam_brightness("photons { spacing 0.02 media 0 }");
    EXPECT_LT(shadowed, 0.05 * direct);
}

}  // namespace
}  // namespace lumen::cli
