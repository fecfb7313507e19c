#include "io/base64.h"

#include <array>

namespace rt {
namespace {

constexpr std::string_view kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

constexpr std::array<std::int8_t, 256> decodingTable() {
    std::array<std::int8_t, 256> table{};
    table.fill(-1);
    for (std::size_t i = 0; i < kAlphabet.size(); ++i) table[std::uint8_t(kAlphabet[i])] = std::int8_t(i);
    return table;
}

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

}  // namespace

std::string encodeBase64(std::span<const std::uint8_t> bytes, std::size_t lineLength) {
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4 + (lineLength ? bytes.size() / lineLength + 1 : 0));
    std::size_t column = 0;
    auto put = [&](char c) {
        if (lineLength && column == lineLength) {
            out += '\n';
            column = 0;
        }
        out += c;
        ++column;
    };
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
        std::uint32_t group = std::uint32_t(bytes[i]) << 16;
        if (n > 1) group |= std::uint32_t(bytes[i + 1]) << 8;
        if (n > 2) group |= bytes[i + 2];
        for (std::size_t k = 0; k < 4; ++k) put(k <= n ? kAlphabet[group >> (18 - 6 * k) & 63] : '=');
    }
    return out;
}

std::optional<std::vector<std::uint8_t>> decodeBase64(std::string_view text, std::size_t& errorAt) {
    static constexpr std::array<std::int8_t, 256> table = decodingTable();
    std::vector<std::uint8_t> out;
    out.reserve(text.size() / 4 * 3);
    std::uint32_t group = 0;
    int digits = 0;   // in the current group of four
    int padding = 0;  // '=' seen so far; only whitespace and more '=' may follow one
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (isSpace(c)) continue;
        const bool pad = c == '=';
        const int value = table[std::uint8_t(c)];
        if ((!pad && (value < 0 || padding > 0)) || (pad && digits < 2)) {
            errorAt = i;
            return std::nullopt;
        }
        padding += pad;
        group = group << 6 | std::uint32_t(pad ? 0 : value);
        if (++digits < 4) continue;
        const int bytesInGroup = 3 - padding;
        for (int k = 0; k < bytesInGroup; ++k) out.push_back(std::uint8_t(group >> (16 - 8 * k)));
        group = 0;
        digits = 0;
        if (padding > 0) padding = 3;  // the text is complete: only whitespace may follow
    }
    if (digits != 0) {
        errorAt = text.size();
        return std::nullopt;
    }
    return out;
}

}  // namespace rt
