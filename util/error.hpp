// The one exception type of ellvor. Input errors carry a location
// ("file:line:column") so that the CLI can print them and exit with status 2;
// the location's parts are kept as fields too, so that other callers (the
// Python module) need not parse the message.
#pragma once

#include <algorithm>
#include <stdexcept>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>

namespace ellvor {

class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A malformed input. With a location, what() is "FILE:LINE:COLUMN: reason".
// A pair of sites that cannot stand together (crossing or duplicate sites)
// also names the two ids, smaller first.
class InputError : public Error {
public:
    using SitePair = std::pair<std::size_t, std::size_t>;

    InputError(const std::string& file, long line, long column, const std::string& reason,
               std::optional<SitePair> sites = std::nullopt)
        : Error(file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + reason),
          file_(file),
          line_(line),
          column_(column),
          reason_(reason),
          sites_(sites) {}
    // No location: what() is the message as given.
    explicit InputError(const std::string& message, std::optional<SitePair> sites = std::nullopt)
        : Error(message), reason_(message), sites_(sites) {}

    bool has_location() const { return line_ > 0; }
    const std::string& file() const { return file_; }  // "" without a location
    long line() const { return line_; }                // 1-based; 0 without a location
    long column() const { return column_; }            // 1-based; 0 without a location
    const std::string& reason() const { return reason_; }  // what() without the location
    const std::optional<SitePair>& sites() const { return sites_; }

private:
    std::string file_;
    long line_ = 0, column_ = 0;
    std::string reason_;
    std::optional<SitePair> sites_;
};

// Two input sites that cross in a way the diagram does not accept
// (docs/DESIGN.md §2: sites may cross in at most two points): thrown
// by the algorithms that discover it, with the ids and the reason, so that a
// caller that knows the file can point at the lines.
class IntersectingSites : public InputError {
public:
    IntersectingSites(std::size_t first, std::size_t second, const std::string& why)
        : InputError("invalid input: sites " + std::to_string(first) + " and " + std::to_string(second) +
                         " cross: " + why,
                     SitePair{first, second}),
          first_(first),
          second_(second),
          why_(why) {}
    // At the later site's line of a file: `reason` names both sites.
    IntersectingSites(const std::string& file, long line, long column, const std::string& reason, std::size_t first,
                      std::size_t second, const std::string& why)
        : InputError(file, line, column, reason, SitePair{std::min(first, second), std::max(first, second)}),
          first_(first),
          second_(second),
          why_(why) {}
    std::size_t first() const { return first_; }
    std::size_t second() const { return second_; }
    const std::string& why() const { return why_; }  // e.g. "their boundaries meet in 4 points"

private:
    std::size_t first_, second_;
    std::string why_;
};

}  // namespace ellvor
