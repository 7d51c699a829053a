#pragma once
#include "scene/Scene.h"

#include <string>

namespace scene {

// The camera as a scene file writes it, on one line (docs/SCENE_FORMAT.md, "Camera"):
// "ex ey ez  tx ty tz  ux uy uz  fovy", then "  lens R F" for a thin lens. Each number has
// the fewest digits that read back as the same float, so the line, pasted over a file's
// camera, gives exactly this camera (what the window's C key writes).
std::string cameraLine(const Camera& camera);

}  // namespace scene
