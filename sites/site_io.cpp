#include "sites/site_io.hpp"

#include "sites/rational_parse.hpp"
#include "util/error.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <functional>
#include <map>
#include <sys/stat.h>
#include <unistd.h>
#include <unordered_map>
#include <utility>

namespace ellvor {

namespace {

struct Token {
    std::string_view text;
    long column;  // 1-based
};

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }

// Reads one line (without '\n', without a trailing '\r') into `line`. Returns
// false at end of input. Throws when the line exceeds kMaxLineLength.
bool read_line(std::streambuf& buf, std::string& line, const std::string& name, long line_number) {
    line.clear();
    bool any = false;
    for (;;) {
        int c = buf.sbumpc();
        if (c == std::char_traits<char>::eof()) break;
        any = true;
        if (c == '\n') break;
        if (line.size() >= kMaxLineLength)
            throw InputError(name, line_number, static_cast<long>(kMaxLineLength) + 1,
                             "line too long: at most " + std::to_string(kMaxLineLength) + " bytes per line");
        line.push_back(static_cast<char>(c));
    }
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return any;
}

std::vector<Token> split(std::string_view line) {
    std::vector<Token> tokens;
    std::size_t end = line.find('#');
    if (end == std::string_view::npos) end = line.size();
    std::size_t i = 0;
    while (i < end) {
        while (i < end && is_space(line[i])) ++i;
        if (i >= end) break;
        std::size_t start = i;
        while (i < end && !is_space(line[i])) ++i;
        tokens.push_back({line.substr(start, i - start), static_cast<long>(start) + 1});
    }
    return tokens;
}

// Column just after the last character before any comment (for "missing field").
long end_column(std::string_view line) {
    std::size_t end = line.find('#');
    if (end == std::string_view::npos) end = line.size();
    while (end > 0 && is_space(line[end - 1])) --end;
    return static_cast<long>(end) + 1;
}

std::string shown(std::string_view token) {
    std::string s;
    for (std::size_t i = 0; i < token.size() && i < 40; ++i) {
        unsigned char c = static_cast<unsigned char>(token[i]);
        s += (c >= 32 && c < 127) ? static_cast<char>(c) : '?';
    }
    if (token.size() > 40) s += "...";
    return "'" + s + "'";
}

}  // namespace

namespace {

// q 2^k, exactly.
Rational times_power_of_two(const Rational& q, long k) {
    Rational r;
    fmpq_mul_2exp(r.get(), q.get(), static_cast<ulong>(k));
    return r;
}

// The extent of the site set (the larger side of the bounding box of the
// sites' bounding circles) against its smallest semi-axis: in doubles when
// they clearly decide, exactly otherwise (numbers beyond the double range,
// or a ratio near the limit).
void require_dynamic_range(const SiteFile& file) {
    if (file.sites.size() < 2) return;
    constexpr double kClearlyInside = 0x1p250;
    double x_lo = HUGE_VAL, x_hi = -HUGE_VAL, y_lo = HUGE_VAL, y_hi = -HUGE_VAL, smallest = HUGE_VAL;
    for (const Ellipse& e : file.sites) {
        const auto& k = e.enclosure();
        const double r = std::max(k.a.hi, k.b.hi);
        x_lo = std::min(x_lo, k.xc.lo - r), x_hi = std::max(x_hi, k.xc.hi + r);
        y_lo = std::min(y_lo, k.yc.lo - r), y_hi = std::max(y_hi, k.yc.hi + r);
        smallest = std::min({smallest, k.a.lo, k.b.lo});
    }
    const double extent = std::max(x_hi - x_lo, y_hi - y_lo);
    if (std::isfinite(extent) && smallest > 0 && extent < kClearlyInside * smallest) return;

    std::size_t tiniest = 0;
    Rational xmin, xmax, ymin, ymax, least;
    for (std::size_t i = 0; i < file.sites.size(); ++i) {
        const Ellipse& e = file.sites[i];
        const Rational r = std::max(e.a(), e.b()), s = std::min(e.a(), e.b());
        if (i == 0 || e.xc() - r < xmin) xmin = e.xc() - r;
        if (i == 0 || e.xc() + r > xmax) xmax = e.xc() + r;
        if (i == 0 || e.yc() - r < ymin) ymin = e.yc() - r;
        if (i == 0 || e.yc() + r > ymax) ymax = e.yc() + r;
        if (i == 0 || s < least) least = s, tiniest = i;
    }
    const Rational span = std::max(xmax - xmin, ymax - ymin);
    if (span <= times_power_of_two(least, kMaxDynamicRangeBits)) return;
    const long bits = static_cast<long>(fmpz_bits(fmpq_numref(span.get()))) -
                      static_cast<long>(fmpz_bits(fmpq_denref(span.get()))) -
                      static_cast<long>(fmpz_bits(fmpq_numref(least.get()))) +
                      static_cast<long>(fmpz_bits(fmpq_denref(least.get())));
    const std::string reason = "the site set spans about 2^" + std::to_string(bits) + " times the smallest semi-axis, " +
                               (file.lines.empty() ? "site " + std::to_string(tiniest) + "'s" : std::string("this site's")) +
                               "; ellvor supports extents up to 2^" + std::to_string(kMaxDynamicRangeBits) +
                               " times the smallest semi-axis";
    if (file.lines.empty()) throw InputError(reason);
    throw InputError(file.name, file.lines[tiniest], 1, reason);
}

// The first site of each point set so far: a lookup rather than a comparison
// with every earlier site (8000 concentric sites took 7.6 s to read when each
// was compared with all). One point set has one center, so sites are hashed
// by their center's double enclosure, and point-set keys (rational quadratic
// forms: most of a reader's time when every site had one) are made only for
// sites whose centers round alike.
class PointSetIndex {
public:
    explicit PointSetIndex(std::size_t expected_sites = 0) { resize(2 * expected_sites); }

