// SPDX-License-Identifier: GPL-3.0-or-later
// The tangential problem with the zone structure found, not assumed (docs/formulation.md,
// sections 7 and 8(g)): one search, generic over the stick-zone operator (stick_zone_operator.hpp: the
// collocation of (4.4), the Glauert system of the one-parameter limit, the three zones of dissimilar
// rollers). The complementarity form of (3.2)-(3.4), for Q >= 0 (Q < 0 is the mirror):
//   stick zone:  v = xi - L1[p1] = 0,          |p1| <= f p                     (3.2), (3.3)
//   slip zone:   p1 = f p sgn v,               v != 0                          (3.4), (3.15)
//   int p1 = Q                                                                 (3.13)
// The structures solved:
//   - the paper's: stick [-1, c0], slip (c0, 1]: the operator's paper_zone, the fast path;
//   - slip [-1, s), stick [s, c0], slip (c0, 1]: the structure when the paper's zone would carry
//     |p1| > f p at its leading end (section 7(c), 7(g)), and every three-zone structure of dissimilar
//     rollers (8(g)). On the stick zone the operator's equation, plus its entry condition (psi(-1) = 0
//     of 7(b), v(s-) = 0 of 7(g)): the traction reaches the bound f p where material enters the stick zone;
//   - gross sliding |Q| = f (gross_sliding.hpp, 7(d)).
// (s, c0) solve Q(s, c0) = |Q| and E(s, c0) = 0 along the zones carrying |Q| (the family of 7(e), 7(g)):
// the paper's zone first where the structure has one (E <= 0 at s = -1 is the edge inequality), then
// near gross sliding the operator's model zone, then Newton from a coarse level's zone (kept where its
// checks hold), then a scan of trial starts and its brackets (the method's data). Other structures
// (several stick zones) are refused (resolution_error), and an answer of the wrong structure fails the
// checks (zone_checks.hpp); zones = "auto" then keeps the single zone.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "roughroll/problems/stick_zone_operator.hpp"
#include "roughroll/problems/tangential_problem.hpp"
#include "roughroll/problems/zone_start.hpp"

namespace roughroll {

class rounding_limits;         // zone_newton.hpp
struct newton_jacobian;        // damped_newton.hpp

// Newton in the ends of the operator's stick zones at the load Q (in the operator's frame) from `ends` (s_1, c_1, ...,
// s_k, c_k; an odd count is std::invalid_argument), for every zone search (ends_newton, zone_newton.hpp: the
// operator's systems, entry condition, residuals and tolerance); empty where it does not converge, its stop at the
// ends' rounding limit noted in `met`. `kept`: a Jacobian carried from the last solve of a sequence (full coupling's
// alternation).
std::optional<tangential_solution> zone_newton(const stick_zone_operator& op, double Q, const std::vector<double>& ends,
                                               rounding_limits& met, newton_jacobian* kept = nullptr);

// The stick-zone operator at a forcing (|beta_D|, or another on a continuation in beta_D/f; the one zone's ignores it).
using zone_operator_at = std::function<stick_zone_operator(double forcing)>;

// The zone search of every structure (docs/formulation.md 7(k)): `starts` tried in order (search_from), each in its
// operator's frame, at Q and `forcing` where a start names none. `ends`: Newton from them; `solved`: that root;
// `three_zones`: the operator's seed (a `holds` at Q ends the search, no root); each then continued along its path
// and in the load to Q, a failure past `shared_after` legs ending the search, its checks made at the end; `search`:
// the one stick zone's general search (zone_solver.cpp), its roots judged inside it. The first root whose checks
// hold answers, else the first found (first_holding); empty where none; rounding stops noted in `met`.
std::optional<tangential_solution> find_zones(const zone_operator_at& op_of, double Q, double forcing,
                                              const std::vector<zone_start<tangential_solution>>& starts,
                                              rounding_limits& met);

class zone_solver {
public:
    // The operator's functions refer to its solver, which must outlive this workspace.
    explicit zone_solver(stick_zone_operator op);

    // The solution of the complementarity problem for the load Q, |Q| <= f: the single zone
    // when its checks hold, else the general search. `force_general` runs the search in any
    // case (where the paper's structure holds it ends at start = -1, the single zone).
    // `ends`: the ends (s, c) of a zone near the one sought (the coarser level's layout, stick_ends), the start of a
    // Newton iteration (7(e)), as the five zones' (zone_start::at_ends); empty: none; another count: std::invalid_argument.
    // Where no zone of the search's structure carries the load (the scan of starts ends on no bracket of the
    // entry condition): a resolution_error with the operator's refusal (find's rounding_limit_error where a Newton of
    // the search stopped at the ends' rounding limit).
    tangential_solution solve(double Q, bool force_general = false, const std::vector<double>& ends = {});
    // The same search, "no zone of the structure" an empty result (a physical outcome the caller words); a
    // numerical fault on the way (a GSL status, a singular system) stays a numerical_error with its own line. Where
    // nothing is found and a Newton of the search stopped at the ends' rounding limit: a rounding_limit_error.
    std::optional<tangential_solution> find(double Q, bool force_general = false,
                                            const std::vector<double>& ends = {});
    // The same search as one route of a caller's larger one: where nothing is found, empty, the rounding limits its
    // Newton met noted in `met` (the caller tries its other routes, and refuses with them where none answers).
    std::optional<tangential_solution> find(double Q, bool force_general, const std::vector<double>& ends,
                                            rounding_limits& met);

    // psi(t = -1) of a collocation solution's stick zone: the coefficient of sqrt(1 + t) in q at its
    // start, the entry condition of 7(b).
    static double entry_coefficient(const tangential_solution& s);

private:
    stick_zone_operator op_;
};

}  // namespace roughroll
