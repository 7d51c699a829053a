#pragma once
// Running a program as a user would (the CLI and window tests): its output streams, exit
// status and running time, and a signal sent to it on a schedule.
#include <csignal>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace testing_support {

struct ProcessOptions {
    std::filesystem::path workingDirectory = ".";
    // Environment variables to set (a value) or remove (nullopt); the rest is inherited.
    std::map<std::string, std::optional<std::string>> environment;
    // Sends `signal` this long after the program started (its exec succeeded: a signal sent
    // before that reaches the test's own child, which is not the program yet),
    std::optional<double> signalAfterSeconds;
    // or as soon as standard error shows this text (with terminalColumns: once the progress
    // line says a frame is done).
    std::optional<std::string> signalWhenErrorShows;
    int signal = SIGINT;
    // The child starts with `signal` blocked: one sent before the program is ready stays
    // pending until the program unblocks it (InterruptWatch does, once its handler is set),
    // so "an interrupt at the very start" is exact rather than a race with its start-up.
    bool startWithSignalBlocked = false;
    // Killed (SIGKILL) after this long; the result then says so.
    double timeoutSeconds = 100.0;
    // Standard error on a pseudo-terminal this many columns wide (0: a terminal that does
    // not report its width) instead of a pipe; what it shows is read into standardError.
    std::optional<int> terminalColumns;
};

struct ProcessResult {
    bool exited = false;        // ended by exit(); else by a signal
    int exitStatus = -1;        // when exited
    int terminatingSignal = 0;  // when not exited
    bool timedOut = false;
    std::string standardOutput;
    std::string standardError;
    double seconds = 0.0;

    // "exit status 2" or "killed by signal 2 (Interrupt)", for messages.
    std::string describeEnd() const;
};

// Runs arguments[0] (a path) with the rest as its arguments; standard input is /dev/null.
ProcessResult runProcess(const std::vector<std::string>& arguments,
                         const ProcessOptions& options = {});

// The non-empty lines of `text`.
std::vector<std::string> nonEmptyLines(const std::string& text);

}  // namespace testing_support
