#include "convergence/References.h"

#include "convergence/TimedRenderer.h"
#include "io/ImageFile.h"
#include "render/ScenePreparation.h"

#include <cstdio>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace convergence {

namespace fs = std::filesystem;

namespace {

// 64-bit FNV-1a (Fowler, Noll and Vo; http://www.isthe.com/chongo/tech/comp/fnv/): a stable
// hash for cache file names, unlike std::hash, which may differ between library versions.
class Fnv1a64 {
public:
    void add(const void* data, std::size_t size)
    {
        const auto* bytes = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i) {
            hash_ ^= bytes[i];
            hash_ *= 0x100000001b3ULL;
        }
    }
    void add(const std::string& text)
    {
        add(text.data(), text.size());
        add("\0", 1);  // separator: "ab"+"c" and "a"+"bc" hash differently
    }
    template <typename T>
    void addVector(const std::vector<T>& values)
    {
        add(values.data(), values.size() * sizeof(T));
        add("\0", 1);
    }
    std::string hex() const
    {
        char text[17];
        std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash_));
        return text;
    }

private:
    std::uint64_t hash_ = 0xcbf29ce484222325ULL;
};

std::string fileBytes(const fs::path& path)
{
    std::ifstream file(path, std::ios::binary);
    if (!file)
        throw std::runtime_error("cannot read " + path.string());
    return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
}

// Everything that decides a reference's pixels: the scene file, the shader exactly as it is
// assembled for the scene (modules and user SDFs included), the numbers the host packs for
// it, the texture files, the settings, the size, the spp and the seed. Anything else the host
// computes at upload time is not covered; --refresh-references re-renders regardless.
std::string referenceKey(const scene::Scene& parsed, const settings::RenderSettings& settings,
                         int width, int height, int samplesPerPixel)
{
    const render::PreparedScene prepared = render::prepareScene(
        parsed, shadergen::shaderBuild(settings), render::defaultShaderDirectory());
    const shadergen::SceneShaderCode& code = prepared.code;
    const render::SceneUniforms& uniforms = prepared.uniforms;
    Fnv1a64 hash;
    hash.add("bench_convergence reference 2");
    hash.add(fileBytes(parsed.sourcePath));
    hash.add(prepared.pathTracerSource.text());
    hash.addVector(code.shapeParameters);
    hash.addVector(uniforms.objects);
    hash.addVector(uniforms.pigments);
    hash.addVector(uniforms.finishes);
    hash.addVector(uniforms.lights);
    for (const fs::path& texture : uniforms.textureLayers)
        hash.add(fileBytes(texture));
    if (!uniforms.environment.mapPath.empty())
        hash.add(fileBytes(uniforms.environment.mapPath));
    hash.add(describeSettings(settings));
    hash.add(std::to_string(width) + "x" + std::to_string(height) + " " +
             std::to_string(samplesPerPixel) + "spp");
    return hash.hex();
}

// Reads `key=value` lines.
std::optional<std::string> sidecarValue(const fs::path& path, const std::string& name)
{
    std::ifstream file(path);
    std::string line;
    while (std::getline(file, line))
        if (line.rfind(name + "=", 0) == 0)
            return line.substr(name.size() + 1);
    return std::nullopt;
}

}  // namespace

