// Every sampling routine against its pdf (STYLE.md: "every sampling routine comes with its
// pdf, and a test that the two agree"), Mitsuba-style: the GPU draws a million directions
// with the renderer's own GLSL, the pdf (also evaluated by the renderer's GLSL) is integrated
// over (theta, phi) bins, and Pearson's chi-square compares the histogram with the
// integrals. Bins are chosen from the pdf alone (equal probability along theta and along
// phi), never from the samples.
#include "render/EnvironmentMap.h"
#include "sampling/ShaderSampler.h"
#include "support/ChiSquare.h"
#include "support/EnvironmentMapImages.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numeric>
#include <sstream>

namespace sampling_tests {
namespace {

using testing_support::ChiSquareResult;
using testing_support::chiSquareTest;

constexpr double kPi = 3.14159265358979323846;
// Per test; the suite runs about twenty of them.
constexpr double kSignificance = 1e-4;
constexpr int kSampleSide = 512;  // samples per draw: 512 x 512
constexpr int kDraws = 4;         // each with its own seed
constexpr int kBinsPerAxis = 16;

glm::mat3 frameAround(const glm::vec3& axis)
{
    const glm::vec3 n = glm::normalize(axis);
    const glm::vec3 helper = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::vec3 t = glm::normalize(glm::cross(helper, n));
    const glm::vec3 b = glm::cross(n, t);
    return glm::mat3(t, b, n);
}

// Bin edges, as grid-cell indices, splitting `mass` (per cell) into about `bins` parts of
// equal probability.
std::vector<int> equalMassEdges(const std::vector<double>& mass, int bins)
{
    const double total = std::accumulate(mass.begin(), mass.end(), 0.0);
    std::vector<int> edges = {0};
    double running = 0.0;
    int next = 1;
    for (std::size_t cell = 0; cell < mass.size(); ++cell) {
        running += mass[cell];
        if (next < bins && running >= total * next / bins) {
            if (static_cast<int>(cell) + 1 > edges.back())
                edges.push_back(static_cast<int>(cell) + 1);
            while (next < bins && running >= total * next / bins)
                ++next;
        }
    }
    if (edges.back() != static_cast<int>(mass.size()))
        edges.push_back(static_cast<int>(mass.size()));
    return edges;
}

int binOf(const std::vector<int>& edges, int cell)
{
    return static_cast<int>(std::upper_bound(edges.begin(), edges.end(), cell) - edges.begin()) - 1;
}

struct Histograms {
    double outsideGrid = 0.0;
    std::vector<double> observed;
    std::vector<double> expected;
    std::vector<std::string> binNames;  // "theta [a, b) phi [c, d)" in degrees
    std::string layout;

