// SPDX-License-Identifier: GPL-3.0-or-later
// Timings of the solvers on Fig. 2's moderate scene (T = A = 0.5, equal kernels) and on
// an unequal-kernel scene. Run: build/bench/bench_roughroll --benchmark_repetitions=5
//   --benchmark_report_aggregates_only=true   (medians are what docs/performance.md quotes)
//   or --benchmark_out=bench.json --benchmark_out_format=json
// docs/performance.md quotes the creep points as ratios to bm_lu (one LU factorisation and
// solve of the same order) read off one run, minimum and median of the repetitions.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <benchmark/benchmark.h>
#include <gsl/gsl_linalg.h>

#include "roughroll/problems/contact_width.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/contact_internals.hpp"
#include "roughroll/io/micro_geometry_input.hpp"
#include "roughroll/model/physical_scene.hpp"
#include "roughroll/layer/roughness_parameters.hpp"
#include "roughroll/io/profile_csv.hpp"
#include "roughroll/io/scene.hpp"
#include "roughroll/io/scene_point.hpp"
#include "roughroll/problems/creep_curve.hpp"
#include "roughroll/problems/dissimilar_zones.hpp"
#include "roughroll/problems/load_ratio.hpp"
#include "../validation/zone_scenes.hpp"

using namespace roughroll;

namespace {
roughness fig2() {
    roughness r;
    r.cylinder1.tangential = r.cylinder1.normal = {0.5, 0.5};
    return r;
}

roughness unequal() {
    roughness r;
    r.cylinder1.tangential = {0.8, 1.5};
    r.cylinder1.normal = {0.5, 0.5};
    r.cylinder2.tangential = {0.3, 3.0};
    return r;
}

// Equal kernels with unequal()'s tangential kernel K1* (two terms) as the normal one too: K2* = K1*,
// so G has no kernel part. Against it, a swept point of unequal() shows what unequal kernels cost
// by themselves; against fig2() (one term), what a second exponential term costs.
roughness equal_two_terms() {
    roughness r;
    r.cylinder1.tangential = r.cylinder1.normal = {0.8, 1.5};
    r.cylinder2.tangential = r.cylinder2.normal = {0.3, 3.0};
    return r;
}

roughness scene_of(int64_t code) { return code == 0 ? fig2() : code == 1 ? unequal() : equal_two_terms(); }

method method_of(int64_t code) {
    return code == 0 ? method::paper : code == 1 ? method::product : method::extrapolated;
}

// The unit of the creep-point goals (issue 10): one GSL LU factorisation and solve of order
// n + 1 (arg n), the matrix copied in first as the solvers do. A point's cost in
// "LU-equivalents" is its time over this one's, read off the same run.
void bm_lu(benchmark::State& state) {
    const std::size_t size = static_cast<std::size_t>(state.range(0)) + 1;
    gsl_matrix* a = gsl_matrix_alloc(size, size);
    gsl_matrix* lu = gsl_matrix_alloc(size, size);
    gsl_vector* b = gsl_vector_alloc(size);
    gsl_vector* x = gsl_vector_alloc(size);
    gsl_permutation* p = gsl_permutation_alloc(size);
    for (std::size_t i = 0; i < size; ++i) {  // a Cauchy-like matrix, as in (4.4)
        gsl_vector_set(b, i, 1.0);
        for (std::size_t j = 0; j < size; ++j)
            gsl_matrix_set(a, i, j, i == j ? 2.0 : 1.0 / (static_cast<double>(i) - j + 0.5));
    }
    for (auto _ : state) {
        int signum = 0;
        gsl_matrix_memcpy(lu, a);
        gsl_linalg_LU_decomp(lu, p, &signum);
        gsl_linalg_LU_solve(lu, p, b, x);
        benchmark::DoNotOptimize(gsl_vector_get(x, 0));
    }
    gsl_permutation_free(p);
    gsl_vector_free(x);
    gsl_vector_free(b);
    gsl_matrix_free(lu);
    gsl_matrix_free(a);
}

// The normal problem alone (4.2)-(4.3).
void bm_normal(benchmark::State& state) {
    const solver_options o{static_cast<int>(state.range(1)), method_of(state.range(0))};
    const kernel k2 = kernel::normal(fig2());
    for (auto _ : state) benchmark::DoNotOptimize(solve_normal(k2, o.n, o.how).lambda);
}

// One creep point at a given Q: normal solve, Brent search for c0, checks.
void bm_point(benchmark::State& state) {
    const solver_options o{static_cast<int>(state.range(1)), method_of(state.range(0))};
    for (auto _ : state) {
        contact c(fig2(), 0.3, o);
        benchmark::DoNotOptimize(c.point(0.15).xi);
    }
}

// The same point with its error estimate (the levels n/4 and n/2 solved at the same Q), as
// `roughroll point` reports it.
void bm_point_estimated(benchmark::State& state) {
    const solver_options o{static_cast<int>(state.range(1)), method_of(state.range(0))};
    for (auto _ : state) {
        contact c(fig2(), 0.3, o);
        const tangential_solution s = c.point(0.15);
        benchmark::DoNotOptimize(c.estimate(s)->xi);
    }
}

// One point along a curve: the normal solution shared, a root search per point (args:
// method 0 paper, 1 product, 2 extrapolated; n; 0 Fig. 2 scene, 1 unequal kernels).
void bm_curve_point(benchmark::State& state) {
    const solver_options o{static_cast<int>(state.range(1)), method_of(state.range(0))};
    contact c(state.range(2) ? unequal() : fig2(), 0.3, o);
    const auto loads = curve_loads(100, 0.3);
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(c.point(loads[1 + i % 98]).xi);
        ++i;
    }
}

