// std::from_chars for double on wasi-libc (see compat/charconv): strtod on a NUL-terminated copy, in the
// C locale (the WASI program never changes it), with from_chars' contract: no leading blanks or '+', a hex
// format without "0x" in the input, no hex in the general format, value untouched on failure, and
// result_out_of_range (ptr past the number) when the value over- or underflows. musl's strtod, like glibc's, is
// correctly rounded, so a number parses to the same double as on the host; the browser test compares.
#include <cerrno>
#include <cfloat>
#include <cstdlib>
#include <string>

#include <charconv>  // compat/charconv (first on the include path), then libc++'s

namespace std {

from_chars_result from_chars(const char* first, const char* last, double& value, chars_format fmt) {
    std::string text(first, last);
    if (text.empty() || text[0] == ' ' || text[0] == '\t' || text[0] == '\n' || text[0] == '\r' ||
        text[0] == '\f' || text[0] == '\v' || text[0] == '+')
        return {first, errc::invalid_argument};
    size_t prefix = 0;
    if (fmt == chars_format::hex) {
        if (text[0] == '-') {
            text.insert(1, "0x");
        } else {
            text.insert(0, "0x");
        }
        prefix = 2;
    } else {
        const size_t x = text.find_first_of("xX");  // from_chars' general format stops at an 'x'
        if (x != std::string::npos) text.resize(x);
    }
    errno = 0;
    char* end = nullptr;
    const double parsed = std::strtod(text.c_str(), &end);
    const size_t used = static_cast<size_t>(end - text.c_str());
    if (used <= prefix) return {first, errc::invalid_argument};
    const char* ptr = first + (used - prefix);
    // musl also reports ERANGE for a subnormal result; from_chars (and the host's libstdc++) accepts
    // those and refuses only results that underflow to zero or overflow to infinity. musl does not set
    // ERANGE when a hex number overflows or underflows, so the result decides there: an infinity the text
    // does not spell ("inf" holds an 'n', no number does), or a zero from a nonzero mantissa.
    const std::string number = text.substr(prefix, used - prefix);
    const bool infinite = parsed > DBL_MAX || parsed < -DBL_MAX;
    const bool spelled_inf = number.find_first_of("nN") != std::string::npos;
    bool nonzero_mantissa = false;
    for (const char c : number) {
        if (c == 'e' || c == 'E' || ((fmt == chars_format::hex) && (c == 'p' || c == 'P'))) break;
        if ((c >= '1' && c <= '9') || (fmt == chars_format::hex && ((c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F'))))
            nonzero_mantissa = true;
    }
    if ((errno == ERANGE && (parsed == 0 || infinite)) || (infinite && !spelled_inf) || (parsed == 0 && nonzero_mantissa))
        return {ptr, errc::result_out_of_range};
    value = parsed;
    return {ptr, errc{}};
}

}  // namespace std
