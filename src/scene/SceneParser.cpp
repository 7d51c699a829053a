#include "scene/SceneParser.h"

#include "scene/PrimitiveKinds.h"
#include "scene/SceneError.h"
#include "scene/SceneFileText.h"
#include "scene/Spelling.h"
#include "scene/TokenCursor.h"
#include "scene/Tokenizer.h"
#include "scene/UserSdfDeclarations.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cstdlib>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace scene {

namespace fs = std::filesystem;

namespace {

const std::set<std::string> kTransformWords = {"translate", "rotate", "scale"};
const std::set<std::string> kSectionKeywords = {"environment"};

// What a scene file may make the parser hold (docs/SCENE_FORMAT.md, "Limits"): far beyond any
// scene this renderer can draw, and small enough that no file can exhaust memory or the stack.
constexpr int kMaxCount = TokenCursor::kMaxCount;  // lights, pigments, finishes, objects, planes
constexpr int kMaxNestingDepth = 64;               // CSG blocks and transforms, one inside another
constexpr std::size_t kMaxTokens = 4u << 20;       // words in the file

// "sphere, polyhedron, ...": every primitive's keyword, for messages.
std::string primitiveWords()
{
    std::string words;
    for (const PrimitiveKind& kind : primitiveKinds())
        words += (words.empty() ? "" : ", ") + std::string(kind.keyword);
    return words;
}

// " (did you mean 'sphere'?)" where `word` is within two edits of one of `keywords`.
std::string didYouMean(const std::string& word, const std::vector<std::string>& keywords)
{
    const auto nearest = nearestWord(word, keywords);
    return nearest ? " (did you mean '" + *nearest + "'?)" : "";
}

// Every word that may stand where an object's type does: the primitives', the CSG operators'
// and the transforms'.
std::vector<std::string> shapeKeywords()
{
    std::vector<std::string> words(kTransformWords.begin(), kTransformWords.end());
    for (const PrimitiveKind& kind : primitiveKinds())
        words.push_back(kind.keyword);
    for (const CsgOperatorDescription& op : csgOperatorDescriptions())
        words.push_back(op.keyword);
    return words;
}

bool isNumberWord(const std::string& word)
{
    char* end = nullptr;
    std::strtod(word.c_str(), &end);
    return !word.empty() && end == word.c_str() + word.size();
}

class Parser : private TokenCursor {
public:
    Parser(std::vector<Token> tokens, std::string fileName, const FileLookup& lookup)
        : TokenCursor(std::move(tokens), std::move(fileName)), lookup_(lookup)
    {
    }

    Scene parse()
    {
        Scene scene;
        parseSectionKeywords(scene);
        parseCamera(scene.camera);
        parseSectionKeywords(scene);
        parsePointLights(scene);
        parseSectionKeywords(scene);
        parsePigments(scene);
        parseSectionKeywords(scene);
        parseFinishes(scene);
        parseSectionKeywords(scene);
        parseObjects(scene);
        parseSectionKeywords(scene);
        if (!atEnd())
            fail("the end of the file (the object count says " +
                 std::to_string(scene.objects.size()) +
                 (scene.objects.size() == 1 ? " object)" : " objects)"));
        return scene;
    }

    // A camera alone (parseCameraText): its groups may follow their words.
    Camera parseCameraAlone()
    {
        labelledCamera_ = true;
        Camera camera;
        parseCamera(camera);
        if (!atEnd())
            fail("the end of the camera (after the field of view, only 'lens R D' may follow)");
        return camera;
    }

private:
    // In a camera alone, the word before a group (any of `words`) is skipped.
    void skipLabel(std::initializer_list<const char*> words)
    {
        if (!labelledCamera_)
            return;
        if (const Token* token = peek())
            for (const char* word : words)
                if (token->text == word) {
                    skip();
                    return;
                }
    }

    // --- sections -----------------------------------------------------------------------

    void parseSectionKeywords(Scene& scene)
    {
        while (const Token* token = peek()) {
            if (kSectionKeywords.count(token->text) == 0) {
                // A misspelt keyword would be read as the next section's first number.
                const std::vector<std::string> keywords(kSectionKeywords.begin(),
                                                        kSectionKeywords.end());
                if (!isNumberWord(token->text))
                    if (const std::string hint = didYouMean(token->text, keywords); !hint.empty())
                        fail("a number, or a section keyword" + hint);
                return;
            }
            skip();
            if (token->text == "environment")
                parseEnvironment(scene.environment);
        }
    }

