#pragma once
#include "app/CommandLine.h"
#include "app/Interrupt.h"

#include "platform/GlContext.h"
#include "render/KernelChoice.h"

#include <filesystem>
#include <string>
#include <vector>

namespace app {

// Exit statuses: 0 done, 1 the scene, GL or a file failed, 2 bad command line, 3 a render to
// --target-error that ended (at its time limit or --spp) without reaching it (its image was
// written all the same), 130 interrupted (the image so far was still written).
constexpr int kExitSuccess = 0;
constexpr int kExitFailure = 1;
constexpr int kExitUsage = 2;
constexpr int kExitTargetNotReached = 3;
constexpr int kExitInterrupted = 130;

// Runs the render the command line asks for, stopping early when `interrupt` asks;
// returns the exit status. Errors propagate as exceptions whose message is the line to show.
int runRender(const CommandLine& line, const InterruptWatch& interrupt);
// The context the command line asks for (--gl, --gl-device, --headless, the window's size).
platform::ContextRequest contextRequest(const CommandLine& line);
// "EGL software device: llvmpipe (...), OpenGL 4.5 (...), fragment kernel": what renders, for
// the summary line.
std::string describeRenderingDevice(const platform::ContextIdentity& gl,
                                    const render::KernelChoice& kernel);
int printFeatures(const CommandLine& line);
int printShader(const CommandLine& line);

// Removes the temporary files that killed runs writing `outputs` left beside them
// (io::removeStaleTemporaries) and says so on standard output, one line each, unless `quiet`.
void removeStaleTemporariesOf(const std::vector<std::filesystem::path>& outputs,
                              bool quiet = false);

}  // namespace app
