// SPDX-License-Identifier: GPL-3.0-or-later
// Where the construction of the variable-k weight's rule goes (docs/formulation.md 8(z), "The cost"; not a test, no
// timing is asserted anywhere). Five zones as free rolling has them (ends -0.7, 0.3, 0.5, 0.5055: the second stick zone
// 0.0055 long), k = -k0, blend, +k0, blend, -k0 (8(x)'s continuous k, k0 = 0.0288) and the piecewise constant
// k = -k0, 0, k0, 0, -k0; both discretisations (economical, dense) in one run, medians of 5 repetitions. Build:
//   g++ -O2 -std=c++17 -Iinclude bench/variable_k_weight_cost.cpp build-s8/libroughroll_core.a $(pkg-config --libs tomlplusplus) -lgsl -lgslcblas
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "roughroll/numerics/variable_k_weight.hpp"

#include "../tests/variable_k_fixture.hpp"  // the five zones and 8(x)'s blended k, as the tests have them

using namespace roughroll;
using variable_k_fixture::blended;
using clock_type = std::chrono::steady_clock;

namespace {
double seconds(clock_type::time_point a, clock_type::time_point b) { return std::chrono::duration<double>(b - a).count(); }
double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}
}  // namespace

int main() {
    const std::vector<double>& ends = variable_k_fixture::free_rolling_ends;
    const double k0 = variable_k_fixture::free_rolling_k0;
    const std::vector<double> k = variable_k_fixture::piecewise_k(k0);
    std::printf("case      n  route       points(w,d)   weight  recurrence(w) recurrence(d) Golub-Welsch(w+d) collocation+LU "
                "  total   [s, medians of 5]\n");
    for (const bool blend : {true, false}) {
        for (const int n : {32, 64, 128, 256}) {
            double total_dense = 0.0;
            for (const discretisation how : {discretisation::dense, discretisation::economical}) {
                std::vector<double> tw, trw, trd, tg, tc, tt;
                std::size_t pw = 0, pd = 0;
                for (int rep = 0; rep < 5; ++rep) {
                    const auto t0 = clock_type::now();
                    const variable_k_weight w = blend ? variable_k_weight(ends, k, blended(ends, k0)) : variable_k_weight(ends, k);
                    const auto t1 = clock_type::now();
                    const orthogonal_recurrence r = recurrence_of(w.weight(), n, how);
                    const auto t2 = clock_type::now();
                    const orthogonal_recurrence d = recurrence_of(w.dual(), n + 1, how);
                    const auto t3 = clock_type::now();
                    const gauss_rule g = gauss_rule_of(r, n), gd = gauss_rule_of(d, n + 1);
                    const auto t4 = clock_type::now();
                    variable_k_collocation c(w, n, how);  // both recurrences and rules again, the defect check
                    c.solve(std::vector<double>(n + 1, 1.0));  // assembly and LU
                    const auto t5 = clock_type::now();
                    tw.push_back(seconds(t0, t1));
                    trw.push_back(seconds(t1, t2));
                    trd.push_back(seconds(t2, t3));
                    tg.push_back(seconds(t3, t4));
                    tc.push_back(seconds(t4, t5));
                    tt.push_back(seconds(t0, t1) + seconds(t4, t5));
                    pw = discretisation_size(w.weight(), n, how);
                    pd = discretisation_size(w.dual(), n + 1, how);
                    if (g.nodes.size() + gd.nodes.size() != static_cast<std::size_t>(2 * n + 1)) return 1;
                }
                const double total = median(tt);
                if (how == discretisation::dense) total_dense = total;
                std::printf("%-9s %3d  %-10s %6zu,%6zu  %7.4f  %7.4f       %7.4f       %8.5f          %7.4f       %7.4f",
                            blend ? "blended" : "piecewise", n, how == discretisation::dense ? "dense" : "economical", pw,
                            pd, median(tw), median(trw), median(trd), median(tg), median(tc), total);
                if (how == discretisation::economical) std::printf("   dense/economical %.1f", total_dense / total);
                std::printf("\n");
            }
        }
    }
}
