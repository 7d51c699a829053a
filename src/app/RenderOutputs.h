#pragma once
// The files a render, a window's save or a merge writes, and what they say of themselves.
#include "film/Accumulation.h"
#include "film/RenderMetadata.h"
#include "io/OutputFiles.h"
#include "platform/GlContext.h"
#include "render/ProgressiveRenderer.h"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace app {

// The metadata of what `renderer` holds, rendered from `sceneFile` (whose files hash to
// `sceneSha256`) by this program in the OpenGL `gl`: size, camera, settings, the context and
// the kernel, and, as for a render from nothing,
// samplesPerPixel() samples of its seed from index 0. The caller sets what differs (the
// ranges of a resumed render, the seconds, an interruption).
film::RenderMetadata describeRender(const std::filesystem::path& sceneFile,
                                    const std::string& sceneSha256,
                                    const render::ProgressiveRenderer& renderer,
                                    const platform::ContextIdentity& gl);

// Each of `images` in the format its extension names, with `metadata` where the format holds
// attributes: an EXR holds the radiance and the accumulation (film/RenderFile.h), .pfm and
// .hdr the radiance, a picture format `picture()` (the tone-mapped picture, made only if one
// is asked for); then the statistics file, if any. For io::writeAllOrNothing.
std::vector<io::OutputImage> renderOutputs(const std::vector<std::filesystem::path>& images,
                                           const std::optional<std::filesystem::path>& statistics,
                                           const film::Accumulation& accumulation,
                                           const film::RenderMetadata& metadata,
                                           const std::function<io::Image()>& picture);

}  // namespace app
