// A site's id: its 0-based index in the input (file order).
#pragma once

#include <cstddef>

namespace ellvor {

using SiteId = std::size_t;

}  // namespace ellvor
