#include "core/json_writer.h"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace rt {

std::string jsonQuoted(std::string_view s) {
    std::string out = "\"";
    for (const char c : s) {
        switch (c) {
            case '"':
                out += "\\\"";
                break;
            case '\\':
                out += "\\\\";
                break;
            case '\n':
                out += "\\n";
                break;
            case '\r':
                out += "\\r";
                break;
            case '\t':
                out += "\\t";
                break;
            case '\b':
                out += "\\b";
                break;
            case '\f':
                out += "\\f";
                break;
            default:
                if (static_cast<unsigned char>(c) < 0x20) {
                    static const char* hex = "0123456789abcdef";
                    out += "\\u00";
                    out += hex[(c >> 4) & 0xf];
                    out += hex[c & 0xf];
                } else {
                    out += c;  // UTF-8 passes through unchanged
                }
        }
    }
    return out + '"';
}

void JsonWriter::newline() {
    out_ << '\n';
    for (std::size_t i = 0; i < levels_.size(); ++i) out_ << "  ";
}

void JsonWriter::beforeValue() {
    if (afterKey_) {
        afterKey_ = false;
        return;
    }
    if (levels_.empty()) return;
    if (!levels_.back().array) throw std::logic_error("JsonWriter: a value inside an object needs a key");
    if (!levels_.back().empty) out_ << ',';
    levels_.back().empty = false;
    newline();
}

void JsonWriter::key(std::string_view name) {
    if (levels_.empty() || levels_.back().array || afterKey_)
        throw std::logic_error("JsonWriter: a key belongs directly inside an object");
    if (!levels_.back().empty) out_ << ',';
    levels_.back().empty = false;
    newline();
    out_ << jsonQuoted(name) << ": ";
    afterKey_ = true;
}

void JsonWriter::beginObject() {
    beforeValue();
    out_ << '{';
    levels_.push_back({false});
}

void JsonWriter::beginDocument() {
    if (!levels_.empty()) throw std::logic_error("JsonWriter: a document begins at the top level");
    beginObject();
    member("version", kJsonSchemaVersion);
}

void JsonWriter::beginArray() {
    beforeValue();
    out_ << '[';
    levels_.push_back({true});
}

void JsonWriter::endObject() {
    if (levels_.empty() || levels_.back().array || afterKey_) throw std::logic_error("JsonWriter: no object to end");
    const bool empty = levels_.back().empty;
    levels_.pop_back();
    if (!empty) newline();
    out_ << '}';
    if (levels_.empty()) out_ << '\n';
}

void JsonWriter::endArray() {
    if (levels_.empty() || !levels_.back().array) throw std::logic_error("JsonWriter: no array to end");
    const bool empty = levels_.back().empty;
    levels_.pop_back();
    if (!empty) newline();
    out_ << ']';
    if (levels_.empty()) out_ << '\n';
}

void JsonWriter::value(std::string_view s) {
    beforeValue();
    out_ << jsonQuoted(s);
}

void JsonWriter::value(bool b) {
    beforeValue();
    out_ << (b ? "true" : "false");
}

void JsonWriter::null() {
    beforeValue();
    out_ << "null";
}

void JsonWriter::value(double d) {
    beforeValue();
    if (!std::isfinite(d)) {
        out_ << "null";
        return;
    }
    // The shortest text that reads back as the same double.
    char buf[32];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, d);
    out_ << std::string_view(buf, ec == std::errc() ? std::size_t(end - buf) : 0);
}

void JsonWriter::value(std::uint64_t n) {
    beforeValue();
    out_ << n;
}

void JsonWriter::value(std::int64_t n) {
    beforeValue();
    out_ << n;
}

}  // namespace rt
