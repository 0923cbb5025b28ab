// The site ids of `ellvor build --remove IDS`: a comma-separated list of
// 0-based ids ("3,17,4"), or "@FILE" with one id a line ('#' starts a
// comment, blank lines are skipped). Each id must name one of the file's
// sites and appear once; the order is kept (the removal order).
#pragma once

#include "decision/site_id.hpp"

#include <string>
#include <vector>

namespace ellvor::cli {

// Throws UsageError for a bad inline list (naming the item), InputError
// (FILE:LINE:COLUMN) for a bad id file or one that cannot be read.
std::vector<SiteId> parse_removal_list(const std::string& spec, std::size_t site_count);

}  // namespace ellvor::cli
