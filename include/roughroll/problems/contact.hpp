// One scene's rolling contact: the normal problem solved once (Hertz's closed form
// when the normal kernel is empty) and shared by every creep point of a curve.
//
// With method::extrapolated the contact holds two product-integration levels, n and n/2,
// and reports P_H/P2, c0 and xi by Richardson's rule for order 4, (16 v_n - v_{n/2})/15;
// the distributions (pressure, tractions, checks) are those of level n.
//
// The zones of each point are found as options.zones says (zone_search, docs/formulation.md
// section 7): the paper's single zone, and zone_solver's general search where it fails its
// checks (automatic) or always (general). Both levels of an extrapolation take the same path;
// a point of the general path (start > -1) is reported at level n, not extrapolated, with
// the difference from n/2 as its estimate.
//
// With method::one_parameter the contact solves the limit t -> 0 of the model instead
// (one_parameter_solver, docs/formulation.md "The one-parameter limit"): same solutions,
// same conventions, no two-parameter tangential solver.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "roughroll/model/carter.hpp"
#include "roughroll/problems/normal_problem.hpp"
#include "roughroll/problems/one_parameter.hpp"
#include "roughroll/model/roughness.hpp"
#include "roughroll/numerics/method.hpp"
#include "roughroll/problems/tangential_problem.hpp"
#include "roughroll/problems/zone_solver.hpp"

namespace roughroll {

// The difference between a point at n and the same point at n/2, per quantity. For a method
// of order p it exceeds the error at n by about 2^p - 1 once n is in the asymptotic range
// (a conservative estimate); docs/performance.md checks it against finer solutions. Where
// n/2 is below min_nodes or cannot resolve the kernel, the companion is 2n, and the
// difference is then about the error at n itself.
struct error_estimate {
    double lambda;        // P_H/P2
    double c0;            // 0 for a point of a curve swept in c0 (c0 is then the input)
    double xi;
    double Q;             // 0 for a point at a given Q (Q is then the input)
    const char* against;  // "n/2", "2n (doubled)" or "level n" (extrapolated)
};

class contact {
public:
    contact(const roughness& surfaces, double f, const solver_options& options);

    // The normal solution as reported (lambda extrapolated for method::extrapolated).
    const normal_solution& normal() const;
    // The two-parameter tangential solver; for method::one_parameter there is none: throws
    // input_error (use traction() and slip_velocity() below, which serve every method).
    tangential_solver& tangential();
    double friction() const { return f_; }

    tangential_solution point(double Q);

    // The solution whose distributions (tractions, slip velocity) belong with s: s itself,
    // or for method::extrapolated the level-n solution at the same Q, whose c0 and xi are
    // level n's (within the error estimate of the extrapolated ones).
    tangential_solution distribution(const tangential_solution& s);

    // The point whose stick zone ends at c0 in [-1, 1], Q = Q(c0) of (4.5): no root search,
    // a creep curve swept in c0. With its estimate (same companion rules as estimate()).
    struct swept_point {
        tangential_solution solution;
        std::optional<error_estimate> estimate;
    };
    swept_point at_stick_end(double c0);

    // The estimate for a solution s of this contact (solves the companion problem once,
    // lazily). Empty when neither n/2 nor 2n is available.
    std::optional<error_estimate> estimate(const tangential_solution& s);

    // p1(r) of (3.15) and the slip velocity v(r) of (3.6) (0 on the stick zone) for a
    // solution d of this contact as returned by distribution(), for every method.
    double traction(const tangential_solution& d, double r);
    double slip_velocity(const tangential_solution& d, double r);
    std::vector<double> slip_velocity(const tangential_solution& d, const std::vector<double>& r);

private:
    // The solution at c0 of this contact's own level (no extrapolation, no estimate).
    tangential_solution level_at_stick_end(double c0, bool checked);
    // The point at Q of this contact's own level, its zones found as options_.zones says, or by
    // the general search when `general`; `coarse`: the coarse level's point, for the guesses.
    tangential_solution level_point(double Q, const tangential_solution* coarse, bool general);
    bool ensure_companion();  // the companion of estimate(): n/2 or 2n; false when neither exists
    // The estimate from s and the companion's solution c at the same Q (or the same c0, swept).
    error_estimate companion_difference(const tangential_solution& s, const tangential_solution& c,
                                        bool swept) const;

    roughness surfaces_;
    solver_options options_;
    std::unique_ptr<contact> companion_;  // at n/2, or 2n; the coarse level when extrapolating
    double f_;
    std::unique_ptr<normal_solution> normal_;  // owned here, referenced by the solver
    std::unique_ptr<normal_solution> reported_;  // extrapolated lambda, or empty
    std::unique_ptr<tangential_solver> tangential_;
    std::unique_ptr<zone_solver> zones_;  // the general search, on tangential_
    std::unique_ptr<one_parameter_solver> limit_;  // method::one_parameter: the only solver
    std::optional<tangential_solution> last_fine_;  // level n of the last extrapolated point
    std::optional<tangential_solution> last_coarse_;  // level n/2 of the last general-path point
};

// P_H/P2 alone, exactly as contact(surfaces, f, options).normal().lambda reports it (the same
// calls, the same extrapolation), for every method, without the tangential solver: for a
// root search in the contact width. The extrapolated method's asymptotic-range condition is
// checked on the normal kernel only (the tangential kernel does not enter P_H/P2).
double load_ratio(const roughness& surfaces, const solver_options& options);

// One row of a creep curve.
struct curve_point {
    tangential_solution solution;
    carter_point smooth;                      // Carter's curve at the same Q
    std::optional<error_estimate> estimate;  // against n/2
};

// Q/f = 1 - (1 - u)^2 for u uniform on [0, 1]: `points` loads from 0 to f, dense
// near Q = f where the creep curve steepens (there xi ~ sqrt(1 - Q/f)).
std::vector<double> curve_loads(int points, double f);

std::vector<curve_point> creep_curve(contact& c, const std::vector<double>& loads);

// A creep curve swept in c0 from 1 to -1 (rho = (1 + c0)/2 uniform): one linear solve per
// point, no root search; the loads are Q(c0), dense near f as in curve_loads.
std::vector<curve_point> swept_curve(contact& c, int points);

}  // namespace roughroll
