#include "cli/removal_list.hpp"

#include "cli/arguments.hpp"
#include "util/error.hpp"

#include <cctype>
#include <fstream>
#include <map>
#include <sstream>

namespace ellvor::cli {
namespace {

// Where an id came from, for messages: "item 3 of --remove" or FILE:LINE:COLUMN.
struct Origin {
    std::string file;      // empty: the inline list
    long line = 0, column = 0;
    long item = 0;         // in the inline list, from 1
    std::string describe() const {
        return file.empty() ? "item " + std::to_string(item) : file + ":" + std::to_string(line) + ":" + std::to_string(column);
    }
    [[noreturn]] void fail(const std::string& what) const {
        if (file.empty()) throw UsageError("option --remove: " + describe() + ": " + what);
        throw InputError(file, line, column, what);
    }
};

// The id in `text` (digits only, no sign, below 2^63).
SiteId parse_id(const std::string& text, const Origin& at) {
    if (text.empty()) at.fail("expected a site id (a 0-based integer), found nothing");
    SiteId id = 0;
    for (char c : text) {
        if (!std::isdigit(static_cast<unsigned char>(c)))
            at.fail("expected a site id (a 0-based integer), found '" + text + "'");
        if (id > (SiteId(1) << 62) / 10) at.fail("site id " + text + " is too large");
        id = 10 * id + static_cast<SiteId>(c - '0');
    }
    return id;
}

class Collector {
public:
    explicit Collector(std::size_t site_count) : site_count_(site_count) {}
    void add(const std::string& text, const Origin& at) {
        const SiteId id = parse_id(text, at);
        if (id >= site_count_)
            at.fail("site id " + std::to_string(id) + " is out of range (the file has " + std::to_string(site_count_) +
                    " sites, ids 0 to " + std::to_string(site_count_ == 0 ? 0 : site_count_ - 1) + ")");
        const auto [first, fresh] = seen_.emplace(id, at);
        if (!fresh) at.fail("site id " + std::to_string(id) + " is listed twice (first at " + first->second.describe() + ")");
        ids_.push_back(id);
    }
    std::vector<SiteId> take() { return std::move(ids_); }

private:
    std::size_t site_count_;
    std::map<SiteId, Origin> seen_;
    std::vector<SiteId> ids_;
};

std::string trim(const std::string& s, std::size_t& start) {
    start = 0;
    while (start < s.size() && std::isspace(static_cast<unsigned char>(s[start]))) ++start;
    std::size_t end = s.size();
    while (end > start && std::isspace(static_cast<unsigned char>(s[end - 1]))) --end;
    return s.substr(start, end - start);
}

}  // namespace

std::vector<SiteId> parse_removal_list(const std::string& spec, std::size_t site_count) {
    Collector ids(site_count);
    if (!spec.empty() && spec[0] == '@') {
        const std::string path = spec.substr(1);
        std::ifstream in(path);
        if (!in) throw InputError(path + ": cannot read the list of site ids to remove");
        std::string line;
        for (long number = 1; std::getline(in, line); ++number) {
            const std::size_t hash = line.find('#');
            if (hash != std::string::npos) line.resize(hash);
            std::size_t start = 0;
            const std::string id = trim(line, start);
            if (!id.empty()) ids.add(id, Origin{path, number, static_cast<long>(start) + 1, 0});
        }
        std::vector<SiteId> out = ids.take();
        if (out.empty()) throw InputError(path + ": no site ids to remove");
        return out;
    }
    std::stringstream items(spec);
    std::string item;
    long k = 0;
    while (std::getline(items, item, ',')) {
        std::size_t start = 0;
        ids.add(trim(item, start), Origin{"", 0, 0, ++k});
    }
    if (k == 0 || (!spec.empty() && spec.back() == ','))
        throw UsageError("option --remove: expected site ids separated by commas (e.g. 3,17,4) or @FILE");
    return ids.take();
}

}  // namespace ellvor::cli
