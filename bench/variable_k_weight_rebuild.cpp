// SPDX-License-Identifier: GPL-3.0-or-later
// The rebuild of the variable-k weight's collocation as a Newton step of the five zones would call it (docs/formulation.md
// 8(z), "The cost"; not a test, no timing is asserted anywhere): the weight, its rule and points (economical
// discretisation), the LU and one solve, for the five zones of free rolling (ends -0.7, 0.3, 0.5, 0.5055, the second
// stick zone 0.0055 long) with 8(x)'s blended k (k0 = 0.0288) and with the piecewise constant k, n = 32 .. 256, medians
// of 5 in CPU time (`bench n` repeats one n 200 times, for perf). Each rebuild moves the ends by 1e-9 (a late Newton step: nothing is
// reused). Prints xi and the load of g = cos 3x so that two builds (old, new) can be compared in one run. Build (from the repository root, after the library):
//   g++ -O3 -DNDEBUG -std=c++17 -Iinclude bench/variable_k_weight_rebuild.cpp build-s8/libroughroll_core.a $(pkg-config --libs tomlplusplus) -lgsl -lgslcblas
#include <algorithm>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <vector>

#include "roughroll/numerics/variable_k_weight.hpp"

#include "../tests/variable_k_fixture.hpp"  // the five zones and 8(x)'s blended k, as the tests have them

using namespace roughroll;
using variable_k_fixture::blended;

namespace {
// The process's CPU time: the machine is shared, wall time measures the neighbours too.
double cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}
}  // namespace

int main(int argc, char** argv) {
    const int only = argc > 1 ? std::atoi(argv[1]) : 0;
    const double k0 = variable_k_fixture::free_rolling_k0;
    const std::vector<double> k = variable_k_fixture::piecewise_k(k0);
    std::printf("case       n   rebuild [CPU s, median of 5]   xi, load of g = cos 3x\n");
    for (const bool blend : {true, false}) {
        for (const int n : {32, 64, 128, 256}) {
            if (only && (n != only || !blend)) continue;
            std::vector<double> times;
            double xi = 0.0, load = 0.0;
            for (int rep = 0; rep < (only ? 200 : 5); ++rep) {
                const double shift = 1e-9 * rep;
                std::vector<double> ends = variable_k_fixture::free_rolling_ends;
                for (std::size_t i = 1; i + 1 < ends.size(); ++i) ends[i] += shift;
                const double t0 = cpu_seconds();
                const variable_k_weight w = blend ? variable_k_weight(ends, k, blended(ends, k0)) : variable_k_weight(ends, k);
                variable_k_collocation c(w, n);
                std::vector<double> g(n + 1);
                for (int m = 0; m <= n; ++m) g[m] = std::cos(3.0 * c.points()[m]);
                const variable_k_collocation::solution s = c.solve(g);
                times.push_back(cpu_seconds() - t0);
                if (rep == 0) {
                    xi = s.xi;
                    load = c.load(s.psi);
                }
            }
            std::sort(times.begin(), times.end());
            std::printf("%-9s %4d   %.5f                  %.16f %.16f\n", blend ? "blended" : "piecewise", n,
                        times[times.size() / 2], xi, load);
        }
    }
}
