// The option table (settings/Options.def) walked row by row: every option is in --help with
// the default the struct holds, every recorded setting comes back from a file's metadata as
// it went in, every setting the shader reads is declared in the shader and read by the
// module named for it, and README.md and docs/USAGE.md name no option the program does not
// have.
#include "app/CommandLine.h"
#include "film/RenderMetadata.h"
#include "render/ScenePreparation.h"
#include "render/SceneUniforms.h"
#include "scene/SceneParser.h"
#include "settings/SettingsTable.h"
#include "shadergen/ShaderSource.h"
#include "shadergen/UniformBlock.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace options_tests {
namespace {

namespace fs = std::filesystem;

const fs::path kSourceDirectory = RAYTRACER_SOURCE_DIR;

std::string fileText(const fs::path& path)
{
    std::ifstream file(path);
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

// --help's text for one option: its line and the lines that continue it.
std::string helpOf(const std::string& flag)
{
    std::istringstream lines(app::usageText());
    std::string text;
    bool inside = false;
    for (std::string line; std::getline(lines, line);) {
        const bool starts = line.rfind("  -", 0) == 0;
        if (starts)
            inside = std::regex_search(line, std::regex("^  (-\\w, )?" + flag + "( |$)"));
        else if (line.rfind("                        ", 0) != 0)
            inside = false;
        if (inside)
            text += line + "\n";
    }
    return text;
}

TEST(OptionsTable, EverySettingWithAFlagIsInHelpWithTheStructsDefault)
{
    const settings::RenderSettings defaults;
    for (const settings::SettingRow& row : settings::settingRows()) {
        if (!row.isOption())
            continue;
        const std::string help = helpOf(row.description.flag);
        ASSERT_FALSE(help.empty()) << row.description.flag << " is not in --help";
        const std::size_t defaults_stated = [&] {
            std::size_t count = 0;
            for (std::size_t at = help.find("(default"); at != std::string::npos;
                 at = help.find("(default", at + 1))
                ++count;
            return count;
        }();
        if (!row.description.showDefault || !row.description.defaultText.empty() || !row.format) {
            EXPECT_LE(defaults_stated, 1u) << help;
            continue;
        }
        EXPECT_EQ(defaults_stated, 1u) << "one default stated: " << help;
        EXPECT_NE(help.find("(default " + row.format(defaults)), std::string::npos)
            << row.description.flag << "'s help should state the struct's default, "
            << row.format(defaults) << ":\n"
            << help;
    }
}

TEST(OptionsTable, ShortSpellingsAreListedInHelp)
{
    EXPECT_NE(helpOf("--output").find("-o, --output FILE"), std::string::npos) << app::usageText();
    EXPECT_NE(helpOf("--help").find("-h, --help"), std::string::npos) << app::usageText();
}

TEST(OptionsTable, AdaptiveTileHelpStatesTheDefaultThePlannerUses)
{
    EXPECT_NE(helpOf("--adaptive-tile")
                  .find("(default " + std::to_string(film::AdaptiveSampling{}.tileSize)),
              std::string::npos)
        << helpOf("--adaptive-tile");
    EXPECT_NE(helpOf("--min-spp")
                  .find("(default " + std::to_string(film::AdaptiveSampling{}.minimumSamples)),
              std::string::npos)
        << helpOf("--min-spp");
}

// A value of each recorded setting other than its default, through the row's own parse.
settings::RenderSettings changedFromDefault(const settings::SettingRow& row)
{
    const settings::RenderSettings defaults;
    settings::RenderSettings changed;
    if (!row.isOption()) {
        EXPECT_TRUE(row.read(changed, row.format(defaults) == "on" ? "off" : "on"));
        return changed;
    }
    if (!row.takesValue()) {
        row.apply(changed, "");
        return changed;
    }
    std::vector<std::string> candidates = row.choiceNames;
    for (const char* number : {"0.5", "0.75", "1.5", "2", "3", "64", "100"})
        candidates.push_back(number);
    for (const std::string& candidate : candidates) {
        settings::RenderSettings trial;
        try {
            row.apply(trial, candidate);
        } catch (const settings::UsageError&) {
            continue;
        }
        if (row.format(trial) != row.format(defaults))
            return trial;
    }
    ADD_FAILURE() << row.description.flag << ": no value other than the default was accepted";
    return changed;
}

TEST(OptionsTable, EveryRecordedSettingRoundTripsThroughAFilesMetadata)
{
    const settings::RenderSettings defaults;
    std::size_t recorded = 0;
    for (const settings::SettingRow& row : settings::settingRows()) {
        if (!row.isRecorded())
            continue;
        ++recorded;
        film::RenderMetadata written;
        written.sceneSha256 = std::string(64, 'a');
        written.settings = changedFromDefault(row);
        ASSERT_NE(row.format(written.settings), row.format(defaults)) << row.field;
        const auto read = film::metadataFromAttributes(film::metadataAttributes(written), "x.exr");
        ASSERT_TRUE(read.has_value());
        EXPECT_EQ(row.format(read->settings), row.format(written.settings))
            << row.description.metadataKey << " did not come back as it was written";
    }
    EXPECT_EQ(recorded, film::imageSettings().size());
}

// The specialised shader of a scene with marched objects (the classic scene 6)
// and the general shader, which has every feature, as assembled: the generated uniforms'
// piece, and the rest.
struct AssembledShader {
    std::vector<std::string> pieces;
    std::string uniforms;
    std::string rest;
};

std::vector<AssembledShader> assembledShaders()
{
    std::vector<AssembledShader> shaders;
    shadergen::ShaderBuild general;
    general.variant = settings::ShaderVariant::General;
    for (const auto& [scene, build] :
         {std::pair{"scene6.in", shadergen::ShaderBuild{}}, std::pair{"scene1.in", general}}) {
        const shadergen::ShaderSource source =
            render::prepareScene(scene::parseSceneFile(kSourceDirectory / "scenes" / scene), build,
                                 render::defaultShaderDirectory())
                .pathTracerSource;
        const std::string text = source.text();
        const std::size_t begin = text.find("void readUniformsOnce()");
        const std::size_t end = text.find("\n#line", begin);
        shaders.push_back({source.pieceNames(), text.substr(0, end), text.substr(end)});
    }
    return shaders;
}

TEST(OptionsTable, EveryUniformSettingIsDeclaredWithItsModuleAndReadInTheShader)
{
    const std::vector<AssembledShader> shaders = assembledShaders();
    for (const settings::SettingRow& row : settings::settingRows()) {
        if (!row.isUniform())
            continue;
        const std::string uniform = settings::uniformName(row.field);
        const std::string copy = settings::perPixelCopyName(row.field);
        const fs::path module =
            kSourceDirectory / "shaders" / "modules" / row.description.uniformModule;
        EXPECT_TRUE(fs::exists(module)) << row.field << " names the module " << module;
        bool read = false;
        for (const AssembledShader& shader : shaders) {
            const bool hasModule =
                std::find(shader.pieces.begin(), shader.pieces.end(),
                          "modules/" + row.description.uniformModule) != shader.pieces.end();
            const bool declared = shader.uniforms.find("uniform " + std::string(row.glslType) +
                                                       " " + uniform + ";") != std::string::npos;
            EXPECT_EQ(declared, hasModule)
                << uniform << " should be declared exactly where " << row.description.uniformModule
                << " is part of the shader";
            EXPECT_EQ(shader.uniforms.find(copy + " = " + uniform + ";") != std::string::npos,
                      declared)
                << uniform << " should be read once where it is declared";
            read = read || std::regex_search(shader.rest, std::regex("\\b" + copy + "\\b"));
        }
        EXPECT_TRUE(read) << "no shader reads " << copy << " (" << row.field << "'s uniform)";
    }
}

TEST(OptionsTable, NoModuleDeclaresAGeneratedUniformOrCopyOfItsOwn)
{
    std::set<std::string> generated;
    for (const shadergen::UniformDeclaration& declaration :
         render::pathTracerUniformDeclarations()) {
        generated.insert(declaration.name);
        generated.insert(declaration.copy);
    }
    for (const auto& entry : fs::directory_iterator(kSourceDirectory / "shaders" / "modules")) {
        const std::string text = fileText(entry.path());
        for (const std::string& name : generated)
            EXPECT_FALSE(std::regex_search(
                text, std::regex("^\\s*(uniform\\s+)?\\w+\\s+" + name + "\\s*[;=\\[]")))
                << entry.path().filename() << " declares " << name
                << ", which the generated preamble declares";
    }
}

TEST(OptionsTable, UserDocsNameOnlyOptionsTheProgramHas)
{
    // merge's own, and other programs' options the docs quote (valgrind's).
    std::set<std::string> known = {"--png", "--trace-children"};
    std::istringstream help(app::usageText());
    const std::regex flag("--[a-z][a-z-]*");
    for (std::string line; std::getline(help, line);)
        for (auto it = std::sregex_iterator(line.begin(), line.end(), flag);
             it != std::sregex_iterator(); ++it)
            known.insert(it->str());
    for (const char* document : {"README.md", "docs/USAGE.md"}) {
        const std::string text = fileText(kSourceDirectory / document);
        const std::regex option("`(--[a-z][a-z-]*)");
        for (auto it = std::sregex_iterator(text.begin(), text.end(), option);
             it != std::sregex_iterator(); ++it)
            EXPECT_TRUE(known.count((*it)[1].str()) != 0)
                << document << " names " << (*it)[1].str() << ", which --help does not list";
    }
}

}  // namespace
}  // namespace options_tests
