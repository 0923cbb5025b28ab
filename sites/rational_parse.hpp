// Parsing one exact rational token (docs/DESIGN.md §6).
//
// Accepted grammar (no spaces inside a token):
//   integer     [sign] digits                         "-12", "+7", "007"
//   fraction    [sign] digits "/" digits              "3/4", "-10/6" (reduced on reading)
//   decimal     [sign] mantissa [exponent]            "0.1" (= 1/10 exactly), ".5", "5.", "-1.25e-3"
//     mantissa  digits | digits "." | "." digits | digits "." digits
//     exponent  ("e" | "E") [sign] digits
// sign is one '+' or '-'. Everything is read EXACTLY: a decimal is p / 10^k.
//
// Rejected: empty tokens, "nan", "inf" (in any case), hexadecimal ("0x10"),
// two signs ("+-1"), a signed or decimal denominator ("1/-2", "1/2.5"; write
// "-1/2" instead), a decimal numerator over a denominator ("1.5/2"), zero
// denominators ("1/0"), several dots ("1.2.3"), exponents on fractions, and any
// number whose reduced numerator or denominator would need more than
// kMaxRationalBits bits. Tokens longer than kMaxTokenLength characters are
// rejected before any big-number arithmetic, and an exponent is checked against
// the limit before 10^exponent is ever computed (so "1e99999999" is refused at
// once).
#pragma once

#include "util/flint_types.hpp"

#include <cstddef>
#include <string>
#include <string_view>

namespace ellvor {

// Largest accepted size (in bits) of the reduced numerator and denominator.
constexpr long kMaxRationalBits = 4096;
// Longest accepted token, in characters (4096 bits need at most 1234 decimal
// digits; the rest leaves room for fractions, leading zeros and exponents).
constexpr std::size_t kMaxTokenLength = 4 * 1024;

// Parses `token`. On success stores the value in `out` and returns true. On
// failure returns false and sets `error` to a message saying what was wrong and
// what was expected (without any location; callers add file:line:column).
bool parse_rational(std::string_view token, Rational& out, std::string& error);

// Same, but throws Error(message) on failure.
Rational parse_rational(std::string_view token);

}  // namespace ellvor
