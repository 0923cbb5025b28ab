#include "sites/rational_parse.hpp"

#include "util/error.hpp"

#include <cctype>

namespace ellvor {

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// The token as shown in messages: quoted, long tokens shortened.
std::string shown(std::string_view token) {
    std::string s;
    const std::size_t limit = 40;
    for (std::size_t i = 0; i < token.size() && i < limit; ++i) {
        unsigned char c = static_cast<unsigned char>(token[i]);
        s += (c >= 32 && c < 127) ? static_cast<char>(c) : '?';
    }
    if (token.size() > limit) s += "...";
    return "'" + s + "'";
}

std::string lower(std::string_view token) {
    std::string s;
    for (char c : token) s += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

const char* kExpected = "expected a rational number (an integer, p/q, or a decimal such as -1.25e-3)";

// Sets z to the integer written by a string of decimal digits (non-empty).
void set_digits(Integer& z, std::string_view digits) {
    std::string s(digits);
    fmpz_set_str(z.get(), s.c_str(), 10);
}

bool too_big(const Rational& q) { return q.bits() > kMaxRationalBits; }

std::string too_big_message(std::string_view token) {
    return "number " + shown(token) + " is too large: numerator and denominator are limited to " +
           std::to_string(kMaxRationalBits) + " bits";
}

}  // namespace

bool parse_rational(std::string_view token, Rational& out, std::string& error) {
    if (token.empty()) {
        error = std::string(kExpected) + ", found nothing";
        return false;
    }
    if (token.size() > kMaxTokenLength) {
        error = "number " + shown(token) + " is too long: at most " + std::to_string(kMaxTokenLength) +
                " characters, found " + std::to_string(token.size());
        return false;
    }
    {
        std::string l = lower(token);
        std::string_view body = l;
        if (!body.empty() && (body[0] == '+' || body[0] == '-')) body.remove_prefix(1);
        if (body == "nan" || body == "inf" || body == "infinity" || body.rfind("nan(", 0) == 0) {
            error = "not a finite number: " + shown(token) + "; " + kExpected;
            return false;
        }
    }

    std::size_t i = 0;
    bool negative = false;
    if (token[i] == '+' || token[i] == '-') {
        negative = token[i] == '-';
        ++i;
    }
    const std::size_t int_start = i;
    while (i < token.size() && is_digit(token[i])) ++i;
    std::string_view int_digits = token.substr(int_start, i - int_start);

    // Fraction p/q.
    if (i < token.size() && token[i] == '/') {
        if (int_digits.empty()) {
            error = std::string(kExpected) + ", found " + shown(token) + " (no digits before '/')";
            return false;
        }
        const std::size_t den_start = ++i;
        while (i < token.size() && is_digit(token[i])) ++i;
        std::string_view den_digits = token.substr(den_start, i - den_start);
        if (den_digits.empty() || i != token.size()) {
            error = std::string(kExpected) + ", found " + shown(token) +
                    " (the denominator of p/q must be unsigned digits only)";
            return false;
        }
        Integer p, q;
        set_digits(p, int_digits);
        set_digits(q, den_digits);
        if (q.is_zero()) {
            error = "zero denominator in " + shown(token);
            return false;
        }
        if (negative) fmpz_neg(p.get(), p.get());
        Rational r(p, q);  // canonicalized
        if (too_big(r)) {
            error = too_big_message(token);
            return false;
        }
        out = std::move(r);
        return true;
    }

    // Decimal: mantissa with optional dot, optional exponent.
    std::string_view frac_digits;
    bool has_dot = false;
    if (i < token.size() && token[i] == '.') {
        has_dot = true;
        const std::size_t frac_start = ++i;
        while (i < token.size() && is_digit(token[i])) ++i;
        frac_digits = token.substr(frac_start, i - frac_start);
    }
    if (int_digits.empty() && frac_digits.empty()) {
        error = std::string(kExpected) + ", found " + shown(token);
        return false;
    }
    long exponent = 0;
    if (i < token.size() && (token[i] == 'e' || token[i] == 'E')) {
        ++i;
        bool exp_negative = false;
        if (i < token.size() && (token[i] == '+' || token[i] == '-')) {
            exp_negative = token[i] == '-';
            ++i;
        }
        const std::size_t exp_start = i;
        while (i < token.size() && is_digit(token[i])) ++i;
        std::string_view exp_digits = token.substr(exp_start, i - exp_start);
        if (exp_digits.empty() || i != token.size()) {
            error = std::string(kExpected) + ", found " + shown(token) + " (malformed exponent)";
            return false;
        }
        // Skip leading zeros, then refuse exponents that cannot possibly fit.
        std::size_t nz = 0;
        while (nz + 1 < exp_digits.size() && exp_digits[nz] == '0') ++nz;
        exp_digits.remove_prefix(nz);
        if (exp_digits.size() > 7) {
            error = too_big_message(token) + " (exponent out of range)";
            return false;
        }
        exponent = std::stol(std::string(exp_digits));
        if (exp_negative) exponent = -exponent;
    }
    if (i != token.size()) {
        if (token[i] == '.' && has_dot)
            error = std::string(kExpected) + ", found " + shown(token) + " (more than one '.')";
        else if (token[i] == '/' && has_dot)
            error = std::string(kExpected) + ", found " + shown(token) +
                    " (p/q takes integers only; write the decimal alone)";
        else
            error = std::string(kExpected) + ", found " + shown(token);
        return false;
    }

    // value = (int_digits frac_digits) * 10^(exponent - len(frac_digits))
    std::string mantissa = std::string(int_digits) + std::string(frac_digits);
    Integer m;
    set_digits(m, mantissa);
    if (negative) fmpz_neg(m.get(), m.get());
    const long shift = exponent - static_cast<long>(frac_digits.size());
    if (m.is_zero()) {
        out = Rational(0);
        return true;
    }
    // 10^k has more than 3.32 k bits: refuse before computing it when even the
    // smallest possible result would be beyond the limit. A positive shift
    // multiplies the numerator; a negative one can be partly cancelled by the
    // trailing zeros of the mantissa (at most its length).
    const long max_digits = kMaxRationalBits * 30103L / 100000L + 2;  // log10(2) = 0.30103
    if (shift > max_digits || -shift > max_digits + static_cast<long>(mantissa.size())) {
        error = too_big_message(token);
        return false;
    }
    Integer ten_power;
    fmpz_ui_pow_ui(ten_power.get(), 10, static_cast<unsigned long>(shift >= 0 ? shift : -shift));
    Rational r;
    if (shift >= 0) {
        Integer num;
        fmpz_mul(num.get(), m.get(), ten_power.get());
        r = Rational(num, Integer(1));
    } else {
        r = Rational(m, ten_power);
    }
    if (too_big(r)) {
        error = too_big_message(token);
        return false;
    }
    out = std::move(r);
    return true;
}

Rational parse_rational(std::string_view token) {
    Rational r;
    std::string error;
    if (!parse_rational(token, r, error)) throw Error(error);
    return r;
}

}  // namespace ellvor
