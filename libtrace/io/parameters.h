// Scene parameters (rt-render --set NAME=VALUE, as Mitsuba 3's -D): `$NAME`, `${NAME}` and
// `${NAME:-default}` in the attribute values of an XML scene are replaced by the value given, so
// that a parameter sweep needs no XML editing (docs/scene-format.md#parameters).
//
// A name is a letter or '_' followed by letters, digits and '_'. `$$` is one '$'; a '$' followed
// by anything else stays as it is. A name that was not given and has no default is an error.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace rt {

using SceneParameters = std::map<std::string, std::string, std::less<>>;

// "NAME=VALUE" (the value may be empty or hold '='); throws rt::InputError if NAME is not a name.
std::pair<std::string, std::string> parseParameterAssignment(const std::string& text);

// `text` with every parameter replaced. On a name that is neither given nor defaulted, returns
// nothing and sets `missing` to the name.
std::optional<std::string> substituteParameters(std::string_view text, const SceneParameters& parameters,
                                                std::string& missing);

}  // namespace rt
