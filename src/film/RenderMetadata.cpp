#include "film/RenderMetadata.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <stdexcept>

namespace film {

namespace {

const std::string kPrefix = "raytracer:";

// The shortest decimal that reads back as the same float (nine significant digits always
// do): 1.2, not 1.20000005.
std::string floatText(float value)
{
    char text[32];
    for (int digits = 6; digits <= 9; ++digits) {
        std::snprintf(text, sizeof text, "%.*g", digits, static_cast<double>(value));
        if (std::strtof(text, nullptr) == value)
            break;
    }
    return text;
}

bool readFloat(const std::string& text, float& value)
{
    if (text.empty())
        return false;
    char* end = nullptr;
    value = std::strtof(text.c_str(), &end);
    return end == text.c_str() + text.size() && std::isfinite(value);
}

bool readInteger(const std::string& text, int& value)
{
    const char* last = text.data() + text.size();
    const auto [end, error] = std::from_chars(text.data(), last, value);
    return !text.empty() && error == std::errc() && end == last;
}

std::string onOff(bool on)
{
    return on ? "on" : "off";
}

bool readOnOff(const std::string& text, bool& value)
{
    if (text != "on" && text != "off")
        return false;
    value = text == "on";
    return true;
}

}  // namespace

const std::vector<ImageSetting>& imageSettings()
{
    // Left out, because they change the time a render takes and not its image: the seed
    // (the sample ranges hold it), samples per frame and band seconds (a pixel's samples do
    // not depend on how frames cut them), ray culling (exact: it skips only what a ray cannot
    // meet) and the profiling counters (they replace the image).
    static const std::vector<ImageSetting> settings = {
        {"hitTolerance", "hit tolerance (pixel footprints)", "--hit-tolerance",
         [](const settings::RenderSettings& s) { return floatText(s.hitTolerance); },
         [](settings::RenderSettings& s, const std::string& t) { return readFloat(t, s.hitTolerance); }},
        {"maxSteps", "sphere-tracing step limit", "--max-steps",
         [](const settings::RenderSettings& s) { return std::to_string(s.maxMarchSteps); },
         [](settings::RenderSettings& s, const std::string& t) { return readInteger(t, s.maxMarchSteps); }},
        {"overRelaxation", "over-relaxation", "--over-relaxation",
         [](const settings::RenderSettings& s) { return floatText(s.overRelaxation); },
         [](settings::RenderSettings& s, const std::string& t) { return readFloat(t, s.overRelaxation); }},
        {"stepScale", "step scale", "--step-scale",
         [](const settings::RenderSettings& s) { return floatText(s.stepScale); },
         [](settings::RenderSettings& s, const std::string& t) { return readFloat(t, s.stepScale); }},
        {"maxBounces", "bounces", "--max-bounces",
         [](const settings::RenderSettings& s) { return std::to_string(s.maxBounces); },
         [](settings::RenderSettings& s, const std::string& t) { return readInteger(t, s.maxBounces); }},
        {"rrDepth", "bounces before Russian roulette", "--rr-depth",
         [](const settings::RenderSettings& s) { return std::to_string(s.russianRouletteDepth); },
         [](settings::RenderSettings& s, const std::string& t) {
             return readInteger(t, s.russianRouletteDepth);
         }},
        {"mis", "multiple importance sampling", "--no-mis",
         [](const settings::RenderSettings& s) { return onOff(s.multipleImportanceSampling); },
         [](settings::RenderSettings& s, const std::string& t) {
             return readOnOff(t, s.multipleImportanceSampling);
         }},
        {"fresnel", "dielectric Fresnel", "--fresnel",
         [](const settings::RenderSettings& s) {
             return std::string(s.dielectricFresnel == settings::FresnelModel::Exact ? "exact" : "schlick");
         },
         [](settings::RenderSettings& s, const std::string& t) {
             if (t != "exact" && t != "schlick")
                 return false;
             s.dielectricFresnel = t == "exact" ? settings::FresnelModel::Exact : settings::FresnelModel::Schlick;
             return true;
         }},
        {"sampler", "sampler", "--sampler",
         [](const settings::RenderSettings& s) {
             return std::string(s.sampler == settings::SamplerKind::Sobol ? "sobol" : "independent");
         },
         [](settings::RenderSettings& s, const std::string& t) {
             if (t != "sobol" && t != "independent")
                 return false;
             s.sampler = t == "sobol" ? settings::SamplerKind::Sobol : settings::SamplerKind::Independent;
             return true;
         }},
        {"exactGeometry", "exact geometry", "--exact-geometry",
         [](const settings::RenderSettings& s) { return onOff(s.exactGeometry); },
         [](settings::RenderSettings& s, const std::string& t) { return readOnOff(t, s.exactGeometry); }},
        // The general shader converges to the same image, but by other float operations:
        // its samples are kept apart all the same.
        {"shader", "shader", "--no-specialize",
         [](const settings::RenderSettings& s) {
             return std::string(s.variant == settings::ShaderVariant::General ? "general" : "specialized");
         },
         [](settings::RenderSettings& s, const std::string& t) {
             if (t != "general" && t != "specialized")
                 return false;
             s.variant = t == "general" ? settings::ShaderVariant::General : settings::ShaderVariant::Specialized;
             return true;
         }},
        // Switched off only in the window's panel.
        {"environment", "environment light", "the window's panel",
         [](const settings::RenderSettings& s) { return onOff(s.environmentLight); },
         [](settings::RenderSettings& s, const std::string& t) { return readOnOff(t, s.environmentLight); }},
    };
    return settings;
}

std::string formatCamera(const scene::Camera& camera)
{
    auto vector = [](const glm::vec3& v) {
        return floatText(v.x) + " " + floatText(v.y) + " " + floatText(v.z);
    };
    return "eye " + vector(camera.eye) + " target " + vector(camera.target) + " up " +
           vector(camera.up) + " fovy " + floatText(camera.verticalFieldOfViewDegrees);
}

namespace {

bool parseCamera(const std::string& text, scene::Camera& camera)
{
    std::istringstream words(text);
    std::string word;
    auto expect = [&](const char* name) { return words >> word && word == name; };
    auto number = [&](float& value) { return words >> word && readFloat(word, value); };
    auto vector = [&](glm::vec3& v) { return number(v.x) && number(v.y) && number(v.z); };
    return expect("eye") && vector(camera.eye) && expect("target") && vector(camera.target) &&
           expect("up") && vector(camera.up) && expect("fovy") &&
           number(camera.verticalFieldOfViewDegrees) && !(words >> word);
}

std::string seedList(const std::vector<SampleRange>& ranges)
{
    std::string text;
    for (std::uint64_t seed : seedsOf(ranges))
        text += (text.empty() ? "" : " ") + std::to_string(seed);
    return text;
}

}  // namespace

std::vector<io::ImageAttribute> metadataAttributes(const RenderMetadata& metadata)
{
    std::vector<io::ImageAttribute> attributes = {
        {kPrefix + "scene", metadata.sceneFile},
        {kPrefix + "sceneSha256", metadata.sceneSha256},
        {kPrefix + "camera", formatCamera(metadata.camera)},
        {kPrefix + "samplesPerPixel", std::to_string(metadata.samplesPerPixel)},
        {kPrefix + "seed", seedList(metadata.sampleRanges)},
        {kPrefix + "sampleRanges", formatSampleRanges(metadata.sampleRanges)},
    };
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.3f", metadata.renderSeconds);
    attributes.push_back({kPrefix + "renderSeconds", seconds});
    for (const ImageSetting& setting : imageSettings())
        attributes.push_back({kPrefix + setting.key, setting.text(metadata.settings)});
    attributes.push_back({kPrefix + "program", metadata.program});
    if (!metadata.gitCommit.empty())
        attributes.push_back({kPrefix + "gitCommit", metadata.gitCommit});
    if (!metadata.interrupted.empty())
        attributes.push_back({kPrefix + "interrupted", metadata.interrupted});
    if (!metadata.mergedFrom.empty()) {
        std::string files;
        for (const std::string& file : metadata.mergedFrom)
            files += (files.empty() ? "" : "\n") + file;
        attributes.push_back({kPrefix + "mergedFrom", files});
    }
    return attributes;
}

std::optional<RenderMetadata> metadataFromAttributes(
    const std::vector<io::ImageAttribute>& attributes, const std::string& file)
{
    std::map<std::string, std::string> values;
    for (const io::ImageAttribute& attribute : attributes)
        if (attribute.name.rfind(kPrefix, 0) == 0)
            values[attribute.name.substr(kPrefix.size())] = attribute.value;
    if (values.count("sceneSha256") == 0)
        return std::nullopt;

    auto malformed = [&](const std::string& key, const std::string& why) {
        return std::runtime_error(file + ": attribute " + kPrefix + key + " " + why);
    };
    auto required = [&](const std::string& key) -> const std::string& {
        const auto found = values.find(key);
        if (found == values.end())
            throw malformed(key, "is missing");
        return found->second;
    };

    RenderMetadata metadata;
    metadata.sceneFile = values["scene"];
    metadata.sceneSha256 = required("sceneSha256");
    if (!parseCamera(required("camera"), metadata.camera))
        throw malformed("camera", "is not 'eye X Y Z target X Y Z up X Y Z fovy F'");
    if (!readInteger(required("samplesPerPixel"), metadata.samplesPerPixel) ||
        metadata.samplesPerPixel < 0)
        throw malformed("samplesPerPixel", "is not a count");
    try {
        metadata.sampleRanges = parseSampleRanges(required("sampleRanges"));
    } catch (const std::invalid_argument& error) {
        throw malformed("sampleRanges", std::string("is malformed: ") + error.what());
    }
    char* end = nullptr;
    const std::string& seconds = required("renderSeconds");
    metadata.renderSeconds = std::strtod(seconds.c_str(), &end);
    if (seconds.empty() || end != seconds.c_str() + seconds.size())
        throw malformed("renderSeconds", "is not a number");
    for (const ImageSetting& setting : imageSettings())
        if (!setting.read(metadata.settings, required(setting.key)))
            throw malformed(setting.key, "has the value '" + values[setting.key] +
                                             "', which is not one of " + setting.option);
    metadata.program = required("program");
    metadata.gitCommit = values["gitCommit"];
    metadata.interrupted = values["interrupted"];
    std::istringstream merged(values["mergedFrom"]);
    for (std::string line; std::getline(merged, line);)
        if (!line.empty())
            metadata.mergedFrom.push_back(line);
    return metadata;
}

std::optional<MetadataDifference> imageDifference(const RenderMetadata& first,
                                                  const RenderMetadata& second)
{
    if (first.width != second.width || first.height != second.height)
        return MetadataDifference{
            "the image size", std::to_string(first.width) + "x" + std::to_string(first.height),
            std::to_string(second.width) + "x" + std::to_string(second.height)};
    if (first.sceneSha256 != second.sceneSha256)
        return MetadataDifference{"the scene (SHA-256 of its files)",
                                  first.sceneSha256.substr(0, 12) + "...",
                                  second.sceneSha256.substr(0, 12) + "..."};
    if (formatCamera(first.camera) != formatCamera(second.camera))
        return MetadataDifference{"the camera", formatCamera(first.camera),
                                  formatCamera(second.camera)};
    for (const ImageSetting& setting : imageSettings()) {
        const std::string a = setting.text(first.settings);
        const std::string b = setting.text(second.settings);
        if (a != b)
            return MetadataDifference{std::string(setting.label) + " (" + setting.option + ")", a, b};
    }
    // Another build may trace other paths (a changed shader) for the same sample index.
    if (first.program != second.program || first.gitCommit != second.gitCommit)
        return MetadataDifference{"the program build", describeProgram(first),
                                  describeProgram(second)};
    return std::nullopt;
}

std::string describeProgram(const RenderMetadata& metadata)
{
    return metadata.program +
           (metadata.gitCommit.empty() ? " (no git commit)" : ", commit " + metadata.gitCommit);
}

}  // namespace film
