// ellvor: dispatch to the subcommands listed in cli/command_list.hpp.
// Exit status: 0 success, 2 bad usage or bad input ("ellvor: FILE:LINE:COL: what"
// on stderr), 1 any other failure.
#include "cli/command_list.hpp"
#include "util/error.hpp"

#include <cstring>
#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <vector>

namespace ellvor::cli {
namespace {

const Command* const kCommands[] = {
#define ELLVOR_COMMAND_ENTRY(id) &command_##id,
    ELLVOR_COMMANDS(ELLVOR_COMMAND_ENTRY)
#undef ELLVOR_COMMAND_ENTRY
};

void print_program_help(std::ostream& out) {
    out << "usage: ellvor COMMAND [ARGS...]\n"
           "       ellvor COMMAND --help\n"
           "\n"
           "Exact Voronoi diagram of ellipses. Site files (.ell) hold one ellipse a line,\n"
           "'a b w xc yc' (semi-axes, w = tan(angle/2), center), each an exact rational:\n"
           "an integer, p/q, or a decimal read exactly (0.1 = 1/10). '#' starts a comment.\n"
           "\n"
           "commands:\n";
    for (const Command* c : kCommands) {
        std::string name = c->name;
        out << "  " << name << std::string(name.size() < 18 ? 18 - name.size() : 1, ' ') << c->summary << '\n';
    }
    out << "\nExit status: 0 success, 2 bad usage or bad input, 1 other failure.\n";
}

const Command* find_command(const std::string& name) {
    for (const Command* c : kCommands)
        if (name == c->name) return c;
    return nullptr;
}

int run(int argc, char** argv) {
    if (argc < 2) {
        print_program_help(std::cerr);
        return kExitInput;
    }
    const std::string first = argv[1];
    if (first == "--help" || first == "-h" || first == "help") {
        if (first == "help" && argc > 2) {
            if (const Command* c = find_command(argv[2])) {
                std::cout << c->help;
                return kExitOk;
            }
        }
        print_program_help(std::cout);
        return kExitOk;
    }
    const Command* command = find_command(first);
    if (!command) {
        std::cerr << "ellvor: unknown command '" << first << "'\nTry 'ellvor --help'.\n";
        return kExitInput;
    }
    std::vector<std::string> args(argv + 2, argv + argc);
    try {
        for (const std::string& a : args) {
            if (a == "--") break;
            if (a == "--help" || a == "-h") {
                std::cout << command->help;
                return kExitOk;
            }
        }
        return command->run(args);
    } catch (const UsageError& e) {
        std::cerr << "ellvor " << command->name << ": " << e.what() << "\nTry 'ellvor " << command->name
                  << " --help'.\n";
        return kExitInput;
    } catch (const InputError& e) {
        std::cerr << "ellvor: " << e.what() << '\n';
        return kExitInput;
    } catch (const std::bad_alloc&) {
        std::cerr << "ellvor: out of memory\n";
        return kExitFailure;
    } catch (const std::exception& e) {
        std::cerr << "ellvor: " << e.what() << '\n';
        return kExitFailure;
    }
}

}  // namespace
}  // namespace ellvor::cli

int main(int argc, char** argv) {
    std::ios::sync_with_stdio(false);
    int status = ellvor::cli::run(argc, argv);
    std::cout.flush();
    if (!std::cout) {
        std::cerr << "ellvor: error writing standard output\n";
        return ellvor::cli::kExitFailure;
    }
    return status;
}
