#pragma once
#include <string>

namespace app {

// The program's version (the CMake project's) and the git commit it was built from, taken
// when the build was configured (CMake configures again when the checkout's HEAD moves);
// empty when it was not built from a git checkout.
const std::string& programVersion();
const std::string& gitCommit();
// "raytracer 1.0.0": what a file's metadata names as its program.
std::string programName();

}  // namespace app