// The i-th c0 of the swept benchmarks' curve: 99 points from 0.98 to -0.98, over again.
double swept_c0(std::size_t i) { return 0.98 - 1.96 * static_cast<double>(i % 99) / 98; }

// One point of a curve swept in c0 (no root search), with its checks and estimate (scene 0
// Fig. 2, 1 unequal kernels, 2 equal kernels with unequal kernels' K1*).
void bm_swept_point(benchmark::State& state) {
    const solver_options o{static_cast<int>(state.range(1)), method_of(state.range(0))};
    contact c(scene_of(state.range(2)), 0.3, o);
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(c.at_stick_end(swept_c0(i)).solution.xi);
        ++i;
    }
}

// The same point once the contact has swept the curve before (untimed): what a point costs
// without the contact's one-time work inside a first sweep (docs/performance.md; for the
// unequal-kernel scene, the second chance of its estimate at c0 = -0.9 builds a contact at 2n).
void bm_swept_point_warm(benchmark::State& state) {
    const solver_options o{static_cast<int>(state.range(1)), method_of(state.range(0))};
    contact c(scene_of(state.range(2)), 0.3, o);
    for (std::size_t i = 0; i < 99; ++i) benchmark::DoNotOptimize(c.at_stick_end(swept_c0(i)).solution.xi);
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(c.at_stick_end(swept_c0(i)).solution.xi);
        ++i;
    }
}

// A contact's one-time work with its first point: the contact (normal problems and workspaces of
// every level), then the swept point at c0 = -0.9, where the unequal-kernel scene's estimate takes
// its second chance at 2n (args: method, n, scene).
void bm_contact_first_point(benchmark::State& state) {
    const solver_options o{static_cast<int>(state.range(1)), method_of(state.range(0))};
    for (auto _ : state) {
        contact c(scene_of(state.range(2)), 0.3, o);
        benchmark::DoNotOptimize(c.at_stick_end(-0.9).solution.xi);
    }
}

// The one-parameter limit (method::one_parameter), 2T/A^2 = 0.2 normal and tangential (arg 1:
// 0 equal, 1 tangential 0.1): a point at a given Q (normal solve, Brent, checks), and one point
// of a curve swept in c0 with the normal solution shared (args: n; scene).
roughness limit_scene(int64_t unequal_kernels) {
    roughness r;
    r.cylinder1.normal = {0.1 * 100.0, 10.0};
    r.cylinder1.tangential = {(unequal_kernels ? 0.05 : 0.1) * 100.0, 10.0};
    return r;
}

