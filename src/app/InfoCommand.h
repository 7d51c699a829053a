#pragma once
#include <filesystem>

namespace app {

// raytracer info FILE: prints what an image file says of itself (film/RenderMetadata.h)
// and, where it holds per-pixel counts, how many samples its pixels hold. Throws with the
// line to show when the file cannot be read or holds no metadata of this program.
int runInfo(const std::filesystem::path& file);

}  // namespace app
