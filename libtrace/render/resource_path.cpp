#include "render/resource_path.h"

#include <filesystem>

namespace rt {

namespace fs = std::filesystem;

std::string findShippedFile(const std::string& installed, const std::string& source) {
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (ec) return {};
    for (fs::path dir = exe.parent_path(); !dir.empty(); dir = dir.parent_path()) {
        for (const fs::path& candidate : {dir / "share/rt" / installed, dir / source})
            if (fs::is_regular_file(candidate, ec)) return candidate.string();
        if (dir == dir.root_path()) break;
    }
    return {};
}

}  // namespace rt
