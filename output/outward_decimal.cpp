#include "output/outward_decimal.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ellvor {
namespace {

// floor(log10(a)) for a rational a > 0.
long decimal_exponent(const Rational& a) {
    long e = static_cast<long>(fmpz_sizeinbase(fmpq_numref(a.get()), 10)) -
             static_cast<long>(fmpz_sizeinbase(fmpq_denref(a.get()), 10));
    while (a < power_of_ten(e)) --e;
    while (a >= power_of_ten(e + 1)) ++e;
    return e;
}

// An endpoint of b (exact), or its text when it is not a finite number.
struct Endpoint {
    bool finite = false;
    Rational value;
    std::string special;  // "inf", "-inf", "nan"
};

Endpoint endpoint(const Ball& b, Rounding side) {
    Arf x;
    if (side == Rounding::down)
        arb_get_lbound_arf(x.get(), b.get(), ARF_PREC_EXACT);
    else
        arb_get_ubound_arf(x.get(), b.get(), ARF_PREC_EXACT);
    Endpoint e;
    if (arf_is_nan(x.get()) || arf_is_nan(arb_midref(b.get())))
        e.special = "nan";
    else if (arf_is_pos_inf(x.get()))
        e.special = "inf";
    else if (arf_is_neg_inf(x.get()))
        e.special = "-inf";
    else {
        e.finite = true;
        arf_get_fmpq(e.value.get(), x.get());
    }
    return e;
}

// Significant digits that show the ball's relative width with 3 to spare.
int digits_for(const Ball& b) {
    const double mid = std::fabs(arf_get_d(arb_midref(b.get()), ARF_RND_NEAR));
    const double rad = mag_get_d(arb_radref(b.get()));
    if (!(rad > 0) || !(mid > 0) || !std::isfinite(mid)) return 17;
    const double width_digits = std::ceil(std::log10(mid / rad)) + 3;
    return static_cast<int>(std::clamp(width_digits, 17.0, 60.0));
}

}  // namespace

Decimal round_decimal(const Rational& q, int digits, Rounding r) {
    Decimal d;
    if (q.is_zero()) return d;
    const bool negative = q.sign() < 0;
    const Rational a = negative ? -q : q;
    const long e = decimal_exponent(a);
    d.exponent = e - digits + 1;
    const Rational scaled = a * power_of_ten(-d.exponent);
    // Rounding q down rounds |q| up when q is negative.
    const bool magnitude_up = (r == Rounding::up) != negative;
    if (magnitude_up)
        fmpz_cdiv_q(d.mantissa.get(), fmpq_numref(scaled.get()), fmpq_denref(scaled.get()));
    else
        fmpz_fdiv_q(d.mantissa.get(), fmpq_numref(scaled.get()), fmpq_denref(scaled.get()));
    if (negative) d.mantissa = -d.mantissa;
    return d;
}

Rational decimal_value(const Decimal& d) { return Rational(d.mantissa) * power_of_ten(d.exponent); }

std::string decimal_text(const Decimal& d, bool keep_trailing_zeros) {
    if (d.mantissa.is_zero()) return "0";
    std::string digits = d.mantissa.str();
    std::string sign;
    if (digits[0] == '-') {
        sign = "-";
        digits.erase(0, 1);
    }
    long last = d.exponent;  // the exponent of the last digit
    while (!keep_trailing_zeros && digits.size() > 1 && digits.back() == '0') {
        digits.pop_back();
        ++last;
    }
    const long n = static_cast<long>(digits.size());
    const long first = last + n - 1;  // the exponent of the first digit
    // Kept zeros are significant: a last digit left of the point needs the exponent.
    if (first >= -5 && first < 21 && !(keep_trailing_zeros && last > 0)) {
        if (last >= 0) return sign + digits + std::string(static_cast<std::size_t>(last), '0');
        if (first >= 0) return sign + digits.substr(0, static_cast<std::size_t>(first + 1)) + "." +
                               digits.substr(static_cast<std::size_t>(first + 1));
        return sign + "0." + std::string(static_cast<std::size_t>(-first - 1), '0') + digits;
    }
    std::string text = sign + digits.substr(0, 1);
    if (n > 1) text += "." + digits.substr(1);
    return text + "e" + std::to_string(first);
}

DecimalBounds decimal_bounds(const Ball& b) {
    const int digits = digits_for(b);
    DecimalBounds out;
    const Endpoint lo = endpoint(b, Rounding::down), hi = endpoint(b, Rounding::up);
    if (lo.special == "nan" || hi.special == "nan") return {"nan", "nan"};
    out.lo = lo.finite ? decimal_text(round_decimal(lo.value, digits, Rounding::down)) : lo.special;
    out.hi = hi.finite ? decimal_text(round_decimal(hi.value, digits, Rounding::up)) : hi.special;
    return out;
}

std::string certain_digits(const Ball& b) {
    const Endpoint lo = endpoint(b, Rounding::down), hi = endpoint(b, Rounding::up);
    if (!lo.finite || !hi.finite) return "nan";
    const Rational mid = (lo.value + hi.value) * Rational(1, 2);
    for (int n = 17; n >= 1; --n)
        for (Rounding r : {Rounding::down, Rounding::up}) {
            const Decimal d = round_decimal(mid, n, r);
            const Rational value = decimal_value(d), unit = power_of_ten(d.exponent);
            if (value - unit <= lo.value && hi.value <= value + unit) return decimal_text(d, true);
        }
    return "nan";
}

std::pair<double, double> double_bounds(const Ball& b) {
    if (arf_is_nan(arb_midref(b.get()))) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        return {nan, nan};
    }
    Arf x;
    arb_get_lbound_arf(x.get(), b.get(), ARF_PREC_EXACT);
    const double lo = arf_get_d(x.get(), ARF_RND_FLOOR);
    arb_get_ubound_arf(x.get(), b.get(), ARF_PREC_EXACT);
    const double hi = arf_get_d(x.get(), ARF_RND_CEIL);
    return {lo, hi};
}

}  // namespace ellvor
