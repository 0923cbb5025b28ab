// The one exception type of ellvor. Input errors carry a location
// ("file:line:column") so that the CLI can print them and exit with status 2.
#pragma once

#include <stdexcept>
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

}  // namespace ellvor
