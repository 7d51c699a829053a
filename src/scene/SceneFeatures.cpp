#include "scene/SceneFeatures.h"

#include "scene/PrimitiveKinds.h"

#include <sstream>

namespace scene {

namespace {

struct ShapeFeatures {
    SceneFeatures& features;

    template <typename P, std::enable_if_t<kIsPrimitive<P>, int> = 0>
    void operator()(const P&)
    {
    }
    void operator()(const UserSdf& user) { features.userSdfs[user.name] = user.sourcePath; }
    void operator()(const CsgNode& node)
    {
        for (const Shape& child : node.children)
            visit(child);
    }

    void visit(const Shape& shape)
    {
        if (shape.transform)
            features.transforms = true;
        std::visit(*this, shape.geometry);
    }
};

template <typename Kind>
std::string join(const std::set<Kind>& kinds)
{
    std::string text;
    for (Kind kind : kinds)
        text += (text.empty() ? "" : ", ") + std::string(toString(kind));
    return text.empty() ? "none" : text;
}

}  // namespace

SceneFeatures analyseFeatures(const Scene& scene)
{
    SceneFeatures features;
    ShapeFeatures shapes{features};
    for (const SceneObject& object : scene.objects) {
        shapes.visit(object.shape);
        const Finish& finish = scene.finishes[object.finish];
        features.materials.insert(finish.material());
        if (describe(finish.material()).model == Model::Microfacet)
            features.microfacets = true;
        if (finish.material() == MaterialKind::Dielectric && finish.ior == 1.0f)
            features.nullInterfaces = true;
        features.pigments.insert(scene.pigments[object.pigment].kind);
    }
    features.thinLens = scene.camera.lens.has_value();
    for (const Light& light : sceneLights(scene))
        features.lights.insert(light.kind);
    features.environment = scene.environment.kind;
    return features;
}

SceneFeatures SceneFeatures::everything(const Scene& scene)
{
    SceneFeatures features;
    features.userSdfs = analyseFeatures(scene).userSdfs;
    features.transforms = true;
    for (const MaterialDescription& material : materialDescriptions())
        features.materials.insert(material.kind);
    features.microfacets = true;
    // The camera is the scene's, as the environment is: a pinhole's rays are not a thin
    // lens's of radius 0 bit for bit, nor is its march from the eye the same.
    features.thinLens = scene.camera.lens.has_value();
    for (const PigmentDescription& pigment : pigmentDescriptions())
        features.pigments.insert(pigment.kind);
    features.nullInterfaces = true;
    // Every kind of light but the environment's where the scene has no such light: its code
    // reads the map's textures, which only a map gives (as only a user SDF's file gives its
    // function).
    const bool environmentLight = analyseFeatures(scene).has(LightKind::Environment);
    for (const LightDescription& light : lightDescriptions())
        if (light.kind != LightKind::Environment || environmentLight)
            features.lights.insert(light.kind);
    features.environment = scene.environment.kind;
    return features;
}

std::string SceneFeatures::describe() const
{
    std::ostringstream text;
    text << "user SDFs:     ";
    if (userSdfs.empty())
        text << "none";
    for (auto it = userSdfs.begin(); it != userSdfs.end(); ++it)
        text << (it == userSdfs.begin() ? "" : ", ") << it->first << " (" << it->second.string()
             << ")";
    text << "\n";
    text << "transforms:    " << (transforms ? "yes" : "no") << "\n";
    text << "materials:     " << join(materials) << "\n";
    text << "pigments:      " << join(pigments) << "\n";
    if (nullInterfaces)
        text << "index-1 dielectrics: yes (transparent to shadow rays)\n";
    text << "camera:        " << (thinLens ? "thin lens" : "pinhole") << "\n";
    text << "lights:        " << join(lights) << "\n";
    text << "environment:   " << toString(environment) << "\n";
    return text.str();
}

const char* toString(MaterialKind kind)
{
    return describe(kind).name;
}

const char* toString(PigmentKind kind)
{
    return describe(kind).keyword;
}

const char* toString(LightKind kind)
{
    return describe(kind).name;
}

const char* toString(EnvironmentKind kind)
{
    return describe(kind).keyword;
}

}  // namespace scene
