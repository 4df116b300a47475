// README.md's memory figures for the sorted algorithms are the code's: the sizes it states for
// ScreenPoly, PieceCut and SortKey, and the bytes per Newell pool entry, are checked here.
#include <hider/sort/newell.hpp>
#include <hider/sort/painter.hpp>

#include <fstream>
#include <iterator>
#include <regex>
#include <string>

#include <doctest/doctest.h>

using namespace hider;

namespace {

std::string readme() {
    std::ifstream in(std::string(HIDER_TEST_DATA) + "/../../README.md");
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// The first number matched by group 1 of `pattern` in text, or -1.
long number(const std::string& text, const std::string& pattern) {
    std::smatch m;
    return std::regex_search(text, m, std::regex(pattern)) ? std::stol(m[1]) : -1;
}

}  // namespace

TEST_CASE("README.md states the sizes the code asserts for the sorted algorithms' memory") {
    const std::string text = readme();
    REQUIRE(!text.empty());
    CHECK(number(text, "`ScreenPoly` is ([0-9]+) bytes") == static_cast<long>(sizeof(ScreenPoly)));
    CHECK(number(text, "`PieceCut` ([0-9]+)") == static_cast<long>(sizeof(PieceCut)));
    CHECK(number(text, "`SortKey` ([0-9]+)") == static_cast<long>(sizeof(SortKey)));
    CHECK(number(text, "\\| `painter` \\| ([0-9]+) B per polygon") == static_cast<long>(sizeof(ScreenPoly)));
    // Newell per pool entry: the polygon, order, heap, heap index, two grid links and the chain entry.
    const long per_entry = static_cast<long>(sizeof(ScreenPoly) + 6 * sizeof(uint32_t));
    CHECK(number(text, "\\| `newell` \\| ([0-9]+) B per pool entry \\(polygon ([0-9]+)") == per_entry);
    CHECK(number(text, "B per pool entry \\(polygon ([0-9]+)") == static_cast<long>(sizeof(ScreenPoly)));
    CHECK(number(text, "\\+ ([0-9]+) B per polygon built \\(sort keys\\)") == static_cast<long>(2 * sizeof(SortKey)));
    CHECK(number(text, "\\+ ([0-9]+) B per cut \\(two") == static_cast<long>(2 * sizeof(PieceCut)));
    CHECK(number(text, "4 B per grid cell \\(([0-9]+) at 320x240\\)") == static_cast<long>(grid_cells(320, 240)));
    CHECK(number(text, "no piece carries more than ([0-9]+) cuts") == kMaxPieceCuts);
}
