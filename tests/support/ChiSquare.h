#pragma once
// Pearson's chi-square test of a histogram against expected counts, as Mitsuba tests its
// samplers: bins whose expected count is below 5 are pooled into one, so that the
// statistic's chi-square distribution holds.
#include <string>
#include <vector>

namespace testing_support {

// Regularised upper incomplete gamma function Q(a, x) = Gamma(a, x) / Gamma(a).
double upperIncompleteGammaRatio(double a, double x);

// P(X >= statistic) for X chi-square distributed with `degreesOfFreedom`.
double chiSquareSurvival(double statistic, int degreesOfFreedom);

// The value a chi-square variable with `degreesOfFreedom` exceeds with `probability`.
double chiSquareQuantileAbove(int degreesOfFreedom, double probability);

struct ChiSquareResult {
    double statistic = 0.0;
    int degreesOfFreedom = 0;
    double pValue = 1.0;
    double threshold = 0.0;  // the statistic's critical value at the test's significance
    bool passed = false;
    std::string describe() const;
};

// observed[i] counts against expected[i] (which must sum to the same total, up to the
// accuracy of their integration), rejecting at `significance`.
ChiSquareResult chiSquareTest(const std::vector<double>& observed,
                              const std::vector<double>& expected, double significance);

}  // namespace testing_support
