// SPDX-License-Identifier: GPL-3.0-or-later
// The rebuild of the variable-k weight's collocation as a Newton step of the five zones would call it (docs/formulation.md
// 8(z), "The cost"; not a test, no timing is asserted anywhere): the weight, its rule and points (economical
// discretisation), the LU and one solve, for the five zones of free rolling (ends -0.7, 0.3, 0.5, 0.5055, the second
// stick zone 0.0055 long) with 8(x)'s blended k (k0 = 0.0288) and with the piecewise constant k, n = 32 .. 256, medians
// of 5 in CPU time (`bench n` repeats one n 200 times, for perf). Each rebuild moves the ends by 1e-9 (a late Newton step: nothing is
// reused). Prints xi and the load of g = cos 3x so that two builds (old, new) can be compared in one run. Build (from the repository root, after the library):
//   g++ -O3 -DNDEBUG -std=c++17 -Iinclude bench/variable_k_weight_rebuild.cpp build-s8/libroughroll_core.a -lgsl -lgslcblas
#include <algorithm>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <vector>

#include "roughroll/numerics/blend_plateau.hpp"
#include "roughroll/numerics/variable_k_weight.hpp"

using namespace roughroll;

namespace {
// The process's CPU time: the machine is shared, wall time measures the neighbours too.
double cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}
std::vector<std::function<double(double)>> blended(const std::vector<double>& e, double k0) {
    auto t_of = [](double x, double l, double r) { return std::clamp((2.0 * x - l - r) / (r - l), -1.0, 1.0); };
    return {{},
            [=](double x) { return k0 * (2.0 * blend_plateau::theta3(t_of(x, e[1], e[2])) - 1.0); },
            {},
            [=](double x) { return k0 * (1.0 - 2.0 * blend_plateau::theta3(t_of(x, e[3], e[4]))); },
            {}};
}
}  // namespace

int main(int argc, char** argv) {
    const int only = argc > 1 ? std::atoi(argv[1]) : 0;
    const double k0 = 0.0288;
    const std::vector<double> k{-k0, 0.0, k0, 0.0, -k0};
    std::printf("case       n   rebuild [CPU s, median of 5]   xi, load of g = cos 3x\n");
    for (const bool blend : {true, false}) {
        for (const int n : {32, 64, 128, 256}) {
            if (only && (n != only || !blend)) continue;
            std::vector<double> times;
            double xi = 0.0, load = 0.0;
            for (int rep = 0; rep < (only ? 200 : 5); ++rep) {
                const double shift = 1e-9 * rep;
                const std::vector<double> ends{-1.0, -0.7 + shift, 0.3 + shift, 0.5 + shift, 0.5055 + shift, 1.0};
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
