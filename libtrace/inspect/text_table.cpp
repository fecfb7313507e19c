#include "inspect/text_table.h"

#include <algorithm>
#include <cstdio>
#include <iomanip>
#include <stdexcept>

namespace rt {

void TextTable::addRow(std::vector<std::string> cells) {
    if (cells.size() != header_.size()) throw std::logic_error("TextTable: row and header differ in length");
    rows_.push_back(std::move(cells));
}

void TextTable::print(std::ostream& out) const {
    std::vector<std::size_t> widths(header_.size());
    for (std::size_t c = 0; c < header_.size(); ++c) {
        widths[c] = header_[c].size();
        for (const auto& row : rows_) widths[c] = std::max(widths[c], row[c].size());
    }
    const auto printRow = [&](const std::vector<std::string>& cells) {
        for (std::size_t c = 0; c < cells.size(); ++c) {
            if (c == 0)
                out << std::left << std::setw(int(widths[c])) << cells[c];
            else
                out << "  " << std::right << std::setw(int(widths[c])) << cells[c];
        }
        out << '\n';
    };
    printRow(header_);
    for (const auto& row : rows_) printRow(row);
}

std::string formatFixed(double value, int decimals) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
    return buf;
}

}  // namespace rt