void bm_limit_point(benchmark::State& state) {
    const solver_options o{static_cast<int>(state.range(0)), method::one_parameter};
    for (auto _ : state) {
        contact c(limit_scene(state.range(1)), 0.3, o);
        benchmark::DoNotOptimize(c.point(0.15).xi);
    }
}

void bm_limit_swept_point(benchmark::State& state) {
    const solver_options o{static_cast<int>(state.range(0)), method::one_parameter};
    contact c(limit_scene(state.range(1)), 0.3, o);
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(c.at_stick_end(swept_c0(i)).solution.xi);
        ++i;
    }
}

// data/steel-rollers.toml's rollers (k, t given), the method from arg 0 (1 product,
// 2 extrapolated, 3 one-parameter; n its default).
scene steel_rollers(const benchmark::State& state) {
    scene s = parse_scene(
        "E = 210e9\nnu = 0.3\nR1 = 0.02\nR2 = 0.02\nP2 = 1e5\nP1 = 1.5e4\nfriction = 0.3\n"
        "[cylinder1.tangential]\nk = 4e14\nt = 1.5e6\n"
        "[cylinder1.normal]\nk = 8e14\nt = 1.5e6\n",
        "bench");
    s.solver = solver_options{0, state.range(0) == 3 ? method::one_parameter : method_of(state.range(0))};
    return s;
}

// A physical scene, data/steel-rollers.toml's rollers (k, t given): the half-width for the
// given load (Brent in a on the normal problem alone at n/2, polished at n), then the point at a given Q (arg: method
// 1 product, 2 extrapolated, 3 one-parameter; n its default).
void bm_physical_point(benchmark::State& state) {
    const scene s = steel_rollers(state);
    const solver_options& o = s.solver;
    for (auto _ : state) {
        // As solve_point does (io/scene_point.cpp): the trial widths and the contact at the width
        // found share their product-integration workspaces.
        normal_cache cache;
        const contact_width w = find_width(
            *s.physical, [&o, &cache](const roughness& r) { return load_ratio(r, o, &cache); },
            [&o, &cache](const roughness& r) { return coarse_load_ratio(r, o, &cache); });
        contact c(roughness_at(*s.physical, w.a), s.friction, o, {}, &cache);
        benchmark::DoNotOptimize(c.point(*s.Q).xi);
    }
}

// The same rollers' point at the width found (the search done once, outside the loop): the
// fixed-width point of the same scene, so that bm_physical_point over this is the cost of the
// width search alone, the unequal kernels of the rollers in both.
void bm_physical_point_fixed(benchmark::State& state) {
    const scene s = steel_rollers(state);
    const solver_options& o = s.solver;
    const contact_width w = find_width(
        *s.physical, [&o](const roughness& r) { return load_ratio(r, o); },
        [&o](const roughness& r) { return coarse_load_ratio(r, o); });
    const roughness at = roughness_at(*s.physical, w.a);
    for (auto _ : state) {
        contact c(at, s.friction, o);
        benchmark::DoNotOptimize(c.point(*s.Q).xi);
    }
}

// The roughness parameters (2.6)-(2.14) of a layer (arg: 0 flat profile, linear decay;
// 1 sine profile, cosine decay; 2 the measured profile of data/profiles/ground.csv).
void bm_roughness_parameters(benchmark::State& state) {
    const char* specs[] = {
        "lambda0 = 1.15e11\nmu0 = 7.7e10\nH = 1e-5\nl = 2e-4\nprofile = \"flat\"\ndecay = \"linear\"\n",
        "lambda0 = 1.15e11\nmu0 = 7.7e10\nH = 1e-5\nl = 2e-4\nprofile = \"sine\"\ndelta = 4e-6\n"
        "decay = \"cosine\"\n",
        "lambda0 = 1.15e11\nmu0 = 7.7e10\nH = 1e-5\nl = 2e-4\nprofile = \"measured\"\n"
        "profile_csv = \"" ROUGHROLL_SOURCE_DIR "/data/profiles/ground.csv\"\ndecay = \"cosine\"\n"};
    const micro_geometry g = parse_roughness_spec(specs[state.range(0)], "bench", ".");
    for (auto _ : state) benchmark::DoNotOptimize(compute_roughness_parameters(g).k_normal);
}

