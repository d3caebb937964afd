// The table of INI keys (POV-Ray 3.7 names) and how each one sets Options.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>

#include "cli/ini_file.hpp"
#include "cli/options.hpp"
#include "cli/text.hpp"
#include "base/diagnostics.hpp"

namespace lumen::cli {
namespace {

// One option value being applied, with what is needed to report a bad one.
struct Setting {
    const std::string& key;
    std::string text;  // unquoted, trimmed (Declare keeps its quotes)
    const SourceLoc& loc;
    SourceManager& sources;
    int depth;
};

[[noreturn]] void bad_value(const Setting& s, const char* expected) {
    throw LumenError(s.loc, "invalid value '" + s.text + "' for " + s.key + ": expected " + expected);
}

double to_double(const Setting& s) {
    char* end = nullptr;
    const double v = std::strtod(s.text.c_str(), &end);
    if (s.text.empty() || *end != '\0' || !std::isfinite(v)) bad_value(s, "a number");
    return v;
}

int to_int(const Setting& s) {
    const double v = to_double(s);
    if (v != std::floor(v) || std::fabs(v) > 1e9) bad_value(s, "an integer");
    return int(v);
}

int to_int_at_least(const Setting& s, int min) {
    const int v = to_int(s);
    if (v < min) bad_value(s, ("an integer >= " + std::to_string(min)).c_str());
    return v;
}

bool to_bool(const Setting& s) { return parse_bool(s.text, s.key, s.loc); }

// POV passes command-line numbers through a 32-bit float and prints them with 6 significant
// digits before the scene sees them (POV-Ray 3.7 checked with Declare=Foo=0.123456789).
double as_scene_float(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", double(float(v)));
    return std::strtod(buf, nullptr);
}

void set_file_type(Options& o, const Setting& s) {
    // Type letter, an optional 'g' (greyscale, written as colour here), then the bit depth.
    std::string t = lower(s.text);
    if (t.empty()) return;  // plain +F keeps the current type
    const char letter = t[0];
    size_t i = 1;
    if (i < t.size() && t[i] == 'g') ++i;
    switch (letter) {
        case 'n': case 's': o.image.type = render::FileType::PNG; break;
        case 'p': o.image.type = render::FileType::PPM; break;
        case 'e': o.image.type = render::FileType::EXR; break;
        case 'h': o.image.type = render::FileType::HDR; break;
        // lumen has no Targa writer: Targa (T, C) requests get an uncompressed TIFF.
        case 't': case 'c': o.image.type = render::FileType::TIFF; break;
        default:
            throw LumenError(s.loc, "output file type '" + s.text + "' is not supported",
                             "lumen writes N (PNG), P (PPM), E (OpenEXR), H (Radiance HDR) and "
                             "T (TIFF)");
    }
    if (i < t.size()) {
        Setting bits{s.key, t.substr(i), s.loc, s.sources, s.depth};
        const int b = to_int(bits);
        if (b < 5 || b > 16) bad_value(s, "a bit depth from 5 to 16");
        o.image.bits = b > 8 ? 16 : 8;
    }
}

void add_declare(Options& o, const Setting& s) {
    const size_t eq = s.text.find('=');
    const std::string name = trim(s.text.substr(0, std::min(eq, s.text.size())));
    const bool ident = !name.empty() && !std::isdigit(static_cast<unsigned char>(name[0])) &&
                       std::all_of(name.begin(), name.end(), [](char c) {
                           return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
                       });
    if (eq == std::string::npos || !ident)
        throw LumenError(s.loc, "Declare needs NAME=value, got '" + s.text + "'");
    const std::string value = trim(s.text.substr(eq + 1));
    interp::InterpOptions::Declare d;
    d.name = name;
    if (value.size() >= 2 && value.front() == '"' && value.back() == '"') {
        d.text = value.substr(1, value.size() - 2);
    } else {
        Setting num{s.key, value, s.loc, s.sources, s.depth};
        d.number = as_scene_float(to_double(num));
    }
    // A later Declare of the same name replaces the earlier one.
    auto& ds = o.scene.declares;
    ds.erase(std::remove_if(ds.begin(), ds.end(), [&](const auto& x) { return x.name == name; }),
             ds.end());
    ds.push_back(std::move(d));
}

void set_file_gamma(Options& o, const Setting& s) {
    if (iequals(s.text, "srgb")) {
        o.image.file_gamma = -1.0;
        return;
    }
    const double g = to_double(s);
    if (g <= 0) bad_value(s, "a positive number or sRGB");
    o.image.file_gamma = g;
}

void ignored(Options& o, const Setting& s) {
    o.notes.push_back(s.loc.str() + ": note: " + s.key + " has no effect in lumen");
}

void accepted(Options&, const Setting&) {}

// One of `names` (case-insensitive), as its index.
int choice(const Setting& s, std::initializer_list<const char*> names, const char* expected) {
    int i = 0;
    for (const char* n : names) {
        if (iequals(s.text, n)) return i;
        ++i;
    }
    bad_value(s, expected);
}

// lumen's radiosity keys (README "Radiosity"); POV's own +RF keys name the patch solution file.
void set_radiosity_method(Options& o, const Setting& s) {
    using M = render::radiosity::Method;
    static const M methods[] = {M::Auto, M::Matrix, M::Jacobi, M::GaussSeidel, M::Progressive};
    o.radiosity.method = methods[choice(s, {"auto", "matrix", "jacobi", "gauss_seidel", "progressive"},
                                        "auto, matrix, jacobi, gauss_seidel or progressive")];
}

void set_form_factors(Options& o, const Setting& s) {
    using F = render::radiosity::FormFactorMethod;
    static const F methods[] = {F::RayCast, F::Analytic, F::Hemicube};
    o.radiosity.form_factors =
        methods[choice(s, {"raycast", "analytic", "hemicube"}, "raycast, analytic or hemicube")];
}

void set_radiosity_display(Options& o, const Setting& s) {
    using D = render::radiosity::DisplayMode;
    o.radiosity.display = choice(s, {"gather", "preview"}, "gather or preview") ? D::Preview : D::Gather;
}

double to_positive(const Setting& s) {
    const double v = to_double(s);
    if (!(v > 0)) bad_value(s, "a positive number");
    return v;
}

double to_nonnegative(const Setting& s) {
    const double v = to_double(s);
    if (!(v >= 0) || !std::isfinite(v)) bad_value(s, "a number from 0 up");
    return v;
}

// A count for the evaluation limits: a whole number from 1 up.
double to_count(const Setting& s) {
    const double v = to_double(s);
    if (v != std::floor(v) || v < 1 || v > 1e15) bad_value(s, "a whole number from 1 to 1e15");
    return v;
}

struct IniKey {
    const char* name;
    void (*set)(Options&, const Setting&);
};

// Keep this table in POV-Ray's spelling: the names are shown in suggestions.
const IniKey kKeys[] = {
    {"Width", [](Options& o, const Setting& s) { o.render.width = to_int_at_least(s, 1); }},
    {"Height", [](Options& o, const Setting& s) { o.render.height = to_int_at_least(s, 1); }},
    {"Input_File_Name", [](Options& o, const Setting& s) { o.input = s.text; }},
    {"Output_File_Name", [](Options& o, const Setting& s) { o.output = s.text; }},
    {"Output_To_File", [](Options& o, const Setting& s) { o.output_to_file = to_bool(s); }},
    {"Output_File_Type", set_file_type},
    {"Output_Alpha", [](Options& o, const Setting& s) { o.image.alpha = to_bool(s); }},
    {"Bits_Per_Color",
     [](Options& o, const Setting& s) {
         const int b = to_int(s);
         if (b < 5 || b > 16) bad_value(s, "a bit depth from 5 to 16");
         o.image.bits = b > 8 ? 16 : 8;
     }},
    {"File_Gamma", set_file_gamma},
    {"Display_Gamma", accepted},  // only affects the preview window, which lumen lacks
    {"Antialias", [](Options& o, const Setting& s) { o.render.antialias = to_bool(s); }},
    {"Antialias_Threshold",
     [](Options& o, const Setting& s) { o.render.aa_threshold = std::max(0.0, to_double(s)); }},
    {"Sampling_Method",
     [](Options& o, const Setting& s) {
         const int m = to_int(s);
         if (m != 1 && m != 2) bad_value(s, "1 or 2");
         o.render.aa_method = m;
     }},
    {"Antialias_Depth",
     [](Options& o, const Setting& s) { o.render.aa_depth = std::clamp(to_int(s), 1, 9); }},
    {"Jitter", [](Options& o, const Setting& s) { o.render.jitter = to_bool(s); }},
    {"Jitter_Amount",
     [](Options& o, const Setting& s) {
         o.render.jitter_amount = std::clamp(to_double(s), 0.0, 1.0);
     }},
    {"Antialias_Gamma", [](Options& o, const Setting& s) { o.render.aa_gamma = to_double(s); }},
    {"Quality", [](Options& o, const Setting& s) { o.render.quality = std::clamp(to_int(s), 0, 9); }},
    {"Start_Row", [](Options& o, const Setting& s) { o.start_row = to_double(s); }},
    {"End_Row", [](Options& o, const Setting& s) { o.end_row = to_double(s); }},
    {"Start_Column", [](Options& o, const Setting& s) { o.start_col = to_double(s); }},
    {"End_Column", [](Options& o, const Setting& s) { o.end_col = to_double(s); }},
    {"Clock", [](Options& o, const Setting& s) { o.clock = to_double(s); }},
    {"Initial_Frame", [](Options& o, const Setting& s) { o.initial_frame = to_int(s); }},
    {"Final_Frame", [](Options& o, const Setting& s) { o.final_frame = to_int(s); }},
    {"Initial_Clock", [](Options& o, const Setting& s) { o.initial_clock = to_double(s); }},
    {"Final_Clock", [](Options& o, const Setting& s) { o.final_clock = to_double(s); }},
    {"Cyclic_Animation", [](Options& o, const Setting& s) { o.cyclic = to_bool(s); }},
    {"Subset_Start_Frame", [](Options& o, const Setting& s) { o.subset_start = to_int(s); }},
    {"Subset_End_Frame", [](Options& o, const Setting& s) { o.subset_end = to_int(s); }},
    {"Work_Threads",
     [](Options& o, const Setting& s) { o.render.threads = to_int_at_least(s, 1); }},
    {"Render_Block_Size",
     [](Options& o, const Setting& s) { o.render.block_size = std::max(4, to_int(s)); }},
    {"Version",
     [](Options& o, const Setting& s) {
         const double v = to_double(s);
         if (v < 1.0 || v > 3.8) bad_value(s, "a language version such as 3.7");
         o.scene.version = v;
     }},
    {"Library_Path",
     [](Options& o, const Setting& s) {
         if (s.text.empty()) bad_value(s, "a folder");
         o.scene.library_paths.push_back(s.text);
     }},
    {"Permitted_Path",  // lumen's: #fopen may also read and write under this folder
     [](Options& o, const Setting& s) {
         if (s.text.empty()) bad_value(s, "a folder");
         o.scene.io_folders.push_back(s.text);
     }},
    {"Declare", add_declare},
    {"Include_Ini",
     [](Options& o, const Setting& s) { read_ini_file(o, s.sources, s.text, s.loc, s.depth + 1); }},
    {"Verbose", [](Options& o, const Setting& s) { o.verbose = to_bool(s); }},
    // lumen's evaluation limits (interp/interpret.hpp), named by the errors they give.
    {"Max_Loop_Iterations",
     [](Options& o, const Setting& s) { o.scene.max_loop_iterations = (long long)to_count(s); }},
    {"Max_Eval_Steps", [](Options& o, const Setting& s) { o.scene.max_steps = (long long)to_count(s); }},
    {"Max_String_Length",
     [](Options& o, const Setting& s) { o.scene.max_string_length = size_t(to_count(s)); }},
    {"Max_Array_Elements",
     [](Options& o, const Setting& s) { o.scene.max_array_elements = size_t(to_count(s)); }},
    {"Max_Eval_Memory",  // MiB
     [](Options& o, const Setting& s) { o.scene.max_memory = size_t(to_count(s)) << 20; }},
    {"Radiosity",
     [](Options& o, const Setting& s) { o.radiosity.enabled = to_bool(s); }},
    {"Radiosity_Method", set_radiosity_method},
    {"Radiosity_Bounces",
     [](Options& o, const Setting& s) { o.radiosity.bounces = to_int_at_least(s, 0); }},
    {"Radiosity_Patch_Size",
     [](Options& o, const Setting& s) { o.radiosity.patch_size = to_positive(s); }},
    {"Radiosity_Form_Factors", set_form_factors},
    {"Radiosity_FF_Rays",
     [](Options& o, const Setting& s) { o.radiosity.ff_rays = to_int_at_least(s, 1); }},
    {"Radiosity_Hemicube_Res",
     [](Options& o, const Setting& s) { o.radiosity.hemicube_res = to_int_at_least(s, 2); }},
    {"Radiosity_Gather_Rays",
     [](Options& o, const Setting& s) { o.radiosity.gather_rays = to_int_at_least(s, 1); }},
    {"Radiosity_Cache_Error",
     [](Options& o, const Setting& s) { o.radiosity.cache_error = to_positive(s); }},
    {"Radiosity_Display", set_radiosity_display},
    {"Radiosity_Subdivide",
     [](Options& o, const Setting& s) { o.radiosity.subdivision.enabled = to_bool(s); }},
    {"Radiosity_Subdivide_Tolerance",
     [](Options& o, const Setting& s) { o.radiosity.subdivision.tolerance = to_positive(s); }},
    {"Radiosity_Subdivide_Budget",
     [](Options& o, const Setting& s) { o.radiosity.subdivision.budget = to_positive(s); }},
    {"Radiosity_Max_Span",
     [](Options& o, const Setting& s) { o.radiosity.subdivision.max_span = to_nonnegative(s); }},
    {"Radiosity_Min_Pixels",
     [](Options& o, const Setting& s) { o.radiosity.subdivision.min_pixels = to_positive(s); }},
    {"Radiosity_Min_Element",
     [](Options& o, const Setting& s) { o.radiosity.subdivision.min_element = to_positive(s); }},
    {"Radiosity_Tolerance",
     [](Options& o, const Setting& s) { o.radiosity.tolerance = to_positive(s); }},
    {"Radiosity_File_Name", [](Options& o, const Setting& s) { o.radiosity.file = s.text; }},
    {"Radiosity_From_File",
     [](Options& o, const Setting& s) { o.radiosity.from_file = to_bool(s); }},
    {"Radiosity_To_File", [](Options& o, const Setting& s) { o.radiosity.to_file = to_bool(s); }},
    {"Output_Crop", [](Options& o, const Setting& s) { o.crop_output = to_bool(s); }},
    {"Radiosity_Store", [](Options& o, const Setting& s) { o.radiosity.store = s.text; }},
    {"Radiosity_Vain_Pretrace", accepted},  // lumen has no pretrace
    // Accepted so POV-Ray INI files load; they change nothing in lumen's output.
    {"Display", accepted},
    {"Pause_When_Done", accepted},
    {"All_Console", accepted},
    {"All_File", accepted},
    {"Debug_Console", accepted},
    {"Fatal_Console", accepted},
    {"Render_Console", accepted},
    {"Statistic_Console", accepted},
    {"Warning_Console", accepted},
    {"Bounding", accepted},
    {"Bounding_Threshold", accepted},
    {"Bounding_Method", accepted},
    {"Remove_Bounds", accepted},
    {"Split_Unions", accepted},
    {"Light_Buffer", accepted},
    {"Vista_Buffer", accepted},
    {"Draw_Vistas", accepted},
    {"Test_Abort", accepted},
    {"Test_Abort_Count", accepted},
    {"High_Reproducibility", accepted},  // lumen is always reproducible
    {"Render_Pattern", accepted},        // the pixel order does not change the image
    {"Preview_Start_Size", accepted},
    {"Preview_End_Size", accepted},
    {"Dither", ignored},
    {"Dither_Method", ignored},
    {"Include_Header", ignored},
    {"Continue_Trace", ignored},
    {"Create_Ini", ignored},
    {"Field_Render", ignored},
    {"Odd_Field", ignored},
};

}  // namespace

bool parse_bool(const std::string& text, const std::string& key, const SourceLoc& loc) {
    const std::string t = lower(trim(text));
    if (t == "on" || t == "true" || t == "yes" || t == "1") return true;
    if (t == "off" || t == "false" || t == "no" || t == "0") return false;
    throw LumenError(loc, "invalid value '" + text + "' for " + key +
                              ": expected on/off, true/false, yes/no or 1/0");
}

const std::vector<std::string>& known_ini_keys() {
    static const std::vector<std::string> keys = [] {
        std::vector<std::string> k;
        for (const IniKey& e : kKeys) k.push_back(e.name);
        return k;
    }();
    return keys;
}

void apply_ini_option(Options& o, const std::string& key, const std::string& value,
                      const SourceLoc& loc, SourceManager& sources, int ini_depth) {
    const std::string wanted = lower(trim(key));
    for (const IniKey& e : kKeys) {
        if (lower(e.name) != wanted) continue;
        const std::string v = trim(value);
        // Declare keeps its quotes: they mark a string value.
        Setting s{e.name, wanted == "declare" ? v : unquote(v), loc, sources, ini_depth};
        e.set(o, s);
        return;
    }
    std::vector<std::string> lowered;
    for (const std::string& k : known_ini_keys()) lowered.push_back(lower(k));
    const std::string match = closest_match(wanted, lowered);
    std::string hint;
    if (!match.empty()) {
        const auto at = std::find(lowered.begin(), lowered.end(), match) - lowered.begin();
        hint = "did you mean '" + known_ini_keys()[size_t(at)] + "'?";
    }
    throw LumenError(loc, "unknown option '" + trim(key) + "'", hint);
}

}  // namespace lumen::cli
