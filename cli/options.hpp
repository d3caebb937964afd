// Everything the command line and INI files can set (POV-Ray 3.7's rules). Switches are
// translated to INI keys, so every setting has exactly one parser: apply_ini_option.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "interp/interpret.hpp"
#include "base/source.hpp"
#include "render/image_output.hpp"
#include "render/radiosity/options.hpp"
#include "render/render.hpp"

namespace lumen::cli {

struct Options {
    std::string input;   // Input_File_Name
    std::string output;  // Output_File_Name; empty = input base name in the current folder
    bool output_to_file = true;

    render::RenderOptions render;  // size, AA, threads, block size, quality
    render::OutputOptions image;   // file type, bits, alpha, file gamma
    interp::InterpOptions scene;   // library paths, Declare=, Version=
    render::radiosity::RadiosityOptions radiosity;  // Radiosity_* keys

    // Partial render exactly as given: a fraction or a 1-based index (resolved by pixel_range).
    std::optional<double> start_row, end_row, start_col, end_col;
    // Output_Crop (lumen's): a partial render's file holds its area alone rather than the
    // whole image with zero margins (POV-Ray's way); lumen farm's tiles, joined by lumen merge.
    bool crop_output = false;

    // Animation. The clock is only used when no frame range is given.
    double clock = 0.0;
    int initial_frame = 1, final_frame = 1;
    double initial_clock = 0.0, final_clock = 1.0;
    bool cyclic = false;
    std::optional<int> subset_start, subset_end;

    // What to do instead of (or around) rendering.
    bool help = false, version = false, dump_scene = false, check = false;
    bool radiosity_only = false;  // --radiosity-only: solve (and save) each frame's radiosity
    bool verbose = false;
    // The process exits once the run is over (main's run, not a test's): what only the exit
    // would free may be left to it (interp::InterpOptions::leave_for_exit).
    bool process_ends = false;

    // Accepted for compatibility but with no effect (Display, Pause_When_Done, ...): noted so
    // the user learns they were ignored.
    std::vector<std::string> notes;
};

// Resolves a Start_/End_ value against the image extent `size`: 0 <= v < 1 (start) or
// 0 <= v <= 1 (end) is a fraction, otherwise a 1-based index. Returns a 0-based pixel index,
// clamped to the image.
int resolve_start(std::optional<double> v, int size);
int resolve_end(std::optional<double> v, int size);

// The render options with the partial-render window filled in.
render::RenderOptions effective_render_options(const Options& o);

// Sets one INI option (`key` is case-insensitive). Throws LumenError at `loc` for an unknown key
// (with a did-you-mean hint) or a bad value. `sources` owns included INI files (Include_Ini).
void apply_ini_option(Options& o, const std::string& key, const std::string& value,
                      const SourceLoc& loc, SourceManager& sources, int ini_depth = 0);

// Every INI key lumen knows, in its canonical spelling (for suggestions and --help).
const std::vector<std::string>& known_ini_keys();

// Parses a boolean INI value: on/true/yes/1 and off/false/no/0 (case-insensitive).
bool parse_bool(const std::string& text, const std::string& key, const SourceLoc& loc);

}  // namespace lumen::cli
