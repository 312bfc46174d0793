// SPDX-License-Identifier: GPL-3.0-or-later
// The independent, low-order route to the tangential problem (docs/formulation.md 7(f)):
// no assumption about the zone structure, in the way of Kalker's CONTACT. The contact [-1, 1]
// is cut into N equal cells, the traction p1 is constant on each, and the tangential
// displacement difference u, whose slope is L1[p1] of 2(b),
//   u(r) = -(1/pi) int p1(eta) log|eta - r| d eta + int p1(eta) Kt(eta - r) d eta,
//   Kt(z) = sum T/A exp(-A |z|)  (d/dr Kt(eta - r) = K1*(eta - r)),
// is integrated exactly over each cell and taken at the cell midpoints r_i (and at the point
// r_{-1} = -1 - h/2 before the leading edge). The slip velocity (3.6) is the upwind difference
// in the rolling direction (material enters at r = -1):
//   v_i = xi - (u_i - u_{i-1})/h,
// and the conditions, for every cell,
//   stick:  v_i = 0,  |p1_i| <= f p_i        (3.2), (3.3)
//   slip:   p1_i = sigma_i f p_i,  sigma_i v_i >= 0      (3.4)
//   h sum_i p1_i = Q                         (3.13)
// Neither G (3.25), nor the stretched kernel (E6), nor the corrective traction q (3.15), nor
// the end conditions of section 7 enter: the full traction is the unknown. The state of each
// cell is found by an active-set (complementarity) iteration: a stick cell whose traction
// exceeds f p slips in the direction of its traction; when none does, a slip cell whose
// velocity opposes its traction sticks again; until nothing changes. Order about 1 in h.
//
// Dissimilar rollers (docs/formulation.md 8(c), (e)), Johnson's approximation: the pressure p
// is that of `normal` (uncoupled), and the displacement difference gains the term of Dundurs'
// beta_D, u' = L1[p1] - beta_D p, i.e. u_p(r) = -beta_D int_{-1}^{r} p, so that
//   v_i = xi - (u_i - u_{i-1})/h + beta_D (p_{i-1} + p_i)/2     (p_{-1} = 0),
// the cell integral of the piecewise-constant cell pressure between r_{i-1} and r_i. With
// beta_D = 0 (the default) every term is the one above.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <gsl/gsl_math.h>

#include "roughroll/model/kernel.hpp"
#include "roughroll/numerics/linear_system.hpp"
#include "roughroll/problems/normal_problem.hpp"

namespace roughroll::validation {

struct grid_solution {
    double xi;
    std::vector<double> r, p, p1, v;  // per cell: midpoint, pressure, traction, slip velocity
    std::vector<int> state;           // 0 stick, +1/-1 slip with that direction
    int iterations;
    double h;

