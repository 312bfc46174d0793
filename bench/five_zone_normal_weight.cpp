// SPDX-License-Identifier: GPL-3.0-or-later
// The five zones' normal solve alone on a fixed source (session 22, helper vkwire; a measurement, not a test): the
// exact weight of 8(z) against 8(x)'s blended treatment on the same linear problem, at rising n, with an independent
// QUADPACK residual. Route A is what full_coupling solves since session 23 (docs/formulation.md 8(z), "Wired"); route B
// the treatment it replaced.
//
// The linear problem (LP): five zones -1 < s1 < c1 <= s2 < c2 < 1 (stick zones [s1, c1], [s2, c2]), k(r) =
// sigma beta_D f (2 B(r) - 1) with B the plateau of 8(p) (blend_plateau: Theta_3 rising on the first zone, falling on
// the second), i.e. 8(x)'s continuous k = sigma beta_D f S_3; q on each stick zone sqrt(1 - t^2) psi_Z(t) (a fixed analytic
// psi_Z: the source's q frozen); unknowns p, gamma, lambda with
//   H[p] + k p + gamma + (2/pi) lambda r = -sigma beta_D q,   int p = 1.
// This is (D1) of one alternation step at the fixed point of the part k p (8(x)); the blend's kinks (8(r)), which both
// routes carry the same way in q, are left out.
// Route A (8(z)): p = w_k psi + p_q on the weight of (H - k_z), k_z = -k (8(z)'s convention), psi by
// variable_k_collocation::solve_loaded, p_q = -(k_z h/(1 + k_z^2) + w_k H[h w_d]) for h = -sigma beta_D q (8(z), "The
// stick zones' part p_q for a varying k": 1/(1 + k^2) inside H), H[h w_d] from h w_d's U-series on each zone.
// Route B (8(x), landed in session 20, replaced in session 23): pressure_kinks on w_N (k_E = -sigma beta_D f), each
// zone's p_q on the square-root weight, the cubic Hermite plateau, normal_solver::solve_weighted with the remainder
// sigma beta_D f (S_3 + 1) p_src on the right side, iterated on p_src to its fixed point (the alternation's, q frozen).
// Build (repository root, after the library):
//   g++ -O3 -DNDEBUG -std=c++17 -Iinclude bench/five_zone_normal_weight.cpp build-s8/libroughroll_core.a \
//       $(pkg-config --libs tomlplusplus) -lgsl -lgslcblas
// Usage: a.out f s1 c1 s2 c2 [quadpack_n]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <functional>
#include <memory>
#include <vector>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include "roughroll/numerics/blend_plateau.hpp"
#include "roughroll/numerics/gauss_chebyshev.hpp"
#include "roughroll/numerics/gauss_jacobi.hpp"
#include "roughroll/numerics/quadrature.hpp"
#include "roughroll/numerics/variable_k_weight.hpp"
#include "roughroll/problems/normal_problem.hpp"
#include "roughroll/problems/pressure_kinks.hpp"

using namespace roughroll;

