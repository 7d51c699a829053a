#include "support/ChiSquare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <stdexcept>

namespace testing_support {

namespace {

constexpr double kMinimumPooledExpectation = 5.0;

// P(a, x) by its power series, for x < a + 1 (Abramowitz and Stegun 6.5.29).
double lowerRatioBySeries(double a, double x)
{
    double term = 1.0 / a;
    double sum = term;
    for (int n = 1; n < 10000; ++n) {
        term *= x / (a + n);
        sum += term;
        if (std::abs(term) < std::abs(sum) * 1e-16)
            break;
    }
    return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

// Q(a, x) by its continued fraction, for x >= a + 1 (A&S 6.5.31), evaluated with the
// modified Lentz method.
double upperRatioByContinuedFraction(double a, double x)
{
    constexpr double tiny = 1e-300;
    double b = x + 1.0 - a;
    double c = 1.0 / tiny;
    double d = 1.0 / b;
    double h = d;
    for (int i = 1; i < 10000; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < tiny)
            d = tiny;
        c = b + an / c;
        if (std::abs(c) < tiny)
            c = tiny;
        d = 1.0 / d;
        const double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1.0) < 1e-16)
            break;
    }
    return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

}  // namespace

double upperIncompleteGammaRatio(double a, double x)
{
    if (x <= 0.0)
        return 1.0;
    if (x < a + 1.0)
        return 1.0 - lowerRatioBySeries(a, x);
    return upperRatioByContinuedFraction(a, x);
}

double chiSquareSurvival(double statistic, int degreesOfFreedom)
{
    return upperIncompleteGammaRatio(0.5 * degreesOfFreedom, 0.5 * statistic);
}

double chiSquareQuantileAbove(int degreesOfFreedom, double probability)
{
    // The survival function falls monotonically: bisect.
    double low = 0.0;
    double high = degreesOfFreedom + 10.0;
    while (chiSquareSurvival(high, degreesOfFreedom) > probability)
        high *= 2.0;
    for (int i = 0; i < 200; ++i) {
        const double middle = 0.5 * (low + high);
        if (chiSquareSurvival(middle, degreesOfFreedom) > probability)
            low = middle;
        else
            high = middle;
    }
    return 0.5 * (low + high);
}

std::string ChiSquareResult::describe() const
{
    char text[256];
    std::snprintf(text, sizeof text,
                  "chi-square = %.2f with %d degrees of freedom (p = %.3g); threshold %.2f",
                  statistic, degreesOfFreedom, pValue, threshold);
    return text;
}

ChiSquareResult chiSquareTest(const std::vector<double>& observed,
                              const std::vector<double>& expected, double significance)
{
    if (observed.size() != expected.size())
        throw std::invalid_argument("chi-square test: histograms of different sizes");

    std::vector<std::size_t> order(observed.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return expected[a] < expected[b]; });

    // Bins expected to hold fewer than 5 samples are pooled; if the pool itself stays
    // below 5, it joins the least populated regular bin, so that no term of the statistic
    // divides by a vanishing expectation (a single sample where the pdf allows one in 10^9
    // is no evidence against it).
    std::vector<double> binObserved;
    std::vector<double> binExpected;
    double pooledObserved = 0.0;
    double pooledExpected = 0.0;
    for (std::size_t i : order) {
        if (expected[i] < kMinimumPooledExpectation) {
            pooledObserved += observed[i];
            pooledExpected += expected[i];
        } else {
            binObserved.push_back(observed[i]);
            binExpected.push_back(expected[i]);
        }
    }
    if (pooledExpected >= kMinimumPooledExpectation || binExpected.empty()) {
        binObserved.push_back(pooledObserved);
        binExpected.push_back(pooledExpected);
    } else if (pooledObserved > 0.0 || pooledExpected > 0.0) {
        // `order` is ascending, so the first regular bin is the least populated.
        binObserved.front() += pooledObserved;
        binExpected.front() += pooledExpected;
    }

    ChiSquareResult result;
    for (std::size_t i = 0; i < binObserved.size(); ++i) {
        const double difference = binObserved[i] - binExpected[i];
        result.statistic += difference * difference / std::max(binExpected[i], 1e-3);
    }
    const int bins = static_cast<int>(binObserved.size());
    result.degreesOfFreedom = std::max(bins - 1, 1);
    result.pValue = chiSquareSurvival(result.statistic, result.degreesOfFreedom);
    result.threshold = chiSquareQuantileAbove(result.degreesOfFreedom, significance);
    result.passed = result.pValue >= significance;
    return result;
}

}  // namespace testing_support
