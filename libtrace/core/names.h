// Closed sets of values that have names on the command line and in files (tree kinds, split
// methods, heat-map scales, ...). Each set is one table beside its enum; the parser, the
// printer and the tools' option checks all read it, so every name is typed once.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rt {

template <class E>
struct Named {
    const char* name;
    E value;
};

template <class E, std::size_t N>
using NamedValues = std::array<Named<E>, N>;

// The value called `name`, nullopt if none is.
template <class E, std::size_t N>
std::optional<E> parseNamed(const NamedValues<E, N>& table, std::string_view name) {
    for (const Named<E>& entry : table)
        if (name == entry.name) return entry.value;
    return std::nullopt;
}

// The name of `value`; "?" for a value the table does not hold.
template <class E, std::size_t N>
const char* nameOf(const NamedValues<E, N>& table, E value) {
    for (const Named<E>& entry : table)
        if (entry.value == value) return entry.name;
    return "?";
}

// A switch given by name (rt-render --alpha on|off).
inline constexpr NamedValues<bool, 2> kOnOffNames{{{"on", true}, {"off", false}}};

// Every name, in the table's order.
template <class E, std::size_t N>
std::vector<std::string> namesOf(const NamedValues<E, N>& table) {
    std::vector<std::string> names;
    for (const Named<E>& entry : table) names.emplace_back(entry.name);
    return names;
}

}  // namespace rt
