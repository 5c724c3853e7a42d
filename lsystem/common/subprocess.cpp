#include "lsystem/common/subprocess.h"

#include <array>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace lsys {

namespace {

// A file descriptor closed when it goes out of scope.
struct Descriptor {
    int fd = -1;
    Descriptor() = default;
    Descriptor(const Descriptor&) = delete;
    Descriptor& operator=(const Descriptor&) = delete;
    ~Descriptor() { reset(); }
    void reset() {
        if (fd >= 0) ::close(fd);
        fd = -1;
    }
};

// [0] is the caller's end, [1] the child's. The child's standard input is a
// socket so that writing to a child that has exited fails with EPIPE
// (MSG_NOSIGNAL) instead of sending the caller SIGPIPE.
bool makeChannel(std::array<Descriptor, 2>& ends, bool socket) {
    int fds[2];
    if (socket ? ::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0 : ::pipe2(fds, O_CLOEXEC) != 0)
        return false;
    // A pipe's read end is fds[0]: the caller reads the child's output.
    ends[0].fd = fds[0];
    ends[1].fd = fds[1];
    ::fcntl(ends[0].fd, F_SETFL, ::fcntl(ends[0].fd, F_GETFL) | O_NONBLOCK);
    return true;
}

// `name` itself when it holds a '/', else the first executable of that name
// in PATH; empty when there is none.
std::string findProgram(const std::string& name) {
    if (name.find('/') != std::string::npos) return ::access(name.c_str(), X_OK) == 0 ? name : std::string();
    const char* path = std::getenv("PATH");
    std::string_view directories = path ? path : "/usr/bin:/bin";
    while (true) {
        const size_t colon = directories.find(':');
        std::string directory(directories.substr(0, colon));
        const std::string candidate = (directory.empty() ? std::string(".") : directory) + "/" + name;
        if (::access(candidate.c_str(), X_OK) == 0) return candidate;
        if (colon == std::string_view::npos) return {};
        directories.remove_prefix(colon + 1);
    }
}

// Starts `program` with the three descriptors as its standard streams and
// the limits as its address-space and CPU-time limits, so that a program
// that reads without end (the C preprocessor given "#include \"/dev/zero\"")
// fails on its own instead of exhausting the machine's memory. The child runs
// only async-signal-safe calls between fork and exec; an exec failure comes
// back through a close-on-exec pipe. Returns 0 or the errno of the failure.
int spawn(const std::string& program, std::vector<char*>& args, std::array<int, 3> streams, const ProcessLimits& limits,
          pid_t& pid) {
    int report[2];
    if (::pipe2(report, O_CLOEXEC) != 0) return errno;
    const rlimit memory{limits.maxMemoryBytes, limits.maxMemoryBytes};
    const rlimit cpu{rlim_t(limits.timeoutSeconds), rlim_t(limits.timeoutSeconds)};
    pid = ::fork();
    if (pid == 0) {
        for (int stream = 0; stream < 3; ++stream) ::dup2(streams[size_t(stream)], stream);
        ::setrlimit(RLIMIT_AS, &memory);
        ::setrlimit(RLIMIT_CPU, &cpu);
        ::execve(program.c_str(), args.data(), environ);
        const int error = errno;
        [[maybe_unused]] ssize_t ignored = ::write(report[1], &error, sizeof error);
        ::_exit(127);
    }
    const int forkError = pid < 0 ? errno : 0;
    ::close(report[1]);
    int error = forkError;
    if (pid > 0) {
        ssize_t n;
        while ((n = ::read(report[0], &error, sizeof error)) < 0 && errno == EINTR) {}
        if (n != sizeof error) error = 0; // closed by a successful exec
        if (error != 0)
            while (::waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {}
    }
    ::close(report[0]);
    return error;
}

void closeEnd(int& fd) {
    if (fd >= 0) ::close(fd);
    fd = -1;
}

} // namespace

Process::Process(const std::vector<std::string>& argv, const ProcessLimits& limits)
    : program_(argv.at(0)), limits_(limits),
      deadline_(std::chrono::steady_clock::now() + std::chrono::seconds(limits.timeoutSeconds)) {
    std::array<Descriptor, 2> in, out, err;
    if (!makeChannel(in, true) || !makeChannel(out, false) || !makeChannel(err, false)) {
        result_.failure = std::string("cannot create pipes: ") + std::strerror(errno);
        return;
    }
    std::vector<char*> args;
    for (const std::string& arg : argv) args.push_back(const_cast<char*>(arg.c_str()));
    args.push_back(nullptr);
    const std::string path = findProgram(program_);
    pid_t pid = -1;
    const int spawned = path.empty() ? ENOENT : spawn(path, args, {in[1].fd, out[1].fd, err[1].fd}, limits, pid);
    if (spawned != 0) {
        result_.failure = "cannot run '" + program_ + "': " + std::strerror(spawned);
        return;
    }
    pid_ = pid;
    result_.started = true;
    for (auto [index, end] : {std::pair{0, &in[0]}, std::pair{1, &out[0]}, std::pair{2, &err[0]}}) {
        ends_[size_t(index)] = end->fd;
        end->fd = -1;
    }
}

Process::~Process() {
    if (started() && !finished_) {
        ::kill(pid_, SIGKILL);
        while (::waitpid(pid_, nullptr, 0) < 0 && errno == EINTR) {}
    }
    for (int& fd : ends_) closeEnd(fd);
}

void Process::pump(std::string_view input) {
    size_t written = 0;
    std::array<char, 65536> buffer;
    while (stopped_.empty() && (input.empty() ? ends_[1] >= 0 || ends_[2] >= 0 : written < input.size())) {
        if (!input.empty() && ends_[0] < 0) return; // the program stopped reading
        std::array<pollfd, 3> polled{pollfd{input.empty() ? -1 : ends_[0], POLLOUT, 0}, pollfd{ends_[1], POLLIN, 0},
                                     pollfd{ends_[2], POLLIN, 0}};
        const auto left =
            std::chrono::duration_cast<std::chrono::milliseconds>(deadline_ - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            stopped_ = "'" + program_ + "' ran longer than " + std::to_string(limits_.timeoutSeconds) + " s";
            break;
        }
        if (::poll(polled.data(), polled.size(), static_cast<int>(left.count())) < 0) {
            if (errno == EINTR) continue;
            stopped_ = "cannot wait for '" + program_ + "': " + std::strerror(errno);
            break;
        }
        if (polled[0].fd >= 0 && polled[0].revents) {
            const ssize_t n = ::send(ends_[0], input.data() + written, input.size() - written, MSG_NOSIGNAL);
            if (n > 0) written += static_cast<size_t>(n);
            if (n < 0 && errno != EAGAIN && errno != EINTR) closeEnd(ends_[0]);
        }
        for (auto [index, text] : {std::pair{1, &result_.out}, std::pair{2, &result_.err}}) {
            int& end = ends_[size_t(index)];
            if (end < 0 || !polled[size_t(index)].revents) continue;
            const ssize_t n = ::read(end, buffer.data(), buffer.size());
            if (n > 0) text->append(buffer.data(), static_cast<size_t>(n));
            if (n == 0 || (n < 0 && errno != EAGAIN && errno != EINTR)) closeEnd(end);
        }
        if (result_.out.size() + result_.err.size() > limits_.maxOutputBytes)
            stopped_ = "'" + program_ + "' wrote more than " + std::to_string(limits_.maxOutputBytes >> 20) + " MiB";
    }
    if (!stopped_.empty()) {
        ::kill(pid_, SIGKILL);
        closeEnd(ends_[0]);
    }
}

bool Process::write(std::string_view data) {
    if (!started() || finished_ || ends_[0] < 0) return false;
    pump(data);
    return ends_[0] >= 0 && stopped_.empty();
}

ProcessResult Process::finish() {
    if (!started() || finished_) return result_;
    closeEnd(ends_[0]);
    pump({});
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {}
    finished_ = true;
    if (!stopped_.empty())
        result_.failure = stopped_;
    else if (WIFEXITED(status))
        result_.exitCode = WEXITSTATUS(status);
    else
        result_.failure = "'" + program_ + "' was stopped by signal " + std::to_string(WTERMSIG(status));
    return result_;
}

ProcessResult runProcess(const std::vector<std::string>& argv, std::string_view input, const ProcessLimits& limits) {
    Process process(argv, limits);
    if (!input.empty()) process.write(input);
    return process.finish();
}

} // namespace lsys
