#include "scene/unique_names.h"

#include <cctype>

#include "core/text.h"

namespace rt {

std::string safeName(const std::string& name) {
    std::string safe = name;
    for (char& c : safe)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.') c = '_';
    if (!safe.empty() && safe.front() == '.') safe.front() = '_';
    return safe;
}

std::string NameTable::claim(const std::string& wanted, const std::string& fallback) {
    const std::string base = wanted.empty() ? fallback : wanted;
    const auto key = [&](const std::string& name) { return caseless_ ? lowerCase(name) : name; };
    std::string name = base;
    for (int suffix = 2; !taken_.insert(key(name)).second; ++suffix) name = base + "_" + std::to_string(suffix);
    return name;
}

}  // namespace rt
