#include "render/ReloadDecision.h"

#include <algorithm>

namespace render {

namespace fs = std::filesystem;

namespace {

// Paths as the watcher and the parser spell them may differ ("./x.glsl" and "x.glsl").
bool samePath(const fs::path& a, const fs::path& b)
{
    return a.lexically_normal() == b.lexically_normal();
}

bool anyChanged(const std::vector<fs::path>& files, const std::vector<fs::path>& changed)
{
    return std::any_of(files.begin(), files.end(), [&](const fs::path& file) {
        return std::any_of(changed.begin(), changed.end(),
                           [&](const fs::path& other) { return samePath(file, other); });
    });
}

// Generated code without its comment lines: the comments name objects' scene-file lines,
// which an edit elsewhere in the file shifts without changing the code.
std::string withoutCommentLines(const std::string& code)
{
    std::string kept;
    std::size_t start = 0;
    while (start < code.size()) {
        std::size_t end = code.find('\n', start);
        end = end == std::string::npos ? code.size() : end + 1;
        const std::size_t first = code.find_first_not_of(' ', start);
        if (!(first < end && code.compare(first, 2, "//") == 0))
            kept.append(code, start, end - start);
        start = end;
    }
    return kept;
}

// Beyond what decides a rebuild: the rest of the code, and the arrays of numbers the code
// carries for upload (the general variant's shape programs, every shape's parameters).
bool sameCodeAndArrays(const shadergen::SceneShaderCode& a, const shadergen::SceneShaderCode& b)
{
    return a.exactGeometry == b.exactGeometry && a.exactFunctions == b.exactFunctions &&
           a.profileCounters == b.profileCounters && a.marchesAnything == b.marchesAnything &&
           a.marchedUnion == b.marchedUnion && a.shapeParameters == b.shapeParameters &&
           a.shapeProgram == b.shapeProgram && a.objectProgramStart == b.objectProgramStart &&
           a.objectBounds == b.objectBounds && a.objectCullingBits == b.objectCullingBits;
}

}  // namespace

ReloadDecision decideReload(const shadergen::SceneShaderCode& shownCode,
                            const SceneUniforms& shownUniforms,
                            const shadergen::SceneShaderCode& editedCode,
                            const SceneUniforms& editedUniforms,
                            const std::vector<fs::path>& changedFiles)
{
    ReloadDecision decision;
    decision.rebuildShader = shownCode.variant != editedCode.variant ||
                             shownCode.defines != editedCode.defines ||
                             withoutCommentLines(shownCode.sceneFunctions) !=
                                 withoutCommentLines(editedCode.sceneFunctions) ||
                             shownCode.userSdfFiles != editedCode.userSdfFiles ||
                             anyChanged(editedCode.userSdfFiles, changedFiles);
    const fs::path& editedMap = editedUniforms.environment.mapPath;
    decision.reloadTextures = shownUniforms.textureLayers != editedUniforms.textureLayers ||
                              anyChanged(editedUniforms.textureLayers, changedFiles) ||
                              shownUniforms.environment.mapPath != editedMap ||
                              (!editedMap.empty() && anyChanged({editedMap}, changedFiles));
    decision.changesNothing = !decision.rebuildShader && !decision.reloadTextures &&
                              sameCodeAndArrays(shownCode, editedCode) &&
                              shownUniforms == editedUniforms;
    return decision;
}

bool cameraLinesChanged(const scene::Camera& before, const scene::Camera& after)
{
    return !sameCamera(before, after);
}

}  // namespace render
