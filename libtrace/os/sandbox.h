// --sandbox DIR (rt-render, rt-convert, rt-inspect), for render farms that read scenes they
// did not write: every file a scene or model names (the scene itself, <model> and RAW files,
// image textures, glTF buffers and images, OBJ material files, what Assimp opens) must lie
// inside DIR once `..` and symbolic links are resolved; any other is refused with exit 2,
// naming the reference, before it is opened. Relative references inside DIR work as ever.
// Process-wide, like --max-input (scene/input_file.h): set once while the options are read.
#pragma once

#include <optional>
#include <string>

namespace rt {

// Confines every later read to `folder`; an empty string lifts the confinement. Throws
// rt::InputError if `folder` is not a folder.
void setSandbox(const std::string& folder);

// Why `path` may not be read, with `asGiven` (the reference as the file spelt it) in front:
// "../x.png resolves to /srv/x.png, outside the sandbox /srv/farm (--sandbox)"; nothing
// when it lies inside the sandbox or none is set.
std::optional<std::string> sandboxRefusal(const std::string& path, const std::string& asGiven);

// Throws rt::InputError "`where`: <sandboxRefusal>" when `path` may not be read.
void requireInsideSandbox(const std::string& path, const std::string& asGiven, const std::string& where);

}  // namespace rt
