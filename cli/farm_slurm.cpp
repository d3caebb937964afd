// The plan as Slurm jobs (run_slurm): sbatch scripts in the work folder, a job for the
// radiosity solve, a job array for the parts (after the solve), a job that joins the tiles or
// checks the frames (after every part), then squeue until they have ended. The work folder
// must be shared with the nodes, as Slurm's own output files are.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

#include "base/diagnostics.hpp"
#include "base/stop_request.hpp"
#include "cli/farm_process.hpp"
#include "cli/farm_run.hpp"
#include "cli/text.hpp"

namespace lumen::cli {
namespace {

namespace fs = std::filesystem;

std::string script_path(const FarmPlan& plan, const std::string& name) {
    return (fs::path(plan.work) / (name + ".sh")).string();
}

void write_script(const std::string& path, const std::string& body) {
    std::ofstream out(path);
    out << "#!/bin/sh\n# written by lumen farm\ncd " << shell_quote(fs::current_path().string())
        << " || exit 1\n" << body;
    out.close();
    if (!out) throw LumenError({}, "cannot write '" + path + "'");
    fs::permissions(path, fs::perms::owner_all | fs::perms::group_read | fs::perms::others_read);
}

// Runs `command` and leaves its exit status in work/status/<name> (sh text).
std::string recorded(const FarmPlan& plan, const std::string& command, const std::string& name) {
    return command + "\nstatus=$?\necho $status > " +
           shell_quote((fs::path(plan.work) / "status").string() + "/") + name +
           "\nexit $status\n";
}

// The exit status a script recorded, or -1.
int recorded_status(const FarmPlan& plan, const std::string& name) {
    std::ifstream in(fs::path(plan.work) / "status" / name);
    int code = -1;
    return in >> code ? code : -1;
}

// The three scripts: solve.sh, parts.sh (the part is SLURM_ARRAY_TASK_ID), finish.sh.
void write_scripts(const FarmPlan& plan) {
    const std::string lumen = lumen_executable();
    if (plan.solve)
        write_script(script_path(plan, "solve"),
                     recorded(plan, command_line(lumen, plan.solve->args), "solve"));
    std::string parts = "case \"$SLURM_ARRAY_TASK_ID\" in\n";
    for (size_t i = 0; i < plan.parts.size(); ++i) {
        std::string set = "set --";
        for (const std::string& a : plan.parts[i].args) set += " " + shell_quote(a);
        parts += std::to_string(i) + ") " + set + " ;;\n";
    }
    parts += "*) echo \"lumen farm: no part $SLURM_ARRAY_TASK_ID\" >&2; exit 1 ;;\nesac\n" +
             recorded(plan, shell_quote(lumen) + " \"$@\"", "part-\"$SLURM_ARRAY_TASK_ID\"");
    write_script(script_path(plan, "parts"), parts);
    std::string finish;
    if (!plan.tiles.empty()) {
        std::vector<std::string> args = merge_arguments(plan);
        args.insert(args.begin(), "merge");
        finish = "exec " + command_line(lumen, args) + "\n";
    } else {
        finish = "for f in";
        for (const std::string& f : plan.frames) finish += " " + shell_quote(f);
        finish += "; do\n  [ -f \"$f\" ] || { echo \"lumen farm: frame file $f is missing\" >&2; exit 1; }\n"
                  "done\necho \"lumen farm: " + std::to_string(plan.frames.size()) + " frames written\"\n";
    }
    write_script(script_path(plan, "finish"), finish);
}

std::string submit(const std::vector<std::string>& args) {
    const Captured r = capture("sbatch", args);
    if (r.status != 0)
        throw LumenError({}, "lumen farm: sbatch failed (exit status " + std::to_string(r.status) +
                                 "): " + r.output,
                         r.status == 127 ? "install Slurm's client (Debian: slurm-client)" : "");
    const std::string id = r.output.substr(0, r.output.find_first_of(";\n"));
    if (id.empty() || id.find_first_not_of("0123456789") != std::string::npos)
        throw LumenError({}, "lumen farm: sbatch answered '" + r.output + "'");
    return id;
}

bool ended(const std::string& state) {
    static const char* kEnded[] = {"COMPLETED", "FAILED",    "CANCELLED", "TIMEOUT",
                                   "NODE_FAIL", "OUT_OF_MEMORY", "PREEMPTED", "BOOT_FAIL",
                                   "DEADLINE",  "REVOKED"};
    for (const char* e : kEnded)
        if (state.rfind(e, 0) == 0) return true;
    return false;
}

// The number of array tasks an squeue id names: "12_3" one, "12_[4-9,11]" seven.
int task_count(const std::string& suffix) {
    if (suffix.empty() || suffix[0] != '[') return 1;
    int count = 0;
    std::stringstream list(suffix.substr(1, suffix.find(']') - 1));
    for (std::string item; std::getline(list, item, ',');) {
        const size_t dash = item.find('-');
        const int a = std::atoi(item.c_str());
        const int b = dash == std::string::npos ? a : std::atoi(item.c_str() + dash + 1);
        count += std::max(1, b - a + 1);
    }
    return count;
}

struct QueueState {
    std::map<std::string, std::string> jobs;      // whole jobs: id -> state
    std::map<std::string, int> parts;             // parts by state, counted
    bool known = true;                            // false when squeue knows none of them
};

QueueState poll(const std::vector<std::string>& ids, const std::string& array_id) {
    std::string list;
    for (const std::string& id : ids) list += (list.empty() ? "" : ",") + id;
    const Captured r = capture("squeue", {"-h", "-r", "-t", "all", "-o", "%i %T", "-j", list}, true);
    QueueState q;
    if (r.status != 0) {
        if (r.output.find("Invalid job id") != std::string::npos) {
            q.known = false;
            return q;
        }
        throw LumenError({}, "lumen farm: squeue failed: " + r.output);
    }
    std::stringstream lines(r.output);
    for (std::string id, state; lines >> id >> state;) {
        const size_t bar = id.find('_');
        if (bar != std::string::npos && id.substr(0, bar) == array_id)
            q.parts[state] += task_count(id.substr(bar + 1));
        else
            q.jobs[id] = state;
    }
    return q;
}

std::string status_text(const QueueState& q, const std::string& solve, const std::string& finish) {
    std::string text = "lumen farm:";
    auto job = [&](const std::string& id) {
        const auto it = q.jobs.find(id);
        return it == q.jobs.end() ? std::string("gone") : lower(it->second);
    };
    if (!solve.empty()) text += " solve " + job(solve) + ";";
    text += " parts";
    if (q.parts.empty()) text += " pending";
    // Done, running, waiting, then anything else (failed, cancelled, ...).
    static const char* kOrder[] = {"COMPLETED", "RUNNING", "PENDING"};
    for (const char* state : kOrder)
        if (const auto it = q.parts.find(state); it != q.parts.end())
            text += " " + std::to_string(it->second) + " " + lower(state);
    for (const auto& [state, n] : q.parts)
        if (std::find(std::begin(kOrder), std::end(kOrder), state) == std::end(kOrder))
            text += " " + std::to_string(n) + " " + lower(state);
    return text + "; " + (finish.empty() ? "" : "finish " + job(finish));
}

[[noreturn]] void job_failed(const std::string& what, const std::string& log) {
    throw LumenError({}, "lumen farm: " + what + " failed on the cluster; the end of " + log +
                             ":\n" + tail_of(log));
}

}  // namespace

void run_slurm(const FarmPlan& plan, const SlurmSettings& s) {
    prepare_work(plan);
    write_scripts(plan);
    const std::string cpus = "--cpus-per-task=" + std::to_string(std::max(1, s.cpus_per_task));
    auto base = [&](const std::string& name, const std::string& log) {
        std::vector<std::string> a = {"--parsable", "--job-name=" + s.job_name + "-" + name,
                                      "--output=" + log, cpus};
        a.insert(a.end(), s.sbatch_args.begin(), s.sbatch_args.end());
        return a;
    };
    std::vector<std::string> ids;
    std::string solve_id, after;
    if (plan.solve) {
        std::vector<std::string> a = base("solve", log_path(plan, "solve"));
        a.push_back(script_path(plan, "solve"));
        solve_id = submit(a);
        ids.push_back(solve_id);
        after = solve_id;
    }
    std::vector<std::string> a =
        base("parts", (fs::path(plan.work) / "logs" / "part-%a.log").string());
    a.push_back("--array=0-" + std::to_string(plan.parts.size() - 1));
    if (!after.empty()) {
        a.push_back("--dependency=afterok:" + after);
        a.push_back("--kill-on-invalid-dep=yes");
    }
    a.push_back(script_path(plan, "parts"));
    const std::string parts_id = submit(a);
    ids.push_back(parts_id);
    a = base("finish", log_path(plan, "finish"));
    a.push_back("--dependency=afterok:" + parts_id);
    a.push_back("--kill-on-invalid-dep=yes");
    a.push_back(script_path(plan, "finish"));
    const std::string finish_id = submit(a);
    ids.push_back(finish_id);
    std::string list;
    for (const std::string& id : ids) list += (list.empty() ? "" : ", ") + id;
    std::fprintf(stderr, "lumen farm: submitted jobs %s (%zu parts); logs in %s\n", list.c_str(),
                 plan.parts.size(), (fs::path(plan.work) / "logs").c_str());

    StatusLine status;
    std::string finish_state;
    for (;;) {
        if (int sig = stop_requested()) {
            status.finish();
            capture("scancel", ids);
            std::fprintf(stderr, "lumen farm: jobs %s cancelled\n", list.c_str());
            throw Interrupted(sig);
        }
        const QueueState q = poll(ids, parts_id);
        if (q.known) status.show(status_text(q, solve_id, finish_id));
        bool active = false;
        for (const auto& [id, state] : q.jobs) active |= !ended(state);
        for (const auto& [state, n] : q.parts) active |= !ended(state);
        if (q.known && q.jobs.count(finish_id)) finish_state = q.jobs.at(finish_id);
        if (!active) break;
        std::this_thread::sleep_for(std::chrono::duration<double>(s.poll_seconds));
    }
    status.finish();
    if (finish_state == "COMPLETED") {
        std::fprintf(stderr, "lumen farm: done: %s\n",
                     plan.tiles.empty() ? (std::to_string(plan.frames.size()) + " frames").c_str()
                                        : plan.output.c_str());
        return;
    }
    // What failed first: the solve, a part (their status files say), or the finish.
    if (plan.solve && recorded_status(plan, "solve") != 0)
        job_failed("the radiosity solve", log_path(plan, "solve"));
    for (size_t i = 0; i < plan.parts.size(); ++i) {
        const std::string name = part_name(i);
        if (recorded_status(plan, name) > 0) job_failed(plan.parts[i].label, log_path(plan, name));
    }
    job_failed("the finishing job (" + (finish_state.empty() ? std::string("state unknown") : lower(finish_state)) + ")",
               log_path(plan, "finish"));
}

}  // namespace lumen::cli
