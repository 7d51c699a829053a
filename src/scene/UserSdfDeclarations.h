#pragma once

#include "scene/Scene.h"

namespace scene {

// Reads the `// @bound R` and `// @lipschitz L` declarations of the user SDF file at
// user.sourcePath into `user`. A declaration the renderer would silently ignore is an error
// (SceneError naming the file, line and value): a dropped @lipschitz makes an overestimating
// function tunnel, a dropped @bound only costs time but is as surely a typo.
void readUserSdfDeclarations(UserSdf& user);

}  // namespace scene
