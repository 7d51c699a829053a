#pragma once
#include "scene/Lights.h"
#include "scene/Scene.h"

#include <filesystem>
#include <map>
#include <set>
#include <string>

namespace scene {

// What a scene uses, so that the shader can be built with nothing else (see
// render/SceneShaderGenerator). Only what is referenced counts: a finish no object uses adds
// no material.
struct SceneFeatures {
    std::map<std::string, std::filesystem::path> userSdfs;  // name -> file
    bool transforms = false;

    std::set<MaterialKind> materials;
    std::set<PigmentKind> pigments;

    // Dielectrics of index exactly 1: light passes them unbent (see lights.glsl).
    bool nullInterfaces = false;

    // A microfacet material (scene/Materials.h, Model::Microfacet): the GGX code they share.
    bool microfacets = false;

    // The camera's thin lens (depth of field); a pinhole without.
    bool thinLens = false;

    std::set<LightKind> lights;
    EnvironmentKind environment = EnvironmentKind::Sky;

    bool has(MaterialKind kind) const { return materials.count(kind) != 0; }
    bool has(PigmentKind kind) const { return pigments.count(kind) != 0; }
    bool has(LightKind kind) const { return lights.count(kind) != 0; }
    bool has(EnvironmentKind kind) const { return environment == kind; }

    // Every feature the renderer has, with the user SDFs of `scene` (GLSL cannot call a
    // function it was not given): what the general, unspecialised shader is built for.
    static SceneFeatures everything(const Scene& scene);

    // A human-readable list, one feature group per line.
    std::string describe() const;
};

SceneFeatures analyseFeatures(const Scene& scene);

const char* toString(MaterialKind kind);
const char* toString(PigmentKind kind);
const char* toString(LightKind kind);
const char* toString(EnvironmentKind kind);

}  // namespace scene
