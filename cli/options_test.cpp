// Command-line switches and INI options (POV-Ray 3.7's rules).
#include <gtest/gtest.h>

#include "cli/command_line.hpp"
#include "cli/frames.hpp"
#include "cli/options.hpp"
#include "base/diagnostics.hpp"

namespace lumen::cli {
namespace {

Options parse(std::vector<std::string> args) {
    SourceManager sources;
    return parse_command_line(args, sources);
}

// The diagnostic a bad command line gives (empty when it parses).
Diagnostic error_of(std::vector<std::string> args) {
    try {
        parse(std::move(args));
    } catch (const LumenError& e) {
        return e.diag;
    }
    return {};
}

TEST(Switches, SizeInputAndOutput) {
    const Options o = parse({"scene.pov", "+W640", "+H480", "+Oout/picture.png"});
    EXPECT_EQ(o.input, "scene.pov");
    EXPECT_EQ(o.render.width, 640);
    EXPECT_EQ(o.render.height, 480);
    EXPECT_EQ(o.output, "out/picture.png");
}

TEST(Switches, AreCaseInsensitiveAndKeepParameterCase) {
    const Options o = parse({"+iScene.POV", "+w64", "+oMyPic"});
    EXPECT_EQ(o.input, "Scene.POV");
    EXPECT_EQ(o.render.width, 64);
    EXPECT_EQ(o.output, "MyPic");
}

TEST(Switches, Antialiasing) {
    Options o = parse({"s.pov", "+A"});
    EXPECT_TRUE(o.render.antialias);
    EXPECT_DOUBLE_EQ(o.render.aa_threshold, 0.3);
    o = parse({"s.pov", "+A0.1", "+AM2", "+R4", "-J"});
    EXPECT_TRUE(o.render.antialias);
    EXPECT_DOUBLE_EQ(o.render.aa_threshold, 0.1);
    EXPECT_EQ(o.render.aa_method, 2);
    EXPECT_EQ(o.render.aa_depth, 4);
    EXPECT_FALSE(o.render.jitter);
    o = parse({"s.pov", "+A0.2", "-A", "+J0.5"});
    EXPECT_FALSE(o.render.antialias);
    EXPECT_TRUE(o.render.jitter);
    EXPECT_DOUBLE_EQ(o.render.jitter_amount, 0.5);
}

TEST(Switches, FileTypes) {
    EXPECT_EQ(parse({"s.pov", "+FN"}).image.type, render::FileType::PNG);
    const Options n16 = parse({"s.pov", "+FN16"});
    EXPECT_EQ(n16.image.type, render::FileType::PNG);
    EXPECT_EQ(n16.image.bits, 16);
    EXPECT_EQ(parse({"s.pov", "+FE"}).image.type, render::FileType::EXR);
    EXPECT_EQ(parse({"s.pov", "+FH"}).image.type, render::FileType::HDR);
    EXPECT_EQ(parse({"s.pov", "+FT"}).image.type, render::FileType::TIFF);
    EXPECT_EQ(parse({"s.pov", "+FP"}).image.type, render::FileType::PPM);
    EXPECT_FALSE(parse({"s.pov", "-F"}).output_to_file);
    EXPECT_EQ(error_of({"s.pov", "+FJ"}).message, "output file type 'J' is not supported");
}

TEST(Switches, AnimationAndMisc) {
    const Options o = parse({"s.pov", "+KFI2", "+KFF10", "+KI1.5", "+KF3", "+K0.25", "+KC",
                             "+WT3", "+BS16", "+Q5", "+MV3.5", "+UA", "+L/usr/inc", "+D", "-V",
                             "+GA", "-P"});
    EXPECT_EQ(o.initial_frame, 2);
    EXPECT_EQ(o.final_frame, 10);
    EXPECT_DOUBLE_EQ(o.initial_clock, 1.5);
    EXPECT_DOUBLE_EQ(o.final_clock, 3);
    EXPECT_DOUBLE_EQ(o.clock, 0.25);
    EXPECT_TRUE(o.cyclic);
    EXPECT_EQ(o.render.threads, 3);
    EXPECT_EQ(o.render.block_size, 16);
    EXPECT_EQ(o.render.quality, 5);
    ASSERT_TRUE(o.scene.version.has_value());
    EXPECT_DOUBLE_EQ(*o.scene.version, 3.5);
    EXPECT_TRUE(o.image.alpha);
    ASSERT_EQ(o.scene.library_paths.size(), 1u);
    EXPECT_EQ(o.scene.library_paths[0], "/usr/inc");
}

TEST(Switches, ThreadsAlias) {
    EXPECT_EQ(parse({"s.pov", "--threads", "2"}).render.threads, 2);
    EXPECT_EQ(parse({"s.pov", "--threads=5"}).render.threads, 5);
}

TEST(Switches, UnknownSwitchSuggests) {
    const Diagnostic d = error_of({"s.pov", "+BX16"});
    EXPECT_EQ(d.message, "unknown switch '+BX16'");
    EXPECT_EQ(d.hint, "did you mean '+BS'?");
    EXPECT_EQ(error_of({"s.pov", "-ZM1"}).hint, "did you mean '-AM'?");
    EXPECT_EQ(error_of({"s.pov", "+Z"}).message, "unknown switch '+Z'");
}

TEST(Switches, ParameterRules) {
    EXPECT_EQ(error_of({"s.pov", "+W"}).message, "switch '+W' needs a value");
    EXPECT_EQ(error_of({"s.pov", "+V5"}).message, "switch '+V' takes no value, got '+V5'");
    EXPECT_EQ(error_of({"s.pov", "+Wabc"}).message,
              "invalid value 'abc' for Width: expected a number");
    EXPECT_EQ(error_of({"s.pov", "+W0"}).message,
              "invalid value '0' for Width: expected an integer >= 1");
}

TEST(Switches, LongOptions) {
    const Options o = parse({"--dump-scene", "s.pov"});
    EXPECT_TRUE(o.dump_scene);
    EXPECT_TRUE(parse({"s.pov", "--check"}).check);
    EXPECT_TRUE(parse({"--help"}).help);  // no input needed
    const Diagnostic d = error_of({"s.pov", "--dump-scen"});
    EXPECT_EQ(d.message, "unknown option '--dump-scen'");
    EXPECT_EQ(d.hint, "did you mean '--dump-scene'?");
    EXPECT_EQ(error_of({"+W10"}).message, "no input file");
}

TEST(PartialRender, FractionsAndIndices) {
    // VERIFIED in POV: +SR10 +ER20 +SC5 +EC0.5 on 32x24 renders rows 9..19, columns 4..15.
    const Options o = parse({"s.pov", "+W32", "+H24", "+SR10", "+ER20", "+SC5", "+EC0.5"});
    const render::RenderOptions r = effective_render_options(o);
    EXPECT_EQ(r.start_row, 9);
    EXPECT_EQ(r.end_row, 19);
    EXPECT_EQ(r.start_col, 4);
    EXPECT_EQ(r.end_col, 15);
}

TEST(PartialRender, FractionBoundaries) {
    EXPECT_EQ(resolve_start(0.0, 100), 0);
    EXPECT_EQ(resolve_start(0.25, 100), 25);
    EXPECT_EQ(resolve_start(1.0, 100), 0);  // 1 is the 1-based index of the first pixel
    EXPECT_EQ(resolve_start(50.0, 100), 49);
    EXPECT_EQ(resolve_end(1.0, 100), 99);  // 1 is a fraction for an end
    EXPECT_EQ(resolve_end(0.5, 100), 49);
    EXPECT_EQ(resolve_end(2.0, 100), 1);
    EXPECT_EQ(resolve_end(500.0, 100), 99);  // clamped
    EXPECT_EQ(resolve_end(std::nullopt, 100), 99);
    const render::RenderOptions r = effective_render_options(parse({"s.pov", "+W40", "+H30"}));
    EXPECT_EQ(r.end_col, 39);
    EXPECT_EQ(r.end_row, 29);
    EXPECT_EQ(error_of({"s.pov", "+SR0.8", "+ER0.5"}).message, "Start_Row is after End_Row");
}

TEST(IniOptions, KeysAreCaseInsensitive) {
    const Options o = parse({"s.pov", "width=99", "HEIGHT=77", "antialias=on",
                             "Antialias_Threshold=0.2", "output_file_type=E"});
    EXPECT_EQ(o.render.width, 99);
    EXPECT_EQ(o.render.height, 77);
    EXPECT_TRUE(o.render.antialias);
    EXPECT_DOUBLE_EQ(o.render.aa_threshold, 0.2);
    EXPECT_EQ(o.image.type, render::FileType::EXR);
}

TEST(IniOptions, Booleans) {
    for (const char* v : {"on", "TRUE", "yes", "1"})
        EXPECT_TRUE(parse({"s.pov", std::string("Antialias=") + v}).render.antialias) << v;
    for (const char* v : {"off", "false", "No", "0"})
        EXPECT_FALSE(parse({"s.pov", "+A", std::string("Antialias=") + v}).render.antialias) << v;
    EXPECT_NE(error_of({"s.pov", "Antialias=maybe"}).message.find("expected on/off"),
              std::string::npos);
}

TEST(IniOptions, UnknownKeySuggests) {
    const Diagnostic d = error_of({"s.pov", "Heigt=10"});
    EXPECT_EQ(d.message, "unknown option 'Heigt'");
    EXPECT_EQ(d.hint, "did you mean 'Height'?");
    EXPECT_EQ(error_of({"s.pov", "Colour=1"}).hint, "");
    const Diagnostic d2 = error_of({"s.pov", "antialias_treshold=0.1"});
    EXPECT_EQ(d2.hint, "did you mean 'Antialias_Threshold'?");
}

TEST(IniOptions, DeclareFloatsAndStrings) {
    const Options o = parse({"s.pov", "Declare=Foo=0.123456789", "Declare=Name=\"hello\"",
                             "Declare=N=3", "Declare=Foo=2.5"});
    ASSERT_EQ(o.scene.declares.size(), 3u);
    EXPECT_EQ(o.scene.declares[0].name, "Name");
    EXPECT_FALSE(o.scene.declares[0].number.has_value());
    EXPECT_EQ(o.scene.declares[0].text, "hello");
    EXPECT_EQ(o.scene.declares[1].name, "N");
    EXPECT_DOUBLE_EQ(*o.scene.declares[1].number, 3.0);
    EXPECT_EQ(o.scene.declares[2].name, "Foo");  // the later Declare wins
    EXPECT_DOUBLE_EQ(*o.scene.declares[2].number, 2.5);
    // Through a 32-bit float and 6 significant digits, as POV does (VERIFIED: 0.123457).
    const Options p = parse({"s.pov", "Declare=Foo=0.123456789"});
    EXPECT_DOUBLE_EQ(*p.scene.declares[0].number, 0.123457);
    EXPECT_EQ(error_of({"s.pov", "Declare=3x=1"}).message, "Declare needs NAME=value, got '3x=1'");
    EXPECT_EQ(error_of({"s.pov", "Declare=X=abc"}).message,
              "invalid value 'abc' for Declare: expected a number");
}

TEST(IniOptions, GammaVersionAndPaths) {
    const Options o = parse({"s.pov", "File_Gamma=2.2", "Version=3.7", "Library_Path=\"/a b\"",
                             "Output_File_Name=x.png", "Input_File_Name=other.pov",
                             "Permitted_Path=/data"});
    EXPECT_EQ(o.scene.io_folders, std::vector<std::string>{"/data"});
    EXPECT_DOUBLE_EQ(o.image.file_gamma, 2.2);
    EXPECT_DOUBLE_EQ(*o.scene.version, 3.7);
    EXPECT_EQ(o.scene.library_paths.at(0), "/a b");
    EXPECT_EQ(o.output, "x.png");
    EXPECT_EQ(o.input, "other.pov");
    EXPECT_DOUBLE_EQ(parse({"s.pov", "File_Gamma=2.2", "File_Gamma=sRGB"}).image.file_gamma, -1.0);
}

TEST(IniOptions, RadiosityKeys) {
    using namespace render::radiosity;
    const Options d = parse({"s.pov"});
    EXPECT_FALSE(d.radiosity.enabled.has_value());
    EXPECT_EQ(d.radiosity.method, Method::Auto);
    EXPECT_EQ(d.radiosity.display, DisplayMode::Preview);
    const Options o = parse({"s.pov", "Radiosity=off", "radiosity_method=Gauss_Seidel",
                             "Radiosity_Bounces=0", "Radiosity_Patch_Size=2.5",
                             "Radiosity_Form_Factors=hemicube", "Radiosity_FF_Rays=64",
                             "Radiosity_Hemicube_Res=32", "Radiosity_Gather_Rays=100",
                             "Radiosity_Cache_Error=0.2", "Radiosity_Display=gather",
                             "Radiosity_Tolerance=1e-3", "+RFsol.rad", "+RFI", "+RFO", "+R4",
                             "Radiosity_Subdivide=off", "Radiosity_Subdivide_Tolerance=0.3",
                             "Radiosity_Min_Element=0.25", "Radiosity_Subdivide_Budget=2",
                             "Radiosity_Min_Pixels=1.5"});
    EXPECT_EQ(o.radiosity.enabled, false);
    EXPECT_EQ(o.radiosity.method, Method::GaussSeidel);
    EXPECT_EQ(o.radiosity.bounces, 0);
    EXPECT_DOUBLE_EQ(o.radiosity.patch_size, 2.5);
    EXPECT_EQ(o.radiosity.form_factors, FormFactorMethod::Hemicube);
    EXPECT_EQ(o.radiosity.ff_rays, 64);
    EXPECT_EQ(o.radiosity.hemicube_res, 32);
    EXPECT_EQ(o.radiosity.gather_rays, 100);
    EXPECT_DOUBLE_EQ(*o.radiosity.cache_error, 0.2);
    EXPECT_EQ(o.radiosity.display, DisplayMode::Gather);
    EXPECT_DOUBLE_EQ(o.radiosity.tolerance, 1e-3);
    EXPECT_EQ(o.radiosity.file, "sol.rad");
    EXPECT_TRUE(o.radiosity.from_file);
    EXPECT_TRUE(o.radiosity.to_file);
    EXPECT_EQ(o.render.aa_depth, 4);  // +R is still the anti-aliasing depth
    EXPECT_TRUE(d.radiosity.subdivision.enabled);
    EXPECT_FALSE(o.radiosity.subdivision.enabled);
    EXPECT_DOUBLE_EQ(o.radiosity.subdivision.tolerance, 0.3);
    EXPECT_DOUBLE_EQ(o.radiosity.subdivision.min_element, 0.25);
    EXPECT_DOUBLE_EQ(o.radiosity.subdivision.budget, 2);
    EXPECT_DOUBLE_EQ(d.radiosity.subdivision.min_pixels, 3);
    EXPECT_DOUBLE_EQ(o.radiosity.subdivision.min_pixels, 1.5);
    EXPECT_NE(error_of({"s.pov", "Radiosity_Method=lu"}).message.find("auto, matrix"),
              std::string::npos);
    EXPECT_NE(error_of({"s.pov", "Radiosity_Patch_Size=0"}).message.find("positive"),
              std::string::npos);
    EXPECT_NE(error_of({"s.pov", "Radiosity_Bounces=-1"}).message.find(">= 0"),
              std::string::npos);
}

TEST(Frames, StillImageOutputName) {
    Options o = parse({"dir/my.scene.pov"});
    EXPECT_EQ(output_path(o, 0), "my.scene.png");
    o = parse({"a.pov", "+FP"});
    EXPECT_EQ(output_path(o, 0), "a.ppm");
    o = parse({"a.pov", "+Oout/"});
    EXPECT_EQ(output_path(o, 0), "out/a.png");
    o = parse({"a.pov", "+Opic"});
    EXPECT_EQ(output_path(o, 0), "pic.png");
    const auto frames = plan_frames(parse({"a.pov", "+K0.1", "+W50", "+H40"}));
    ASSERT_EQ(frames.size(), 1u);
    EXPECT_EQ(frames[0].output, "a.png");
    EXPECT_EQ(frames[0].scene.clock, double(0.1f));  // the clock is a 32-bit float
    EXPECT_EQ(frames[0].scene.image_width, 50);
    EXPECT_EQ(frames[0].scene.image_height, 40);
    EXPECT_FALSE(frames[0].scene.clock_on);
}

TEST(Frames, AnimationClocksAndNames) {
    // VERIFIED in POV: +KFI1 +KFF3 gives clocks 0, 0.5, 1 in name1 .. name3.
    auto frames = plan_frames(parse({"name.pov", "+KFI1", "+KFF3", "+FP"}));
    ASSERT_EQ(frames.size(), 3u);
    EXPECT_EQ(frames[0].output, "name1.ppm");
    EXPECT_EQ(frames[2].output, "name3.ppm");
    EXPECT_DOUBLE_EQ(frames[0].scene.clock, 0.0);
    EXPECT_DOUBLE_EQ(frames[1].scene.clock, 0.5);
    EXPECT_DOUBLE_EQ(frames[2].scene.clock, 1.0);
    EXPECT_EQ(frames[1].scene.frame_number, 2);
    EXPECT_TRUE(frames[1].scene.clock_on);
    // Zero-padded to the digits of the final frame; clock_delta printed with 6 digits.
    frames = plan_frames(parse({"a.pov", "+KFI1", "+KFF12", "+SF9", "+EF10", "+Oanim.png"}));
    ASSERT_EQ(frames.size(), 2u);
    EXPECT_EQ(frames[0].output, "anim09.png");
    EXPECT_EQ(frames[1].output, "anim10.png");
    frames = plan_frames(parse({"a.pov", "+KFI1", "+KFF4"}));
    EXPECT_DOUBLE_EQ(frames[0].scene.clock_delta, 0.333333);
    EXPECT_EQ(error_of({"a.pov", "+KFI5", "+KFF2"}).message,
              "Final_Frame 2 is before Initial_Frame 5");
}

}  // namespace
}  // namespace lumen::cli
