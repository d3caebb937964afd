#include "cli/command_line.hpp"

#include "cli/ini_file.hpp"
#include "cli/switches.hpp"
#include "cli/text.hpp"
#include "base/diagnostics.hpp"

namespace lumen::cli {
namespace {

const std::vector<std::string> kLongOptions = {"--help", "--version", "--dump-scene", "--check",
                                               "--threads", "--radiosity-only"};

// Rejects settings that make no sense together, once everything has been read.
void validate(const Options& o) {
    const SourceLoc cmd;
    if (o.input.empty())
        throw LumenError(cmd, "no input file", "usage: lumen scene.pov [options] [file.ini ...]");
    const render::RenderOptions r = effective_render_options(o);
    if (r.start_row > r.end_row) throw LumenError(cmd, "Start_Row is after End_Row");
    if (r.start_col > r.end_col) throw LumenError(cmd, "Start_Column is after End_Column");
    if (o.final_frame < o.initial_frame)
        throw LumenError(cmd, "Final_Frame " + std::to_string(o.final_frame) +
                                  " is before Initial_Frame " + std::to_string(o.initial_frame));
}

}  // namespace

void apply_argument(Options& o, SourceManager& sources, const std::string& word,
                    const SourceLoc& loc, int ini_depth) {
    if (word.empty()) return;
    if (word[0] == '+' || word[0] == '-') {
        apply_switch(o, sources, word, loc, ini_depth);
        return;
    }
    const size_t eq = word.find('=');
    if (eq != std::string::npos && word[0] != '"') {
        apply_ini_option(o, word.substr(0, eq), word.substr(eq + 1), loc, sources, ini_depth);
        return;
    }
    const std::string file = unquote(word);
    if (ends_with_nocase(file, ".pov")) {
        o.input = file;
    } else if (file.back() == '/') {
        o.scene.library_paths.push_back(file);
    } else {
        read_ini_file(o, sources, file, loc, ini_depth + 1);
    }
}

Options parse_command_line(const std::vector<std::string>& args, SourceManager& sources) {
    Options o;
    const SourceLoc cmd;  // "<command line>"
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a.rfind("--", 0) != 0) {
            apply_argument(o, sources, a, cmd);
            continue;
        }
        const std::string name = a.substr(0, a.find('='));
        if (name == "--help") {
            o.help = true;
        } else if (name == "--version") {
            o.version = true;
        } else if (name == "--dump-scene") {
            o.dump_scene = true;
        } else if (name == "--check") {
            o.check = true;
        } else if (name == "--radiosity-only") {
            o.radiosity_only = true;
        } else if (name == "--threads") {
            std::string n;
            if (a.size() > name.size()) {
                n = a.substr(name.size() + 1);
            } else if (i + 1 < args.size()) {
                n = args[++i];
            } else {
                throw LumenError(cmd, "--threads needs a number");
            }
            apply_ini_option(o, "Work_Threads", n, cmd, sources);
        } else {
            throw LumenError(cmd, "unknown option '" + a + "'", did_you_mean(name, kLongOptions));
        }
    }
    if (!o.help && !o.version) validate(o);
    return o;
}

std::string usage_text() {
    return "usage: lumen scene.pov [options] [file.ini[Section] ...]\n"
           "\n"
           "Renders a POV-Ray 3.7 scene. Options follow POV-Ray: +X turns switch X on or sets it,\n"
           "-X turns it off, Key=Value sets an INI option, other words are INI files (or library\n"
           "folders when they end in /). Default output: the scene's base name + .png here.\n"
           "\n"
           "lumen options:\n"
           "  --help           this text\n"
           "  --version        print the version\n"
           "  --dump-scene     print the evaluated scene as JSON and do not render\n"
           "  --check          list the features lumen does not support yet (exit 1 if any)\n"
           "  --threads N      same as +WTN\n"
           "  --radiosity-only solve each frame's radiosity and save it (+RF +RFO or\n"
           "                   Radiosity_Store=DIR); render nothing\n"
           "\n"
           "  lumen farm ...   render in parts, locally or on a Slurm cluster (lumen farm --help)\n"
           "  lumen merge ...  join partial renders into one image (lumen merge --help)\n"
           "\n"
           "switches [INI key]:\n" +
           switch_help() +
           "\n"
           "INI-only keys include Declare=NAME=value, File_Gamma=, Bits_Per_Color=, "
           "Include_Ini=,\nOutput_Crop=on (lumen: a partial render's file holds its area alone).\n"
           "\n"
           "evaluation limits (an endless loop or runaway scene stops with an error naming one):\n"
           "  Max_Loop_Iterations=N (1e7 per loop), Max_Eval_Steps=N (1e8 loop iterations and\n"
           "  macro/function calls), Max_String_Length=N (16 MiB), Max_Array_Elements=N (1e7),\n"
           "  Max_Eval_Memory=MiB (half the memory, at most 8 GiB)\n"
           "\n"
           "radiosity (lumen's patch solution; README \"Radiosity\"):\n"
           "  Radiosity=on|off              force on (POV defaults) or ignore the scene's block\n"
           "  Radiosity_Method=auto|matrix|jacobi|gauss_seidel|progressive\n"
           "  Radiosity_Bounces=N           bounces (scene's recursion_limit; 0 = converge)\n"
           "  Radiosity_Patch_Size=S        largest element edge (from the scene bounds)\n"
           "  Radiosity_Form_Factors=raycast|analytic|hemicube, Radiosity_FF_Rays=N,\n"
           "  Radiosity_Hemicube_Res=R      form factor method, rays per vertex, resolution\n"
           "  Radiosity_Gather_Rays=N       final gather rays (from count)\n"
           "  Radiosity_Cache_Error=E       irradiance cache error (error_bound / 10)\n"
           "  Radiosity_Display=gather|preview  final gather or interpolated patches\n"
           "  Radiosity_Subdivide=on|off    split receiving elements where G changes (on)\n"
           "  Radiosity_Subdivide_Tolerance=T, Radiosity_Min_Element=S,\n"
           "  Radiosity_Subdivide_Budget=K  split threshold (0.2), smallest edge (patch/8),\n"
           "                                new vertices at most K x gathered ones (2)\n"
           "  Radiosity_Min_Pixels=P        no split of elements under P pixels across (3)\n"
           "  Radiosity_Max_Span=F          split elements seen wider than F x the image (1/8)\n"
           "  Radiosity_Tolerance=T         iterative/progressive stop\n"
           "  Radiosity_File_Name=F (+RF), Radiosity_From_File (+RFI), Radiosity_To_File (+RFO)\n"
           "                                load/save the patch solution\n"
           "  Radiosity_Store=DIR           solutions by scene: loaded when there, else saved\n";
}

}  // namespace lumen::cli
