// A tiny command-line parser shared by the ellvor subcommands.
//
// Options are declared with their spelling ("--count", "-o") and whether they
// take a value; values are given as "--count 5" or "--count=5". "--" ends the
// options; "-" alone is a positional argument (standard input). "--help" and
// "-h" never get here: cli/main.cpp answers them before a command runs.
// Anything else starting with '-' is an unknown option (a UsageError). Conversions of values also throw UsageError with a
// message naming the option and what was expected.
#pragma once

#include "util/error.hpp"
#include "util/flint_types.hpp"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace ellvor::cli {

// Wrong command line: the CLI prints the message and "Try 'ellvor CMD --help'" and exits 2.
class UsageError : public Error {
public:
    using Error::Error;
};

struct OptionSpec {
    std::string name;         // "--count", "-o"
    bool takes_value = false;
    std::string alias = "";   // e.g. "--output" for "-o"
};

class Arguments {
public:
    Arguments(const std::vector<std::string>& args, const std::vector<OptionSpec>& specs);

    const std::vector<std::string>& positional() const { return positional_; }
    // Throws UsageError unless the number of positional arguments is in [min, max].
    void expect_positional(std::size_t min, std::size_t max, const std::string& what) const;

    bool has(const std::string& name) const { return values_.count(name) != 0; }
    std::string value(const std::string& name, const std::string& fallback = "") const;
    // The option's value as an integer in [min, max]; `fallback` when absent.
    long integer(const std::string& name, long fallback, long min, long max) const;
    std::uint64_t unsigned_integer(const std::string& name, std::uint64_t fallback) const;
    // The option's value as a finite double ("1e-9", "0.5"); `fallback` when absent.
    double real(const std::string& name, double fallback) const;
    // An exact rational (see sites/rational_parse.hpp); `fallback` when absent.
    Rational rational(const std::string& name, const Rational& fallback) const;
    // Throws UsageError when the option is absent.
    void require(const std::string& name) const;

private:
    const OptionSpec* find(const std::string& name) const;
    std::vector<OptionSpec> specs_;
    std::vector<std::string> positional_;
    std::map<std::string, std::string> values_;  // canonical name -> value ("" for flags)
};

}  // namespace ellvor::cli
