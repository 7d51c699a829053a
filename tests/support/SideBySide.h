#pragma once
// The picture a failed comparison leaves behind for a person to look at.
#include "support/ImageComparison.h"
#include "support/RenderRun.h"

#include <filesystem>

namespace testing_support {

// How much the difference panel magnifies |render - reference|.
constexpr float kDifferenceMagnification = 8.0f;

// Writes, left to right, each enlarged 4x: the reference | the render | the magnified absolute
// difference | the channel mean's z per block (red: render brighter, blue: darker, full
// colour at |z| >= 4). Radiance is shown as x / (1 + x) with gamma 2.2. Returns the path.
std::filesystem::path writeSideBySide(const std::filesystem::path& path,
                                      const RenderedImage& reference, const RenderedImage& render,
                                      const Comparison& comparison, int blockSize);

}  // namespace testing_support
