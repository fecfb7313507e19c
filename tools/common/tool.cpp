#include "tool.h"

#include <exception>
#include <iostream>
#include <new>

#include "core/error.h"
#include "core/real.h"
#include "version.h"

namespace rt::tool {

std::string versionLine(const std::string& toolName) {
    std::string line = toolName + " " + kVersion + " (geometry in " + realTypeName();
#ifdef _OPENMP
    line += ", OpenMP";
#endif
    return line + ")";
}

void printError(const std::string& toolName, const std::string& message) {
    std::cerr << toolName << " ERROR: " << message << std::endl;
}

int run(const std::string& toolName, const std::function<int()>& body) {
    try {
        return body();
    } catch (const InputError& e) {
        printError(toolName, e.what());
        return kExitBadInput;
    } catch (const std::bad_alloc&) {
        printError(toolName, "out of memory: the scene, its tree or the image is too large for this machine");
        return kExitFailure;
    } catch (const std::exception& e) {
        printError(toolName, e.what());
        return kExitFailure;
    }
}

}  // namespace rt::tool
