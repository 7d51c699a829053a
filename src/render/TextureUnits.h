#pragma once

// Every texture unit the renderer's programs read, in one list: two owners of one unit would
// each read the other's texture, without an error from OpenGL. Unit 2 is free.
namespace render::texture_units {

// The path tracer's program (ProgressiveRenderer).
constexpr int kPreviousEstimate = 0;
constexpr int kPreviousMoments = 1;
constexpr int kPigmentTextures = 3;
constexpr int kTileSampleTargets = 4;
constexpr int kEnvironmentRadiance = 5;
constexpr int kEnvironmentDistribution = 6;
// The scene read as data (SceneDataBuffers): shapes, objects and their hierarchy.
constexpr int kShapeParameters = 7;
constexpr int kShapeProgram = 8;
constexpr int kObjectRecords = 9;
constexpr int kHierarchyBoxes = 10;
constexpr int kHierarchyLinks = 11;
// The feature buffers (--feature-buffers), read by the path tracer and the preview denoiser.
constexpr int kAlbedoDepth = 12;
constexpr int kNormalCoverage = 13;
// The preview denoiser's own program (PreviewDenoiser): its pass's input and the moments.
constexpr int kDenoiserSource = 14;
constexpr int kDenoiserMoments = 15;

// OpenGL 3.3 promises 16 units to a fragment shader.
constexpr int kUnitsPromised = 16;
static_assert(kDenoiserMoments < kUnitsPromised, "a unit beyond what OpenGL 3.3 promises");

}  // namespace render::texture_units
