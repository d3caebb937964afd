#include "cli/farm_process.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <deque>
#include <filesystem>
#include <fstream>

#include "base/diagnostics.hpp"

extern char** environ;

namespace lumen::cli {
namespace {

std::vector<char*> argv_of(const std::string& program, const std::vector<std::string>& args) {
    std::vector<char*> argv;
    argv.push_back(const_cast<char*>(program.c_str()));
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    return argv;
}

struct FileActions {
    posix_spawn_file_actions_t actions;
    FileActions() { posix_spawn_file_actions_init(&actions); }
    ~FileActions() { posix_spawn_file_actions_destroy(&actions); }
};

}  // namespace

std::string lumen_executable() {
    std::error_code ec;
    const auto path = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) throw LumenError({}, "cannot find the lumen executable: " + ec.message());
    return path.string();
}

pid_t start_process(const std::string& program, const std::vector<std::string>& args,
                    const std::string& log) {
    FileActions fa;
    posix_spawn_file_actions_addopen(&fa.actions, STDOUT_FILENO, log.c_str(),
                                     O_WRONLY | O_CREAT | O_APPEND, 0644);
    posix_spawn_file_actions_adddup2(&fa.actions, STDOUT_FILENO, STDERR_FILENO);
    pid_t pid = 0;
    std::vector<char*> argv = argv_of(program, args);
    const int err = posix_spawnp(&pid, program.c_str(), &fa.actions, nullptr, argv.data(), environ);
    if (err != 0)
        throw LumenError({}, "cannot start " + program + ": " + std::strerror(err));
    return pid;
}

Captured capture(const std::string& program, const std::vector<std::string>& args,
                 bool merge_stderr) {
    Captured result;
    int pipe_fds[2];
    if (pipe2(pipe_fds, O_CLOEXEC) != 0) return result;
    FileActions fa;
    posix_spawn_file_actions_adddup2(&fa.actions, pipe_fds[1], STDOUT_FILENO);
    if (merge_stderr) posix_spawn_file_actions_adddup2(&fa.actions, pipe_fds[1], STDERR_FILENO);
    pid_t pid = 0;
    std::vector<char*> argv = argv_of(program, args);
    const int err = posix_spawnp(&pid, program.c_str(), &fa.actions, nullptr, argv.data(), environ);
    close(pipe_fds[1]);
    if (err != 0) {
        close(pipe_fds[0]);
        result.status = 127;
        result.output = program + ": " + std::strerror(err);
        return result;
    }
    char buf[4096];
    for (;;) {
        const ssize_t n = read(pipe_fds[0], buf, sizeof buf);
        if (n > 0) result.output.append(buf, size_t(n));
        else if (n == 0 || errno != EINTR) break;
    }
    close(pipe_fds[0]);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
    result.status = exit_status(status);
    return result;
}

int exit_status(int wait_status) {
    if (WIFEXITED(wait_status)) return WEXITSTATUS(wait_status);
    if (WIFSIGNALED(wait_status)) return 128 + WTERMSIG(wait_status);
    return 1;
}

std::string shell_quote(const std::string& text) {
    std::string q = "'";
    for (const char c : text) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

std::string command_line(const std::string& program, const std::vector<std::string>& args) {
    std::string line = shell_quote(program);
    for (const std::string& a : args) line += " " + shell_quote(a);
    return line;
}

std::string tail_of(const std::string& path, int lines) {
    std::ifstream in(path);
    std::deque<std::string> last;
    for (std::string line; std::getline(in, line);) {
        last.push_back(line);
        if (int(last.size()) > lines) last.pop_front();
    }
    std::string text;
    for (const std::string& l : last) text += "    " + l + "\n";
    return text;
}

void make_folder(const std::string& path) {
    std::error_code ec;
    std::filesystem::create_directories(path, ec);
    if (ec) throw LumenError({}, "cannot create the folder '" + path + "': " + ec.message());
}

}  // namespace lumen::cli

namespace lumen::cli {

StatusLine::StatusLine() : terminal_(isatty(STDERR_FILENO) != 0) {}

void StatusLine::show(const std::string& text) {
    if (text == last_) return;
    if (terminal_) std::fprintf(stderr, "\r%s\033[K", text.c_str());
    else std::fprintf(stderr, "%s\n", text.c_str());
    std::fflush(stderr);
    last_ = text;
}

void StatusLine::finish() {
    if (terminal_ && !last_.empty()) std::fputc('\n', stderr);
    last_.clear();
}

}  // namespace lumen::cli
