// Runs the real ellvor binary (ELLVOR_BINARY, set by the Makefile) on files
// written into a scratch directory, capturing stdout, stderr and the exit
// status -- shared by the CLI tests.
#pragma once

#include <catch2/catch.hpp>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace ellvor::test {

struct CommandResult {
    int status;
    std::string out, err;
};

inline std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

inline bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

class ScratchDirectory {
public:
    ScratchDirectory() {
        char pattern[] = "/tmp/ellvor_test_XXXXXX";
        REQUIRE(::mkdtemp(pattern) != nullptr);
        path_ = pattern;
    }
    ~ScratchDirectory() { std::system(("rm -rf '" + path_ + "'").c_str()); }
    ScratchDirectory(const ScratchDirectory&) = delete;
    ScratchDirectory& operator=(const ScratchDirectory&) = delete;

    const std::string& path() const { return path_; }
    // Writes `content` to path/name and returns the path.
    std::string write(const std::string& name, const std::string& content) const {
        const std::string p = path_ + "/" + name;
        std::ofstream(p, std::ios::binary) << content;
        return p;
    }
    // Runs `ellvor ARGS` (ARGS as a shell word list) with stdin from `input`.
    CommandResult ellvor(const std::string& args, const std::string& input = "/dev/null") const {
        const std::string out = path_ + "/.stdout", err = path_ + "/.stderr";
        const std::string command =
            std::string("'") + ELLVOR_BINARY + "' " + args + " >'" + out + "' 2>'" + err + "' <'" + input + "'";
        const int raw = std::system(command.c_str());
        return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, read_file(out), read_file(err)};
    }

private:
    std::string path_;
};

}  // namespace ellvor::test