    // Throws unless site `id` of the file is a point set that no earlier site
    // is; the error is at the later site's line when the file has lines.
    void require_new(const SiteFile& file, std::size_t id) {
        const Ellipse& e = file.sites[id];
        // + 0.0: -0.0 and 0.0 are one center.
        const double x = e.enclosure().xc.lo + 0.0, y = e.enclosure().yc.lo + 0.0;
        if (4 * (used_ + 1) > 3 * slots_.size()) resize(2 * slots_.size());
        Slot& slot = slots_[find(x, y)];
        if (slot.first == kEmpty) {
            slot = {x, y, id};
            ++used_;
            return;
        }
        std::map<Ellipse::PointSetKey, std::size_t>& keyed = keyed_[slot.first];
        if (keyed.empty()) keyed.emplace(file.sites[slot.first].point_set_key(), slot.first);
        const auto [earlier, inserted] = keyed.emplace(e.point_set_key(), id);
        if (!inserted) duplicate(file, earlier->second, id);
    }

private:
    // Open addressing (linear probing, at most 3/4 full) on the centers: one
    // flat array, no allocation a site (a node-based map's allocations and
    // frees were 60% of making a tiled build's tile of sites).
    static constexpr std::size_t kEmpty = static_cast<std::size_t>(-1);
    struct Slot {
        double x = 0, y = 0;
        std::size_t first = kEmpty;  // the first site with this center
    };
    std::size_t find(double x, double y) const {
        std::uint64_t bx, by;
        std::memcpy(&bx, &x, sizeof bx);
        std::memcpy(&by, &y, sizeof by);
        const std::size_t mask = slots_.size() - 1;
        std::uint64_t h = bx * 0x9e3779b97f4a7c15ull ^ by;  // then a 64-bit finalizer (MurmurHash3's)
        h = (h ^ (h >> 33)) * 0xff51afd7ed558ccdull;
        h = (h ^ (h >> 33)) * 0xc4ceb9fe1a85ec53ull;
        std::size_t k = static_cast<std::size_t>(h ^ (h >> 33)) & mask;
        while (slots_[k].first != kEmpty && !(slots_[k].x == x && slots_[k].y == y)) k = (k + 1) & mask;
        return k;
    }
    void resize(std::size_t wanted) {
        std::size_t size = 16;
        while (size < wanted) size *= 2;
        std::vector<Slot> old(size);
        old.swap(slots_);
        for (const Slot& s : old)
            if (s.first != kEmpty) slots_[find(s.x, s.y)] = s;
    }
    [[noreturn]] static void duplicate(const SiteFile& file, std::size_t other, std::size_t id) {
        const Ellipse& e = file.sites[id];
        const bool lines = !file.lines.empty();
        auto line_of = [&](std::size_t k) { return lines ? " (line " + std::to_string(file.lines[k]) + ")" : std::string(); };
        const std::string reason = "duplicate site: site " + std::to_string(id) + line_of(id) + " is the same " +
                                   (file.sites[other] == e ? "ellipse" : "point set") + " as site " +
                                   std::to_string(other) + line_of(other) + "; sites must be distinct";
        const InputError::SitePair pair{other, id};
        if (!lines) throw InputError(reason, pair);
        throw InputError(file.name, file.lines[id], 1, reason, pair);
    }
    std::vector<Slot> slots_;
    std::size_t used_ = 0;
    // Per center met twice (keyed by its first site): the point-set keys.
    std::unordered_map<std::size_t, std::map<Ellipse::PointSetKey, std::size_t>> keyed_;
};

}  // namespace

