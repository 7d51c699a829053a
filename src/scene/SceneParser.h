#pragma once
#include "scene/FileLookup.h"
#include "scene/Scene.h"

#include <filesystem>
#include <string>

namespace scene {

// Reads the `.in` scene format (../shared/SCENE_FORMAT.md, docs/SCENE_FORMAT.md): the classic
// part, and our extensions (comments, `environment`, CSG blocks and transforms). Any error
// throws SceneError naming the file, line, token and what was expected; nothing is returned
// half-read.
Scene parseSceneFile(const std::filesystem::path& path);
Scene parseSceneText(const std::string& text, const std::string& fileName,
                     const FileLookup& lookup);

// A camera alone, written as a scene file writes it (SCENE_FORMAT.md, "Camera"): eye, target,
// up, field of view and the optional `lens R D`, each group of the four optionally after its
// word as `raytracer info` prints it (`eye`, `target` or `look-at`, `up`, `fovy` or `fov`), so
// that a file's camera line can be pasted. Checked as the file's camera is; errors are
// SceneErrors whose file is `source` and whose line is 1.
Camera parseCameraText(const std::string& text, const std::string& source);

// Words that have a meaning in the object-type slot and so cannot name a user SDF.
bool isReservedShapeWord(const std::string& word);

}  // namespace scene
