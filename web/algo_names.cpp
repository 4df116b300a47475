// The wasm module's one export besides _start: prints the names --algo accepts (algo_names() of
// tools/common/render.cpp), so the page lists exactly the algorithms this build of hider-render has.
#include <cstdio>
#include <string>

#include "common/render.hpp"

extern "C" __attribute__((export_name("hider_algo_names"))) void hider_algo_names() {
    const std::string names = hider::tool::algo_names();
    std::fwrite(names.data(), 1, names.size(), stdout);
    std::fflush(stdout);
}
