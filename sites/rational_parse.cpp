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

// The digits from token[i] on (possibly none); i moves past them.
std::string_view digits_at(std::string_view token, std::size_t& i) {
    const std::size_t start = i;
    while (i < token.size() && is_digit(token[i])) ++i;
    return token.substr(start, i - start);
}

// Refuses what is no number before any scanning: nothing, a token too long
// for big-number arithmetic, NaN and infinities.
bool check_token(std::string_view token, std::string& error) {
    if (token.empty()) {
        error = std::string(kExpected) + ", found nothing";
        return false;
    }
    if (token.size() > kMaxTokenLength) {
        error = "number " + shown(token) + " is too long: at most " + std::to_string(kMaxTokenLength) +
                " characters, found " + std::to_string(token.size());
        return false;
    }
    const std::string l = lower(token);
    std::string_view body = l;
    if (!body.empty() && (body[0] == '+' || body[0] == '-')) body.remove_prefix(1);
    if (body == "nan" || body == "inf" || body == "infinity" || body.rfind("nan(", 0) == 0) {
        error = "not a finite number: " + shown(token) + "; " + kExpected;
        return false;
    }
    return true;
}

// Stores r in out unless it is beyond kMaxRationalBits.
bool accept(Rational r, std::string_view token, Rational& out, std::string& error) {
    if (too_big(r)) {
        error = too_big_message(token);
        return false;
    }
    out = std::move(r);
    return true;
}

// p/q: token[i] is the '/' after the numerator's digits.
bool parse_fraction(std::string_view token, bool negative, std::string_view int_digits, std::size_t i,
                    Rational& out, std::string& error) {
    if (int_digits.empty()) {
        error = std::string(kExpected) + ", found " + shown(token) + " (no digits before '/')";
        return false;
    }
    ++i;
    const std::string_view den_digits = digits_at(token, i);
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
    return accept(Rational(p, q), token, out, error);  // canonicalized
}

// The exponent after 'e' or 'E' (token[i]), which must end the token.
bool parse_exponent(std::string_view token, std::size_t i, long& exponent, std::string& error) {
    ++i;
    bool exp_negative = false;
    if (i < token.size() && (token[i] == '+' || token[i] == '-')) {
        exp_negative = token[i] == '-';
        ++i;
    }
    std::string_view exp_digits = digits_at(token, i);
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
    return true;
}

// What is wrong with a decimal's character token[i], where the token should
// have ended.
std::string trailing_character_message(std::string_view token, std::size_t i, bool has_dot) {
    if (token[i] == '.' && has_dot) return std::string(kExpected) + ", found " + shown(token) + " (more than one '.')";
    if (token[i] == '/' && has_dot)
        return std::string(kExpected) + ", found " + shown(token) +
               " (p/q takes integers only; write the decimal alone)";
    return std::string(kExpected) + ", found " + shown(token);
}

// value = (int_digits frac_digits) * 10^(exponent - len(frac_digits)), exactly.
bool decimal_value(std::string_view token, bool negative, std::string_view int_digits, std::string_view frac_digits,
                   long exponent, Rational& out, std::string& error) {
    const std::string mantissa = std::string(int_digits) + std::string(frac_digits);
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
    if (shift < 0) return accept(Rational(m, ten_power), token, out, error);
    Integer num;
    fmpz_mul(num.get(), m.get(), ten_power.get());
    return accept(Rational(num, Integer(1)), token, out, error);
}

}  // namespace

bool parse_rational(std::string_view token, Rational& out, std::string& error) {
    if (!check_token(token, error)) return false;

    std::size_t i = 0;
    bool negative = false;
    if (token[i] == '+' || token[i] == '-') {
        negative = token[i] == '-';
        ++i;
    }
    const std::string_view int_digits = digits_at(token, i);
    if (i < token.size() && token[i] == '/') return parse_fraction(token, negative, int_digits, i, out, error);

    // Decimal: mantissa with optional dot, optional exponent.
    std::string_view frac_digits;
    const bool has_dot = i < token.size() && token[i] == '.';
    if (has_dot) frac_digits = digits_at(token, ++i);
    if (int_digits.empty() && frac_digits.empty()) {
        error = std::string(kExpected) + ", found " + shown(token);
        return false;
    }
    long exponent = 0;
    if (i < token.size() && (token[i] == 'e' || token[i] == 'E'))
        return parse_exponent(token, i, exponent, error) &&
               decimal_value(token, negative, int_digits, frac_digits, exponent, out, error);
    if (i != token.size()) {
        error = trailing_character_message(token, i, has_dot);
        return false;
    }
    return decimal_value(token, negative, int_digits, frac_digits, exponent, out, error);
}

Rational parse_rational(std::string_view token) {
    Rational r;
    std::string error;
    if (!parse_rational(token, r, error)) throw Error(error);
    return r;
}

}  // namespace ellvor
