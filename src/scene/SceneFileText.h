#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

namespace scene {

// The most bytes a scene file may hold (docs/SCENE_FORMAT.md, "Limits").
constexpr std::size_t kMaxSceneFileBytes = 64u << 20;

// The whole of the scene file at `path`, read through POSIX calls so that a failure carries
// the system's reason: std::runtime_error naming the file and why (missing, unreadable, a
// folder, larger than kMaxSceneFileBytes, even where its size is only found by reading).
std::string readSceneFileText(const std::filesystem::path& path);

}  // namespace scene