    // The bins that add most to the chi-square statistic, for the failure message.
    std::string worstBins(int count) const
    {
        std::vector<std::size_t> order(observed.size());
        std::iota(order.begin(), order.end(), 0);
        auto contribution = [&](std::size_t i) {
            const double difference = observed[i] - expected[i];
            return difference * difference / std::max(expected[i], 1.0);
        };
        std::sort(order.begin(), order.end(),
                  [&](std::size_t a, std::size_t b) { return contribution(a) > contribution(b); });
        std::ostringstream text;
        for (int k = 0; k < count && k < static_cast<int>(order.size()); ++k)
            text << "\n    " << binNames[order[k]] << ": observed " << observed[order[k]]
                 << ", expected " << expected[order[k]];
        return text.str();
    }
};

// Draws the samples, bins them, and integrates the pdf over the same bins. The last bin is
// "no sample returned", whose probability is what the pdf leaves of 1. Directions beyond
// the grid, where the pdf is zero, are counted apart.
Histograms histogramsFor(const SamplingCase& samplingCase, const GridLayout& grid)
{
    const ShaderSampler sampler;
    const std::vector<float> pdf = sampler.pdfOnGrid(samplingCase, grid);
    const double cellTheta = grid.thetaMax / grid.thetaCells;
    const double cellPhi = 2.0 * kPi / grid.phiCells;

    // Probability of each grid cell: the pdf at its centre times its exact solid angle.
    std::vector<double> cellMass(pdf.size());
    std::vector<double> thetaMass(grid.thetaCells, 0.0);
    std::vector<double> phiMass(grid.phiCells, 0.0);
    for (int j = 0; j < grid.phiCells; ++j)
        for (int i = 0; i < grid.thetaCells; ++i) {
            const double solidAngle =
                (std::cos(i * cellTheta) - std::cos((i + 1) * cellTheta)) * cellPhi;
            const double mass = std::max(0.0f, pdf[j * grid.thetaCells + i]) * solidAngle;
            cellMass[j * grid.thetaCells + i] = mass;
            thetaMass[i] += mass;
            phiMass[j] += mass;
        }
    const std::vector<int> thetaEdges = equalMassEdges(thetaMass, kBinsPerAxis);
    const std::vector<int> phiEdges = equalMassEdges(phiMass, kBinsPerAxis);
    const int thetaBins = static_cast<int>(thetaEdges.size()) - 1;
    const int phiBins = static_cast<int>(phiEdges.size()) - 1;
    const int noSampleBin = thetaBins * phiBins;

    Histograms histograms;
    histograms.observed.assign(noSampleBin + 1, 0.0);
    histograms.expected.assign(noSampleBin + 1, 0.0);
    std::ostringstream layout;
    layout << thetaBins << " x " << phiBins << " bins in (theta, phi)";
    histograms.layout = layout.str();
    const double degreesPerCellTheta = cellTheta * 180.0 / kPi;
    const double degreesPerCellPhi = cellPhi * 180.0 / kPi;
    for (int b = 0; b < phiBins; ++b)
        for (int a = 0; a < thetaBins; ++a) {
            std::ostringstream name;
            name << "theta [" << thetaEdges[a] * degreesPerCellTheta << ", "
                 << thetaEdges[a + 1] * degreesPerCellTheta << ") phi ["
                 << phiEdges[b] * degreesPerCellPhi << ", " << phiEdges[b + 1] * degreesPerCellPhi
                 << ")";
            histograms.binNames.push_back(name.str());
        }
    histograms.binNames.push_back("no sample returned");

    double samples = 0.0;
    for (int draw = 0; draw < kDraws; ++draw) {
        // The renderer's own sampler: every fragment a pixel of its own, at sample `draw`.
        SamplerChoice choice;
        choice.sampleIndex = draw;
        const auto values =
            sampler.sampleDirections(samplingCase, kSampleSide, kSampleSide,
                                     1000 + static_cast<std::uint64_t>(draw), choice);
        for (const glm::vec4& value : values) {
            samples += 1.0;
            if (value.w < 0.0f) {
                histograms.observed[noSampleBin] += 1.0;
                continue;
            }
            const glm::dvec3 local = glm::transpose(glm::dmat3(grid.frame)) *
                                     glm::normalize(glm::dvec3(glm::vec3(value)));
            const double theta = std::atan2(std::hypot(local.x, local.y), local.z);
            double phi = std::atan2(local.y, local.x);
            if (phi < 0.0)
                phi += 2.0 * kPi;
            // Rounding may put a direction a hair beyond the grid's last edge.
            if (theta > grid.thetaMax * (1.0 + 1e-4)) {
                histograms.outsideGrid += 1.0;
                continue;
            }
            const int i = std::min(static_cast<int>(theta / cellTheta), grid.thetaCells - 1);
            const int j = std::min(static_cast<int>(phi / cellPhi), grid.phiCells - 1);
            histograms.observed[binOf(phiEdges, j) * thetaBins + binOf(thetaEdges, i)] += 1.0;
        }
    }

    double total = 0.0;
    for (int j = 0; j < grid.phiCells; ++j)
        for (int i = 0; i < grid.thetaCells; ++i) {
            const double mass = cellMass[j * grid.thetaCells + i];
            histograms.expected[binOf(phiEdges, j) * thetaBins + binOf(thetaEdges, i)] +=
                samples * mass;
            total += mass;
        }
    histograms.expected[noSampleBin] = samples * std::max(0.0, 1.0 - total);
    return histograms;
}

void expectSamplesFollowPdf(const SamplingCase& samplingCase, const GridLayout& grid,
                            const std::string& what)
{
    const Histograms histograms = histogramsFor(samplingCase, grid);
    const ChiSquareResult result =
        chiSquareTest(histograms.observed, histograms.expected, kSignificance);
    std::cout << what << ": " << histograms.layout << ", " << result.describe() << "\n";
    EXPECT_TRUE(result.passed) << what << ": the sampled directions should follow the pdf ("
                               << histograms.layout << ", " << kDraws * kSampleSide * kSampleSide
                               << " samples, significance " << kSignificance << "), but "
                               << result.describe() << "; samples with no direction "
                               << histograms.observed.back() << " (expected "
                               << histograms.expected.back()
                               << "); the bins furthest from their expectation:"
                               << histograms.worstBins(6);
    EXPECT_EQ(histograms.outsideGrid, 0.0)
        << what << ": directions were drawn where the pdf is zero (beyond theta = " << grid.thetaMax
        << ")";
}

// --- the statistics themselves --------------------------------------------------------

TEST(ChiSquareDistribution, MatchesTabulatedQuantiles)
{
    // Upper 5% and 0.1% points of the chi-square distribution (Abramowitz and Stegun,
    // table 26.8).
    EXPECT_NEAR(testing_support::chiSquareSurvival(3.841, 1), 0.05, 1e-4);
    EXPECT_NEAR(testing_support::chiSquareSurvival(18.307, 10), 0.05, 1e-4);
    EXPECT_NEAR(testing_support::chiSquareSurvival(29.588, 10), 0.001, 1e-5);
    EXPECT_NEAR(testing_support::chiSquareQuantileAbove(100, 0.05), 124.342, 1e-2);
}

TEST(ChiSquareTest, PoolsSparseBinsInsteadOfDividingByTinyExpectations)
{
    // One sample where 1e-9 were expected is no evidence against the pdf.
    const auto result = chiSquareTest({1.0, 500.0, 499.0}, {1e-9, 500.0, 500.0}, 1e-4);
    EXPECT_TRUE(result.passed) << result.describe();
}

TEST(ChiSquareTest, RejectsAHistogramFromAnotherDistribution)
{
    const auto result = chiSquareTest({600.0, 400.0}, {500.0, 500.0}, 1e-4);
    EXPECT_FALSE(result.passed) << result.describe();
}

// --- the routines of sampling.glsl, in their local frame ---------------------------------

TEST(CosineHemisphereSampling, DirectionsFollowCosineHemispherePdf)
{
    SamplingCase samplingCase;
    samplingCase.routine = SamplingRoutine::CosineHemisphere;
    expectSamplesFollowPdf(samplingCase, GridLayout{}, "sampleCosineHemisphere");
}

class ConeSampling : public ::testing::TestWithParam<float> {};

TEST_P(ConeSampling, DirectionsFollowUniformConePdf)
{
    SamplingCase samplingCase;
    samplingCase.routine = SamplingRoutine::UniformCone;
    samplingCase.oneMinusCosThetaMax = GetParam();
    GridLayout grid;
    // The grid ends exactly at the cone's edge, so no cell straddles it.
    const double oneMinusCos = GetParam();
    grid.thetaMax = static_cast<float>(
        2.0 * std::asin(std::sqrt(oneMinusCos / 2.0)));  // 1 - cos t = 2 sin^2(t / 2)
    expectSamplesFollowPdf(samplingCase, grid,
                           "sampleUniformCone with 1 - cos(thetaMax) = " +
                               std::to_string(GetParam()));
}

std::string coneName(const ::testing::TestParamInfo<float>& info)
{
    const char* const names[] = {"hemisphere", "wide", "narrow", "tiny"};
    return names[info.index];
}

INSTANTIATE_TEST_SUITE_P(OneMinusCosThetaMax, ConeSampling,
                         ::testing::Values(1.0f, 0.3f, 1e-3f, 1e-6f), coneName);

class BlinnPhongHalfVectorSampling : public ::testing::TestWithParam<float> {};

TEST_P(BlinnPhongHalfVectorSampling, HalfVectorsFollowBlinnPhongHalfVectorPdf)
{
    SamplingCase samplingCase;
    samplingCase.routine = SamplingRoutine::BlinnPhongHalfVector;
    samplingCase.exponent = GetParam();
    GridLayout grid;
    grid.thetaCells = 1024;
    expectSamplesFollowPdf(samplingCase, grid,
                           "sampleBlinnPhongHalfVector with exponent " +
                               std::to_string(GetParam()));
}

std::string exponentName(const ::testing::TestParamInfo<float>& info)
{
    return "n" + std::to_string(static_cast<int>(info.param));
}

INSTANTIATE_TEST_SUITE_P(Exponent, BlinnPhongHalfVectorSampling,
                         ::testing::Values(1.0f, 20.0f, 500.0f), exponentName);

// --- the Blinn-Phong material of materials.glsl, in world space --------------------------

struct MaterialCase {
    float exponent;
    float viewDegrees;  // angle between wo and the normal
    float pigment;      // R0: 1 makes Schlick's Fresnel 1, so only the lobe is sampled
    glm::vec3 normal;
    const char* name;
};

SamplingCase materialSamplingCase(const MaterialCase& material, glm::mat3& frame)
{
    frame = frameAround(material.normal);
    const float angle = glm::radians(material.viewDegrees);
    SamplingCase samplingCase;
    samplingCase.routine = SamplingRoutine::BlinnPhongMaterial;
    samplingCase.exponent = material.exponent;
    samplingCase.normal = frame[2];
    samplingCase.outgoing = glm::normalize(std::cos(angle) * frame[2] + std::sin(angle) * frame[0]);
    samplingCase.pigment = glm::vec3(material.pigment);
    return samplingCase;
}

// Test names in ctest show the case's name rather than its bytes.
void PrintTo(const MaterialCase& material, std::ostream* out)
{
    *out << material.name;
}

class BlinnPhongMaterialSampling : public ::testing::TestWithParam<MaterialCase> {};

TEST_P(BlinnPhongMaterialSampling, DirectionsFollowBlinnPhongPdf)
{
    // At grazing views the sharp lobe is under two degrees wide in azimuth: 8192 cells in phi
    // keep the midpoint rule's error far below the counts' noise.
    GridLayout grid;
    grid.thetaCells = 1024;
    grid.phiCells = 8192;
    const SamplingCase samplingCase = materialSamplingCase(GetParam(), grid.frame);
    std::ostringstream what;
    what << "blinnPhongSample (exponent " << GetParam().exponent << ", wo "
         << GetParam().viewDegrees << " degrees from the normal, pigment " << GetParam().pigment
         << ")";
    expectSamplesFollowPdf(samplingCase, grid, what.str());
}

// The weight blinnPhongSample returns is f cos / pdf, so its mean over many samples is the
// directional albedo: the integral of blinnPhongEvaluate * cos over the hemisphere.
TEST_P(BlinnPhongMaterialSampling, SampleWeightsAverageToTheIntegralOfEvaluate)
{
    GridLayout grid;
    grid.thetaCells = 1024;
    grid.phiCells = 1024;
    const SamplingCase samplingCase = materialSamplingCase(GetParam(), grid.frame);
    const ShaderSampler sampler;

    const std::vector<glm::vec3> reflectance = sampler.reflectanceOnGrid(samplingCase, grid);
    const double cellTheta = grid.thetaMax / grid.thetaCells;
    const double cellPhi = 2.0 * kPi / grid.phiCells;
    double integral = 0.0;
    for (int j = 0; j < grid.phiCells; ++j)
        for (int i = 0; i < grid.thetaCells; ++i) {
            const glm::vec3 value = reflectance[j * grid.thetaCells + i];
            integral += (value.x + value.y + value.z) / 3.0 *
                        (std::cos(i * cellTheta) - std::cos((i + 1) * cellTheta)) * cellPhi;
        }

    double sum = 0.0;
    double squares = 0.0;
    double count = 0.0;
    for (int draw = 0; draw < kDraws; ++draw)
        for (const glm::vec4& weight : sampler.sampleWeights(
                 samplingCase, kSampleSide, kSampleSide, 2000 + static_cast<std::uint64_t>(draw),
                 SamplerChoice{true, false, draw, 4})) {
            const double value = (weight.x + weight.y + weight.z) / 3.0;
            sum += value;
            squares += value * value;
            count += 1.0;
        }
    const double mean = sum / count;
    const double standardError = std::sqrt(std::max(0.0, squares / count - mean * mean) / count);
    // Five standard errors of the mean, and 0.2% for the midpoint quadrature of the lobe.
    const double tolerance = 5.0 * standardError + 2e-3 * integral;
    EXPECT_NEAR(mean, integral, tolerance)
        << "the mean sample weight (" << count << " samples) should equal the integral of f cos "
        << "(quadrature on " << grid.thetaCells << " x " << grid.phiCells << " cells)";
}

const MaterialCase kMaterialCases[] = {
    {1.0f, 0.0f, 1.0f, {0, 0, 1}, "n1_normal_view"},
    {1.0f, 45.0f, 1.0f, {0, 0, 1}, "n1_view45"},
    {20.0f, 0.0f, 1.0f, {0, 0, 1}, "n20_normal_view"},
    {20.0f, 45.0f, 1.0f, {0, 0, 1}, "n20_view45"},
    {20.0f, 80.0f, 1.0f, {0, 0, 1}, "n20_view80"},
    {500.0f, 0.0f, 1.0f, {0, 0, 1}, "n500_normal_view"},
    {500.0f, 45.0f, 1.0f, {0, 0, 1}, "n500_view45"},
    {500.0f, 80.0f, 1.0f, {0, 0, 1}, "n500_view80"},
    {20.0f, 60.0f, 0.2f, {1, 2, 3}, "n20_view60_mixed_with_diffuse_tilted_normal"},
};

std::string materialName(const ::testing::TestParamInfo<MaterialCase>& info)
{
    return info.param.name;
}

INSTANTIATE_TEST_SUITE_P(Lobe, BlinnPhongMaterialSampling, ::testing::ValuesIn(kMaterialCases),
                         materialName);

// --- the rough materials of materials.glsl (GGX, visible normals), in world space ----------

struct RoughCase {
    SamplingRoutine routine;
    float alpha;
    float viewDegrees;  // angle between wo and the normal
    bool entering;      // the dielectric: wo outside the medium of index 1.5
    float pigment;      // the conductor's R0 (1: Fresnel 1)
    glm::vec3 normal;
    const char* name;
};

void PrintTo(const RoughCase& rough, std::ostream* out)
{
    *out << rough.name;
}

SamplingCase roughSamplingCase(const RoughCase& rough, glm::mat3& frame)
{
    frame = frameAround(rough.normal);
    const float angle = glm::radians(rough.viewDegrees);
    SamplingCase samplingCase;
    samplingCase.routine = rough.routine;
    samplingCase.roughness = rough.alpha;
    samplingCase.normal = frame[2];
    samplingCase.outgoing = glm::normalize(std::cos(angle) * frame[2] + std::sin(angle) * frame[0]);
    samplingCase.pigment = glm::vec3(rough.pigment);
    samplingCase.ior = 1.5f;
    samplingCase.entering = rough.entering;
    return samplingCase;
}

// The whole sphere for the dielectric (reflection and transmission), the hemisphere above
// the surface for the conductor. A narrow lobe seen at a grazing angle is a few tenths of a
// degree wide in azimuth: the finer grid keeps the midpoint rule's error far below the
// counts' noise. A rough dielectric's transmitted lobe ends in an edge, where the visible
// normals reach the horizon (D there is alpha^2 / pi, not 0), along nearly one theta: the
// midpoint rule misses up to half a ring of cells there, which at alpha = 1 and 2048 cells
// in theta was 1400 of a million samples in one bin, so the rough ones get 8192.
GridLayout roughGrid(const RoughCase& rough)
{
    GridLayout grid;
    const bool dielectric = rough.routine == SamplingRoutine::RoughDielectricMaterial;
    grid.thetaMax = dielectric ? static_cast<float>(kPi) : static_cast<float>(kPi / 2.0);
    grid.thetaCells = dielectric ? (rough.alpha > 0.5f ? 8192 : 2048) : 1024;
    grid.phiCells = rough.alpha < 0.1f ? 8192 : 2048;
    return grid;
}

std::string describeRough(const RoughCase& rough)
{
    std::ostringstream what;
    if (rough.routine == SamplingRoutine::RoughConductorMaterial)
        what << "roughConductorSample (alpha " << rough.alpha << ", pigment " << rough.pigment;
    else
        what << "roughDielectricSample (alpha " << rough.alpha << ", index 1.5, "
             << (rough.entering ? "entering" : "leaving");
    what << ", wo " << rough.viewDegrees << " degrees from the normal)";
    return what.str();
}

class RoughMaterialSampling : public ::testing::TestWithParam<RoughCase> {};

// The density each sample returns is the one the sampler drew from: the histogram of the
// sampled directions follows the pdf that bsdfPdf (and so MIS) uses.
TEST_P(RoughMaterialSampling, DirectionsFollowTheirPdf)
{
    GridLayout grid = roughGrid(GetParam());
    const SamplingCase samplingCase = roughSamplingCase(GetParam(), grid.frame);
    expectSamplesFollowPdf(samplingCase, grid, describeRough(GetParam()));
}

const RoughCase kRoughCases[] = {
    {SamplingRoutine::RoughConductorMaterial,
     0.05f,
     0.0f,
     true,
     1.0f,
     {0, 0, 1},
     "conductor_a005_normal_view"},
    {SamplingRoutine::RoughConductorMaterial,
     0.05f,
     45.0f,
     true,
     1.0f,
     {0, 0, 1},
     "conductor_a005_view45"},
    {SamplingRoutine::RoughConductorMaterial,
     0.05f,
     80.0f,
     true,
     1.0f,
     {0, 0, 1},
     "conductor_a005_view80"},
    {SamplingRoutine::RoughConductorMaterial,
     0.3f,
     0.0f,
     true,
     1.0f,
     {0, 0, 1},
     "conductor_a03_normal_view"},
    {SamplingRoutine::RoughConductorMaterial,
     0.3f,
     45.0f,
     true,
     1.0f,
     {0, 0, 1},
     "conductor_a03_view45"},
    {SamplingRoutine::RoughConductorMaterial,
     0.3f,
     80.0f,
     true,
     1.0f,
     {0, 0, 1},
     "conductor_a03_view80"},
    {SamplingRoutine::RoughConductorMaterial,
     1.0f,
     0.0f,
     true,
     1.0f,
     {0, 0, 1},
     "conductor_a1_normal_view"},
    {SamplingRoutine::RoughConductorMaterial,
     1.0f,
     45.0f,
     true,
     1.0f,
     {0, 0, 1},
     "conductor_a1_view45"},
    {SamplingRoutine::RoughConductorMaterial,
     1.0f,
     80.0f,
     true,
     1.0f,
     {0, 0, 1},
     "conductor_a1_view80"},
    {SamplingRoutine::RoughConductorMaterial,
     0.3f,
     60.0f,
     true,
     0.5f,
     {1, 2, 3},
     "conductor_a03_view60_tinted_tilted_normal"},
    {SamplingRoutine::RoughDielectricMaterial,
     0.05f,
     45.0f,
     true,
     1.0f,
     {0, 0, 1},
     "dielectric_a005_entering_view45"},
    {SamplingRoutine::RoughDielectricMaterial,
     0.05f,
     80.0f,
     true,
     1.0f,
     {0, 0, 1},
     "dielectric_a005_entering_view80"},
    {SamplingRoutine::RoughDielectricMaterial,
     0.05f,
     30.0f,
     false,
     1.0f,
     {0, 0, 1},
     "dielectric_a005_leaving_view30"},
    {SamplingRoutine::RoughDielectricMaterial,
     0.05f,
     60.0f,
     false,
     1.0f,
     {0, 0, 1},
     "dielectric_a005_leaving_view60"},
    {SamplingRoutine::RoughDielectricMaterial,
     0.3f,
     45.0f,
     true,
     1.0f,
     {0, 0, 1},
     "dielectric_a03_entering_view45"},
    {SamplingRoutine::RoughDielectricMaterial,
     0.3f,
     80.0f,
     true,
     1.0f,
     {0, 0, 1},
     "dielectric_a03_entering_view80"},
    {SamplingRoutine::RoughDielectricMaterial,
     0.3f,
     30.0f,
     false,
     1.0f,
     {0, 0, 1},
     "dielectric_a03_leaving_view30"},
    {SamplingRoutine::RoughDielectricMaterial,
     0.3f,
     60.0f,
     false,
     1.0f,
     {0, 0, 1},
     "dielectric_a03_leaving_view60"},
    {SamplingRoutine::RoughDielectricMaterial,
     1.0f,
     0.0f,
     true,
     1.0f,
     {0, 0, 1},
     "dielectric_a1_entering_normal_view"},
    {SamplingRoutine::RoughDielectricMaterial,
     1.0f,
     80.0f,
     true,
     1.0f,
     {0, 0, 1},
     "dielectric_a1_entering_view80"},
    {SamplingRoutine::RoughDielectricMaterial,
     1.0f,
     30.0f,
     false,
     1.0f,
     {1, 2, 3},
     "dielectric_a1_leaving_view30_tilted_normal"},
    {SamplingRoutine::RoughDielectricMaterial,
     1.0f,
     60.0f,
     false,
     1.0f,
     {0, 0, 1},
     "dielectric_a1_leaving_view60"},
};

std::string roughName(const ::testing::TestParamInfo<RoughCase>& info)
{
    return info.param.name;
}

INSTANTIATE_TEST_SUITE_P(Ggx, RoughMaterialSampling, ::testing::ValuesIn(kRoughCases), roughName);

// The weight each sample returns is f |cos| / pdf, so its mean is the integral of
// <prefix>Evaluate |cos| over the sphere: sampling, density and evaluation agree.
class RoughMaterialWeights : public ::testing::TestWithParam<RoughCase> {};

TEST_P(RoughMaterialWeights, SampleWeightsAverageToTheIntegralOfEvaluate)
{
    GridLayout grid = roughGrid(GetParam());
    const SamplingCase samplingCase = roughSamplingCase(GetParam(), grid.frame);
    const ShaderSampler sampler;

    const std::vector<glm::vec3> reflectance = sampler.reflectanceOnGrid(samplingCase, grid);
    const double cellTheta = grid.thetaMax / grid.thetaCells;
    const double cellPhi = 2.0 * kPi / grid.phiCells;
    double integral = 0.0;
    for (int j = 0; j < grid.phiCells; ++j)
        for (int i = 0; i < grid.thetaCells; ++i) {
            const glm::vec3 value = reflectance[j * grid.thetaCells + i];
            integral += (value.x + value.y + value.z) / 3.0 *
                        (std::cos(i * cellTheta) - std::cos((i + 1) * cellTheta)) * cellPhi;
        }

    double sum = 0.0;
    double squares = 0.0;
    double count = 0.0;
    for (int draw = 0; draw < kDraws; ++draw)
        for (const glm::vec4& weight : sampler.sampleWeights(
                 samplingCase, kSampleSide, kSampleSide, 3000 + static_cast<std::uint64_t>(draw),
                 SamplerChoice{true, false, draw, 4})) {
            const double value = (weight.x + weight.y + weight.z) / 3.0;
            sum += value;
            squares += value * value;
            count += 1.0;
        }
    const double mean = sum / count;
    const double standardError = std::sqrt(std::max(0.0, squares / count - mean * mean) / count);
    const double tolerance = 5.0 * standardError + 2e-3 * integral;
    std::cout << describeRough(GetParam()) << ": mean weight " << mean << ", integral of f |cos| "
              << integral << "\n";
    EXPECT_NEAR(mean, integral, tolerance)
        << describeRough(GetParam()) << ": the mean sample weight (" << count
        << " samples) should equal the integral of f |cos| (quadrature on " << grid.thetaCells
        << " x " << grid.phiCells << " cells)";
}

const RoughCase kRoughWeightCases[] = {
    {SamplingRoutine::RoughConductorMaterial,
     0.05f,
     45.0f,
     true,
     1.0f,
     {0, 0, 1},
     "conductor_a005_view45"},
    {SamplingRoutine::RoughConductorMaterial,
     0.3f,
     80.0f,
     true,
     1.0f,
     {0, 0, 1},
     "conductor_a03_view80"},
    {SamplingRoutine::RoughConductorMaterial,
     1.0f,
     0.0f,
     true,
     0.5f,
     {1, 2, 3},
     "conductor_a1_normal_view_tinted"},
    {SamplingRoutine::RoughDielectricMaterial,
     0.05f,
     45.0f,
     true,
     1.0f,
     {0, 0, 1},
     "dielectric_a005_entering_view45"},
    {SamplingRoutine::RoughDielectricMaterial,
     0.3f,
     30.0f,
     false,
     1.0f,
     {0, 0, 1},
     "dielectric_a03_leaving_view30"},
    {SamplingRoutine::RoughDielectricMaterial,
     1.0f,
     60.0f,
     true,
     1.0f,
     {0, 0, 1},
     "dielectric_a1_entering_view60"},
};

INSTANTIATE_TEST_SUITE_P(Ggx, RoughMaterialWeights, ::testing::ValuesIn(kRoughWeightCases),
                         roughName);

// --- the environment map's sampler (environment.glsl), in world space ---------------------

struct EnvironmentCase {
    const char* name;
    io::Image image;
    float rotationDegrees;
    int split;  // grid cells along each side of a texel
};

// The grid's cells split each texel into `split` x `split` (theta from +y, phi from the map's
// left edge, turned with the map). The density is constant over each texel, in solid angle,
// so the pdf at a cell's centre times the cell's solid angle is the cell's probability
// exactly; and cells smaller than a texel catch a sampler that puts the right share in each
// texel but spreads it wrongly inside.
GridLayout environmentGrid(const render::EnvironmentMap& map, float rotationDegrees, int split)
{
    const float angle = glm::radians(rotationDegrees);
    const float c = std::cos(angle);
    const float s = std::sin(angle);
    // The map's frame turned about +y (x' = c x + s z, z' = -s x + c z).
    auto turned = [&](const glm::vec3& m) {
        return glm::vec3(c * m.x + s * m.z, m.y, -s * m.x + c * m.z);
    };
    GridLayout grid;
    grid.thetaCells = map.height * split;
    grid.phiCells = map.width * split;
    grid.thetaMax = static_cast<float>(kPi);
    // Column 0's edge faces +z, a quarter of the way across -x, the top row +y.
    grid.frame = glm::mat3(turned({0, 0, 1}), turned({-1, 0, 0}), glm::vec3(0, 1, 0));
    return grid;
}

class EnvironmentMapSampling : public ::testing::TestWithParam<int> {};

EnvironmentCase environmentCase(int which)
{
    using namespace testing_support;
    switch (which) {
    case 0: {
        SkyWithSun sky;
        sky.sunRadiusDegrees = 8.0;
        sky.sunRadiance = 40.0;
        return {"sky_with_sun_turned_30_degrees", skyWithSunEnvironmentMap(64, 32, sky), 30.0f, 2};
    }
    case 1:
        return {"octants", octantEnvironmentMap(32, 16), 0.0f, 2};
    case 2:
        return {"black_but_a_patch_turned_minus_100_degrees",
                patchEnvironmentMap(48, 24, 40, 3, 5, 4, glm::vec3(5.0f, 1.0f, 0.5f)), -100.0f, 2};
    default: {
        // Texels of 90 degrees: the bins split each many times, down to the poles.
        io::Image image(4, 2, 3);
        const float values[8] = {1.0f, 4.0f, 0.5f, 2.0f, 3.0f, 0.25f, 1.5f, 6.0f};
        for (int texel = 0; texel < 8; ++texel)
            for (int channel = 0; channel < 3; ++channel)
                image.at(texel % 4, texel / 4, channel) = values[texel];
        return {"four_by_two_texels", image, 0.0f, 64};
    }
    }
}

TEST_P(EnvironmentMapSampling, DirectionsFollowEnvironmentMapPdf)
{
    const EnvironmentCase environment = environmentCase(GetParam());
    const render::EnvironmentMap map = render::buildEnvironmentMap(environment.image);
    SamplingCase samplingCase;
    samplingCase.routine = SamplingRoutine::EnvironmentMap;
    samplingCase.environmentMap = &map;
    samplingCase.environmentRotationDegrees = environment.rotationDegrees;
    expectSamplesFollowPdf(samplingCase,
                           environmentGrid(map, environment.rotationDegrees, environment.split),
                           std::string("sampleEnvironmentMap, ") + environment.name);
}

// The density the shader returns integrates to 1 over the sphere, and gives each texel the
// probability the host's distribution does: the pdf is the sampler's, not another.
TEST_P(EnvironmentMapSampling, PdfIntegratesToOneAndMatchesTheHostsDistribution)
{
    const EnvironmentCase environment = environmentCase(GetParam());
    const render::EnvironmentMap map = render::buildEnvironmentMap(environment.image);
    SamplingCase samplingCase;
    samplingCase.routine = SamplingRoutine::EnvironmentMap;
    samplingCase.environmentMap = &map;
    samplingCase.environmentRotationDegrees = environment.rotationDegrees;
    const GridLayout grid = environmentGrid(map, environment.rotationDegrees, 1);
    const std::vector<float> pdf = ShaderSampler().pdfOnGrid(samplingCase, grid);
    double total = 0.0;
    double worst = 0.0;
    for (int row = 0; row < map.height; ++row)
        for (int column = 0; column < map.width; ++column) {
            const double mass = pdf[column * map.height + row] * map.texelSolidAngle(row);
            total += mass;
            worst = std::max(worst, std::abs(mass - map.texelProbability(column, row)));
        }
    EXPECT_NEAR(total, 1.0, 1e-4) << environment.name;
    EXPECT_LT(worst, 1e-6) << environment.name
                           << ": some texel's probability differs from the host's by " << worst;
}

INSTANTIATE_TEST_SUITE_P(Map, EnvironmentMapSampling, ::testing::Values(0, 1, 2, 3),
                         [](const ::testing::TestParamInfo<int>& info) {
                             return std::string(environmentCase(info.param).name);
                         });

}  // namespace
}  // namespace sampling_tests
