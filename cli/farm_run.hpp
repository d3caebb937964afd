// Running a farm plan (cli/farm_plan.hpp): on this machine, a few lumen processes at a time,
// or on a Slurm cluster as a job for the radiosity solve, a job array for the parts and a
// dependent job that joins the tiles (or checks the frames), with the queue's progress on the
// terminal. Both stop on the first failed part with its log, and on SIGINT/SIGTERM (cancelling
// what they started).
#pragma once
#include <string>
#include <vector>

#include "cli/farm_plan.hpp"

namespace lumen::cli {

// Runs every part with at most `jobs` at a time, then finishes the plan.
void run_local(const FarmPlan& plan, int jobs);

struct SlurmSettings {
    int cpus_per_task = 1;
    std::vector<std::string> sbatch_args;  // --sbatch=ARG: partition, account, time, ...
    double poll_seconds = 1;
    std::string job_name = "lumen";
};

// Submits the plan with sbatch and follows it with squeue until it has ended.
void run_slurm(const FarmPlan& plan, const SlurmSettings& s);

// The last step: joins the tiles into the output, or checks that every frame was written.
void finish_plan(const FarmPlan& plan);

// The folders a plan writes into (parts, logs, status), created.
void prepare_work(const FarmPlan& plan);
std::string log_path(const FarmPlan& plan, const std::string& name);  // work/logs/name.log
// Part `index`'s name in logs and exit statuses ("part-3": Slurm's part-%a).
std::string part_name(size_t index);

}  // namespace lumen::cli
