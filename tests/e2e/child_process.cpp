#include "tests/e2e/child_process.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <iterator>

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

// Runs `args` and SIGKILLs it as soon as it has printed its k-th "committed" line (the write is
// durable then; the child is somewhere in its next frames). What it printed before dying is read
// to the end: every committed line there is a write that must survive.
KilledRun run_and_kill_after(const std::vector<std::string>& args, int k,
                             const std::string& tmpdir) {
    KilledRun run;
    auto [pid, fd] = spawn(args, tmpdir);
    if (pid <= 0) return run;
    int committed = 0;
    std::size_t scanned = 0;
    bool sent = false;
    char buffer[4096];
    for (;;) {
        pollfd p{fd, POLLIN, 0};
        if (poll(&p, 1, 60000) <= 0) {
            run.stalled = true;
            break;
        }
        const ssize_t n = read(fd, buffer, sizeof buffer);
        if (n <= 0) break;  // the child has ended (or died)
        run.output.append(buffer, static_cast<std::size_t>(n));
        for (std::size_t end; !sent && (end = run.output.find('\n', scanned)) != std::string::npos;
             scanned = end + 1) {
            if (run.output.compare(scanned, 10, "committed ") == 0 && ++committed == k) {
                kill(pid, SIGKILL);
                sent = true;
            }
        }
    }
    if (!sent) kill(pid, SIGKILL);  // stalled: do not leave it behind
    int status = 0;
    waitpid(pid, &status, 0);
    run.output += read_all(fd);
    run.killed = WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL && sent;
    return run;
}

}  // namespace monoplane