// The whole Fig. 2 as `roughroll figure` computes it (without writing files): six curves
// of 100 points swept in c0, normal problems included.
void bm_figure(benchmark::State& state) {
    const solver_options o{static_cast<int>(state.range(1)), method_of(state.range(0))};
    for (auto _ : state) {
        for (auto [T, A] : {std::pair{0.0, 0.5}, {0.5, 0.5}, {1.0, 0.5}, {0.5, 0.0}, {0.5, 0.5}, {0.5, 1.0}}) {
            roughness r;
            r.cylinder1.tangential = r.cylinder1.normal = {T, A};
            contact c(r, 0.3, o);
            benchmark::DoNotOptimize(swept_curve(c, 100).size());
        }
    }
}

// ---- Measured profiles of real size (issue 11, section 3; docs/performance.md, "Roughness
// parameters of measured profiles"). A seeded random smooth profile: 40 harmonics of one
// period l = 200 um, amplitude 0.5 um/k, phases from std::mt19937_64(11), lifted to a minimum
// of 0.1 um; N samples written as CSV text in memory.
std::string measured_profile_csv(int64_t samples) {
    const double l = 2e-4;
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> phase(0.0, 2.0 * M_PI);
    std::vector<double> phases(40);
    for (double& p : phases) p = phase(random);
    std::vector<double> h(static_cast<std::size_t>(samples));
    for (int64_t j = 0; j < samples; ++j) {
        for (int k = 1; k <= 40; ++k) h[j] += 0.5e-6 / k * std::sin(2.0 * M_PI * k * j / samples + phases[k - 1]);
    }
    const double lift = 1e-7 - *std::min_element(h.begin(), h.end());
    std::string text = "x1,h0\n";
    char line[64];
    for (int64_t j = 0; j < samples; ++j) {
        std::snprintf(line, sizeof line, "%.12e,%.12e\n", l * j / samples, h[j] + lift);
        text += line;
    }
    return text;
}

micro_geometry measured_layer(const std::string& csv) {
    micro_geometry g;
    g.material = {1.15e11, 7.7e10, 1e-5, 2e-4};
    g.bottom.kind = profile_kind::measured;
    g.bottom.measured = parse_profile_csv(csv, "bench.csv", g.material.l);
    g.decay = decay_kind::cosine;
    return g;
}

// `roughroll roughness` on a measured profile of N samples, from the CSV text: parsing,
// the conditions (samples and spline), the averages (arg 2: 0 the piecewise rule, the default;
// 1 the nested adaptive one), (2.11)-(2.15).
void bm_measured_roughness(benchmark::State& state) {
    const std::string csv = measured_profile_csv(state.range(0));
    const averages_rule rule = state.range(1) == 0 ? averages_rule::piecewise : averages_rule::adaptive;
    for (auto _ : state) {
        const micro_geometry g = measured_layer(csv);
        check_conditions(g);
        benchmark::DoNotOptimize(compute_roughness_parameters(g, rule).k_normal);
    }
    state.counters["samples"] = static_cast<double>(state.range(0));
}

// Parsing the profile CSV alone (profile_csv.hpp).
void bm_profile_csv(benchmark::State& state) {
    const std::string csv = measured_profile_csv(state.range(0));
    for (auto _ : state) benchmark::DoNotOptimize(parse_profile_csv(csv, "bench.csv", 2e-4).x1.size());
}
}  // namespace

BENCHMARK(bm_measured_roughness)->ArgsProduct({{1000, 10000, 100000, 1000000}, {0}})->Unit(benchmark::kMillisecond);
BENCHMARK(bm_measured_roughness)->ArgsProduct({{1000, 10000}, {1}})->Unit(benchmark::kMillisecond);
BENCHMARK(bm_profile_csv)->Arg(1000)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);
// ---- end of the measured-profile block

