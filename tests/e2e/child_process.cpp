#include "tests/e2e/child_process.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <tuple>

namespace monoplane {

std::string source_dir() {
    const char* dir = std::getenv("MONOPLANE_SOURCE_DIR");
    return dir ? dir : ".";
}

// Starts `args` with stdout on a pipe; returns the pid and the pipe's read end. tmpdir: the
// child's TMPDIR, where the simulated headset writes its runtime script (a killed child leaves
// it behind), and where its stderr goes (stderr.log); empty: inherited, and stderr discarded.
std::pair<pid_t, int> spawn(const std::vector<std::string>& args, const std::string& tmpdir) {
    int fds[2];
    if (pipe(fds) != 0) return {-1, -1};
    const pid_t pid = fork();
    if (pid == 0) {
        dup2(fds[1], STDOUT_FILENO);
        const std::string log = tmpdir.empty() ? "/dev/null" : tmpdir + "/stderr.log";
        const int err = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        dup2(err, STDERR_FILENO);
        close(fds[0]);
        close(fds[1]);
        if (!tmpdir.empty()) setenv("TMPDIR", tmpdir.c_str(), 1);
        std::vector<char*> argv;
        for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        execv(argv[0], argv.data());
        _exit(127);
    }
    close(fds[1]);
    return {pid, fds[0]};
}

std::string read_all(int fd) {
    std::string text;
    char buffer[4096];
    ssize_t n = 0;
    while ((n = read(fd, buffer, sizeof buffer)) > 0)
        text.append(buffer, static_cast<std::size_t>(n));
    close(fd);
    return text;
}

// Runs `args` to its end; returns its exit status and, in *output, what it printed (on stdout,
// then on stderr where tmpdir holds it).
int run_to_end(const std::vector<std::string>& args, std::string* output,
               const std::string& tmpdir) {
    auto [pid, fd] = spawn(args, tmpdir);
    std::string text = read_all(fd);
    if (!tmpdir.empty()) {
        std::ifstream err(tmpdir + "/stderr.log");
        text += std::string(std::istreambuf_iterator<char>(err), {});
    }
    if (output) *output = text;
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

namespace {

// Waits until the child stops (true) or ends (false; its status in *status).
bool wait_until_stopped(pid_t pid, int* status) {
    while (waitpid(pid, status, WUNTRACED) < 0) {
        if (errno != EINTR) return false;
    }
    return WIFSTOPPED(*status);
}

}  // namespace

namespace {

// Lets the child run, one committed write at a time, until chosen(k, line) holds of its k-th
// committed line, where it is left stopped; or until it ends or stalls. A child left stopped at
// its line before is continued past it first.
void step_until(SteppedChild& child, const std::function<bool(int, const std::string&)>& chosen) {
    char buffer[4096];
    for (;;) {
        for (std::size_t end; (end = child.output.find('\n', child.scanned)) != std::string::npos;
             child.scanned = end + 1) {
            if (child.output.compare(child.scanned, 10, "committed ") != 0) continue;
            if (child.stepped_past == child.committed) {
                // It printed the line, then stopped; it prints nothing more until continued.
                if (!wait_until_stopped(child.pid, &child.ended_status)) {
                    child.reaped = true;
                    return;
                }
                ++child.committed;
            }
            const std::string line =
                child.output.substr(child.scanned + 10, end - child.scanned - 10);
            if (child.stepped_past < child.committed && chosen(child.committed, line)) {
                child.stopped = true;
                return;
            }
            child.stepped_past = child.committed;
            kill(child.pid, SIGCONT);
        }
        pollfd p{child.fd, POLLIN, 0};
        if (poll(&p, 1, 60000) <= 0) {
            child.stalled = true;
            return;
        }
        const ssize_t n = read(child.fd, buffer, sizeof buffer);
        if (n <= 0) return;  // the child has ended (or died)
        child.output.append(buffer, static_cast<std::size_t>(n));
    }
}

}  // namespace

SteppedChild run_until_committed(const std::vector<std::string>& args,
                                 const std::function<bool(int, const std::string&)>& chosen,
                                 const std::string& tmpdir) {
    std::vector<std::string> stepped = args;
    stepped.emplace_back("--trace-stop");
    SteppedChild child;
    std::tie(child.pid, child.fd) = spawn(stepped, tmpdir);
    if (child.pid > 0) step_until(child, chosen);
    return child;
}

int continue_to_end(SteppedChild& child) {
    if (child.pid <= 0) return -1;
    child.stopped = false;
    step_until(child, [](int, const std::string&) { return false; });
    if (child.stalled) kill(child.pid, SIGKILL);
    child.output += read_all(child.fd);
    child.fd = -1;
    int status = child.ended_status;
    if (!child.reaped) waitpid(child.pid, &status, 0);
    child.reaped = true;
    child.ended_status = status;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

KilledRun kill_child(SteppedChild child) {
    KilledRun run;
    if (child.pid <= 0) return run;
    int status = child.ended_status;
    if (!child.reaped) {
        kill(child.pid, SIGKILL);
        waitpid(child.pid, &status, 0);
    }
    run.output = child.output + (child.fd >= 0 ? read_all(child.fd) : std::string());
    run.killed = child.stopped && WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL;
    run.stalled = child.stalled;
    return run;
}

KilledRun run_and_kill_after(const std::vector<std::string>& args, int k,
                             const std::string& tmpdir) {
    return kill_child(run_until_committed(
        args, [k](int committed, const std::string&) { return committed == k; }, tmpdir));
}

}  // namespace monoplane
