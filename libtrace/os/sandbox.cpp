#include "os/sandbox.h"

#include <filesystem>

#include "core/error.h"

namespace rt {
namespace {

namespace fs = std::filesystem;

fs::path& sandboxFolder() {  // canonical; empty: no sandbox
    static fs::path folder;
    return folder;
}

}  // namespace

void setSandbox(const std::string& folder) {
    std::error_code ec;
    if (folder.empty()) {
        sandboxFolder().clear();
        return;
    }
    const fs::path canonical = fs::canonical(folder, ec);
    if (ec || !fs::is_directory(canonical, ec))
        throw InputError("--sandbox " + folder + ": not a folder" + (ec ? ": " + ec.message() : ""));
    sandboxFolder() = canonical;
}

std::optional<std::string> sandboxRefusal(const std::string& path, const std::string& asGiven) {
    const fs::path& folder = sandboxFolder();
    if (folder.empty()) return std::nullopt;
    // weakly_canonical resolves the symbolic links of the part that exists and `..` everywhere,
    // so a link inside the folder that points out of it is caught, and so is a missing file's `..`.
    std::error_code ec;
    const fs::path resolved = fs::weakly_canonical(fs::absolute(path, ec), ec);
    const fs::path relative = resolved.lexically_relative(folder);
    if (!ec && !relative.empty() && *relative.begin() != "..") return std::nullopt;
    return asGiven + (ec ? " cannot be resolved" : " resolves to " + resolved.string()) + ", outside the sandbox " +
           folder.string() + " (--sandbox)";
}

void requireInsideSandbox(const std::string& path, const std::string& asGiven, const std::string& where) {
    if (const std::optional<std::string> why = sandboxRefusal(path, asGiven)) throw InputError(where + ": " + *why);
}

}  // namespace rt
