#include "io/obj_syntax.h"

#include <charconv>
#include <cmath>

namespace rt {
namespace {

// Calls take(token) for each blank-separated token after the line's keyword, up to a
// comment; stops early and returns false when take does.
template <typename Take>
bool forEachToken(std::string_view line, Take take) {
    constexpr std::string_view kBlank = " \t\r";
    std::size_t at = line.find_first_not_of(kBlank);
    at = line.find_first_of(kBlank, at);  // past the keyword
    while (at != std::string_view::npos) {
        at = line.find_first_not_of(kBlank, at);
        if (at == std::string_view::npos || line[at] == '#') break;
        const std::size_t end = std::min(line.find_first_of(kBlank, at), line.size());
        if (!take(line.substr(at, end - at))) return false;
        at = end;
    }
    return true;
}

std::optional<double> wholeNumber(std::string_view token) {
    if (token.size() > 1 && token[0] == '+' && token[1] != '-') token.remove_prefix(1);  // from_chars takes no '+'
    double value = 0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size() || !std::isfinite(value)) return std::nullopt;
    return value;
}

// An optional sign and 1-9 digits.
bool isIndex(std::string_view part) {
    if (!part.empty() && (part[0] == '-' || part[0] == '+')) part.remove_prefix(1);
    if (part.empty() || part.size() > 9) return false;
    for (const char c : part)
        if (c < '0' || c > '9') return false;
    return true;
}

}  // namespace

std::optional<Point3f> parseObjVertex(std::string_view line) {
    Point3f p{};
    int count = 0;
    const bool numbers = forEachToken(line, [&](std::string_view token) {
        const std::optional<double> v = wholeNumber(token);
        if (!v) return false;
        if (count < 3) p[std::size_t(count)] = float(*v);
        ++count;
        return true;
    });
    if (!numbers || count < 3 || !std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
        return std::nullopt;
    return p;
}

bool isObjFace(std::string_view line) {
    if (line.find('#') != std::string_view::npos) return false;  // tinyobjloader would read it as corners
    return forEachToken(line, [](std::string_view corner) {
        const std::size_t slash1 = corner.find('/');
        if (slash1 == std::string_view::npos) return isIndex(corner);
        const std::size_t slash2 = corner.find('/', slash1 + 1);
        const std::string_view texture =
            corner.substr(slash1 + 1, slash2 == std::string_view::npos ? std::string_view::npos : slash2 - slash1 - 1);
        const bool normalOk = slash2 == std::string_view::npos || isIndex(corner.substr(slash2 + 1));
        return isIndex(corner.substr(0, slash1)) && (texture.empty() || isIndex(texture)) && normalOk;
    });
}

}  // namespace rt
