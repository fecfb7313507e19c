// The one JSON writer of rt: every document the tools print (rt-render --stats-json,
// rt-inspect --json and --dump json, rt-convert --json) goes through it. A small streaming
// writer: it tracks nesting and commas, escapes strings (RFC 8259) and writes numbers so
// that they read back exactly. Two-space indentation, one member per line, like `jq .`.
// The documents and their fields are described in docs/json.md and docs/schema/.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace rt {

// The version of the documents' schema (docs/schema/), the first member of every document.
// It grows when a field is removed or changes its meaning or type; a new field keeps it.
inline constexpr int kJsonSchemaVersion = 2;

class JsonWriter {
public:
    explicit JsonWriter(std::ostream& out) : out_(out) {}

    // A tool's document: the top-level object, opened with its "version" member.
    void beginDocument();

    void beginObject();
    void endObject();
    void beginArray();
    void endArray();
    // The name of the next member of the current object.
    void key(std::string_view name);

    void value(std::string_view s);
    void value(const char* s) { value(std::string_view(s)); }
    void value(bool b);
    void null();
    void value(double d);  // non-finite numbers, which JSON cannot hold, become null
    void value(std::uint64_t n);
    void value(std::int64_t n);
    void value(std::uint32_t n) { value(std::uint64_t(n)); }
    void value(int n) { value(std::int64_t(n)); }

    // key(name) then value(v).
    template <typename T>
    void member(std::string_view name, const T& v) {
        key(name);
        value(v);
    }

private:
    void beforeValue();
    void newline();

    struct Level {
        bool array;
        bool empty = true;
    };
    std::ostream& out_;
    std::vector<Level> levels_;
    bool afterKey_ = false;
};

// `s` as a quoted JSON string with the characters JSON requires escaped.
std::string jsonQuoted(std::string_view s);

}  // namespace rt
