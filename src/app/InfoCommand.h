#pragma once
#include <filesystem>

namespace app {

// raytracer info FILE: prints what an image file says of itself (film/RenderMetadata.h)
// and, where it holds per-pixel counts, how many samples its pixels hold. The file is read as
// untrusted, as merge reads it (io/ImageFile.h, film/RenderFileChecks.h). Throws with the
// line to show when the file cannot be read, holds no metadata of this program or a value
// no render holds.
int runInfo(const std::filesystem::path& file);

}  // namespace app
