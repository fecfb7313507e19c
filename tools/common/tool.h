// What the rt tools share: the version line and one way of failing.
// Exit codes: 0 success, 1 runtime failure, 2 bad usage or bad input.
#pragma once

#include <functional>
#include <string>
#include <string_view>

namespace rt::tool {

constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;
constexpr int kExitBadInput = 2;

// "rt-render 0.1.0 (geometry in double, OpenMP 4.5)"
std::string versionLine(const std::string& toolName);

// Runs the body of a tool, with the temporaries of its outputs removed on SIGINT and SIGTERM
// (os/atomic_file.h). An rt::InputError prints "tool ERROR: message" and returns 2;
// any other exception prints the same shape and returns 1, and so does standard output that
// could not be written (a full device, a closed stream): everything the body printed there
// is flushed and checked before run returns.
int run(const std::string& toolName, const std::function<int()>& body);

// Prints "tool ERROR: message" on stderr, on one line (oneLine).
void printError(const std::string& toolName, const std::string& message);

// `message` as one line: a library's message of several lines (OpenImageIO's, libpng's through
// it) with each line break and the blanks around it turned into "; ", trailing ones dropped, so
// that every error and warning is one line, as docs/robustness.md promises.
std::string oneLine(std::string_view message);

}  // namespace rt::tool
