#include "command_line.h"

#include <omp.h>
#include <pthread.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <fstream>

#include "core/error.h"
#include "core/text.h"
#include "os/input_file.h"
#include "os/sandbox.h"
#include "tool.h"

namespace rt::tool {

namespace {

// Every name `app`'s options answer to, with their dashes: "-x", "--width", ...
std::vector<std::string> optionNames(const CLI::App& app) {
    std::vector<std::string> names;
    for (const CLI::Option* option : app.get_options()) {
        for (const std::string& name : option->get_snames()) names.push_back("-" + name);
        for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
    }
    return names;
}

// What was left over, in the order given (CLI11's own message reverses it), with the option
// meant where an unknown one is near a known one's name ("--widht": "did you mean --width?").
std::string leftOverMessage(const CLI::App& app) {
    const std::vector<std::string> left = app.remaining();
    std::string message = std::string(left.size() > 1 ? "The following arguments were not expected: "
                                                      : "The following argument was not expected: ") +
                          CLI::detail::join(left, " ");
    const auto unknown = std::find_if(left.begin(), left.end(), [](const std::string& word) {
        return word.size() > 1 && word[0] == '-' && !std::isdigit(static_cast<unsigned char>(word[1]));
    });
    if (unknown == left.end()) return message;
    const std::string typed = unknown->substr(0, unknown->find('='));  // --widht=100 means --widht
    if (const std::optional<std::string> meant = nearestName(typed, optionNames(app)))
        message += "; did you mean " + *meant + "?";
    return message;
}

// Whether CLI11 reads `option`'s value as a number (its type names are INT, UINT, FLOAT, NUMBER,
// followed by any check's description).
bool takesNumber(const CLI::Option& option) {
    const std::string type = option.get_type_name();
    return type.starts_with("INT") || type.starts_with("UINT") || type.starts_with("FLOAT") ||
           type.starts_with("NUMBER");
}

OptionValue::Type typeOf(const CLI::Option& option, const std::vector<std::string>& values) {
    if (option.get_items_expected_max() > 1) return OptionValue::Type::List;
    // A flag is true or false; one with a value (--adaptive=GRID) holds a number.
    const bool truth = values.size() == 1 && (values[0] == "true" || values[0] == "false");
    if (option.get_items_expected_max() == 0 && truth) return OptionValue::Type::Boolean;
    if (option.get_items_expected_max() == 0 || takesNumber(option)) return OptionValue::Type::Number;
    return OptionValue::Type::Text;
}

}  // namespace

std::optional<int> parseCommandLine(CLI::App& app, const std::string& toolName, int argc, char** argv) {
    // A mistake on the command line ends with the pointer to the options (docs/rt-render.md).
    app.failure_message([toolName](const CLI::App*, const CLI::Error& e) {
        return toolName + " ERROR: " + e.what() + " (" + toolName + " --help lists the options)\n";
    });
    try {
        app.parse(argc, argv);
        return std::nullopt;
    } catch (const CLI::ParseError& e) {
        // CLI11 checks required arguments and values before it looks at what is left over.
        const bool isError = e.get_exit_code() != int(CLI::ExitCodes::Success);
        const int code = isError && !app.remaining().empty()
                             ? app.exit(CLI::ExtrasError(leftOverMessage(app), CLI::ExitCodes::ExtrasError))
                             : app.exit(e);
        return code == 0 ? kExitOk : kExitBadInput;
    }
}

OptionValues optionValues(const CLI::App& app) {
    OptionValues values;
    for (const CLI::Option* option : app.get_options()) {
        const std::string name = option->get_single_name();
        if (name == "help" || name == "version") continue;
        std::vector<std::string> given = option->reduced_results();
        const std::string fallback = option->get_default_str();
        const bool list = option->get_items_expected_max() > 1;
        if (given.empty() && !fallback.empty() && !(list && fallback == "[]")) given.push_back(fallback);
        if (given.empty() && !list && option->get_expected_min() == 0) given.push_back("false");  // a flag not given
        const OptionValue::Type type = typeOf(*option, given);
        values.push_back({name, type, std::move(given)});
    }
    return values;
}

CLI::Validator positiveNumber() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            double value = 0;
            if (!CLI::detail::lexical_cast(text, value)) return text + " is not a number";
            if (!(value > 0 && std::isfinite(value))) return text + " is not a positive number";
            return {};
        },
        "POSITIVE");
}

namespace {

// Why `threads` threads cannot all start, or nothing. A thread OpenMP cannot make ends the
// process with libgomp's own message ("Thread creation failed"), not rt's error line; under an
// address-space limit (ulimit -v) that happens when their stacks (glibc's default size, which
// libgomp takes too) do not fit in what the limit leaves, so that is checked first.
std::string threadStacksProblem(int threads) {
    rlimit limit{};
    if (threads <= 1 || getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return {};
    pthread_attr_t attributes;
    std::size_t stack = 0;
    if (pthread_attr_init(&attributes) != 0) return {};
    pthread_attr_getstacksize(&attributes, &stack);
    pthread_attr_destroy(&attributes);
    std::uint64_t pages = 0;  // the address space in use: the first field of statm, in pages
    std::ifstream("/proc/self/statm") >> pages;
    const std::uint64_t used = pages * std::uint64_t(sysconf(_SC_PAGESIZE));
    const std::uint64_t stacks = std::uint64_t(threads - 1) * stack;
    if (used + stacks <= limit.rlim_cur) return {};
    return std::to_string(threads) + " threads need " + gigabytes(stacks) + " of address space for their stacks; " +
           "the limit (ulimit -v) leaves " + gigabytes(limit.rlim_cur > used ? limit.rlim_cur - used : 0) +
           ": use fewer threads";
}

}  // namespace

CLI::Option* addThreadsOption(CLI::App& app, int& threads) {
    return app.add_option("--threads", threads, "Threads of the build and the render (default 0: all cores)")
        ->check(numberIn(0, kMaxThreads))
        ->check(
            CLI::Validator([](std::string& text) { return threadStacksProblem(std::stoi(text)); }, "", "thread stacks"))
        ->each([](const std::string& text) {
            if (const int n = std::stoi(text); n > 0) omp_set_num_threads(n);
        });
}

CLI::Option* addMaxInputOption(CLI::App& app) {
    return app
        .add_option_function<std::uint64_t>(
            "--max-input", [](std::uint64_t mib) { setMaxInputBytes(mib << 20); },
            "Largest input file or standard input in MiB [default: " + std::to_string(kDefaultMaxInputBytes >> 20) +
                "]")
        ->check(numberIn<std::uint64_t>(1, std::uint64_t(1) << 30));
}

CLI::Option* addMaxMemoryOption(CLI::App& app, std::optional<double>& gigabytes) {
    return app
        .add_option("--max-memory", gigabytes,
                    "Refuse to start work estimated to need more memory than this, in GB (the picture, the scene and "
                    "tree, textures) [default: 3/4 of the machine's]")
        ->check(numberIn(0.01, 1e6));
}

CLI::Option* addSandboxOption(CLI::App& app) {
    return app
        .add_option_function<std::string>(
            "--sandbox",
            [](const std::string& folder) {
                try {
                    setSandbox(folder);
                } catch (const InputError& e) {
                    throw CLI::ValidationError(e.what());
                }
            },
            "Read only files inside this folder (after .. and symbolic links): the scene, its models, textures "
            "and buffers; for scenes you did not write")
        ->check(CLI::ExistingDirectory);
}

}  // namespace rt::tool
