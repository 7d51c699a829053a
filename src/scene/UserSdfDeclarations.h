#pragma once

#include "scene/Scene.h"

namespace scene {

// Reads the `// @bound R`, `// @lipschitz L`, `// @hull NX NY NZ D` and `// @intersect
// FUNCTION` declarations of the user SDF file at user.sourcePath into `user`. A declaration the renderer would silently
// ignore is an error (SceneError naming the file, line and value): a dropped @lipschitz
// makes an overestimating function tunnel, a dropped @bound, @hull or @intersect only costs time
// but is as surely a typo.
void readUserSdfDeclarations(UserSdf& user);

// Letters, digits and `_`, not starting with a digit, and none of the names GLSL reserves
// (starting with gl_, or holding a double underscore).
bool isGlslIdentifier(const std::string& word);

}  // namespace scene
