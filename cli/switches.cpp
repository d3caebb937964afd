// The switch table: each switch is a spelling of one or two INI keys.
#include "cli/switches.hpp"

#include <cctype>

#include "cli/text.hpp"
#include "base/diagnostics.hpp"

namespace lumen::cli {
namespace {

enum class Kind {
    Flag,       // +X on, -X off, no parameter
    Value,      // +Xv sets key = v; the parameter is required
    FlagValue,  // +X[v]: key on (and value_key = v when given); -X: key off
};

struct Switch {
    const char* name;  // matched case-insensitively, in table order
    Kind kind;
    const char* key;
    const char* value_key;  // FlagValue only; null when the parameter is ignored
    const char* help;
};

// Longer names come before their prefixes ("AM" before "A", "KFI" before "KF" before "K").
const Switch kSwitches[] = {
    {"AM", Kind::Value, "Sampling_Method", nullptr, "anti-aliasing method 1 or 2"},
    {"AG", Kind::Value, "Antialias_Gamma", nullptr, "anti-aliasing gamma (2.5)"},
    {"A", Kind::FlagValue, "Antialias", "Antialias_Threshold", "anti-alias [threshold, 0.3]"},
    {"BS", Kind::Value, "Render_Block_Size", nullptr, "render block size (32)"},
    {"D", Kind::FlagValue, "Display", nullptr, "preview window (accepted, none shown)"},
    {"EC", Kind::Value, "End_Column", nullptr, "last column: fraction or 1-based index"},
    {"ER", Kind::Value, "End_Row", nullptr, "last row: fraction or 1-based index"},
    {"EF", Kind::Value, "Subset_End_Frame", nullptr, "last frame of the subset to render"},
    {"F", Kind::FlagValue, "Output_To_File", "Output_File_Type",
     "write a file of type N[bits] P E H T (PNG PPM EXR HDR TIFF); -F writes none"},
    {"GA", Kind::FlagValue, "All_Console", "All_File", "message streams (accepted)"},
    {"HR", Kind::Flag, "High_Reproducibility", nullptr, "(accepted: lumen is deterministic)"},
    {"HI", Kind::Value, "Include_Header", nullptr, "include header (ignored)"},
    {"H", Kind::Value, "Height", nullptr, "image height in pixels"},
    {"I", Kind::Value, "Input_File_Name", nullptr, "input scene file"},
    {"J", Kind::FlagValue, "Jitter", "Jitter_Amount", "anti-aliasing jitter [amount, 1.0]"},
    {"KFI", Kind::Value, "Initial_Frame", nullptr, "first animation frame"},
    {"KFF", Kind::Value, "Final_Frame", nullptr, "last animation frame"},
    {"KC", Kind::Flag, "Cyclic_Animation", nullptr, "cyclic animation"},
    {"KI", Kind::Value, "Initial_Clock", nullptr, "clock at the first frame (0)"},
    {"KF", Kind::Value, "Final_Clock", nullptr, "clock at the last frame (1)"},
    {"K", Kind::Value, "Clock", nullptr, "clock value of a still image"},
    {"L", Kind::Value, "Library_Path", nullptr, "add an include folder"},
    {"MV", Kind::Value, "Version", nullptr, "initial language version"},
    {"O", Kind::Value, "Output_File_Name", nullptr, "output file (or folder ending in /)"},
    {"P", Kind::Flag, "Pause_When_Done", nullptr, "(accepted)"},
    {"Q", Kind::Value, "Quality", nullptr, "quality 0..9 (9)"},
    {"RP", Kind::Value, "Render_Pattern", nullptr, "(accepted)"},
    {"RFI", Kind::Flag, "Radiosity_From_File", nullptr, "load the radiosity patch solution"},
    {"RFO", Kind::Flag, "Radiosity_To_File", nullptr, "save the radiosity patch solution"},
    {"RF", Kind::Value, "Radiosity_File_Name", nullptr, "radiosity solution file"},
    {"RVP", Kind::Flag, "Radiosity_Vain_Pretrace", nullptr, "(accepted)"},
    {"R", Kind::Value, "Antialias_Depth", nullptr, "anti-aliasing depth 1..9 (3)"},
    {"SC", Kind::Value, "Start_Column", nullptr, "first column: fraction or 1-based index"},
    {"SR", Kind::Value, "Start_Row", nullptr, "first row: fraction or 1-based index"},
    {"SF", Kind::Value, "Subset_Start_Frame", nullptr, "first frame of the subset to render"},
    {"UA", Kind::Flag, "Output_Alpha", nullptr, "write an alpha channel"},
    {"V", Kind::Flag, "Verbose", nullptr, "verbose messages"},
    {"WT", Kind::Value, "Work_Threads", nullptr, "render threads (all cores)"},
    {"W", Kind::Value, "Width", nullptr, "image width in pixels"},
    {"X", Kind::FlagValue, "Test_Abort", nullptr, "(accepted)"},
};

std::string letters_of(const std::string& body) {
    std::string s;
    for (char c : body) {
        if (!std::isalpha(static_cast<unsigned char>(c))) break;
        s += char(std::toupper(static_cast<unsigned char>(c)));
    }
    return s;
}

[[noreturn]] void unknown_switch(const std::string& arg, const SourceLoc& loc) {
    const std::string sign(1, arg[0]);
    const std::string name = letters_of(arg.substr(1));
    std::string hint;
    // Single letters are all one edit apart: only suggest for longer names.
    if (name.size() >= 2) {
        std::vector<std::string> names;
        for (const Switch& s : kSwitches) names.push_back(s.name);
        const std::string m = closest_match(name, names);
        if (!m.empty()) hint = "did you mean '" + sign + m + "'?";
    }
    throw LumenError(loc, "unknown switch '" + arg + "'", hint);
}

}  // namespace

void apply_switch(Options& o, SourceManager& sources, const std::string& arg, const SourceLoc& loc,
                  int ini_depth) {
    if (arg.size() < 2 || (arg[0] != '+' && arg[0] != '-'))
        throw LumenError(loc, "'" + arg + "' is not a switch");
    const bool on = arg[0] == '+';
    const std::string body = arg.substr(1);
    for (const Switch& s : kSwitches) {
        const std::string name = s.name;
        if (body.size() < name.size() || !iequals(body.substr(0, name.size()), name)) continue;
        const std::string param = body.substr(name.size());
        const std::string shown = arg.substr(0, 1 + name.size());
        switch (s.kind) {
            case Kind::Flag:
                if (!param.empty())
                    throw LumenError(loc, "switch '" + shown + "' takes no value, got '" + arg + "'");
                apply_ini_option(o, s.key, on ? "on" : "off", loc, sources, ini_depth);
                return;
            case Kind::Value:
                if (param.empty()) throw LumenError(loc, "switch '" + shown + "' needs a value");
                apply_ini_option(o, s.key, param, loc, sources, ini_depth);
                return;
            case Kind::FlagValue:
                apply_ini_option(o, s.key, on ? "on" : "off", loc, sources, ini_depth);
                if (!param.empty() && s.value_key)
                    apply_ini_option(o, s.value_key, param, loc, sources, ini_depth);
                return;
        }
    }
    unknown_switch(arg, loc);
}

std::string switch_help() {
    std::string out;
    for (const Switch& s : kSwitches) {
        std::string left = std::string("  +") + s.name;
        if (s.kind == Kind::Value) left += "<v>";
        if (s.kind == Kind::FlagValue && s.value_key) left += "[v]";
        left.resize(std::max<size_t>(left.size() + 1, 10), ' ');
        out += left + s.help + "  [" + s.key + "]\n";
    }
    return out;
}

}  // namespace lumen::cli