std::string formatNumber(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

std::string describeSettings(const settings::RenderSettings& s)
{
    std::ostringstream text;
    text << "hitTolerance=" << formatNumber(s.hitTolerance) << " maxMarchSteps=" << s.maxMarchSteps
         << " overRelaxation=" << formatNumber(s.overRelaxation)
         << " stepScale=" << formatNumber(s.stepScale) << " maxBounces=" << s.maxBounces
         << " russianRouletteDepth=" << s.russianRouletteDepth
         << " mis=" << (s.multipleImportanceSampling ? 1 : 0) << " fresnel="
         << (s.dielectricFresnel == settings::FresnelModel::Exact ? "exact" : "schlick")
         << " variant=" << static_cast<int>(s.variant) << " seed=" << s.seed;
    return text.str();
}

std::string sceneName(const fs::path& path)
{
    return path.stem().string();
}

Reference obtainReference(const scene::Scene& scene, int width, int height,
                          const ReferenceOptions& options)
{
    settings::RenderSettings settings;
    settings.seed = options.seed;
    Reference reference;
    reference.samplesPerPixel = options.samplesPerPixel;
    reference.key = referenceKey(scene, settings, width, height, options.samplesPerPixel);
    const std::string stem = sceneName(scene.sourcePath) + "-" + std::to_string(width) + "x" +
                             std::to_string(height) + "-" +
                             std::to_string(options.samplesPerPixel) + "spp-" + reference.key;
    const fs::path fullPath = options.cacheDirectory / (stem + ".exr");
    const fs::path halfPath = options.cacheDirectory / (stem + "-half.exr");
    const fs::path sidecarPath = options.cacheDirectory / (stem + ".txt");

    const bool cached = fs::exists(fullPath) && fs::exists(halfPath) && fs::exists(sidecarPath);
    if (cached && !options.refresh) {
        auto recorded = [&](const std::string& name) {
            return sidecarValue(sidecarPath, name).value_or("0");
        };
        reference.image = io::readImage(fullPath);
        reference.halfImage = io::readImage(halfPath);
        reference.renderSeconds = std::stod(recorded("render_seconds"));
        reference.compileSeconds = std::stod(recorded("compile_seconds"));
        reference.warmUpSeconds = std::stod(recorded("warm_up_seconds"));
        reference.discardedSamples = std::stoull(recorded("discarded_samples"));
        reference.brightnessNoise = std::stod(recorded("brightness_noise"));
        reference.fromCache = true;
        reference.image.channels = reference.halfImage.channels = 3;
        if (reference.image.width != width || reference.image.height != height)
            throw std::runtime_error(fullPath.string() + " is not " + std::to_string(width) + "x" +
                                     std::to_string(height));
    } else {
        std::fprintf(stderr, "rendering the reference of %s: %dx%d, %d spp ...\n",
                     sceneName(scene.sourcePath).c_str(), width, height, options.samplesPerPixel);
        TimedRenderer run(scene, width, height, settings, defaultSamplesPerFrame(width, height));
        const int half = options.samplesPerPixel / 2;
        // Progress in tenths, for references that take an hour.
        for (int tenth = 1; tenth <= 10; ++tenth) {
            const int target = options.samplesPerPixel * tenth / 10;
            if (half >= 1 && target >= half && reference.halfImage.pixels.empty()) {
                run.renderTo(half);
                reference.halfImage = run.renderer().radiance();
            }
            run.renderTo(target);
            std::fprintf(stderr, "  %d/%d spp, %.0f s\n", run.samplesPerPixel(),
                         options.samplesPerPixel, run.renderSeconds());
        }
        reference.image = run.renderer().radiance();
        if (reference.halfImage.pixels.empty())  // a reference of 1 spp: no noise estimate
            reference.halfImage = reference.image;
        reference.renderSeconds = run.renderSeconds();
        reference.compileSeconds = run.compileSeconds();
        reference.warmUpSeconds = run.warmUpSeconds();
        reference.discardedSamples = run.renderer().discardedSamples();
        reference.brightnessNoise =
            brightnessNoise(run.renderer().sampleStatistics(), imageSum(reference.image));
        fs::create_directories(options.cacheDirectory);
        io::writeImage(fullPath, reference.image);
        io::writeImage(halfPath, reference.halfImage);
        std::ofstream sidecar(sidecarPath);
        sidecar << "scene=" << fs::absolute(scene.sourcePath).string() << "\n"
                << "size=" << width << "x" << height << "\n"
                << "spp=" << options.samplesPerPixel << "\n"
                << "settings=" << describeSettings(settings) << "\n"
                << "render_seconds=" << reference.renderSeconds << "\n"
                << "compile_seconds=" << reference.compileSeconds << "\n"
                << "warm_up_seconds=" << reference.warmUpSeconds << "\n"
                << "discarded_samples=" << reference.discardedSamples << "\n"
                << "brightness_noise=" << reference.brightnessNoise << "\n";
    }
    reference.noise = noiseOfMean(reference.halfImage, reference.image, reference.image);
    return reference;
}

}  // namespace convergence
