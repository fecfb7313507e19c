#include "tool.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <new>
#include <stdexcept>

#include "core/error.h"
#include "core/real.h"
#include "os/atomic_file.h"
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
    std::cerr << toolName << " ERROR: " << oneLine(message) << std::endl;
}

std::string oneLine(std::string_view message) {
    const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
    std::string line;
    for (std::size_t i = 0; i < message.size(); ++i) {
        if (message[i] != '\n' && message[i] != '\r') {
            line += message[i];
            continue;
        }
        while (!line.empty() && blank(line.back())) line.pop_back();
        while (i + 1 < message.size() && blank(message[i + 1])) ++i;
        if (!line.empty() && i + 1 < message.size()) line += "; ";
    }
    return line;
}

namespace {

// Every write to standard output is checked here, once, rather than after each `<<`: a tool
// whose table, JSON or -b line reached a full device or a closed stream must not exit 0.
// The reason is known only if this last flush fails; an earlier one (std::endl) has lost it.
void checkStandardOutput() {
    errno = 0;
    std::cout.flush();
    if (std::fflush(stdout) == 0 && std::cout && !std::ferror(stdout)) return;
    throw std::runtime_error(std::string("standard output: cannot write") + (errno ? ": " : "") +
                             (errno ? std::strerror(errno) : ""));
}

}  // namespace

int run(const std::string& toolName, const std::function<int()>& body) {
    removeTemporariesOnSignals();
    try {
        const int status = body();
        checkStandardOutput();
        return status;
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