SiteFile read_site_file(std::istream& in, const std::string& name, SiteFormat format) {
    SiteFile file;
    file.name = name;
    const bool cin_format = format == SiteFormat::cin;
    const std::size_t nfields = cin_format ? 3 : 5;
    const char* fields_text = cin_format ? "3 fields x y r" : "5 fields a b w xc yc";
    static const char* ell_names[] = {"a", "b", "w", "xc", "yc"};
    static const char* cin_names[] = {"x", "y", "r"};
    const char** names = cin_format ? cin_names : ell_names;

    PointSetIndex point_sets;

    std::streambuf* buf = in.rdbuf();
    if (!buf) throw InputError(name, 1, 1, "cannot read input");
    std::string line;
    long line_number = 0;
    while (read_line(*buf, line, name, line_number + 1)) {
        ++line_number;
        std::size_t nul = line.find('\0');
        if (nul != std::string::npos && nul < line.find('#'))
            throw InputError(name, line_number, static_cast<long>(nul) + 1,
                             "unexpected NUL byte; expected a text file");
        std::vector<Token> tokens = split(line);
        if (tokens.empty()) continue;
        if (tokens.size() < nfields)
            throw InputError(name, line_number, end_column(line),
                             std::string("expected ") + fields_text + ", found " + std::to_string(tokens.size()) +
                                 " (missing field " + names[tokens.size()] + ")");
        if (tokens.size() > nfields)
            throw InputError(name, line_number, tokens[nfields].column,
                             std::string("expected ") + fields_text + ", found " + std::to_string(tokens.size()) +
                                 " (extra field " + shown(tokens[nfields].text) + ")");
        std::vector<Rational> values(nfields);
        for (std::size_t k = 0; k < nfields; ++k) {
            std::string error;
            if (!parse_rational(tokens[k].text, values[k], error))
                throw InputError(name, line_number, tokens[k].column, "field " + std::string(names[k]) + ": " + error);
        }
        auto positive = [&](std::size_t k, const char* what) {
            if (values[k].sign() <= 0)
                throw InputError(name, line_number, tokens[k].column,
                                 std::string(what) + " must be positive, found " + values[k].str());
        };
        if (cin_format) {
            positive(2, "radius r");
        } else {
            positive(0, "semi-axis a");
            positive(1, "semi-axis b");
            const bool a_larger = values[0] > values[1];
            const Rational& larger = values[a_larger ? 0 : 1];
            const Rational& smaller = values[a_larger ? 1 : 0];
            if (larger > times_power_of_two(smaller, kMaxAspectBits))
                throw InputError(name, line_number, tokens[a_larger ? 0 : 1].column,
                                 "semi-axes " + shown(tokens[0].text) + " and " + shown(tokens[1].text) +
                                     " differ by more than a factor 2^" + std::to_string(kMaxAspectBits) +
                                     ", the largest ratio ellvor supports");
        }
        if (file.sites.size() >= kMaxSites)
            throw InputError(name, line_number, 1, "too many sites: at most " + std::to_string(kMaxSites));
        Ellipse e = cin_format ? Ellipse::circle(values[0], values[1], values[2])
                               : Ellipse(values[0], values[1], values[2], values[3], values[4]);
        file.sites.push_back(std::move(e));
        file.lines.push_back(line_number);
        point_sets.require_new(file, file.sites.size() - 1);
    }
    if (in.bad()) throw InputError(name, line_number + 1, 1, "read error");
    require_dynamic_range(file);
    return file;
}

