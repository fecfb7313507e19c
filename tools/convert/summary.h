// What rt-convert tells the user about a conversion: a readable summary for stderr and
// the same figures as one JSON object for scripts (--json).
#pragma once

#include <ostream>
#include <string>

#include "io/import.h"

namespace rt::tool::convert {

struct Summary {
    std::string input;
    std::string output;  // empty when nothing was written
    const ImportResult* result = nullptr;
};

void printSummary(std::ostream& out, const Summary& summary);
void printSummaryJson(std::ostream& out, const Summary& summary);

}  // namespace rt::tool::convert
