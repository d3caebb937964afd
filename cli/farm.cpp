#include "cli/farm.hpp"

#include <cstdio>
#include <filesystem>
#include <thread>

#include "base/diagnostics.hpp"
#include "cli/command_line.hpp"
#include "cli/farm_process.hpp"
#include "cli/farm_run.hpp"
#include "cli/run.hpp"
#include "cli/text.hpp"
#include "render/object_queries.hpp"

namespace lumen::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* kUsage =
    "usage: lumen farm [farm options] scene.pov [lumen options]\n"
    "\n"
    "Renders in parts, each a lumen process of its own: a still in tiles (+SR/+ER/+SC/+EC)\n"
    "joined at the end, an animation in frame ranges (+SF/+EF). With radiosity, a first run\n"
    "solves it once for every part (Radiosity_Store). The files are those one lumen run\n"
    "writes, byte for byte.\n"
    "\n"
    "farm options:\n"
    "  --parts=N          tiles of a still, or frame ranges of an animation (16)\n"
    "  --jobs=N           parts at a time on this machine (1), each with a share of the cores\n"
    "  --slurm            submit the parts to Slurm (sbatch) and follow them (squeue)\n"
    "  --cpus-per-task=N  Slurm: CPUs (render threads) of each part (1)\n"
    "  --sbatch=ARG       Slurm: an extra sbatch argument (repeatable): --sbatch=--partition=x\n"
    "  --poll=SECONDS     Slurm: how often to ask squeue (1)\n"
    "  --work=DIR         parts, logs and scripts (the output's name + .farm); Slurm's nodes\n"
    "                     must see it and the scene at the same paths\n"
    "  --keep             keep the work folder after a successful run\n"
    "  --plan             print the plan as an sh script (each run a command line), and\n"
    "                     run nothing\n";

struct FarmCommand {
    FarmSettings settings;
    bool slurm = false, keep = false, help = false, print_plan = false;
    int jobs = 1;
    SlurmSettings slurm_settings;
    std::vector<std::string> lumen_args;
};

int to_count(const std::string& option, const std::string& value) {
    char* end = nullptr;
    const long n = std::strtol(value.c_str(), &end, 10);
    if (value.empty() || *end || n < 1 || n > 100000)
        throw LumenError({}, option + " needs a whole number from 1 to 100000, not '" + value + "'");
    return int(n);
}

FarmCommand parse_farm_args(const std::vector<std::string>& args) {
    static const std::vector<std::string> kOptions = {
        "--parts", "--jobs", "--slurm", "--cpus-per-task", "--sbatch", "--poll", "--work", "--keep", "--plan", "--help"};
    FarmCommand c;
    size_t i = 0;
    for (; i < args.size() && args[i].rfind("--", 0) == 0; ++i) {
        const std::string& a = args[i];
        const size_t eq = a.find('=');
        const std::string name = a.substr(0, eq);
        const std::string value = eq == std::string::npos ? std::string() : a.substr(eq + 1);
        if (name == "--parts") c.settings.parts = to_count(name, value);
        else if (name == "--jobs") c.jobs = to_count(name, value);
        else if (name == "--slurm") c.slurm = true;
        else if (name == "--cpus-per-task") c.slurm_settings.cpus_per_task = to_count(name, value);
        else if (name == "--sbatch") c.slurm_settings.sbatch_args.push_back(value);
        else if (name == "--poll") c.slurm_settings.poll_seconds = std::max(0.05, std::atof(value.c_str()));
        else if (name == "--work") c.settings.work = value;
        else if (name == "--keep") c.keep = true;
        else if (name == "--plan") c.print_plan = true;
        else if (name == "--help") c.help = true;
        else break;  // a lumen option (--threads, ...)
    }
    c.lumen_args.assign(args.begin() + long(i), args.end());
    for (const std::string& a : c.lumen_args)
        if (a.rfind("--", 0) == 0 && std::find(kOptions.begin(), kOptions.end(), a.substr(0, a.find('='))) != kOptions.end())
            throw LumenError({}, "farm option '" + a + "' after the scene's arguments",
                             "put farm options first: lumen farm " + a + " scene.pov ...");
    return c;
}

// --plan: the plan as an sh script on stdout, each run a command line, in order.
void print_plan(const FarmPlan& plan) {
    const std::string lumen = lumen_executable();
    std::printf("set -e\nmkdir -p %s\n", shell_quote((fs::path(plan.work) / "parts").string()).c_str());
    if (plan.solve) std::printf("# %s\n%s\n", plan.solve->label.c_str(), command_line(lumen, plan.solve->args).c_str());
    for (const FarmRun& run : plan.parts)
        std::printf("# %s\n%s\n", run.label.c_str(), command_line(lumen, run.args).c_str());
    if (!plan.tiles.empty()) {
        std::vector<std::string> merge = merge_arguments(plan);
        merge.insert(merge.begin(), "merge");
        std::printf("# join the tiles\n%s\n", command_line(lumen, merge).c_str());
    }
}

// Removes what the plan put in the work folder, and the folder when nothing else is left.
void remove_work(const FarmPlan& plan) {
    const fs::path work(plan.work);
    std::error_code ec;
    for (const char* sub : {"parts", "logs", "status", "radiosity"}) fs::remove_all(work / sub, ec);
    for (const char* script : {"solve.sh", "parts.sh", "finish.sh"}) fs::remove(work / script, ec);
    fs::remove(work, ec);  // only when empty
}

int farm(const FarmCommand& c, SourceManager& sources) {
    Options o = parse_command_line(c.lumen_args, sources);
    if (o.help || o.version) throw LumenError({}, "lumen farm renders: see lumen --help");
    FarmSettings s = c.settings;
    if (s.work.empty()) {
        Options still = o;
        still.final_frame = still.initial_frame;
        s.work = fs::path(output_path(still, 0)).replace_extension(".farm").string();
    }
    const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
    if (o.render.threads == 0)  // the user's +WT wins
        s.threads = c.slurm ? c.slurm_settings.cpus_per_task : c.jobs > 1 ? std::max(1, cores / c.jobs) : 0;
    // The first frame here: its errors now rather than from every part, and whether the
    // scene has radiosity to solve first.
    const interp::WarningSink quiet = [](const Diagnostic&) {};
    const scene::Scene scene =
        interpret_frame(o, plan_frames(o).front(), sources, quiet, render::make_object_queries());
    s.radiosity = scene.globals.radiosity.has_value();
    const FarmPlan plan = plan_farm(c.lumen_args, o, s);
    if (c.print_plan) {
        print_plan(plan);
        return 0;
    }
    std::fprintf(stderr, "lumen farm: %zu parts%s, %s; work folder %s\n", plan.parts.size(),
                 plan.solve ? " after a radiosity solve" : "",
                 c.slurm ? "on Slurm" : ("on this machine, " + std::to_string(c.jobs) + " at a time").c_str(),
                 plan.work.c_str());
    if (c.slurm) {
        SlurmSettings slurm = c.slurm_settings;
        slurm.job_name = "lumen-" + fs::path(o.input).stem().string();
        run_slurm(plan, slurm);
    } else {
        run_local(plan, c.jobs);
    }
    if (!c.keep) remove_work(plan);
    return 0;
}

}  // namespace

int run_farm(const std::vector<std::string>& args) {
    return run_guarded([&](SourceManager& sources) {
        const FarmCommand c = parse_farm_args(args);
        if (c.help || c.lumen_args.empty()) {
            std::fputs(kUsage, c.help ? stdout : stderr);
            return c.help ? 0 : 1;
        }
        return farm(c, sources);
    });
}

}  // namespace lumen::cli
