#include "film/RenderMetadata.h"

#include "film/Accumulation.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace film {

namespace {

const std::string kPrefix = "raytracer:";

std::string floatText(float value)
{
    return settings::shortestFloatText(value);
}

template <typename Integer>
bool readInteger(const std::string& text, Integer& value)
{
    const char* last = text.data() + text.size();
    const auto [end, error] = std::from_chars(text.data(), last, value);
    return !text.empty() && error == std::errc() && end == last;
}

}  // namespace

std::vector<const settings::SettingRow*> imageSettings()
{
    std::vector<const settings::SettingRow*> recorded;
    for (const settings::SettingRow& row : settings::settingRows())
        if (row.isRecorded())
            recorded.push_back(&row);
    return recorded;
}

std::string formatCrop(const PixelCrop& crop)
{
    return std::to_string(crop.x0) + " " + std::to_string(crop.y0) + " " + std::to_string(crop.x1) +
           " " + std::to_string(crop.y1);
}

std::optional<PixelCrop> parseCrop(const std::string& text)
{
    std::string spaced = text;
    std::replace(spaced.begin(), spaced.end(), ',', ' ');
    std::istringstream words(spaced);
    int values[4];
    for (int& value : values) {
        std::string word;
        if (!(words >> word))
            return std::nullopt;
        const char* last = word.data() + word.size();
        const auto [end, error] = std::from_chars(word.data(), last, value);
        if (error != std::errc() || end != last)
            return std::nullopt;
    }
    std::string more;
    if (words >> more)
        return std::nullopt;
    return PixelCrop{values[0], values[1], values[2], values[3]};
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
    auto number = [&](float& value) { return words >> word && settings::readFloat(word, value); };
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
    for (const settings::SettingRow* setting : imageSettings())
        attributes.push_back(
            {kPrefix + setting->description.metadataKey, setting->format(metadata.settings)});
    for (const auto& [key, value] :
         {std::pair{"glContext", &metadata.glContext},
          std::pair{"glRenderer", &metadata.glRenderer},
          std::pair{"glVersion", &metadata.glVersion}, std::pair{"kernel", &metadata.kernel}})
        if (!value->empty())
            attributes.push_back({kPrefix + key, *value});
    attributes.push_back({kPrefix + "program", metadata.program});
    if (!metadata.gitCommit.empty())
        attributes.push_back({kPrefix + "gitCommit", metadata.gitCommit});
    if (!metadata.interrupted.empty())
        attributes.push_back({kPrefix + "interrupted", metadata.interrupted});
    if (metadata.crop)
        attributes.push_back({kPrefix + "crop", formatCrop(*metadata.crop)});
    if (!metadata.mergedFrom.empty()) {
        std::string files;
        for (const std::string& file : metadata.mergedFrom)
            files += (files.empty() ? "" : "\n") + file;
        attributes.push_back({kPrefix + "mergedFrom", files});
    }
    return attributes;
}

std::optional<RenderMetadata>
metadataFromAttributes(const std::vector<io::ImageAttribute>& attributes, const std::string& file)
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
    const std::string largest = std::to_string(kLargestSampleCount);
    if (!readInteger(required("samplesPerPixel"), metadata.samplesPerPixel) ||
        metadata.samplesPerPixel < 0 || metadata.samplesPerPixel > kLargestSampleCount)
        throw malformed("samplesPerPixel",
                        "is '" + values["samplesPerPixel"] + "', not a count from 0 to " + largest);
    try {
        metadata.sampleRanges = parseSampleRanges(required("sampleRanges"));
    } catch (const std::invalid_argument& error) {
        throw malformed("sampleRanges", std::string("is malformed: ") + error.what());
    }
    // A pixel's sample indices run from 0 to its count, which is at most the largest.
    for (const SampleRange& range : metadata.sampleRanges)
        if (range.first > kLargestSampleCount || range.count > kLargestSampleCount - range.first)
            throw malformed("sampleRanges", "holds " + std::to_string(range.count) +
                                                " samples of seed " + std::to_string(range.seed) +
                                                " from index " + std::to_string(range.first) +
                                                ", beyond the " + largest +
                                                " samples a pixel can hold");
    char* end = nullptr;
    const std::string& seconds = required("renderSeconds");
    metadata.renderSeconds = std::strtod(seconds.c_str(), &end);
    if (seconds.empty() || end != seconds.c_str() + seconds.size() ||
        !std::isfinite(metadata.renderSeconds) || metadata.renderSeconds < 0.0)
        throw malformed("renderSeconds", "is '" + seconds + "', not a number of seconds");
    for (const settings::SettingRow* setting : imageSettings()) {
        const std::string& key = setting->description.metadataKey;
        if (!setting->read(metadata.settings, required(key)))
            throw malformed(key, "has the value '" + values[key] + "', which is not one of " +
                                     setting->setBy());
    }
    metadata.program = required("program");
    metadata.gitCommit = values["gitCommit"];
    metadata.glContext = values["glContext"];
    metadata.glRenderer = values["glRenderer"];
    metadata.glVersion = values["glVersion"];
    metadata.kernel = values["kernel"];
    metadata.interrupted = values["interrupted"];
    if (values.count("crop") != 0) {
        metadata.crop = parseCrop(values["crop"]);
        if (!metadata.crop || metadata.crop->x0 < 0 || metadata.crop->y0 < 0 ||
            metadata.crop->width() <= 0 || metadata.crop->height() <= 0)
            throw malformed("crop", "is '" + values["crop"] +
                                        "', not 'X0 Y0 X1 Y1' with X0 < X1 "
                                        "and Y0 < Y1, from 0");
    }
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
    for (const settings::SettingRow* setting : imageSettings()) {
        const std::string a = setting->format(first.settings);
        const std::string b = setting->format(second.settings);
        if (a != b)
            return MetadataDifference{
                setting->description.metadataLabel + " (" + setting->setBy() + ")", a, b};
    }
    // Another build may trace other paths (a changed shader) for the same sample index.
    if (first.program != second.program || first.gitCommit != second.gitCommit)
        return MetadataDifference{"the program build", describeProgram(first),
                                  describeProgram(second)};
    return std::nullopt;
}

void addRenderingDevice(RenderMetadata& metadata, const RenderMetadata& other)
{
    auto add = [](std::string& values, const std::string& value) {
        if (value.empty())
            return;
        std::istringstream list(values);
        for (std::string item; std::getline(list, item, ';');)
            if (item == value || item == " " + value)
                return;
        values += (values.empty() ? "" : "; ") + value;
    };
    add(metadata.glContext, other.glContext);
    add(metadata.glRenderer, other.glRenderer);
    add(metadata.glVersion, other.glVersion);
    add(metadata.kernel, other.kernel);
}

std::string describeProgram(const RenderMetadata& metadata)
{
    return metadata.program +
           (metadata.gitCommit.empty() ? " (no git commit)" : ", commit " + metadata.gitCommit);
}

}  // namespace film
