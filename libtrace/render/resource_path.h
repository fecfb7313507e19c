// Files rt ships beside its programs (the OpenColorIO config, the demo scene), found from
// the running executable: installed as <prefix>/bin/rt-render with <prefix>/share/rt/...,
// or built anywhere under the source tree.
#pragma once

#include <string>

namespace rt {

// The first of <dir>/share/rt/<installed> and <dir>/<source> that exists, for each folder
// <dir> from the executable's own up to the root; "" if none does.
std::string findShippedFile(const std::string& installed, const std::string& source);

}  // namespace rt
