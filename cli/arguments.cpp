#include "cli/arguments.hpp"

#include "sites/rational_parse.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace ellvor::cli {

Arguments::Arguments(const std::vector<std::string>& args, const std::vector<OptionSpec>& specs) : specs_(specs) {
    bool options_done = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (options_done || arg == "-" || arg.empty() || arg[0] != '-') {
            positional_.push_back(arg);
            continue;
        }
        if (arg == "--") {
            options_done = true;
            continue;
        }
        std::string name = arg, value;
        bool inline_value = false;
        std::size_t eq = arg.find('=');
        if (arg.rfind("--", 0) == 0 && eq != std::string::npos) {
            name = arg.substr(0, eq);
            value = arg.substr(eq + 1);
            inline_value = true;
        }
        const OptionSpec* spec = find(name);
        if (!spec) {
            // A negative number ("-2", "-1/3", "-.5e-3") is a positional argument
            // (a coordinate); its syntax is checked where it is parsed.
            if (arg.size() > 1 && (arg[1] == '.' || (arg[1] >= '0' && arg[1] <= '9'))) {
                positional_.push_back(arg);
                continue;
            }
            throw UsageError("unknown option '" + name + "'");
        }
        if (spec->takes_value) {
            if (!inline_value) {
                if (i + 1 >= args.size()) throw UsageError("option " + spec->name + " needs a value");
                value = args[++i];
            }
        } else if (inline_value) {
            throw UsageError("option " + spec->name + " takes no value");
        }
        if (values_.count(spec->name)) throw UsageError("option " + spec->name + " given twice");
        values_[spec->name] = value;
    }
}

const OptionSpec* Arguments::find(const std::string& name) const {
    for (const OptionSpec& s : specs_)
        if (s.name == name || (!s.alias.empty() && s.alias == name)) return &s;
    return nullptr;
}

void Arguments::expect_positional(std::size_t min, std::size_t max, const std::string& what) const {
    if (positional_.size() < min) throw UsageError("missing argument: expected " + what);
    if (positional_.size() > max)
        throw UsageError("unexpected argument '" + positional_[max] + "': expected " + what);
}

std::string Arguments::value(const std::string& name, const std::string& fallback) const {
    auto it = values_.find(name);
    return it == values_.end() ? fallback : it->second;
}

void Arguments::require(const std::string& name) const {
    if (!has(name)) throw UsageError("missing option " + name);
}

long Arguments::integer(const std::string& name, long fallback, long min, long max) const {
    if (!has(name)) return fallback;
    const std::string v = value(name);
    errno = 0;
    char* end = nullptr;
    long x = std::strtol(v.c_str(), &end, 10);
    if (v.empty() || *end != '\0' || errno == ERANGE || x < min || x > max)
        throw UsageError("option " + name + ": expected an integer in [" + std::to_string(min) + ", " +
                         std::to_string(max) + "], got '" + v + "'");
    return x;
}

std::uint64_t Arguments::unsigned_integer(const std::string& name, std::uint64_t fallback) const {
    if (!has(name)) return fallback;
    const std::string v = value(name);
    errno = 0;
    char* end = nullptr;
    unsigned long long x = std::strtoull(v.c_str(), &end, 10);
    if (v.empty() || v[0] == '-' || v[0] == '+' || *end != '\0' || errno == ERANGE)
        throw UsageError("option " + name + ": expected an unsigned 64-bit integer, got '" + v + "'");
    return static_cast<std::uint64_t>(x);
}

double Arguments::real(const std::string& name, double fallback) const {
    if (!has(name)) return fallback;
    const std::string v = value(name);
    errno = 0;
    char* end = nullptr;
    const double x = std::strtod(v.c_str(), &end);
    if (v.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(x))
        throw UsageError("option " + name + ": expected a number, got '" + v + "'");
    return x;
}

Rational Arguments::rational(const std::string& name, const Rational& fallback) const {
    if (!has(name)) return fallback;
    Rational r;
    std::string error;
    if (!parse_rational(value(name), r, error)) throw UsageError("option " + name + ": " + error);
    return r;
}

}  // namespace ellvor::cli
