// Strict reading of XML elements for the scene loader: every error names the file and
// the line ("scene.xml:12: unknown attribute 'colour' on <material>"). pugixml reports
// byte offsets only, so XmlFile keeps the text and maps offsets to lines.
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <pugixml.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "core/color.h"
#include "core/names.h"
#include "core/vec3.h"
#include "io/parameters.h"

namespace rt {

// A parsed XML text and the line each of its bytes is on.
class XmlFile {
public:
    // Parses `text` and fills in the parameters of its attribute values (scene/parameters.h);
    // throws rt::InputError "name:line: what" for malformed XML or a parameter without a value.
    XmlFile(std::string text, std::string name, const SceneParameters& parameters = {});
    XmlFile(const XmlFile&) = delete;
    XmlFile& operator=(const XmlFile&) = delete;

    const pugi::xml_document& document() const { return doc_; }
    const std::string& name() const { return name_; }
    int lineAt(std::ptrdiff_t offset) const;  // 1-based
    // Throws rt::InputError "name:line: message" at the line of `node`.
    [[noreturn]] void failAt(pugi::xml_node node, const std::string& message) const;

private:
    void substitute(const SceneParameters& parameters);

    // newlinesBefore_[i]: the newlines before byte i * kLineBlock. A table of every line's start
    // took 8 bytes a line, 8 GB for a file of 1 GB of empty lines.
    static constexpr std::size_t kLineBlock = 4096;
    std::string text_;
    std::string name_;
    std::vector<std::uint64_t> newlinesBefore_;
    pugi::xml_document doc_;
};

// One element, read strictly: the constructor rejects attributes not in `allowed`, and
// every accessor throws rt::InputError at the element's line for a missing or bad value.
class XmlElement {
public:
    XmlElement(const XmlFile& file, pugi::xml_node node, std::initializer_list<std::string_view> allowed);

    pugi::xml_node node() const { return node_; }
    std::string tag() const;  // "<name>", for messages
    int line() const { return file_->lineAt(node_.offset_debug()); }
    [[noreturn]] void fail(const std::string& message) const;

    bool has(const char* attribute) const { return bool(node_.attribute(attribute)); }
    std::string string(const char* attribute) const;  // required
    std::optional<std::string> optionalString(const char* attribute) const;
    // "true" or "false"; anything else is an error.
    bool boolean(const char* attribute, bool fallback) const;

    // Finite decimal numbers ("1", "-0.5", "2e3"); NaN and infinities are errors.
    Real number(const char* attribute) const;  // required
    Real number(const char* attribute, Real fallback) const;
    // Like number(), and also an error below zero or (for positive) at zero.
    Real nonNegative(const char* attribute, Real fallback) const;
    Real positive(const char* attribute) const;
    // Whitespace-separated numbers, exactly `count` of them.
    std::vector<Real> numbers(const char* attribute, std::size_t count) const;

    // nonNegative() kept as a float (colours, material factors): beyond kMaxColorValue
    // (core/color.h) is an error here, not +inf in the picture.
    float nonNegativeFloat(const char* attribute, float fallback) const;
    // number() kept as a float whose magnitude is at most `limit` (a texture's transform).
    float floatWithin(const char* attribute, float fallback, double limit) const;
    // One of the names in `table`; an error naming them all for any other.
    template <class E, std::size_t N>
    E named(const char* attribute, const NamedValues<E, N>& table, E fallback) const {
        const std::optional<std::string> text = optionalString(attribute);
        if (!text) return fallback;
        if (const std::optional<E> value = parseNamed(table, *text)) return *value;
        std::string known;
        for (const std::string& name : namesOf(table)) known += (known.empty() ? "" : ", ") + name;
        fail("unknown " + std::string(attribute) + " '" + *text + "' (" + known + ")");
    }

    Vec3 xyz(Real fallback) const;                             // attributes x, y, z
    Color rgb(float fallback) const;                           // attributes r, g, b, each >= 0 and a finite float
    Color color(const char* attribute, Color fallback) const;  // "r g b", each >= 0 and a finite float

    // Child elements other than those named in `allowed`, and any text, are errors.
    void requireOnlyChildren(std::initializer_list<std::string_view> allowed) const;
    void requireNoChildren() const { requireOnlyChildren({}); }

private:
    Real parseNumber(const char* attribute, std::string_view text) const;

    const XmlFile* file_;
    pugi::xml_node node_;
};

}  // namespace rt
