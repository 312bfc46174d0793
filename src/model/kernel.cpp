// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/model/kernel.hpp"

#include <algorithm>
#include <cmath>
#include <gsl/gsl_math.h>

#include "roughroll/base/error.hpp"

namespace roughroll {

kernel::kernel(std::vector<exponential_term> terms) {
    for (const auto& t : terms)
        if (t.T != 0.0) terms_.push_back(t);
}

namespace {
std::vector<exponential_term> terms_of(const roughness_term& a, const roughness_term& b) {
    return {{a.T, a.A}, {b.T, b.A}};
}
}  // namespace

kernel kernel::tangential(const roughness& r) {  // K1*, (3.23)
    return kernel(terms_of(r.cylinder1.tangential, r.cylinder2.tangential));
}

kernel kernel::normal(const roughness& r) {  // K2*, (3.24)
    return kernel(terms_of(r.cylinder1.normal, r.cylinder2.normal));
}

double kernel::strength() const {
    double sum = 0.0;
    for (const exponential_term& t : terms_) sum += std::fabs(t.T);
    return sum;
}

double kernel::max_rate() const {
    double a = 0.0;
    for (const auto& t : terms_) a = std::max(a, t.A);
    return a;
}

double kernel::operator()(double z) const {
    double sum = 0.0;
    const double az = std::fabs(z);
    for (const auto& t : terms_) sum += t.T * std::exp(-t.A * az);
    return z > 0 ? sum : -sum;
}

kernel kernel::minus(const kernel& other) const {
    std::vector<exponential_term> mine = terms_;
    std::vector<exponential_term> result;
    for (const auto& o : other.terms_) {
        auto same =
            std::find_if(mine.begin(), mine.end(), [&](const exponential_term& t) { return t.T == o.T && t.A == o.A; });
        if (same != mine.end())
            mine.erase(same);
        else
            result.push_back({-o.T, o.A});
    }
    result.insert(result.end(), mine.begin(), mine.end());
    return kernel(result);
}

kernel kernel::stretched(double rho) const {
    std::vector<exponential_term> s;
    for (const auto& t : terms_) s.push_back({rho * t.T, rho * t.A});
    return kernel(s);
}

}  // namespace roughroll
