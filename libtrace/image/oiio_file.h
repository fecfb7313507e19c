// One way for every image rt writes through OpenImageIO: the file is encoded in memory, then
// written by os/atomic_file (checked writes, fsync, size check, rename; or in place for
// standard output and devices). OpenImageIO's own file writing does not report every failure:
// its PNG writer left a 0-byte or truncated file on a full disk and returned success.
#pragma once

#include <OpenImageIO/imageio.h>

#include <string>

namespace rt {

// Encodes `pixels` (of `pixelType`, laid out as `spec` says) with OpenImageIO's writer named
// `oiioFormat` ("png", "openexr", "targa") and writes the file to `path`; "-" is standard output.
// Throws std::runtime_error naming `path` if it cannot be encoded or written.
void writeImageFile(const std::string& path, const char* oiioFormat, const OIIO::ImageSpec& spec,
                    OIIO::TypeDesc pixelType, const void* pixels);

}  // namespace rt
