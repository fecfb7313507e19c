#include "command_line.h"

#include <omp.h>
#include <pthread.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <fstream>

#include "core/error.h"
#include "core/text.h"
#include "scene/input_file.h"
#include "scene/sandbox.h"
#include "tool.h"

namespace rt::tool {

std::optional<int> parseCommandLine(CLI::App& app, const std::string& toolName, int argc, char** argv) {
    app.failure_message(
        [toolName](const CLI::App*, const CLI::Error& e) { return toolName + " ERROR: " + e.what() + "\n"; });
    try {
        app.parse(argc, argv);
        return std::nullopt;
    } catch (const CLI::ParseError& e) {
        // CLI11 checks required arguments and values before it looks at what is left over.
        const bool isError = e.get_exit_code() != int(CLI::ExitCodes::Success);
        const int code =
            isError && !app.remaining().empty() ? app.exit(CLI::ExtrasError(app.remaining())) : app.exit(e);
        return code == 0 ? kExitOk : kExitBadInput;
    }
}

OptionValues optionValues(const CLI::App& app) {
    OptionValues values;
    for (const CLI::Option* option : app.get_options()) {
        const std::string name = option->get_single_name();
        if (name == "help" || name == "version") continue;
        std::vector<std::string> given = option->reduced_results();
        if (given.empty() && !option->get_default_str().empty()) given.push_back(option->get_default_str());
        if (given.empty() && option->get_expected_min() == 0) given.push_back("false");  // a flag not given
        values.emplace_back(name, std::move(given));
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
