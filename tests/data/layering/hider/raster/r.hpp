// Fixture: raster/ must not include a part (sort/).
#pragma once
#include <hider/sort/s.hpp>
