#include "os/contained.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <new>
#include <stdexcept>

#include "core/error.h"
#include "core/text.h"

namespace rt {
namespace {

// The child's reply: one of these bytes, then the result or the error message.
constexpr char kResult = 'R', kInputError = 'E', kOutOfMemory = 'M', kOtherError = 'F';

// Set in the child when an allocation failed: Assimp catches std::bad_alloc and reports it as
// a parse error, which is then reported as what it is.
bool allocationFailed = false;
void noteFailedAllocation() {
    allocationFailed = true;
    throw std::bad_alloc();
}

std::uint64_t addressSpaceInUse() {
    std::ifstream statm("/proc/self/statm");
    std::uint64_t pages = 0;
    statm >> pages;
    return pages * std::uint64_t(sysconf(_SC_PAGESIZE));
}

void setLimit(int resource, rlim_t soft, rlim_t hard) {
    const rlimit limit{soft, hard};
    setrlimit(resource, &limit);
}

bool writeAll(int fd, const std::string& bytes) {
    for (std::size_t done = 0; done < bytes.size();) {
        const ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        done += std::size_t(n);
    }
    return true;
}

std::string reply(const std::function<std::string()>& work) {
    try {
        return kResult + work();
    } catch (const InputError& e) {
        return (allocationFailed ? kOutOfMemory : kInputError) + std::string(e.what());
    } catch (const std::bad_alloc&) {
        return std::string(1, kOutOfMemory);
    } catch (const std::exception& e) {
        return (allocationFailed ? kOutOfMemory : kOtherError) + std::string(e.what());
    }
}

// The child: limits first, then the work; its reply goes to `out`, anything it prints to `log`.
// _exit, not exit: the parent's atexit handlers and stream buffers are not the child's to run.
[[noreturn]] void runChild(const std::function<std::string()>& work, const ContainmentLimits& limits, int out,
                           int log) {
    dup2(log, STDOUT_FILENO);
    dup2(log, STDERR_FILENO);
    signal(SIGINT, SIG_DFL);  // the tool's handlers remove its temporaries: not the child's to do
    signal(SIGTERM, SIG_DFL);
    setLimit(RLIMIT_CORE, 0, 0);
    const rlim_t cpu = rlim_t(std::ceil(limits.cpuSeconds));
    setLimit(RLIMIT_CPU, cpu, cpu + 1);
    const rlim_t space = rlim_t(addressSpaceInUse() + limits.memoryBytes);
    setLimit(RLIMIT_AS, space, space);
    std::set_new_handler(noteFailedAllocation);
    _exit(writeAll(out, reply(work)) ? 0 : 3);
}

struct Pipe {
    int read = -1, write = -1;
    Pipe() {
        int fds[2];
        if (pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error(std::string("cannot make a pipe: ") + strerror(errno));
        read = fds[0];
        write = fds[1];
    }
    ~Pipe() {
        if (read >= 0) close(read);
        if (write >= 0) close(write);
    }
    void closeWrite() {
        close(write);
        write = -1;
    }
};

// What the parent saw of the child.
struct ChildOutcome {
    std::string reply, log;
    bool timedOut = false, replyTooLarge = false;
    int status = 0;  // waitpid's
};

// Reads the reply and the log until the child closes both, or time runs out, or the reply
// grows beyond its limit; then kills the child (if it still runs) and reaps it.
ChildOutcome collect(pid_t pid, Pipe& out, Pipe& log, const ContainmentLimits& limits) {
    using Clock = std::chrono::steady_clock;
    const auto deadline =
        Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limits.wallSeconds));
    ChildOutcome o;
    pollfd fds[2] = {{out.read, POLLIN, 0}, {log.read, POLLIN, 0}};
    std::string* sinks[2] = {&o.reply, &o.log};
    char buffer[1 << 16];
    while ((fds[0].fd >= 0 || fds[1].fd >= 0) && !o.timedOut && !o.replyTooLarge) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
        const int ready = left > 0 ? poll(fds, 2, int(left)) : 0;
        if (ready < 0 && errno == EINTR) continue;
        if (ready <= 0) {
            o.timedOut = true;
            break;
        }
        for (int i = 0; i < 2; ++i) {
            if (fds[i].fd < 0 || !fds[i].revents) continue;
            const ssize_t n = read(fds[i].fd, buffer, sizeof buffer);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0)
                fds[i].fd = -1;  // poll skips negative descriptors
            else if (i == 0 || o.log.size() < 4096)
                sinks[i]->append(buffer, std::size_t(n));
        }
        o.replyTooLarge = o.reply.size() > limits.replyBytes;
    }
    if (o.timedOut || o.replyTooLarge) kill(pid, SIGKILL);
    while (waitpid(pid, &o.status, 0) < 0 && errno == EINTR) {}
    return o;
}

// The first line the child wrote, shortened: what an assertion or a sanitizer said.
std::string firstLine(const std::string& log) {
    const std::size_t begin = log.find_first_not_of(" \t\r\n");
    if (begin == std::string::npos) return "";
    const std::string line = log.substr(begin, std::min(log.find('\n', begin), begin + 200) - begin);
    return ": " + line;
}

// The result, or the one error that says what went wrong.
std::string outcome(const ChildOutcome& o, const std::string& file, const std::string& parser,
                    const ContainmentLimits& limits) {
    const std::string what = file + ": " + parser;
    const std::string seconds = std::to_string(int(std::ceil(limits.cpuSeconds)));
    if (o.timedOut)
        throw InputError(what + " did not finish reading the file in " +
                         std::to_string(int(std::ceil(limits.wallSeconds))) + " s; stopped");
    if (o.replyTooLarge)
        throw InputError(what + " made more than " + gigabytes(limits.replyBytes) + " of the file; stopped");
    if (WIFSIGNALED(o.status)) {
        const int signal = WTERMSIG(o.status);
        if (signal == SIGXCPU || signal == SIGKILL)  // SIGKILL: the hard CPU limit, or the OOM killer
            throw InputError(what + " used more than " + seconds +
                             " s of CPU time or all memory reading the file; stopped");
        throw InputError(what + " crashed reading the file (" + strsignal(signal) + ")" + firstLine(o.log));
    }
    if (WEXITSTATUS(o.status) != 0 || o.reply.empty())
        throw InputError(what + " failed reading the file (exit status " + std::to_string(WEXITSTATUS(o.status)) + ")" +
                         firstLine(o.log));
    const std::string message = o.reply.substr(1);
    switch (o.reply[0]) {
        case kResult:
            return message;
        case kInputError:
            throw InputError(message);
        case kOutOfMemory:
            throw InputError(what + " needed more than " + gigabytes(limits.memoryBytes) +
                             " of memory reading the file; stopped");
        default:
            throw InputError(what + " failed reading the file: " + message);
    }
}

}  // namespace

std::string runContained(const std::string& file, const std::string& parser, const std::function<std::string()>& work,
                         const ContainmentLimits& limits) {
    Pipe out, log;
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("cannot start a process for " + parser + ": " + strerror(errno));
    if (pid == 0) runChild(work, limits, out.write, log.write);
    out.closeWrite();
    log.closeWrite();
    return outcome(collect(pid, out, log, limits), file, parser, limits);
}

}  // namespace rt
