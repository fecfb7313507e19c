#include "scene/model_file.h"

#include <filesystem>

#include "core/error.h"
#include "core/text.h"
#include "scene/raw_model.h"

namespace rt {
std::optional<Model::Format> modelFormatFromName(const std::string& name) {
    const std::string n = lowerCase(name);
    if (n == "raw") return Model::Format::Raw;
    if (n == "3ds") return Model::Format::Max3ds;
    return std::nullopt;
}

std::optional<Model::Format> modelFormatFromExtension(const std::string& path) {
    const std::string ext = std::filesystem::path(path).extension().string();
    return ext.empty() ? std::nullopt : modelFormatFromName(ext.substr(1));
}

const char* modelFormatName(Model::Format format) { return format == Model::Format::Raw ? "raw" : "3ds"; }

Model readRawModelFileOnly(const std::string& path, Model::Format format) {
    if (format != Model::Format::Raw)
        throw InputError(path +
                         ": a 3ds model is read through the import layer (rt::loadScene); "
                         "this scene reader takes RAW models only");
    return readRawFile(path);
}

}  // namespace rt