namespace {
// Issue 12, the general zone search (docs/formulation.md section 7). One point along a curve
// (the contact shared) of a scene whose single zone fails near gross sliding (K1* dominating
// K2* at the leading edge), Q/f = 1 - 1e-2 or 1 - 1e-6 (arg 0: 2 or 6), by method (arg 1:
// 1 product, 2 extrapolated), n (arg 2). zones = "auto": the single zone fails its checks, the
// search follows; the single zone alone (zones = "single") for the comparison is arg 3 = 1.
void bm_zone_point(benchmark::State& state) {
    const solver_options o{static_cast<int>(state.range(2)), method_of(state.range(1)),
                           state.range(3) == 1 ? zone_search::single : zone_search::automatic};
    contact c(zone_scenes::tangential_dominates_a(), 0.3, o);
    const double Q = 0.3 * (1.0 - std::pow(10.0, -static_cast<double>(state.range(0))));
    for (auto _ : state) benchmark::DoNotOptimize(c.point(Q).xi);
}

// The one-parameter zone search (docs/formulation.md 7(g)): eps1 = 0.1 < eps2 = 0.3, where the
// paper's zone fails from Q/f = 0.9971 on. Args: Q/f (0: 0.999, 1: 1 - 1e-6), n, and 1 for
// zones = "single" (the failing single zone alone). The contact shared, as along a curve.
void bm_limit_zone_point(benchmark::State& state) {
    roughness r;
    r.cylinder1.normal = {0.15 * 100.0, 10.0};
    r.cylinder1.tangential = {0.05 * 100.0, 10.0};
    const solver_options o{static_cast<int>(state.range(1)), method::one_parameter,
                           state.range(2) == 1 ? zone_search::single : zone_search::automatic};
    contact c(r, 0.3, o);
    const double Q = 0.3 * (state.range(0) == 0 ? 0.999 : 1.0 - 1e-6);
    // Two loads 1e-14 apart in turn: contact keeps the last point, a repeated Q would cost nothing.
    std::size_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(c.point(Q * (1.0 - 1e-14 * static_cast<double>(i++ % 2))).xi);
}

// Issue 13, dissimilar rollers at Johnson's level (docs/formulation.md 8(j)): one fresh point (the
// contact built inside the loop: its levels' points are cached) of aluminium on steel, f = 0.05,
// arg 0: 0 braked Q/f = -0.75 (both slip zones with Q), 1 driven Q/f = +0.9 (the blended stick
// zone); arg 1: 0 smooth, 1 the layers (T, A) = (1, 0.5) tangential, (0.5, 2) normal; arg 2: n
// (method extrapolated, the default); arg 3: 1 for beta_D = 0 at the same load (today's problem).
void bm_dissimilar_point(benchmark::State& state) {
    const double beta = state.range(3) == 1 ? 0.0 : 0.1438337435056057;
    roughness r;
    if (state.range(1) == 1) r = roughness{{{1.0, 0.5}, {0.5, 2.0}}, {}};
    const double f = 0.05, Q = state.range(0) == 0 ? -0.75 * f : 0.9 * f;
    const solver_options o{static_cast<int>(state.range(2)), method::extrapolated};
    for (auto _ : state) {
        contact c(r, f, o, dissimilar{beta, coupling_level::johnson});
        benchmark::DoNotOptimize(c.point(Q).xi);
    }
}

// Issue 13, five zones (docs/formulation.md 8(j) item 4): one fresh point of aluminium on steel at
// f = 0.05 by dissimilar_zones::five_zones without a guess (product integration at n, no levels);
// arg 0: 0 free rolling (the start from Q/f = 1/4 and two continuation steps), 1 driven Q/f = +0.75
// (Bentall and Johnson's case, smooth: the start from its own three zones); arg 1: 0 smooth, 1 the
// layers of bm_dissimilar_point (free rolling only: driven at 0.75 they keep three zones); arg 2: n.
void bm_five_zones(benchmark::State& state) {
    const double beta = 0.1438337435056057, f = 0.05, Q = state.range(0) == 0 ? 0.0 : 0.75 * f;
    roughness r;
    if (state.range(1) == 1) r = roughness{{{1.0, 0.5}, {0.5, 2.0}}, {}};
    for (auto _ : state) {
        contact c(r, f, solver_options{static_cast<int>(state.range(2)), method::product},
                  dissimilar{beta, coupling_level::johnson});
        dissimilar_zones d(tangential_of(c), kernel::tangential(r), beta);
        const auto s = d.five_zones(Q);
        if (!s) state.SkipWithError("five zones: no answer");
        benchmark::DoNotOptimize(s ? s->xi : 0.0);
    }
}

// Issue 13, five zones as contact::point reports them (8(j) item 9): one fresh point with its
// three levels n/4, n/2, n (each from the coarser level's ends) and the estimate, aluminium on
// steel, f = 0.05, smooth, method extrapolated (the default); arg 0: 0 free rolling, 1 Q/f = +0.75;
// arg 1: n.
void bm_five_zone_point(benchmark::State& state) {
    const double beta = 0.1438337435056057, f = 0.05, Q = state.range(0) == 0 ? 0.0 : 0.75 * f;
    for (auto _ : state) {
        contact c(roughness{}, f, solver_options{static_cast<int>(state.range(1)), method::extrapolated},
                  dissimilar{beta, coupling_level::johnson});
        const tangential_solution s = c.point(Q);
        benchmark::DoNotOptimize(c.estimate(s));
    }
}

// The same free-rolling point with bm_five_zones' layers (the pressure then has n terms that W
// sums at every value: u_series_table.hpp); arg: n.
void bm_five_zone_point_layers(benchmark::State& state) {
    const double beta = 0.1438337435056057, f = 0.05;
    const roughness r{{{1.0, 0.5}, {0.5, 2.0}}, {}};
    for (auto _ : state) {
        contact c(r, f, solver_options{static_cast<int>(state.range(0)), method::extrapolated},
                  dissimilar{beta, coupling_level::johnson});
        const tangential_solution s = c.point(0.0);
        benchmark::DoNotOptimize(c.estimate(s));
    }
}

// Issue 13, the two coupling levels (docs/formulation.md 8(e)): one fresh point of aluminium on
// steel at f = 0.05, smooth, product integration at n, no levels and no estimate (at full coupling
// the estimate refuses these loads at the default n: 8(e)); arg 0: 0 braked Q/f = -0.75 (three
// zones), 1 free rolling (five zones); arg 1: 0 Johnson's level, 1 full coupling; arg 2: n.
void bm_coupling_point(benchmark::State& state) {
    const double beta = 0.1438337435056057, f = 0.05, Q = state.range(0) == 0 ? -0.75 * f : 0.0;
    const coupling_level level = state.range(1) == 0 ? coupling_level::johnson : coupling_level::full;
    for (auto _ : state) {
        contact c(roughness{}, f, solver_options{static_cast<int>(state.range(2)), method::product},
                  dissimilar{beta, level});
        benchmark::DoNotOptimize(c.point(Q).xi);
    }
}
// The ladder's climb at the default settings (issue 24, 4 and 5; docs/performance.md "The rungs share their
// levels"), as `roughroll point` solves it: arg 0, the one-parameter case near gross sliding (eps1 = 0.1,
// eps2 = 0.3, Q/f = 0.9999: rungs 128 and 256, whose levels the store shares); 1, Fig. 2a's T = 1 at
// Q/f = 0.5 (answered at the first rung, 128); 2, aluminium on steel at full coupling, driven Q/f = +0.75
// (rungs 128, 256, 512, whose levels are each rung's own).
void bm_ladder_point(benchmark::State& state) {
    const std::string data = std::string(ROUGHROLL_SOURCE_DIR) + "/data/";
    scene s;
    if (state.range(0) == 0) {
        s = parse_scene(
            "friction = 0.3\nQ = 0.29997\n[cylinder1.tangential]\nT = 0.05\nA = 1\n"
            "[cylinder1.normal]\nT = 0.15\nA = 1\n[solver]\nmethod = \"one-parameter\"\n",
            "near-sliding.toml");
    } else if (state.range(0) == 1) {
        s = read_scene(data + "fig2a-T1.toml");
    } else {
        s = read_scene(data + "aluminium-on-steel.toml");
        s.materials.coupling = coupling_level::full;
        s.Q = 0.75 * s.friction;
    }
    for (auto _ : state) benchmark::DoNotOptimize(solve_point(s, std::nullopt).solution.xi);
}
}  // namespace