    void parseEnvironment(Environment& environment)
    {
        const std::string expected = "an environment: none, sky, a colour 'r g b', or map FILE";
        const Token* token = peek();
        if (token == nullptr)
            fail(expected);
        const int line = token->line;
        const EnvironmentDescription* kind = findEnvironmentKind(token->text);
        if (kind == nullptr && !isNumberWord(token->text)) {
            std::vector<std::string> words;
            for (const EnvironmentDescription& description : environmentDescriptions()) {
                words.push_back(description.keyword);
                if (*description.alias != '\0')
                    words.push_back(description.alias);
            }
            if (const std::string hint = didYouMean(token->text, words); !hint.empty())
                fail(expected + hint);
        }
        if (kind != nullptr)
            skip();
        else
            // A colour alone is a constant environment: its word may be left out.
            kind = &describe(EnvironmentKind::Constant);
        environment = Environment();
        environment.kind = kind->kind;
        environment.line = line;
        kind->read(*this, lookup_, environment);
    }

    void parseCamera(Camera& camera)
    {
        skipLabel({"eye"});
        camera.eye = vector3("camera eye position");
        skipLabel({"target", "look-at"});
        const std::size_t targetToken = mark();
        camera.target = vector3("camera target point");
        skipLabel({"up"});
        const std::size_t upToken = mark();
        camera.up = vector3("camera up vector");
        skipLabel({"fovy", "fov"});
        const std::size_t fovToken = mark();
        camera.verticalFieldOfViewDegrees = number("vertical field of view in degrees");

        // In double, as cameraFrame() computes: a float's squared length overflows for far
        // points, and a NaN would pass for the wrong fault.
        const glm::dvec3 view = glm::dvec3(camera.target) - glm::dvec3(camera.eye);
        if (!(glm::length(view) > 0.0))
            failAtMark(targetToken, "a camera target different from the eye position");
        const glm::dvec3 up(camera.up);
        if (!(glm::length(up) > 0.0))
            failAtMark(upToken, "a camera up vector that is not zero");
        if (!(glm::length(glm::cross(glm::normalize(view), glm::normalize(up))) >= 1e-6))
            failAtMark(upToken, "a camera up vector not parallel to the view direction (from "
                                "the eye to the target)");
        if (!(camera.verticalFieldOfViewDegrees > 0.0f &&
              camera.verticalFieldOfViewDegrees < 180.0f))
            failAtMark(fovToken, "a vertical field of view strictly between 0 and 180 degrees");

        // The thin lens (extension): `lens APERTURE_RADIUS FOCUS_DISTANCE`. A classic file has
        // the point light count here, never a word.
        if (const Token* token = peek(); token != nullptr && token->text == "lens") {
            skip();
            ThinLens lens;
            lens.apertureRadius = numberAtLeast("lens aperture radius", 0.0f);
            lens.focusDistance = positiveNumber("lens focus distance");
            // A radius of 0 is the pinhole.
            if (lens.apertureRadius > 0.0f)
                camera.lens = lens;
        }
    }

    void parsePointLights(Scene& scene)
    {
        const int lights = count("number of point lights");
        for (int i = 0; i < lights; ++i) {
            const std::string which =
                "point light " + std::to_string(i + 1) + " of " + std::to_string(lights);
            PointLight light;
            light.position = vector3(which + " position");
            light.intensity = colour(which + " intensity");
            scene.pointLights.push_back(light);
        }
    }

    void parsePigments(Scene& scene)
    {
        const int pigments = count("number of pigments");
        for (int i = 0; i < pigments; ++i) {
            const std::string which = "pigment " + std::to_string(i) + " (" +
                                      std::to_string(i + 1) + " of " + std::to_string(pigments) +
                                      ")";
            const std::string expected = "a pigment kind for " + which + ": " + pigmentKeywords();
            const Token& word = next(expected);
            const PigmentDescription* kind = findPigmentKind(word.text);
            if (kind == nullptr) {
                std::vector<std::string> words;
                for (const PigmentDescription& description : pigmentDescriptions())
                    words.push_back(description.keyword);
                failAt(word, expected + didYouMean(word.text, words));
            }
            Pigment pigment;
            pigment.kind = kind->kind;
            pigment.line = word.line;
            kind->read(*this, lookup_, which, pigment);
            scene.pigments.push_back(pigment);
        }
    }

