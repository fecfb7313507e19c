// The command-line conventions the rt tools share: parse errors in one line, in the order a
// user should fix them, and numbers checked with messages that say what is wrong
// ("abc is not a number", "-1 is not in 0-1024"), where CLI11's Range says "not in range"
// for both and prints the limits of double in full.
#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/names.h"

namespace rt::tool {

// --flat of rt-convert and rt-render (a model file read directly): ImportOptions::flat.
inline constexpr const char* kFlatHelp =
    "Keep the facets of meshes without vertex normals (default: normals by a crease angle of 30 degrees)";

// --double-sided of rt-convert and rt-render: ImportOptions::doubleSided.
inline constexpr const char* kDoubleSidedHelp =
    "Make every material two-sided, whatever the file says (glTF doubleSided false): for a model whose triangles "
    "face inwards and that renders inside out";

// The scene argument of rt-render and rt-inspect, which read it the same way (import/load_scene.h).
inline constexpr const char* kSceneHelp = "Scene: rt XML (- reads standard input) or any model rt-convert reads";

// Parses the command line. Returns the exit code when the tool must stop (0 after --help or
// --version, 2 after a parse error, printed as "tool ERROR: what"), nothing when it runs.
// An unknown argument is reported before anything else: "--treads 2" is a typo, and a
// missing scene or a bad value reported instead of it would send the user the wrong way.
std::optional<int> parseCommandLine(CLI::App& app, const std::string& toolName, int argc, char** argv);

// One option's value as a statistics record keeps it (--stats-json), typed as the option is:
// a flag is a boolean, a number a number, an option given several times (-f) a list.
struct OptionValue {
    enum class Type { Boolean, Number, Text, List };
    std::string name;  // the long name, without dashes
    Type type = Type::Text;
    std::vector<std::string> values;  // the command line's words, else the default; empty: neither
};
using OptionValues = std::vector<OptionValue>;

// Every option of `app` after parsing, by its long name, with the values the command line gave it,
// else its default, else none (a flag: false): what a statistics record needs to repeat a run.
OptionValues optionValues(const CLI::App& app);

// A validator for a number from `lowest` to `highest` (inclusive) that T holds.
template <class T>
CLI::Validator numberIn(T lowest, T highest) {
    std::ostringstream range;
    range << lowest << "-" << highest;
    return CLI::Validator(
        [=, range = range.str()](std::string& text) -> std::string {
            double number = 0;
            T value{};
            if (!CLI::detail::lexical_cast(text, number)) return text + " is not a number";
            if (!(number >= double(lowest) && number <= double(highest))) return text + " is not in " + range;
            if (!CLI::detail::lexical_cast(text, value)) return text + " is not a whole number";
            return {};
        },
        CLI::Range(lowest, highest).get_description());
}

// --option NAME with one of `table`'s names (core/names.h), stored as the value it names; the
// check and --help list the names, and --help shows the current value as the default.
template <class E, std::size_t N>
CLI::Option* addNamedOption(CLI::App& app, const std::string& flags, E& value, const NamedValues<E, N>& table,
                            const std::string& help) {
    return app
        .add_option_function<std::string>(
            flags, [&value, &table](const std::string& name) { value = *parseNamed(table, name); }, help)
        ->check(CLI::IsMember(namesOf(table)))
        ->default_str(nameOf(table, value));
}

// A validator for a finite number above zero.
CLI::Validator positiveNumber();

// The most threads --threads accepts: far beyond any machine rt runs on, small enough that a
// typo (a negative number read as huge) is caught instead of starting thousands of threads.
constexpr int kMaxThreads = 1024;

// --threads N (0, the default, lets OpenMP use every core), checked as 0 to kMaxThreads. N > 0 is
// every parallel region's count from then on (the tree's build too), not only the render's.
CLI::Option* addThreadsOption(CLI::App& app, int& threads);

// --max-input MIB: the largest scene, model file or standard input read (scene/input_file.h).
CLI::Option* addMaxInputOption(CLI::App& app);

// --max-memory GB: the estimate a run must stay within (render/memory_estimate.h); unset: the default.
CLI::Option* addMaxMemoryOption(CLI::App& app, std::optional<double>& gigabytes);

// --sandbox DIR: every file the scene names must lie inside DIR (scene/sandbox.h).
CLI::Option* addSandboxOption(CLI::App& app);

}  // namespace rt::tool