    // The ends of the runs of equal state, as (from, to, state), from r = -1 to 1.
    struct run {
        double from, to;
        int state;
    };
    std::vector<run> runs() const {
        std::vector<run> out;
        for (std::size_t i = 0; i < state.size(); ++i) {
            const double lo = r[i] - 0.5 * h, hi = r[i] + 0.5 * h;
            if (out.empty() || out.back().state != state[i])
                out.push_back({lo, hi, state[i]});
            else
                out.back().to = hi;
        }
        return out;
    }
};

// Displacement of a unit traction on [lo, hi] at r: -(1/pi) int log|eta - r| + int Kt(eta - r).
inline double cell_displacement(const kernel& k, double lo, double hi, double r) {
    const auto log_antiderivative = [](double x) { return x == 0.0 ? 0.0 : x * std::log(std::fabs(x)) - x; };
    double u = -M_1_PI * (log_antiderivative(hi - r) - log_antiderivative(lo - r));
    for (const auto& term : k.terms()) {
        // int_{d0}^{d1} Kt over distances 0 <= d0 <= d1 from r.
        const auto side = [&](double d0, double d1) {
            if (term.A == 0.0) return -term.T * 0.5 * (d1 * d1 - d0 * d0);  // Kt = -T |z|
            return term.T / (term.A * term.A) * (std::exp(-term.A * d0) - std::exp(-term.A * d1));
        };
        if (lo >= r)
            u += side(lo - r, hi - r);
        else if (hi <= r)
            u += side(r - hi, r - lo);
        else
            u += side(0.0, hi - r) + side(0.0, r - lo);
    }
    return u;
}

// The displacement of the pressure term of 8(c) at r_{-1} .. r_{N-1} (index i + 1), for the cell
// pressures p (constant per cell of width h): u_p(r) = -beta_D int_{-1}^{r} p, zero before r = -1.
inline std::vector<double> pressure_displacement(const std::vector<double>& p, double h, double beta_d) {
    std::vector<double> u(p.size() + 1, 0.0);
    double below = 0.0;  // int_{-1}^{lower end of cell i} p
    for (std::size_t i = 0; i < p.size(); ++i) {
        u[i + 1] = -beta_d * (below + 0.5 * h * p[i]);
        below += h * p[i];
    }
    return u;
}

// The complete-slip limit f -> 0 of the same grid equations (docs/formulation.md 8(f)): p1 =
// O(f) drops out of v, v_i = xi + beta_D pbar_i with pbar_i = (p_{i-1} + p_i)/2, every cell
// slips with p1_i = f p_i sgn v_i except the cell where v = 0, and h sum p1 = Q fixes xi. The
// cells with sgn(beta_D) v > 0 are those of the largest pbar (a central band, p even and
// decreasing); they must carry (1 + sgn(beta_D) Q/f)/2 of the load. The band's ends are
// quantised to cells, so xi/beta_D = -pbar_k (k the cell with v = 0) is known to within the
// change of pbar over a cell or two there: `resolution` = 2 max |pbar_{k+-1} - pbar_k|, O(h).
// The closed form is xi/beta_D = -(2/pi) cos(phi) for Hertz and Q = 0.
struct complete_slip {
    double xi_over_beta;
    double resolution;
};
inline complete_slip complete_slip_creep(const normal_solution& normal, double Q_over_f, double sign_beta, int N) {
    const double h = 2.0 / N;
    std::vector<double> p(N), pbar(N);
    double total = 0.0;
    for (int i = 0; i < N; ++i) {
        p[i] = normal.pressure(-1.0 + (i + 0.5) * h);
        total += h * p[i];
    }
    for (double& pi : p) pi /= total;
    for (int i = 0; i < N; ++i) pbar[i] = 0.5 * ((i > 0 ? p[i - 1] : 0.0) + p[i]);
    std::vector<int> order(N);
    for (int i = 0; i < N; ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return pbar[a] > pbar[b]; });
    const double target = 0.5 * (1.0 + sign_beta * Q_over_f);
    double carried = 0.0;
    for (int k : order) {
        if (carried + h * p[k] >= target) {  // the cell with v = 0: xi = -beta_D pbar_k
            double step = 0.0;
            if (k > 0) step = std::max(step, std::fabs(pbar[k - 1] - pbar[k]));
            if (k + 1 < N) step = std::max(step, std::fabs(pbar[k + 1] - pbar[k]));
            return {-pbar[k], 2.0 * step};
        }
        carried += h * p[k];
    }
    throw std::runtime_error("grid route: |Q| > f in the complete-slip limit");
}