    void parseFinishes(Scene& scene)
    {
        const int finishes = count("number of finishes");
        for (int i = 0; i < finishes; ++i) {
            const std::string which = "finish " + std::to_string(i) + " (" + std::to_string(i + 1) +
                                      " of " + std::to_string(finishes) + ")";
            Finish finish;
            // A finish written with its material's keyword (extension); a classic one starts
            // with a number.
            if (const Token* token = peek()) {
                if (const MaterialDescription* kind = findFinishKeyword(token->text)) {
                    skip();
                    finish.keywordMaterial = kind->kind;
                    kind->read(*this, which, finish);
                    scene.finishes.push_back(finish);
                    continue;
                }
            }
            finish.emission =
                colour(which + " emitted radiance, or a finish keyword: " + finishKeywords());
            finish.phongExponent = numberAtLeast(which + " Blinn-Phong exponent", 0.0f);
            finish.reflection = number(which + " kr");
            finish.transmission = number(which + " kt");
            const std::size_t iorToken = mark();
            finish.ior = number(which + " index of refraction");
            if (finish.transmission > 0.0f && !(finish.ior > 0.0f))
                failAtMark(iorToken,
                           "a positive index of refraction (" + which + " is transmissive)");
            scene.finishes.push_back(finish);
        }
    }

    void parseObjects(Scene& scene)
    {
        const int objects = count("number of objects");
        for (int i = 0; i < objects; ++i) {
            const std::string which =
                "object " + std::to_string(i + 1) + " of " + std::to_string(objects);
            SceneObject object;
            object.line = peek() != nullptr ? peek()->line : 0;
            object.pigment = index("pigment", scene.pigments.size());
            object.finish = index("finish", scene.finishes.size());
            const std::size_t typeToken = mark();
            object.shape = parseShape(which, 0);
            const bool emissive = scene.finishes[object.finish].isEmissive();
            if (emissive && !std::holds_alternative<Sphere>(object.shape.geometry))
                failAtMark(typeToken, "a sphere: finish " + std::to_string(object.finish) +
                                          " emits light, and only spheres may emit");
            scene.objects.push_back(std::move(object));
        }
    }

    // --- shapes -------------------------------------------------------------------------

    // `depth`: the CSG blocks and transforms this shape is inside.
    Shape parseShape(const std::string& which, int depth)
    {
        const std::string expected = "an object type for " + which + " (" + primitiveWords() +
                                     ", a CSG operation, a transform, or the name of a user "
                                     "SDF)";
        const Token& type = next(expected);
        const std::string& word = type.text;

        const bool nests = kTransformWords.count(word) != 0 || isCsgKeyword(word);
        if (nests && depth >= kMaxNestingDepth)
            failAt(type, "a primitive or user SDF: CSG blocks and transforms nest at most " +
                             std::to_string(kMaxNestingDepth) + " deep (" + which + ")");
        if (kTransformWords.count(word) != 0)
            return parseTransformed(type, which, depth + 1);
        if (isCsgKeyword(word))
            return {parseCsg(type, which, depth + 1), std::nullopt};
        if (const PrimitiveKind* primitive = findPrimitiveKind(word))
            return {primitive->read(*this), std::nullopt};
        if (word == "{" || word == "}" || !isGlslIdentifier(word))
            failAt(type, expected + didYouMean(word, shapeKeywords()));

        UserSdf user;
        user.name = word;
        const auto found = lookup_.findUserSdf(word);
        if (!found)
            failAt(type, "an object type, or a user SDF with a shader file " + shownToken(word) +
                             ".glsl (looked in " + joinFolders(lookup_.shaderFolders()) + ")" +
                             didYouMean(word, shapeKeywords()));
        user.sourcePath = *found;
        readUserSdfDeclarations(user);
        user.position = vector3(shownToken(word) + " position");
        return {user, std::nullopt};
    }

