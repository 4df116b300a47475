// hider-scenes: writes a generated test scene (tools/common/gen_scenes.hpp) as OBJ and prints the
// hider-render options for its camera. Usage: hider-scenes NAME -o OUT.obj. Errors exit 2.
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "common/cli.hpp"
#include "common/gen_scenes.hpp"
#include "host/ppm.hpp"

int main(int argc, char** argv) {
    hider::tool::exit_2_when_out_of_memory("hider-scenes");
    using namespace hider::tool;
    std::string name, out;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "-o" && i + 1 < argc) out = argv[++i];
        else if (a == "-h" || a == "--help") {
            std::cout << "usage: hider-scenes NAME -o OUT.obj\nNAME: " << gen::name_patterns() << "\n";
            return 0;
        } else if (!a.empty() && a[0] != '-' && name.empty()) name = a;
        else {
            std::cerr << "hider-scenes: unexpected argument '" << a << "'\nusage: hider-scenes NAME -o OUT.obj\n";
            return 2;
        }
    }
    if (name.empty() || out.empty()) {
        std::cerr << "hider-scenes: need a scene name and -o OUT.obj\nNAME: " << gen::name_patterns() << "\n";
        return 2;
    }
    gen::GenScene s;
    std::string why;
    if (!gen::by_name(name, s, why)) {
        std::cerr << "hider-scenes: " << why << "\n";
        return 2;
    }
    std::ostringstream text;
    gen::write_obj(s, text);
    if (!hider::port::write_file(out, text.str(), why)) {  // no partial OBJ left behind
        std::cerr << "hider-scenes: " << why << "\n";
        return 2;
    }
    std::cout << gen::camera_flags(s) << "\n";
    return 0;
}