BENCHMARK(bm_ladder_point)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(3);
BENCHMARK(bm_coupling_point)
    ->ArgsProduct({{0, 1}, {0, 1}, {32, 64}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(3);
BENCHMARK(bm_five_zone_point)
    ->ArgsProduct({{0, 1}, {32, 128}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(3);
BENCHMARK(bm_five_zone_point_layers)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(3);
BENCHMARK(bm_five_zones)
    ->ArgsProduct({{0, 1}, {0}, {32, 64}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(3);
BENCHMARK(bm_five_zones)
    ->ArgsProduct({{0}, {1}, {32, 64}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(3);
BENCHMARK(bm_zone_point)->ArgsProduct({{15}, {1, 2}, {128}, {0, 1}})->Unit(benchmark::kMillisecond);
BENCHMARK(bm_limit_zone_point)->ArgsProduct({{0, 1}, {128, 256}, {0, 1}})->Unit(benchmark::kMillisecond);
BENCHMARK(bm_dissimilar_point)->ArgsProduct({{0, 1}, {0, 1}, {64, 128}, {0, 1}})->Unit(benchmark::kMillisecond);
BENCHMARK(bm_zone_point)->ArgsProduct({{2, 6}, {1, 2}, {64, 128}, {0, 1}})->Unit(benchmark::kMillisecond);
BENCHMARK(bm_lu)->Arg(48)->Arg(64)->Arg(96)->Arg(128)->Arg(200)->Unit(benchmark::kMillisecond);
BENCHMARK(bm_normal)->ArgsProduct({{0, 1}, {48, 96, 200}})->Unit(benchmark::kMillisecond);
BENCHMARK(bm_point)->ArgsProduct({{0, 1, 2}, {64, 96, 128, 200}})->Unit(benchmark::kMillisecond);
BENCHMARK(bm_point_estimated)->ArgsProduct({{1, 2}, {96, 128}})->Unit(benchmark::kMillisecond);
BENCHMARK(bm_curve_point)->ArgsProduct({{0, 1, 2}, {96, 128, 200}, {0, 1}})->Unit(benchmark::kMillisecond);
BENCHMARK(bm_swept_point)->ArgsProduct({{1, 2}, {96, 128}, {0, 1, 2}})->Unit(benchmark::kMillisecond);
BENCHMARK(bm_swept_point_warm)->ArgsProduct({{2}, {128}, {0, 1, 2}})->Unit(benchmark::kMillisecond);
BENCHMARK(bm_contact_first_point)->ArgsProduct({{2}, {128}, {0, 1, 2}})->Unit(benchmark::kMillisecond);
BENCHMARK(bm_limit_point)->ArgsProduct({{64, 128, 256}, {0, 1}})->Unit(benchmark::kMillisecond);
BENCHMARK(bm_limit_swept_point)->ArgsProduct({{128, 256}, {0, 1}})->Unit(benchmark::kMillisecond);
BENCHMARK(bm_physical_point)->DenseRange(1, 3)->Unit(benchmark::kMillisecond);
BENCHMARK(bm_physical_point_fixed)->DenseRange(1, 3)->Unit(benchmark::kMillisecond);
BENCHMARK(bm_roughness_parameters)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(bm_figure)->ArgsProduct({{1, 2}, {96, 128}})->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
