#pragma once
#include "app/CommandLine.h"

namespace app {

// Exit statuses: 0 done, 1 the scene, GL or a file failed, 2 bad command line,
// 130 interrupted (the image so far was still written).
constexpr int kExitSuccess = 0;
constexpr int kExitFailure = 1;
constexpr int kExitUsage = 2;
constexpr int kExitInterrupted = 130;

// Runs the render the command line asks for; returns the exit status. Errors propagate as
// exceptions whose message is the line to show.
int runRender(const CommandLine& line);
int printFeatures(const CommandLine& line);
int printShader(const CommandLine& line);

}  // namespace app
