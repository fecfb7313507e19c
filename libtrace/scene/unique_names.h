// The names a scene writes: safe as XML attribute values and as file names, and unique within
// their table (materials, models, model files), so that every reference finds its target.
// One rule everywhere (rt-convert's names and saveSceneXml's): a name that is taken gets "_2",
// "_3", ... appended, the first that is free.
#pragma once

#include <set>
#include <string>

namespace rt {

// `name` with letters, digits, '_', '-' and '.' kept and anything else turned into '_'; a
// leading '.' becomes '_' too (no hidden files, no "..").
std::string safeName(const std::string& name);

// Hands out names unique within one table.
class NameTable {
public:
    // A caseless table tells names apart as lower case: file names on case-insensitive file systems.
    explicit NameTable(bool caseless = false) : caseless_(caseless) {}

    // `wanted`, or `fallback` when it is empty, with "_2", "_3", ... appended when taken.
    std::string claim(const std::string& wanted, const std::string& fallback);

private:
    bool caseless_;
    std::set<std::string> taken_;
};

}  // namespace rt
