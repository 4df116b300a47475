// Fixture for the layering check's negative test: core must not include raster/.
#pragma once
#include <hider/raster/r.hpp>
namespace hider { namespace detail { inline int core_private() { return 1; } }  // namespace detail
}  // namespace hider
