// One ellvor subcommand. Adding a command = one new file cli/command_NAME.cpp
// defining `const Command command_NAME = {...};` plus one line X(NAME) in
// cli/command_list.hpp.
#pragma once

#include "cli/arguments.hpp"

#include <string>
#include <vector>

namespace ellvor::cli {

struct Command {
    const char* name;     // as typed: "check", "side-of-bisector"
    const char* summary;  // one line for `ellvor --help`
    const char* help;     // the full `ellvor NAME --help` text, starting with "usage: ellvor NAME ..."
    // Runs with the arguments after the command name. Returns the exit status;
    // may throw UsageError / InputError (exit 2) or Error (exit 1).
    int (*run)(const std::vector<std::string>& args);
};

// Exit statuses.
constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;   // internal or system error
constexpr int kExitInput = 2;     // bad input, bad usage, invalid site set

}  // namespace ellvor::cli
