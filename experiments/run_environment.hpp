// Where a benchmark ran: the machine, its load and the source state, for the
// headers of the result files in experiments/results/.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <string>
#include <vector>

namespace ellvor::experiments {

// "model name, N logical CPUs" from /proc/cpuinfo.
inline std::string cpu_model() {
    std::ifstream in("/proc/cpuinfo");
    std::string line, model = "unknown";
    int n = 0;
    while (std::getline(in, line)) {
        if (line.rfind("model name", 0) == 0 && model == "unknown") model = line.substr(line.find(':') + 2);
        if (line.rfind("processor", 0) == 0) ++n;
    }
    return model + ", " + std::to_string(n) + " logical CPUs";
}

// The git commit and how many tracked files differ from it.
inline std::string source_state() {
    std::string out;
    if (FILE* f = popen("git rev-parse --short HEAD 2>/dev/null && git status --porcelain -uno 2>/dev/null | wc -l", "r")) {
        char buf[128];
        std::string head, dirty;
        if (fgets(buf, sizeof buf, f)) head = buf;
        if (fgets(buf, sizeof buf, f)) dirty = buf;
        pclose(f);
        auto trim = [](std::string& s) {
            while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
        };
        trim(head);
        trim(dirty);
        if (!head.empty()) out = "git HEAD " + head + ", " + dirty + " tracked files modified in the work tree";
    }
    return out.empty() ? "unknown (not run from the repository)" : out;
}

// The 1, 5 and 15 minute load averages.
inline std::string loadavg() {
    std::ifstream in("/proc/loadavg");
    std::string a, b, c;
    in >> a >> b >> c;
    return a + " " + b + " " + c;
}

// Wall-clock and process CPU time in seconds (differences only).
inline double now_wall() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
inline double now_cpu() {
    timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

// The median (the mean of the middle two for an even count; 0 for none).
inline double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

// The nearest-rank quantile q in (0, 1] (NAN for none).
inline double quantile(std::vector<double> v, double q) {
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    const std::size_t r = static_cast<std::size_t>(std::ceil(q * v.size()));
    return v[std::min(v.size() - 1, r ? r - 1 : 0)];
}

// Runs `build` until 0.3 s of wall time and at least min_reps runs (at most
// 20): the medians of its wall and CPU times, the fastest and slowest CPU
// time, and how many runs.
struct Timing {
    double wall = 0, cpu = 0, cpu_min = 0, cpu_max = 0;
    int reps = 0;
};
template <class F>
Timing timed_runs(F build, int min_reps = 1) {
    std::vector<double> w, c;
    double total = 0;
    while (true) {
        const double w0 = now_wall(), c0 = now_cpu();
        build();
        const double w1 = now_wall(), c1 = now_cpu();
        w.push_back(w1 - w0);
        c.push_back(c1 - c0);
        total += w1 - w0;
        if ((total >= 0.3 && static_cast<int>(w.size()) >= min_reps) || w.size() >= 20) break;
    }
    return {median(w), median(c), *std::min_element(c.begin(), c.end()), *std::max_element(c.begin(), c.end()),
            static_cast<int>(w.size())};
}

// timed_runs with one run at least: the medians and the number of runs.
template <class F>
void timed(F build, double& wall, double& cpu, int& reps) {
    const Timing t = timed_runs(build);
    wall = t.wall;
    cpu = t.cpu;
    reps = t.reps;
}

// The common command line of the experiments: [--full] [--out DIR].
struct BenchArguments {
    bool full = false;
    std::string out_dir;  // empty: print only
    std::string command;  // as typed, for the results file
};

// Parses the common command line; on anything else prints `usage` and
// returns false.
inline bool parse_bench_arguments(int argc, char** argv, const std::string& name, const char* usage,
                                  BenchArguments& args) {
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--full") {
            args.full = true;
        } else if (a == "--out" && i + 1 < argc) {
            args.out_dir = argv[++i];
        } else {
            std::fputs(usage, stderr);
            return false;
        }
    }
    args.command = "build/experiments/" + name;
    for (int i = 1; i < argc; ++i) args.command += std::string(" ") + argv[i];
    return true;
}

}  // namespace ellvor::experiments