namespace {
double cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

const double beta_d = 0.1438337435056057;  // aluminium on steel (the JSON's beta_d)
const double sigma = 1.0;

struct problem {
    double f, s1, c1, s2, c2;
    blend_plateau B;
    problem(double f_, double a, double b, double c, double d) : f(f_), s1(a), c1(b), s2(c), c2(d), B(a, b, c, d) {}
    double k(double r) const { return sigma * beta_d * f * (2.0 * B(r) - 1.0); }
    // psi_Z of the frozen q, analytic, of the size f p.
    static double psi1(double f, double t) { return 0.6 * f * (0.4 + 0.3 * t + 0.1 * std::cos(2.0 * t)); }
    static double psi2(double f, double t) { return 0.4 * f * (0.2 - 0.5 * t + 0.1 * std::exp(t)); }
    // q(r) (0 off the stick zones).
    double q(double r) const {
        if (r > s1 && r < c1) {
            const double t = (2.0 * r - s1 - c1) / (c1 - s1);
            return std::sqrt((1.0 - t) * (1.0 + t)) * psi1(f, t);
        }
        if (r > s2 && r < c2) {
            const double t = (2.0 * r - s2 - c2) / (c2 - s2);
            return std::sqrt((1.0 - t) * (1.0 + t)) * psi2(f, t);
        }
        return 0.0;
    }
};

struct result {
    double lambda, gamma;
    std::function<double(double)> p;
    double seconds;  // CPU of the solve (A: weight, rule, points, LU, p_q, solve; B: every iteration)
    int iterations = 1;
    std::shared_ptr<void> keep;  // what p refers to
};

// Route A: the exact weight.
result route_a(const problem& P, int n, bool control = false) {
    const double t0 = cpu_seconds();
    const double k0 = -sigma * beta_d * P.f;  // k_z = -k = k0 (2 B - 1)
    auto t_of = [](double x, double l, double r) { return std::clamp((2.0 * x - l - r) / (r - l), -1.0, 1.0); };
    const std::vector<double> ends{-1.0, P.s1, P.c1, P.s2, P.c2, 1.0};
    const double s1 = P.s1, c1 = P.c1, s2 = P.s2, c2 = P.c2;
    std::vector<std::function<double(double)>> varying{
        {}, [=](double x) { return k0 * (2.0 * blend_plateau::theta3(t_of(x, s1, c1)) - 1.0); }, {},
        [=](double x) { return k0 * (1.0 - 2.0 * blend_plateau::theta3(t_of(x, s2, c2)) ); }, {}};
    struct state {
        std::unique_ptr<variable_k_weight> w;
        std::unique_ptr<variable_k_collocation> c;
        variable_k_collocation::solution s;
        std::vector<double> b1, b2;
    };
    auto st = std::make_shared<state>();
    st->w = std::make_unique<variable_k_weight>(ends, std::vector<double>{-k0, 0.0, k0, 0.0, -k0}, varying);
    st->c = std::make_unique<variable_k_collocation>(*st->w, n);
    const variable_k_weight& w = *st->w;
    // h w_d = sqrt(1 - t^2) g(t) on each zone, g = -sigma beta_D psi_Z(t) w_d(r(t)): its U-series on n nodes.
    const gauss_chebyshev rule = gauss_chebyshev::transform(n);
    double C = 0.0, load_q = 0.0;
    const double mu0 = w.mu0();
    for (int z = 0; z < 2; ++z) {
        const double s = z == 0 ? P.s1 : P.s2, c = z == 0 ? P.c1 : P.c2, rho = 0.5 * (c - s), m = 0.5 * (s + c);
        std::vector<double> g(n);
        for (int i = 0; i < n; ++i) {
            const double t = rule.nodes[i];
            g[i] = -sigma * beta_d * (z == 0 ? problem::psi1(P.f, t) : problem::psi2(P.f, t)) * w.dual()(m + rho * t);
            // The control of 8(z): 1/(1 + k^2) outside H (h/w_k inside), which is exact only where k is constant on h.
            if (control) g[i] *= 1.0 + std::pow(w.k_at(m + rho * t), 2);
        }
        std::vector<double> b = u_coefficients(rule, g);
        // C = -(1/pi) int h w_d = -(1/pi) rho (pi/2) b_0; int p_q = -int h (x + 1 - mu_0) w_d, x = m + rho t, t = U_1/2.
        C += -0.5 * rho * b[0];
        load_q += -rho * M_PI_2 * ((m + 1.0 - mu0) * b[0] + rho * 0.5 * (b.size() > 1 ? b[1] : 0.0));
        (z == 0 ? st->b1 : st->b2) = std::move(b);
    }
    std::vector<double> zero(n + 1, 0.0);
    st->s = st->c->solve_loaded(zero, st->c->points(), 1.0 - load_q);
    const double seconds = cpu_seconds() - t0;
    const problem Pc = P;
    auto pq = [st, Pc, control](double x) {
        const variable_k_weight& w = *st->w;
        const double kz = w.k_at(x), h = -sigma * beta_d * Pc.q(x);
        const double t1 = (2.0 * x - Pc.s1 - Pc.c1) / (Pc.c1 - Pc.s1), t2 = (2.0 * x - Pc.s2 - Pc.c2) / (Pc.c2 - Pc.s2);
        const double hw = cauchy_u_series(st->b1, t1) + cauchy_u_series(st->b2, t2);
        return -(kz * h / (1.0 + kz * kz) + w(x) * hw / (control ? 1.0 + kz * kz : 1.0));
    };
    result r;
    r.lambda = -M_PI_2 * st->s.lambda;
    r.gamma = -(st->s.xi + C);
    r.p = [st, pq](double x) {
        if (std::fabs(x) >= 1.0) return 0.0;
        return (*st->w)(x) * st->c->interpolate(st->s.psi, x) + pq(x);
    };
    r.seconds = seconds;
    r.keep = st;
    return r;
}

// Route B: 8(x) as landed (pressure_kinks on w_N with the plateau, solve_weighted), iterated on p_src.
result route_b(const problem& P, int n) {
    const double t0 = cpu_seconds();
    const double k_e = -sigma * beta_d * P.f;
    auto solver = std::make_shared<normal_solver>(n, method::product);
    std::shared_ptr<normal_solution> src;
    std::function<double(double)> p_src = [](double r) {
        return std::fabs(r) < 1.0 ? M_2_PI * std::sqrt((1.0 - r) * (1.0 + r)) : 0.0;
    };
    const std::vector<double> kinks{P.s1, P.c1, P.s2, P.c2};
    double lambda = 0.0, gamma = 0.0;
    int it = 0;
    for (it = 1; it <= 60; ++it) {
        auto k = std::make_shared<pressure_kinks>();
        k->set_weight(k_e);
        const double f = P.f;
        k->add_weighted_zone(n, beta_d, sigma, P.s1, P.c1, 0.5, [f](double t) { return problem::psi1(f, t); });
        k->add_weighted_zone(n, beta_d, sigma, P.s2, P.c2, 0.5, [f](double t) { return problem::psi2(f, t); });
        // The plateau as weighted_kinks_of (full_coupling.cpp) builds it from the source's pressure.
        const double a_n = k->weight_a();
        const auto g = [&p_src, a_n](double r) { return p_src(r) / jacobi_weight(a_n, 1.0 - a_n, r); };
        const auto slope_at = [&g](double m, double rho) {
            const double d = 1e-3 * rho;
            return (g(m + d) - g(m - d)) / (2.0 * d);
        };
        const double m1 = 0.5 * (P.s1 + P.c1), m2 = 0.5 * (P.s2 + P.c2);
        k->add_weighted_plateau(beta_d, sigma, f, blend_plateau(P.s1, P.c1, P.s2, P.c2), {g(m1), g(m2)},
                                {slope_at(m1, 0.5 * (P.c1 - P.s1)), slope_at(m2, 0.5 * (P.c2 - P.s2))});
        const problem Pc = P;
        const std::function<double(double)> coupled = [Pc, &p_src](double r) {
            return sigma * beta_d * (Pc.f * (2.0 * Pc.B(r) - 1.0) * p_src(r) + Pc.q(r));
        };
        auto next = std::make_shared<normal_solution>(solver->solve_weighted(coupled, p_src, kinks, k));
        const double change = std::max(std::fabs(next->lambda - lambda), std::fabs(next->gamma - gamma));
        lambda = next->lambda;
        gamma = next->gamma;
        src = next;
        p_src = [src](double r) { return src->pressure(r); };
        if (change < 1e-15 && it > 2) break;
    }
    result r;
    r.lambda = lambda;
    r.gamma = gamma;
    r.p = p_src;
    r.seconds = cpu_seconds() - t0;
    r.iterations = it;
    r.keep = std::shared_ptr<void>(solver, solver.get());
    return r;
}

// The residual of the LP at x by QUADPACK: H[p](x) (QAWC about x, QAGS on the pieces between the zone ends and the
// edges) + k p + gamma + (2/pi) lambda x + sigma beta_D q.
struct qp {
    const std::function<double(double)>* p;
    double x;
};
double residual(const problem& P, const result& r, double x) {
    gsl_set_error_handler_off();
    gsl_integration_workspace* ws = gsl_integration_workspace_alloc(2000);
    std::vector<double> cuts{-1.0, P.s1, P.c1, P.s2, P.c2, 1.0};
    double dmin = 1.0;
    for (double c : cuts) dmin = std::min(dmin, std::fabs(x - c));
    const double d = std::min(1e-2, 0.5 * dmin);
    cuts.push_back(x - d);
    cuts.push_back(x + d);
    std::sort(cuts.begin(), cuts.end());
    qp data{&r.p, x};
    double sum = 0.0;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        const double a = cuts[i], b = cuts[i + 1];
        double v = 0.0, e = 0.0;
        int status;
        if (a == x - d) {
            gsl_function F{[](double t, void* v) { return (*static_cast<qp*>(v)->p)(t); }, &data};
            status = gsl_integration_qawc(&F, a, b, x, 1e-15, 1e-13, 2000, ws, &v, &e);
        } else {
            gsl_function F{[](double t, void* v) {
                               const qp& q = *static_cast<qp*>(v);
                               return (*q.p)(t) / (t - q.x);
                           },
                           &data};
            status = gsl_integration_qags(&F, a, b, 1e-15, 1e-13, 2000, ws, &v, &e);
        }
        if (status && e > 1e-12) std::fprintf(stderr, "quadpack status %d on [%g, %g] err %g\n", status, a, b, e);
        sum += v;
    }
    gsl_integration_workspace_free(ws);
    return sum / M_PI + P.k(x) * r.p(x) + r.gamma + M_2_PI * r.lambda * x + sigma * beta_d * P.q(x);
}
}  // namespace

