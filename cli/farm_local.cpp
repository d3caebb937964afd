// The plan on this machine (run_local), and what both runners share.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <filesystem>
#include <map>
#include <thread>

#include "base/diagnostics.hpp"
#include "base/stop_request.hpp"
#include "cli/farm_process.hpp"
#include "cli/farm_run.hpp"
#include "cli/merge.hpp"

namespace lumen::cli {
namespace {

[[noreturn]] void run_failed(const FarmRun& run, int status, const std::string& log) {
    throw LumenError({}, "lumen farm: " + run.label + " failed (exit status " +
                             std::to_string(status) + "); the end of " + log + ":\n" +
                             tail_of(log));
}

// Runs `runs` with at most `jobs` at a time; on a failure or a stop request the others are
// stopped (SIGTERM: each removes its unfinished file) before this throws.
void run_all(const std::vector<const FarmRun*>& runs,
             const std::vector<std::string>& logs, int jobs, const std::string& what) {
    const std::string lumen = lumen_executable();
    std::map<pid_t, size_t> running;
    size_t next = 0, done = 0;
    StatusLine status;
    auto stop_all = [&] {
        for (const auto& [pid, i] : running) kill(pid, SIGTERM);
        for (const auto& [pid, i] : running) {
            int st = 0;
            while (waitpid(pid, &st, 0) < 0 && errno == EINTR) {}
        }
        running.clear();
        status.finish();
    };
    while (done < runs.size()) {
        while (int(running.size()) < jobs && next < runs.size()) {
            std::error_code ec;
            std::filesystem::remove(logs[next], ec);
            running[start_process(lumen, runs[next]->args, logs[next])] = next;
            ++next;
        }
        status.show("lumen farm: " + what + " " + std::to_string(done) + "/" +
                    std::to_string(runs.size()) + " done, " + std::to_string(running.size()) +
                    " running");
        int st = 0;
        const pid_t pid = waitpid(-1, &st, WNOHANG);
        if (pid > 0 && running.count(pid)) {
            const size_t i = running[pid];
            running.erase(pid);
            if (const int code = exit_status(st); code != 0) {
                stop_all();
                if (int sig = stop_requested()) throw Interrupted(sig);
                run_failed(*runs[i], code, logs[i]);
            }
            ++done;
            continue;
        }
        if (int sig = stop_requested()) {
            stop_all();
            throw Interrupted(sig);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    status.show("lumen farm: " + what + " " + std::to_string(done) + "/" +
                std::to_string(runs.size()) + " done");
    status.finish();
}

}  // namespace

std::string part_name(size_t index) { return "part-" + std::to_string(index); }

std::string log_path(const FarmPlan& plan, const std::string& name) {
    return (std::filesystem::path(plan.work) / "logs" / (name + ".log")).string();
}

void prepare_work(const FarmPlan& plan) {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::remove_all(fs::path(plan.work) / "status", ec);  // a previous run's exit statuses
    for (const char* sub : {"parts", "logs", "status"}) make_folder((fs::path(plan.work) / sub).string());
    for (const FarmRun& run : plan.parts)
        for (const std::string& out : run.outputs)
            if (const fs::path parent = fs::path(out).parent_path(); !parent.empty())
                make_folder(parent.string());
}

void finish_plan(const FarmPlan& plan) {
    if (!plan.tiles.empty()) {
        if (run_merge(merge_arguments(plan)) != 0)
            throw LumenError({}, "lumen farm: the tiles could not be joined");
        return;
    }
    for (const std::string& frame : plan.frames)
        if (!std::filesystem::exists(frame))
            throw LumenError({}, "lumen farm: frame file '" + frame + "' is missing");
    std::fprintf(stderr, "lumen farm: %zu frames written\n", plan.frames.size());
}

void run_local(const FarmPlan& plan, int jobs) {
    prepare_work(plan);
    if (plan.solve) run_all({&*plan.solve}, {log_path(plan, "solve")}, 1, "radiosity solve");
    std::vector<const FarmRun*> runs;
    std::vector<std::string> logs;
    for (size_t i = 0; i < plan.parts.size(); ++i) {
        runs.push_back(&plan.parts[i]);
        logs.push_back(log_path(plan, part_name(i)));
    }
    run_all(runs, logs, std::max(1, jobs), "parts");
    finish_plan(plan);
}

}  // namespace lumen::cli
