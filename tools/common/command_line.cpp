#include "command_line.h"

#include <omp.h>

#include <cmath>

#include "core/error.h"
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

CLI::Option* addThreadsOption(CLI::App& app, int& threads) {
    return app.add_option("--threads", threads, "Threads of the build and the render (default 0: all cores)")
        ->check(numberIn(0, kMaxThreads))
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
