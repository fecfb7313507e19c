// An aligned plain-text table for people reading a terminal: the first column (labels)
// left-aligned, the others (numbers) right-aligned, columns separated by two spaces.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace rt {

class TextTable {
public:
    explicit TextTable(std::vector<std::string> header) : header_(std::move(header)) {}

    // A row must have as many cells as the header.
    void addRow(std::vector<std::string> cells);
    void print(std::ostream& out) const;

private:
    std::vector<std::string> header_;
    std::vector<std::vector<std::string>> rows_;
};

// A number with a fixed count of decimals ("12.35"), for table cells.
std::string formatFixed(double value, int decimals);

}  // namespace rt