int main(int argc, char** argv) {
    if (argc < 6) {
        std::fprintf(stderr, "usage: %s f s1 c1 s2 c2 [quadpack_n]\n", argv[0]);
        return 2;
    }
    const problem P(std::atof(argv[1]), std::atof(argv[2]), std::atof(argv[3]), std::atof(argv[4]), std::atof(argv[5]));
    const int qn = argc > 6 ? std::atoi(argv[6]) : 0;
    if (argc > 7) {  // the control alone: route A with 1/(1 + k^2) outside H, its QUADPACK residual at n = qn
        const result c = route_a(P, qn, true), a = route_a(P, qn);
        std::printf("control (1/(1 + k^2) outside H) at n = %d: lambda %.16f (exact form %.16f)\n", qn, c.lambda, a.lambda);
        for (double x : {-0.9, 0.5 * (P.s1 + P.c1), 0.5 * (P.c1 + P.s2), 0.5 * (P.s2 + P.c2), P.c1 + 1e-3, P.s2 - 1e-4})
            std::printf("  x %+.6f  residual: control %.2e  exact form %.2e\n", x, residual(P, c, x), residual(P, a, x));
        return 0;
    }
    // Probe points: the zone ends, the zones' quarter points, the centre, near the edges.
    std::vector<double> probes{P.s1, P.c1, P.s2, P.c2, -0.9, 0.5 * (P.s1 + P.c1), 0.5 * (P.c1 + P.s2),
                               0.5 * (P.s2 + P.c2), 0.5 * (P.c2 + 1.0), 0.0};
    std::vector<double> grid;
    for (int i = 1; i < 400; ++i) grid.push_back(-1.0 + 2.0 * i / 400.0);
    std::printf("f %g  zones [%.10f, %.10f] [%.10f, %.10f]\n", P.f, P.s1, P.c1, P.s2, P.c2);
    const std::vector<int> ns{32, 64, 128, 256, 512};
    std::vector<result> A, B;
    for (int n : ns) {
        A.push_back(route_a(P, n));
        B.push_back(route_b(P, n));
        std::printf("n %4d  A: lambda %.16f gamma %.16e  %.4f s | B: lambda %.16f gamma %.16e  %.4f s (%d it)\n", n,
                    A.back().lambda, A.back().gamma, A.back().seconds, B.back().lambda, B.back().gamma,
                    B.back().seconds, B.back().iterations);
        std::fflush(stdout);
    }
    const result& Ar = A.back();
    std::printf("\nerrors against route A at n = %d: |d lambda|, |d gamma|, max |d p| at the 4 zone ends, max |d p| on a "
                "grid of 399, then p at the probes (A, B at 512)\n", ns.back());
    for (std::size_t i = 0; i < ns.size(); ++i) {
        for (int route = 0; route < 2; ++route) {
            const result& r = route == 0 ? A[i] : B[i];
            double ends = 0.0, grd = 0.0;
            for (int j = 0; j < 4; ++j) ends = std::max(ends, std::fabs(r.p(probes[j]) - Ar.p(probes[j])));
            for (double x : grid) grd = std::max(grd, std::fabs(r.p(x) - Ar.p(x)));
            std::printf("n %4d %c  %.2e %.2e  ends %.2e  grid %.2e\n", ns[i], route == 0 ? 'A' : 'B',
                        std::fabs(r.lambda - Ar.lambda), std::fabs(r.gamma - Ar.gamma), ends, grd);
        }
    }
    std::printf("\np at the probes (route A %d, route B %d):\n", ns.back(), ns.back());
    for (double x : probes) std::printf("  x %+.10f  A %.16f  B %.16f  diff %.2e\n", x, Ar.p(x), B.back().p(x), Ar.p(x) - B.back().p(x));
    if (qn > 0) {
        const auto at = std::find(ns.begin(), ns.end(), qn) - ns.begin();
        std::printf("\nQUADPACK residual of the LP at n = %d (probes off the zone ends; A, B):\n", qn);
        for (std::size_t j = 4; j < probes.size(); ++j)
            std::printf("  x %+.6f  A %.2e  B %.2e\n", probes[j], residual(P, A[at], probes[j]),
                        residual(P, B[at], probes[j]));
        for (double x : {P.s1 + 1e-3 * (P.c1 - P.s1), P.c1 + 1e-3, P.s2 - 1e-4, P.c2 - 1e-3 * (P.c2 - P.s2)})
            std::printf("  x %+.6f  A %.2e  B %.2e\n", x, residual(P, A[at], x), residual(P, B[at], x));
    }
}
