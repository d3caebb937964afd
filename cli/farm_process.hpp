// What `lumen farm` needs of processes: starting lumen (or sbatch, squeue) with its output in a
// log file or captured, waiting without missing a stop request, and reporting a failed run.
#pragma once
#include <sys/types.h>

#include <string>
#include <vector>

namespace lumen::cli {

// This lumen executable, as an absolute path (what every part runs).
std::string lumen_executable();

// Starts `program` with `args`, stdout and stderr appended to `log`. Throws LumenError when it
// cannot be started.
pid_t start_process(const std::string& program, const std::vector<std::string>& args,
                    const std::string& log);

// Runs `program` to completion, its stdout captured (stderr too where `merge_stderr`).
struct Captured {
    int status = -1;  // the exit status; 127 when it could not be started
    std::string output;
};
Captured capture(const std::string& program, const std::vector<std::string>& args,
                 bool merge_stderr = true);

// The exit status of a process waitpid reported (128 + the signal that ended it).
int exit_status(int wait_status);

// `text` quoted for sh.
std::string shell_quote(const std::string& text);
// `program` and `args` as one sh command line.
std::string command_line(const std::string& program, const std::vector<std::string>& args);

// The last `lines` lines of a file, for a failed run's report.
std::string tail_of(const std::string& path, int lines = 8);

// Creates the folder and its parents; throws LumenError when it cannot.
void make_folder(const std::string& path);

}  // namespace lumen::cli

namespace lumen::cli {

// One line of progress on stderr: rewritten in place on a terminal, else printed when it
// changes.
class StatusLine {
public:
    StatusLine();
    void show(const std::string& text);
    void finish();  // ends the line on a terminal

private:
    bool terminal_;
    std::string last_;
};

}  // namespace lumen::cli
