#include "io/parameters.h"

#include "core/error.h"

namespace rt {
namespace {

bool isNameStart(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool isNameChar(char c) { return isNameStart(c) || (c >= '0' && c <= '9'); }

// The length of the name at the start of `text` (0 if there is none).
std::size_t nameLength(std::string_view text) {
    if (text.empty() || !isNameStart(text[0])) return 0;
    std::size_t n = 1;
    while (n < text.size() && isNameChar(text[n])) ++n;
    return n;
}

// One reference after its '$': the name, its default (${NAME:-default}) and its length in `text`.
struct Reference {
    std::string_view name;
    std::optional<std::string_view> fallback;
    std::size_t length = 0;  // 0: not a reference, the '$' stays
};

Reference referenceAt(std::string_view text) {
    if (text.empty() || text[0] != '{') return {text.substr(0, nameLength(text)), std::nullopt, nameLength(text)};
    const std::size_t close = text.find('}');
    const std::size_t n = nameLength(text.substr(1));
    if (close == std::string_view::npos || n == 0) return {};
    const std::string_view inside = text.substr(1, close - 1);
    if (n == inside.size()) return {inside, std::nullopt, close + 1};
    if (inside.substr(n, 2) != ":-") return {};
    return {inside.substr(0, n), inside.substr(n + 2), close + 1};
}

}  // namespace

std::pair<std::string, std::string> parseParameterAssignment(const std::string& text) {
    const std::size_t equals = text.find('=');
    const std::string name = text.substr(0, equals);
    if (equals == std::string::npos || name.empty() || nameLength(name) != name.size())
        throw InputError("--set: expected NAME=VALUE (NAME of letters, digits and _), got '" + text + "'");
    return {name, text.substr(equals + 1)};
}

std::optional<std::string> substituteParameters(std::string_view text, const SceneParameters& parameters,
                                                std::string& missing) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '$') {
            out += text[i];
            continue;
        }
        const std::string_view rest = text.substr(i + 1);
        if (!rest.empty() && rest[0] == '$') {  // $$: one literal '$'
            out += '$';
            ++i;
            continue;
        }
        const Reference ref = referenceAt(rest);
        if (ref.length == 0) {
            out += '$';
            continue;
        }
        const auto given = parameters.find(ref.name);
        if (given == parameters.end() && !ref.fallback) {
            missing = std::string(ref.name);
            return std::nullopt;
        }
        out += given != parameters.end() ? std::string_view(given->second) : *ref.fallback;
        i += ref.length;
    }
    return out;
}

}  // namespace rt
