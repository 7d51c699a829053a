// The table the rough conductor's energy compensation reads (shaders/modules/
// ggx_albedo_table.glsl, made by tools/make_ggx_albedo_table.py by integrating over the
// sampler's visible normals) against an independent integral of the lobe itself: the
// directional albedo E(mu, alpha) = integral of D(h) G2(wo, wi) / (4 mu) over the hemisphere
// of wi (Fresnel 1), by the midpoint rule in (theta, phi) of wi, in double.
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace sampling_tests {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct AlbedoTable {
    int size = 0;
    std::vector<double> values;  // row j (alpha = j / (size - 1)), column i (mu = (i + 1/2) / size)
};

AlbedoTable readTable()
{
    std::ifstream file(testing_support::sourceDirectory() / "shaders" / "modules" /
                       "ggx_albedo_table.glsl");
    std::stringstream text;
    text << file.rdbuf();
    const std::string glsl = text.str();
    AlbedoTable table;
    std::smatch size;
    if (std::regex_search(glsl, size, std::regex("kGgxAlbedoSize = (\\d+);")))
        table.size = std::stoi(size[1]);
    const std::size_t start = glsl.find("float[", glsl.find("kGgxAlbedo["));
    const std::string body = glsl.substr(glsl.find('(', start) + 1);
    const std::regex number("\\d+\\.\\d+");
    for (auto it = std::sregex_iterator(body.begin(), body.end(), number);
         it != std::sregex_iterator(); ++it)
        table.values.push_back(std::stod(it->str()));
    return table;
}

double lambda(double cosTheta, double alpha)
{
    const double x = alpha * alpha * (1.0 - cosTheta * cosTheta) / (cosTheta * cosTheta);
    return x / (2.0 * (1.0 + std::sqrt(1.0 + x)));
}

double directionalAlbedo(double mu, double alpha)
{
    const int thetaCells = 2048;
    const int phiCells = 1024;  // over [0, pi]: the lobe is symmetric about wo's plane
    const double dTheta = 0.5 * kPi / thetaCells;
    const double dPhi = kPi / phiCells;
    const double sinO = std::sqrt(1.0 - mu * mu);
    const double lambdaO = lambda(mu, alpha);
    const double alpha2 = alpha * alpha;
    double sum = 0.0;
    for (int a = 0; a < thetaCells; ++a) {
        const double theta = (a + 0.5) * dTheta;
        const double cosI = std::cos(theta);
        const double sinI = std::sin(theta);
        const double solidAngle = (std::cos(a * dTheta) - std::cos((a + 1) * dTheta)) * dPhi;
        const double shadowing = 1.0 / (1.0 + lambdaO + lambda(cosI, alpha));
        for (int b = 0; b < phiCells; ++b) {
            const double phi = (b + 0.5) * dPhi;
            double hx = sinI * std::cos(phi) + sinO;
            double hy = sinI * std::sin(phi);
            double hz = cosI + mu;
            const double length = std::sqrt(hx * hx + hy * hy + hz * hz);
            hx /= length;
            hy /= length;
            hz /= length;
            const double t = hx * hx + hy * hy + alpha2 * hz * hz;
            const double distribution = alpha2 / (kPi * t * t);
            sum += distribution * shadowing / (4.0 * mu) * solidAngle;
        }
    }
    return 2.0 * sum;
}

TEST(GgxAlbedoTable, HoldsTheAlbedoOfTheLobeWithAFresnelOfOne)
{
    const AlbedoTable table = readTable();
    ASSERT_GT(table.size, 2);
    ASSERT_EQ(table.values.size(), static_cast<std::size_t>(table.size * table.size));
    // Where a uniform grid of directions resolves the lobe (alpha >= 1/4).
    for (const int j : {table.size / 4, table.size / 2, table.size - 1})
        for (const int i : {0, table.size / 5, table.size / 2, table.size - 1}) {
            const double alpha = static_cast<double>(j) / (table.size - 1);
            const double mu = (i + 0.5) / table.size;
            const double expected = directionalAlbedo(mu, alpha);
            EXPECT_NEAR(table.values[j * table.size + i], expected, 2e-3)
                << "E(mu = " << mu << ", alpha = " << alpha << ")";
        }
    // A smooth surface reflects all: the row of alpha = 0 is 1.
    for (int i = 0; i < table.size; ++i)
        EXPECT_EQ(table.values[i], 1.0) << "E(mu, alpha = 0) at column " << i;
}

}  // namespace
}  // namespace sampling_tests
