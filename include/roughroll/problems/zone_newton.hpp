// SPDX-License-Identifier: GPL-3.0-or-later
// The zone search's Newton (docs/formulation.md 7(e), 7(g), 8(g), 8(j) item 3): the residuals of k stick zones
// for every zone search (ends_newton), on interval_newton (numerics/interval_newton.hpp: the ends' parametrisation,
// the Jacobian by differences, the damped steps), and the rounding limits a search met on its routes.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <gsl/gsl_math.h>

#include "roughroll/numerics/damped_newton.hpp"
#include "roughroll/numerics/interval_newton.hpp"
#include "roughroll/problems/tangential_problem.hpp"

namespace roughroll {

// Newton's iterations in every zone search (zone_solver, the five zones).
constexpr int zone_newton_iterations = 40;

// The rounding limits a search met on its routes (newton_stop::rounding_limit: the zone ends' Newton stopped at a
// rounding beyond its cap). To a route such a stop is "no root from here": it tries its next start, bracket or
// fallback (Brent), as for any Newton without a root, and notes the stop here. Only the search that ends with nothing
// on every route, the limit met on one of them, refuses with it (rounding_limit_error, `refusal`): the rounding grows
// with n, so "no zones at this n" would advise the wrong change (docs/formulation.md 8(q), "The stop's reason").
class rounding_limits {
public:
    // Notes damped_newton's stop where it is the rounding limit (Newton's tolerance `tolerance`); else nothing.
    void note(const newton_result& stop, double tolerance);
    // Notes what `other` met (the largest rounding of both kept).
    void note(const rounding_limits& other);
    bool met() const { return met_; }
    // The refusal's line: what limits the ends (the largest rounding met), and what lowers it.
    std::string refusal() const;

private:
    bool met_ = false;
    double rounding_ = 0.0, tolerance_ = 0.0;  // the largest rounding met, and its Newton's tolerance
};

// The stick zones' systems of a solution, in order from r = -1 (tangential_solution::zone_system, which holds them to
// one per stick zone of the layout): the solution itself for one stick zone, each zone's for the five zones
// (dissimilar_zones.hpp).
inline std::vector<const tangential_solution*> stick_systems(const tangential_solution& s) {
    std::vector<const tangential_solution*> systems;
    for (std::size_t k = 0; k < s.layout.stick_zones(); ++k) systems.push_back(&s.zone_system(k));
    return systems;
}

// Newton in the ends of k stick zones at the load Q, for every zone search. `solve`: the systems on the zones,
// empty where they fail (the step is halved). The residuals, per zone structure:
//   - `relative` (k = 1, one slip direction: 7(e), 7(g)): F_0 = log(-rho (pi/2) psi_0 / (f - Q)), the load's
//     gap f - Q(s, c) = -rho int q relative to f - Q > 0, which keeps its digits as the zone collapses at gross
//     sliding and is close to linear in u = log rho (rho int q ~ -kappa rho^k), so that Newton converges from a
//     zone far off in size; F_1 = `entry` (psi(-1)/|psi_0|, or q'(s) in the one-parameter limit); in (m, log rho);
//   - else the blend (8(g); 8(j) item 3): F = ((Q(zones) - Q)/f, E(zone_1), ..., E(zone_k), (xi_1 - xi_2)/f, ...,
//     (xi_{k-1} - xi_k)/f) in (m_i, rho_i), absolute (the blend's Q keeps f's scale: its zones do not collapse
//     onto a point); k = 1 the three zones of dissimilar rollers, k = 2 the five zones.
// Empty where Newton does not converge (the caller falls back or searches on), and where it stops at the ends'
// rounding beyond its cap, which it notes in `met` (the search refuses with it where no route answers).
// `kept`: a Jacobian carried from the last solve of a sequence (full coupling's alternation), damped_newton.hpp.
template <class Solution>
std::optional<Solution> ends_newton(const std::function<std::optional<Solution>(const std::vector<stick_span>&)>& solve,
                                    const std::function<double(const tangential_solution&)>& entry, double Q, double f,
                                    const std::vector<stick_span>& from, bool relative, int max_iterations,
                                    double tolerance, rounding_limits& met, newton_jacobian* kept = nullptr) {
    if (relative && !(f - Q > 0.0)) return std::nullopt;
    std::optional<Solution> last;  // the solve at the last zones, which are the root's
    const auto residual = [&](const std::vector<stick_span>& z) -> std::optional<std::vector<double>> {
        last = solve(z);
        if (!last) return std::nullopt;
        const std::vector<const tangential_solution*> systems = stick_systems(*last);
        std::vector<double> F;
        if (relative) {
            const double deficit = -z[0].rho * M_PI_2 * systems[0]->psi_b[0];
            if (!(deficit > 0.0)) return std::nullopt;  // this zone carries more than f: off the family
            F.push_back(std::log(deficit / (f - Q)));
        } else {
            F.push_back((last->Q - Q) / f);
        }
        for (const tangential_solution* t : systems) F.push_back(entry(*t));
        for (std::size_t i = 1; i < systems.size(); ++i) F.push_back((systems[i - 1]->xi - systems[i]->xi) / f);
        return F;
    };
    // The ends' rounding (damped_newton's stop at it): the systems' coefficients psi_b carry about eps/rcond of LU
    // (rcond the worst zone system's), which the entry conditions' sums psi(-1) = sum b_j U_j(-1) carry into the
    // ends. The five zones' steps at their floor, once Newton's contraction has ended: 0.004 to 0.17 times eps/rcond
    // (median 0.04 to 0.07) at n = 384, 512, 768 (free rolling of the pair, both coupling levels), 2e-11 to 3e-10 in
    // r, above the tolerance 1e-11 from n ~ 300 on, where Newton stopped below it only by chance (8(q)).
    const auto rounding = [&]() {
        double rcond = 1.0;
        for (const tangential_solution* t : stick_systems(*last)) rcond = std::min(rcond, t->rcond);
        return std::numeric_limits<double>::epsilon() / rcond;
    };
    const newton_result result = interval_newton(residual, from, relative, max_iterations, tolerance,
                                             relative ? std::function<double()>{} : rounding, kept);
    met.note(result, tolerance);
    const std::optional<newton_root>& root = result.root;
    if (!root || !last) return std::nullopt;
    last->iterations = root->iterations;  // the solution at the root, the last one solved
    // The ends are known to their rounding however Newton stopped: a last step below the tolerance beneath that floor
    // came by chance (8(q): from n ~ 300 on), and the root of the rounded equations still lies anywhere within it
    // (measured 0.004 to 0.17 of eps/rcond). So the resolution is at least eps/rcond, the rounding stop's own, which
    // the estimates take as their floor (newton_floor_excess): a level difference below it is not a convergence rate
    // (docs/formulation.md 8(j) "The ends' resolution").
    last->ends_resolution = relative ? root->resolution : std::max(root->resolution, rounding());
    return last;
}

}  // namespace roughroll