    Shape parseTransformed(const Token& keyword, const std::string& which, int depth)
    {
        Transform transform;
        if (keyword.text == "translate") {
            transform.translation = vector3("translation");
        } else if (keyword.text == "rotate") {
            const std::size_t first = mark();
            const glm::vec3 axis = vector3("rotation axis");
            const float degrees = number("rotation angle in degrees");
            if (!(glm::length(axis) > 0.0f))
                failAtMark(first, "a rotation axis that is not zero");
            transform.rotation = glm::mat3(
                glm::rotate(glm::mat4(1.0f), glm::radians(degrees), glm::normalize(axis)));
        } else {
            transform.scale = positiveNumber("uniform scale factor");
        }
        Shape inner = parseShape(which, depth);
        inner.transform = inner.transform ? compose(transform, *inner.transform) : transform;
        return inner;
    }

    CsgNode parseCsg(const Token& keyword, const std::string& which, int depth)
    {
        CsgNode node;
        const std::string& word = keyword.text;
        if (const CsgOperatorDescription* sharp = findCsgOperator(word, "")) {
            node.op = sharp->op;
        } else {
            const std::string expected =
                "a smooth-operator kind: exp (sharpness k) or poly (radius)";
            const Token& mode = next(expected);
            const CsgOperatorDescription* smooth = findCsgOperator(word, mode.text);
            if (smooth == nullptr) {
                std::vector<std::string> words;
                for (const CsgOperatorDescription& op : csgOperatorDescriptions())
                    if (op.keyword == word && *op.smoothingWord != '\0')
                        words.push_back(op.smoothingWord);
                failAt(mode, expected + didYouMean(mode.text, words));
            }
            node.op = smooth->op;
            node.parameter = smooth->smoothing == CsgSmoothing::Exponential
                                 ? positiveNumber("smooth-min sharpness k")
                                 : numberAtLeast("smooth-min blend radius", 0.0f);
        }
        expectWord("{");
        while (const Token* token = peek()) {
            if (token->text == "}")
                break;
            node.children.push_back(parseShape(which + ", inside '" + word + "'", depth));
        }
        if (atEnd())
            fail("'}' closing the '" + word + "' opened on line " + std::to_string(keyword.line));
        if (node.children.size() < 2)
            fail("at least two shapes inside '" + word + "' (opened on line " +
                 std::to_string(keyword.line) + ")");
        skip();
        return node;
    }

    const FileLookup& lookup_;
    bool labelledCamera_ = false;
};

}  // namespace

bool isReservedShapeWord(const std::string& word)
{
    return isCsgKeyword(word) || kTransformWords.count(word) != 0 ||
           findPrimitiveKind(word) != nullptr;
}

Scene parseSceneText(const std::string& text, const std::string& fileName, const FileLookup& lookup)
{
    std::string_view content = text;
    // An editor's UTF-8 byte-order mark means nothing here; a UTF-16 file cannot be read.
    constexpr std::string_view kUtf8Mark = "\xEF\xBB\xBF";
    if (content.substr(0, kUtf8Mark.size()) == kUtf8Mark)
        content.remove_prefix(kUtf8Mark.size());
    if (content.substr(0, 2) == "\xFF\xFE" || content.substr(0, 2) == "\xFE\xFF")
        throw SceneError(fileName, 1, std::string(content.substr(0, 2)),
                         "ASCII or UTF-8 text: this file is UTF-16 (its first bytes are a "
                         "UTF-16 byte-order mark); save it as UTF-8");
    std::vector<Token> tokens = tokenize(content, kMaxTokens + 1);
    if (tokens.size() > kMaxTokens)
        throw SceneError(fileName, tokens.back().line, tokens.back().text,
                         "the end of the file: a scene file holds at most " +
                             std::to_string(kMaxTokens) + " words");
    Parser parser(std::move(tokens), fileName, lookup);
    Scene scene = parser.parse();
    scene.sourcePath = fileName;
    return scene;
}

Camera parseCameraText(const std::string& text, const std::string& source)
{
    // A camera names no file: nothing is looked up.
    const FileLookup noFiles{fs::path(), fs::path()};
    Parser parser(tokenize(text, kMaxTokens), source, noFiles);
    return parser.parseCameraAlone();
}

Scene parseSceneFile(const fs::path& path)
{
    return parseSceneText(readSceneFileText(path), path.string(), FileLookup::forScene(path));
}

}  // namespace scene
