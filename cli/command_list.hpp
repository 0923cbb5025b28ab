// The table of ellvor subcommands (an X-macro: X(identifier)). The command
// `command_IDENT` is defined in cli/command_IDENT.cpp; its typed name is
// Command::name (so X(side_of_bisector) may be called "side-of-bisector").
#pragma once

#include "cli/command.hpp"

#define ELLVOR_COMMANDS(X) \
    X(build)               \
    X(cells)               \
    X(check)               \
    X(generate)            \
    X(side_of_bisector)    \
    X(bitangent)           \
    X(incircle)            \
    X(voronoi_circle)      \
    X(resultant)

namespace ellvor::cli {
#define ELLVOR_DECLARE_COMMAND(id) extern const Command command_##id;
ELLVOR_COMMANDS(ELLVOR_DECLARE_COMMAND)
#undef ELLVOR_DECLARE_COMMAND
}  // namespace ellvor::cli