SiteFile read_site_file(const std::string& path, SiteFormat format) {
    if (path == "-") return read_site_file(std::cin, "<stdin>", format);
    struct stat st;
    if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
        throw InputError(path, 1, 1, "cannot read: is a directory; expected a site file");
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        const int err = errno;
        throw InputError(path, 1, 1, std::string("cannot open file: ") + std::strerror(err));
    }
    return read_site_file(in, path, format);
}

void check_site_set(const SiteFile& file) {
    PointSetIndex point_sets(file.sites.size());
    for (std::size_t id = 0; id < file.sites.size(); ++id) point_sets.require_new(file, id);
    require_dynamic_range(file);
}

std::vector<Ellipse> read_sites(std::istream& in, const std::string& name, SiteFormat format) {
    return read_site_file(in, name, format).sites;
}

std::vector<Ellipse> read_sites(const std::string& path, SiteFormat format) {
    return read_site_file(path, format).sites;
}

namespace {
void write_header(std::ostream& out, const std::string& header) {
    if (header.empty()) return;
    std::size_t start = 0;
    while (start <= header.size()) {
        std::size_t end = header.find('\n', start);
        if (end == std::string::npos) end = header.size();
        out << "# " << header.substr(start, end - start) << '\n';
        if (end == header.size()) break;
        start = end + 1;
    }
}
}  // namespace

void write_ell(std::ostream& out, const std::vector<Ellipse>& sites, const std::string& header) {
    write_header(out, header);
    for (const Ellipse& e : sites) out << e.str() << '\n';
}

void write_cin(std::ostream& out, const std::vector<Ellipse>& sites, const std::string& header) {
    for (std::size_t i = 0; i < sites.size(); ++i)
        if (!sites[i].is_circle())
            throw Error("write_cin: site " + std::to_string(i) + " is not a circle (a != b)");
    write_header(out, header);
    for (const Ellipse& e : sites) out << e.xc().str() << ' ' << e.yc().str() << ' ' << e.a().str() << '\n';
}

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
    std::string dir = ".", base = path;
    std::size_t slash = path.rfind('/');
    if (slash != std::string::npos) {
        dir = slash == 0 ? "/" : path.substr(0, slash);
        base = path.substr(slash + 1);
    }
    if (base.empty()) throw Error("cannot write '" + path + "': not a file name");
    std::string tmpl = dir + "/." + base + ".tmp.XXXXXX";
    std::vector<char> name(tmpl.begin(), tmpl.end());
    name.push_back('\0');
    int fd = ::mkstemp(name.data());
    if (fd < 0) throw Error("cannot write '" + path + "': " + std::strerror(errno));
    mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);
    ::close(fd);
    const std::string tmp(name.data());
    try {
        {
            std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
            if (!out) throw Error("cannot write '" + path + "': cannot open temporary file");
            write(out);
            out.flush();
            if (!out) throw Error("cannot write '" + path + "': write failed");
        }
        if (std::rename(tmp.c_str(), path.c_str()) != 0)
            throw Error("cannot write '" + path + "': " + std::strerror(errno));
    } catch (...) {
        std::remove(tmp.c_str());
        throw;
    }
}

IntersectingSites crossing_sites_error(const SiteFile& file, std::size_t first, std::size_t second, const std::string& why) {
    if (first > second) std::swap(first, second);
    return IntersectingSites(file.name, file.lines[second], 1,
                             "site " + std::to_string(second) + " crosses site " + std::to_string(first) + " (line " +
                                 std::to_string(file.lines[first]) + "): " + why,
                             first, second, why);
}

}  // namespace ellvor
