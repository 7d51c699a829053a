#include "support/ChildProcess.h"

#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <sys/ioctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <sstream>
#include <stdexcept>

extern char** environ;

namespace testing_support {

namespace {

std::vector<std::string>
childEnvironment(const std::map<std::string, std::optional<std::string>>& changes)
{
    std::vector<std::string> result;
    for (char** entry = environ; *entry != nullptr; ++entry) {
        const std::string variable = *entry;
        const std::string name = variable.substr(0, variable.find('='));
        if (changes.count(name) == 0)
            result.push_back(variable);
    }
    for (const auto& [name, value] : changes)
        if (value)
            result.push_back(name + "=" + *value);
    return result;
}

std::vector<char*> pointers(std::vector<std::string>& strings)
{
    std::vector<char*> result;
    for (std::string& text : strings)
        result.push_back(text.data());
    result.push_back(nullptr);
    return result;
}

}  // namespace

std::string ProcessResult::describeEnd() const
{
    if (timedOut)
        return "timed out and was killed";
    if (exited)
        return "exit status " + std::to_string(exitStatus);
    return "killed by signal " + std::to_string(terminatingSignal) + " (" +
           strsignal(terminatingSignal) + ")";
}

ProcessResult runProcess(const std::vector<std::string>& arguments, const ProcessOptions& options)
{
    // Everything the child needs is prepared before fork: after it, only async-signal-safe
    // calls are allowed.
    std::vector<std::string> argumentStrings = arguments;
    std::vector<char*> argv = pointers(argumentStrings);
    std::vector<std::string> environmentStrings = childEnvironment(options.environment);
    std::vector<char*> envp = pointers(environmentStrings);
    const std::string directory = options.workingDirectory.string();

    int outputPipe[2];
    int errorPipe[2];
    // Close-on-exec: another thread may fork a child of its own meanwhile (the window tests
    // drive xdotool while the program runs), which must not hold these pipes open.
    if (pipe2(outputPipe, O_CLOEXEC) != 0)
        throw std::runtime_error("pipe failed");
    if (options.terminalColumns) {
        winsize size{};
        size.ws_row = 24;
        size.ws_col = static_cast<unsigned short>(*options.terminalColumns);
        // errorPipe[0] is the terminal's master side, errorPipe[1] the child's.
        if (openpty(&errorPipe[0], &errorPipe[1], nullptr, nullptr, &size) != 0)
            throw std::runtime_error("openpty failed");
        fcntl(errorPipe[0], F_SETFD, FD_CLOEXEC);
        fcntl(errorPipe[1], F_SETFD, FD_CLOEXEC);
    } else if (pipe2(errorPipe, O_CLOEXEC) != 0) {
        throw std::runtime_error("pipe failed");
    }

    // Closed by the exec (close-on-exec), so that the parent knows when the program runs; a
    // failed exec writes its errno first.
    int execPipe[2];
    if (pipe2(execPipe, O_CLOEXEC) != 0)
        throw std::runtime_error("pipe failed");

    // Blocked before fork, so that the child has it blocked from its first instruction (a
    // signal sent at once cannot come before); the parent restores its own mask after.
    sigset_t parentMask;
    if (options.startWithSignalBlocked) {
        sigset_t blocked;
        sigemptyset(&blocked);
        sigaddset(&blocked, options.signal);
        sigprocmask(SIG_BLOCK, &blocked, &parentMask);
    }
    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = fork();
    if (pid < 0) {
        if (options.startWithSignalBlocked)
            sigprocmask(SIG_SETMASK, &parentMask, nullptr);
        throw std::runtime_error("fork failed");
    }
    if (pid == 0) {
        const int nullInput = open("/dev/null", O_RDONLY);
        dup2(nullInput, STDIN_FILENO);
        dup2(outputPipe[1], STDOUT_FILENO);
        dup2(errorPipe[1], STDERR_FILENO);
        close(outputPipe[0]);
        close(errorPipe[0]);
        close(outputPipe[1]);
        close(errorPipe[1]);
        if (chdir(directory.c_str()) != 0)
            _exit(126);

        close(execPipe[0]);
        execve(argv[0], argv.data(), envp.data());
        const int error = errno;
        (void)!write(execPipe[1], &error, sizeof error);
        _exit(127);
    }
    if (options.startWithSignalBlocked)
        sigprocmask(SIG_SETMASK, &parentMask, nullptr);
    close(outputPipe[1]);
    close(errorPipe[1]);
    close(execPipe[1]);
    // Until the exec: end of file (it succeeded) or its errno.
    int execError = 0;
    while (read(execPipe[0], &execError, sizeof execError) < 0 && errno == EINTR) {
    }
    close(execPipe[0]);
    const auto started = std::chrono::steady_clock::now();

    ProcessResult result;
    auto elapsed = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    bool signalled = false;
    pollfd streams[2] = {{outputPipe[0], POLLIN, 0}, {errorPipe[0], POLLIN, 0}};
    std::string* sinks[2] = {&result.standardOutput, &result.standardError};
    int openStreams = 2;
    while (openStreams > 0) {
        if (options.signalAfterSeconds && !signalled &&
            std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count() >=
                *options.signalAfterSeconds) {
            kill(pid, options.signal);
            signalled = true;
        }
        if (!result.timedOut && elapsed() >= options.timeoutSeconds) {
            kill(pid, SIGKILL);
            result.timedOut = true;
        }
        // Short waits while a signal is due, so that it goes within a millisecond of its time.
        const int waitMilliseconds = options.signalAfterSeconds && !signalled ? 1 : 20;
        if (poll(streams, 2, waitMilliseconds) < 0)
            continue;
        for (int i = 0; i < 2; ++i) {
            if (streams[i].fd < 0 || streams[i].revents == 0)
                continue;
            char buffer[4096];
            // A terminal's master side reads EIO once the child's side is closed: the end.
            const ssize_t count = read(streams[i].fd, buffer, sizeof buffer);
            if (count > 0) {
                sinks[i]->append(buffer, static_cast<std::size_t>(count));
                if (options.signalWhenErrorShows && !signalled && i == 1 &&
                    result.standardError.find(*options.signalWhenErrorShows) != std::string::npos) {
                    kill(pid, options.signal);
                    signalled = true;
                }
            } else {
                close(streams[i].fd);
                streams[i].fd = -1;
                --openStreams;
            }
        }
    }
    int status = 0;
    waitpid(pid, &status, 0);
    result.seconds = elapsed();
    result.exited = WIFEXITED(status);
    if (result.exited)
        result.exitStatus = WEXITSTATUS(status);
    else if (WIFSIGNALED(status))
        result.terminatingSignal = WTERMSIG(status);
    return result;
}

std::vector<std::string> nonEmptyLines(const std::string& text)
{
    std::vector<std::string> lines;
    std::istringstream stream(text);
    std::string line;
    while (std::getline(stream, line))
        if (line.find_first_not_of(" \t\r") != std::string::npos)
            lines.push_back(line);
    return lines;
}

}  // namespace testing_support
