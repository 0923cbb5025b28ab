// The one exception type of ellvor. Input errors carry a location
// ("file:line:column") so that the CLI can print them and exit with status 2.
#pragma once

#include <stdexcept>
#include <cstddef>
#include <string>

namespace ellvor {

class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A malformed input: the message already names file, line and column.
class InputError : public Error {
public:
    InputError(const std::string& file, long line, long column, const std::string& what)
        : Error(file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + what) {}
    explicit InputError(const std::string& message) : Error(message) {}
};

// Two input sites whose boundaries cross (not a valid pair of sites): thrown
// by the algorithms that discover it, with the ids, so that a caller that
// knows the file can point at the lines.
class IntersectingSites : public InputError {
public:
    IntersectingSites(std::size_t first, std::size_t second)
        : InputError("invalid input: sites " + std::to_string(first) + " and " + std::to_string(second) +
                     " intersect (sites must be disjoint or nested)"),
          first_(first),
          second_(second) {}
    std::size_t first() const { return first_; }
    std::size_t second() const { return second_; }

private:
    std::size_t first_, second_;
};

}  // namespace ellvor