// The complementarity solution for the load Q (|Q| <= f) on N cells, found by rolling: from
// no traction, the cylinders roll one cell per step, and each step is the static frictional
// problem of the shift: a particle now in cell i was in cell i-1, and its slip over the step,
//   w_i = delta - (u_i(new) - u_{i-1}(old)),   delta = h xi (the rigid shift, unknown),
// is zero where it sticks, with p1_i = f p_i sgn w_i where it slips, and h sum p1 = Q. At the
// steady state u(new) = u(old) and w_i = h v_i: the conditions above. Each step is solved by
// the active-set iteration (stick cells over the bound slip; when none, slip cells whose slip
// opposes the traction stick), which settles for these static problems where the steady
// iteration itself cycles (measured). Once the states stop changing the steady equations are
// solved for them directly and kept when every condition holds (the march itself converges
// only geometrically). `normal` supplies the pressure; the cell pressures are rescaled so that
// h sum p_i = 1 exactly.
inline grid_solution solve_on_grid(const normal_solution& normal, const kernel& k1, double f, double Q, int N,
                                   int max_steps = 0, double beta_d = 0.0) {
    grid_solution s{};
    const double h = 2.0 / N;
    s.h = h;
    s.r.resize(N);
    s.p.resize(N);
    double total = 0.0;
    for (int i = 0; i < N; ++i) {
        s.r[i] = -1.0 + (i + 0.5) * h;
        s.p[i] = normal.pressure(s.r[i]);
        total += h * s.p[i];
    }
    for (double& pi : s.p) pi /= total;
    // U(i, j): displacement at r_i (i = -1 .. N-1, row i + 1) of a unit traction on cell j.
    std::vector<double> U(static_cast<std::size_t>(N + 1) * N);
    for (int j = 0; j < N; ++j) {
        const double lo = -1.0 + j * h, hi = lo + h;
        for (int i = -1; i < N; ++i) U[(i + 1) * N + j] = cell_displacement(k1, lo, hi, -1.0 + (i + 0.5) * h);
    }
    // The pressure term of 8(c): u_p at r_i (i = -1 .. N-1, index i + 1), exactly zero for beta_D = 0.
    const std::vector<double> u_p = pressure_displacement(s.p, h, beta_d);
    const auto displacement = [&](const std::vector<double>& p1, int i) {  // i = -1 .. N-1
        double u = 0.0;
        for (int j = 0; j < N; ++j) u += U[(i + 1) * N + j] * p1[j];
        if (beta_d != 0.0) u += u_p[i + 1];
        return u;
    };
    // The stick cells of `state`, the traction f p sgn on its slip cells and their load h sum.
    struct active_set {
        std::vector<int> stick;
        std::vector<double> known;
        double known_load = 0.0;
    };
    const auto split = [&](const std::vector<int>& state, const std::vector<double>& p) {
        active_set a{{}, std::vector<double>(N, 0.0), 0.0};
        for (int j = 0; j < N; ++j) {
            if (state[j] == 0) {
                a.stick.push_back(j);
            } else {
                a.known[j] = state[j] * f * p[j];
                a.known_load += h * a.known[j];
            }
        }
        return a;
    };
    s.state.assign(N, 0);
    s.p1.assign(N, 0.0);
    s.v.assign(N, 0.0);
    if (max_steps == 0) max_steps = 4 * N;
    std::vector<int> previous_state;
    int unchanged = 0;
    // The steady problem for the states of s: v_i = xi - (u_i - u_{i-1})/h = 0 on stick cells,
    // h sum p1 = Q; true (and s updated) when the result satisfies every condition.
    const auto steady = [&](grid_solution& g) {
        const auto [stick, known, known_load] = split(g.state, g.p);
        const std::size_t m = stick.size();
        dense_system sys(m + 1);
        gsl_matrix* a = sys.matrix();
        gsl_vector* b = sys.rhs();
        for (std::size_t ii = 0; ii < m; ++ii) {
            const int i = stick[ii];
            gsl_vector_set(b, ii, -(displacement(known, i) - displacement(known, i - 1)));
            for (std::size_t jj = 0; jj < m; ++jj)
                gsl_matrix_set(a, ii, jj, U[(i + 1) * N + stick[jj]] - U[i * N + stick[jj]]);
            gsl_matrix_set(a, ii, m, -h);
        }
        for (std::size_t jj = 0; jj < m; ++jj) gsl_matrix_set(a, m, jj, h);
        gsl_matrix_set(a, m, m, 0.0);
        gsl_vector_set(b, m, Q - known_load);
        const gsl_vector* x = sys.solve("grid route (steady)");
        std::vector<double> p1 = known, v(N, 0.0);
        for (std::size_t jj = 0; jj < m; ++jj) p1[stick[jj]] = gsl_vector_get(x, jj);
        const double xi = gsl_vector_get(x, m);
        for (int i = 0; i < N; ++i) {
            if (g.state[i] == 0) {
                if (std::fabs(p1[i]) > f * g.p[i]) return false;
            } else {
                v[i] = xi - (displacement(p1, i) - displacement(p1, i - 1)) / h;
                if (g.state[i] * v[i] < 0.0) return false;
            }
        }
        g.p1 = p1;
        g.v = v;
        g.xi = xi;
        return true;
    };
    for (int step = 1; step <= max_steps; ++step) {
        std::vector<double> old_u(N);  // u_{i-1}(old) for each cell i
        for (int i = 0; i < N; ++i) old_u[i] = displacement(s.p1, i - 1);
        const std::vector<double> old_p1 = s.p1;
        // The states travel with the material: cell i starts from cell i-1's (stick at entry).
        for (int i = N - 1; i > 0; --i) s.state[i] = s.state[i - 1];
        s.state[0] = 0;
        double delta = 0.0;
        int iterations = 0;
        for (;; ++iterations) {
            if (iterations > 4 * N) throw std::runtime_error("grid route: the active set of a step did not settle");
            const auto [stick, known, known_load] = split(s.state, s.p);
            const std::size_t m = stick.size();
            if (m == 0) throw std::runtime_error("grid route: no stick cell (gross sliding is not solved here)");
            dense_system sys(m + 1);
            gsl_matrix* a = sys.matrix();
            gsl_vector* b = sys.rhs();
            for (std::size_t ii = 0; ii < m; ++ii) {
                const int i = stick[ii];
                // u_i(new) - delta = u_{i-1}(old)
                gsl_vector_set(b, ii, old_u[i] - displacement(known, i));
                for (std::size_t jj = 0; jj < m; ++jj) gsl_matrix_set(a, ii, jj, U[(i + 1) * N + stick[jj]]);
                gsl_matrix_set(a, ii, m, -1.0);
            }
            for (std::size_t jj = 0; jj < m; ++jj) gsl_matrix_set(a, m, jj, h);
            gsl_matrix_set(a, m, m, 0.0);
            gsl_vector_set(b, m, Q - known_load);
            const gsl_vector* x = sys.solve("grid route");
            s.p1 = known;
            for (std::size_t jj = 0; jj < m; ++jj) s.p1[stick[jj]] = gsl_vector_get(x, jj);
            delta = gsl_vector_get(x, m);
            std::vector<double> w(N, 0.0);
            for (int i = 0; i < N; ++i)
                if (s.state[i] != 0) w[i] = delta - (displacement(s.p1, i) - old_u[i]);
            bool changed = false;
            for (int i = 0; i < N; ++i)
                if (s.state[i] == 0 && std::fabs(s.p1[i]) > f * s.p[i]) {
                    s.state[i] = s.p1[i] > 0.0 ? 1 : -1;
                    changed = true;
                }
            if (!changed)
                for (int i = 0; i < N; ++i)
                    if (s.state[i] != 0 && s.state[i] * w[i] < 0.0) {
                        s.state[i] = 0;
                        changed = true;
                    }
            if (!changed) {
                for (int i = 0; i < N; ++i) s.v[i] = w[i] / h;
                break;
            }
        }
        s.xi = delta / h;
        s.iterations = step;
        double change = 0.0;
        for (int i = 0; i < N; ++i) change = std::max(change, std::fabs(s.p1[i] - old_p1[i]));
        if (change < 1e-13 * f) return s;  // steady: w = h v
        // The march settles slowly (geometrically); once the states have stopped changing,
        // solve the steady equations for them directly and keep that if every condition holds.
        if (s.state == previous_state && ++unchanged >= 8 && steady(s)) {
            s.iterations = step;
            return s;
        }
        if (s.state != previous_state) unchanged = 0;
        previous_state = s.state;
    }
    throw std::runtime_error("grid route: no steady state within the steps allowed");
}

}  // namespace roughroll::validation
