// Peak memory of one piece of work, measured in a forked child: the child's
// own high-water mark (VmHWM) after the work, against its RSS once its input
// is prepared (the baseline; the memory the preparation freed returned to
// the system and the high-water mark restarted there).
#pragma once

#include <cstring>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <utility>

#include <malloc.h>
#include <sys/wait.h>
#include <unistd.h>

namespace ellvor::experiments {

// How the benchmarks measure a build's peak memory, for their reports.
constexpr const char* kPeakMemoryMethod =
    "One more build each, in a child forked before this program builds anything else; the child generates its "
    "sites, returns the memory the generation freed to the system (malloc_trim) and restarts its high-water mark, "
    "then builds. The growth of the child's resident memory over the build (VmHWM after it minus VmRSS before it)";

inline long status_kb(const char* field) {
    std::ifstream in("/proc/self/status");
    std::string line;
    const std::size_t n = std::strlen(field);
    while (std::getline(in, line))
        if (line.compare(0, n, field) == 0 && line.size() > n && line[n] == ':') return std::stol(line.substr(n + 1));
    return -1;
}

struct PeakMemory {
    long start_kb = -1, peak_kb = -1;  // the child's VmRSS before the build, its VmHWM after
    std::string error;
};

// Runs `prepare` (its input, not measured) and then `build` once in a forked
// child and reads the child's own high-water mark, so that the peaks of
// different builds are not mixed (a child's VmHWM starts at its RSS at the
// fork, not at the parent's peak). Fork before the parent has done large work:
// the child reuses memory the parent freed but still holds, which hides growth.
template <class Prepare, class F>
PeakMemory peak_memory_in_child(Prepare&& prepare, F&& build) {
    PeakMemory m;
    int fd[2];
    if (pipe(fd) != 0) return {-1, -1, "pipe failed"};
    std::cout.flush();
    std::cerr.flush();
    const pid_t pid = fork();
    if (pid < 0) {
        close(fd[0]);
        close(fd[1]);
        return {-1, -1, "fork failed"};
    }
    if (pid == 0) {
        close(fd[0]);
        // glibc raises its mmap threshold to the size of each large block
        // freed: the allocator's policy for the build would depend on what
        // `prepare` allocated. Fixed at glibc's default, it does not.
        mallopt(M_MMAP_THRESHOLD, 128 * 1024);
        long out[2] = {-1, -1};
        int status = 0;
        try {
            prepare();
            // The memory `prepare` freed goes back to the system: else the
            // build reuses it unseen, and its growth depends on how much its
            // input's preparation happened to free.
            malloc_trim(0);
            // The high-water mark restarts here (Linux: "5" resets VmHWM to
            // VmRSS), else the preparation's own peak may stand for the build's.
            { std::ofstream("/proc/self/clear_refs") << "5"; }
            out[0] = status_kb("VmRSS");
            if (status_kb("VmHWM") > out[0] + 1024) throw std::runtime_error("cannot reset VmHWM");
            build();
            out[1] = status_kb("VmHWM");
        } catch (...) {
            status = 1;
        }
        if (write(fd[1], out, sizeof out) != static_cast<ssize_t>(sizeof out)) status = 1;
        _exit(status);
    }
    close(fd[1]);
    long in[2] = {-1, -1};
    const bool got = read(fd[0], in, sizeof in) == static_cast<ssize_t>(sizeof in);
    close(fd[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    if (!got || !WIFEXITED(status) || WEXITSTATUS(status) != 0) m.error = "child failed";
    m.start_kb = in[0];
    m.peak_kb = in[1];
    return m;
}

template <class F>
PeakMemory peak_memory_in_child(F&& build) {
    return peak_memory_in_child([] {}, std::forward<F>(build));
}

}  // namespace ellvor::experiments
