// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/full_coupling.hpp"

#include <algorithm>
#include <array>
#include <cfloat>
#include <functional>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>

#include <gsl/gsl_math.h>

#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"
#include "roughroll/numerics/gauss_chebyshev.hpp"
#include "roughroll/numerics/gauss_jacobi.hpp"
#include "roughroll/problems/zone_newton.hpp"

namespace roughroll {

namespace {
// 8(v), "The cost": the Jacobi operator from the step whose source is this level's and whose ends moved by at most this
// (earlier steps, whose ends lag the source's by 1e-5, dip below the checks on that weight and send the zone search to
// the blended structure).
constexpr double settled_for_jacobi = 1e-6;
std::string coupling_at_load(double Q, double f) { return "full coupling at Q/f = " + shortest(Q / f) + ": "; }
}  // namespace

double coupling_value_floor(double lambda, double offset, double xi, double f, double normal_rcond,
                            double tangential_rcond) {
    const double rcond = std::min(normal_rcond, tangential_rcond);
    if (!(rcond > 0.0)) return 0.0;  // no condition known: the tolerance alone, as before
    const double scale =
        std::max({std::fabs(lambda), std::fabs(offset), std::fabs(xi) + f * std::max(1.0, std::fabs(lambda))});
    return 2.0 * DBL_EPSILON * scale / rcond;
}

// One step k of the alternation: p^(k) (solving (D1) with beta_D p1^(k-1)), its solver and zones
// workspace (the tangential solver keeps a reference to `normal`, so an iterate never moves: it
// is held by unique_ptr), and the point solved on them.
struct full_coupling::iterate {
    normal_solution normal;
    std::unique_ptr<tangential_solver> tangential;
    std::unique_ptr<dissimilar_zones> zones;
    tangential_solution s;
};

double coupled_layers_crossing(double beta_d, double f) {
    const double epsilon = std::log((1.0 - beta_d) / (1.0 + beta_d)) / (2.0 * M_PI);  // 8(p), "The fundamental function"
    return 2.0 / (1.0 + std::exp(std::atan(f) / std::fabs(epsilon)));
}

double coupling_fixed_point_distance(const coupling_summary& summary, double band, double step_rounding) {
    // From a coarser level's start the first change is the levels' difference, no step of this map (coupling_settled).
    return coupling_fixed_point_distance(summary.changes, summary.start_level > 0 ? 1 : 0, band, step_rounding);
}

double coupling_fixed_point_distance(const std::vector<double>& d, std::size_t own_from, double band,
                                     double step_rounding) {
    if (d.empty()) return std::numeric_limits<double>::infinity();
    double kappa = 0.5;
    bool read = false;
    for (std::size_t j = own_from + 1; j < d.size(); ++j)
        if (d[j] > band && d[j - 1] > band) {
            kappa = read ? std::max(kappa, d[j] / d[j - 1]) : d[j] / d[j - 1];
            read = true;
        }
    if (!(kappa < 1.0)) return std::numeric_limits<double>::infinity();
    // One step's rounding in all of (lambda, e, xi): the normal solve's bound, but a step is also G's assembly and the
    // tangential solve, whose rounding the changes within the band show (the driven pair at n = 256: 1.2e-14 then
    // 2.7e-14 under kappa <= 1/2 needs rho >= 1.05e-14, twice lambda's solve bound): at least the band.
    const double rho = std::max(step_rounding, band);
    return (kappa * d.back() + rho) / (1.0 - kappa);
}

bool coupling_settled(const std::vector<double>& changes, std::size_t own_from, double tolerance) {
    if (changes.empty()) return false;
    const std::size_t k = changes.size() - 1;
    if (changes[k] <= tolerance) return true;
    if (k < own_from + 1) return false;
    // 8(e), "The stop from the contraction": |x_k - x*| <= kappa/(1 - kappa) |x_k - x_{k-1}| for a map contracting by
    // kappa. kappa is the largest ratio of the level's own changes (one ratio can read low: they grow up to 3.5 times
    // within an alternation), trusted up to 1/2, and the bound asked within a quarter of the tolerance, so that a
    // constant up to 4 times the ratio read still leaves every number within about the tolerance.
    double kappa = 0.0;
    for (std::size_t j = own_from + 1; j <= k; ++j) {
        if (!(changes[j - 1] > 0.0)) return false;
        kappa = std::max(kappa, changes[j] / changes[j - 1]);
    }
    return kappa <= 0.5 && kappa / (1.0 - kappa) * changes[k] <= 0.25 * tolerance;
}

full_coupling::full_coupling(const kernel& k1, const kernel& k2, int n, method how, double f, double beta_d)
    : k1_(k1), k2_(k2), f_(f), beta_d_(beta_d), normal_solver_(n, how) {
    check_beta_d(beta_d);
    if (beta_d == 0.0)
        throw input_error("full coupling: beta_d = 0 is the uncoupled problem (docs/formulation.md 8(d))");
}

full_coupling::~full_coupling() = default;

const normal_solution& full_coupling::normal() const { return current_->normal; }
tangential_solver& full_coupling::tangential() { return *current_->tangential; }
dissimilar_zones& full_coupling::zones() { return *current_->zones; }

namespace {
// The tangential solve of one step: Newton from the previous iterate's ends on its structure
// (five zones by their four ends; else three zones or gross sliding by dissimilar_zones::solve,
// which tries the previous kind first), with the checks (3.3)-(3.4) of the answer made; full_coupling::solve
// acts on them (a point reported; a level of an estimate need not hold them, as at Johnson's level).
// `checked` false: five zones' checks are not made (docs/formulation.md 8(q), "The checks where they are read": no one
// reads a level's; s.checks not made: NaN margins); three zones' are (their search chooses by them).
// A structure the alternation cannot follow is a resolution_error (a curve's refused row), not a fault.
// `kept`: the five zones' Newton Jacobian from the last step (damped_newton.hpp).
tangential_solution step(dissimilar_zones& z, const tangential_solution& previous, double Q, double f,
                         newton_jacobian& kept, bool one_kind, bool checked) {
    tangential_solution t;
    if (previous.layout.stick_zones() == 2) {
        rounding_limits met;
        const auto v = z.five_zones(Q, previous.layout.stick_ends(), std::nullopt, &met, &kept, checked);
        if (!v && met.met()) throw rounding_limit_error(coupling_at_load(Q, f) + met.refusal());
        if (!v)
            throw resolution_error(coupling_at_load(Q, f) +
                                   "the five zones (slip, stick, reversed slip, stick, slip) are not found again "
                                   "from the previous step of the alternation at this n (docs/formulation.md 8(e), "
                                   "8(q)); another n may answer, and coupling = \"johnson\" answers the load");
        t = *v;
        t.Q = Q;
    } else {
        // With the weighted pressure (8(w)) the braked three zones' steps keep their own structure: the step that
        // switches the zone to its Jacobi weight lags by the square-root weight's error and fails the checks by
        // 1e-8..1e-6, which the search took as a reason to try every bracket and the blended zone (18-58 s of the
        // strong point at n = 64..256, 8(w) "Cost"); the checks are acted on at the converged iterate (solve).
        t = z.solve(Q, previous.layout.stick_ends(), previous.layout.opposite(),
                    one_kind && !previous.layout.opposite());
    }
    return t;
}

}  // namespace

std::string coupled_failure_cause(bool pressure) {
    return pressure ? "the coupling term beta_d p1 of the normal problem, of order beta_d f, outweighs the pressure at "
                      "this friction, so the contact would open: the load is beyond the coupled model "
                      "(docs/formulation.md 8(e))"
                    : "the zone structure changes under the coupling at this load, which the alternation from "
                      "Johnson's zones does not follow (docs/formulation.md 8(e))";
}

std::string coupled_failure_advice(bool pressure) {
    return pressure ? "coupling = \"johnson\" answers it without that term, an approximation of order beta_d f here"
                    : "coupling = \"johnson\" answers the load, and loads further from that change may answer at "
                      "full coupling";
}

std::string alternation_failure_advice() {
    return "coupling = \"johnson\" answers the load with the pressure uncoupled, an approximation of order beta_d f";
}

namespace {
// The refusal of a reported point whose coupled zones fail the checks (3.3)-(3.4): either the zone structure changes
// under the coupling (8(e)), or the discrete solution at this n misses them next to a zone end, where the exact
// slip velocity vanishes like (s - r)^(3/2) and the discrete one keeps a square-root residual of the entry condition
// whose sign is chance at a given n (free rolling of the pair at n = 32: 8(r)). The checks take no tolerance: the
// point is refused at this n, and the message says what may answer it.
failed_checks_error failed_checks(const tangential_solution& t, double Q, double f) {
    // The coupled pressure below zero: the term beta_D p1 of (D1), of order beta_D f, outweighs the load's
    // pressure (aluminium on steel at f = 1e6, gross sliding: margin -3.9e4), so the contact would open.
    if (!t.checks.pressure_holds)
        return failed_checks_error(coupling_at_load(Q, f) + "the coupled pressure turns negative (margin p " +
                                       shortest(t.checks.pressure_margin) + "): " + coupled_failure_cause(true) +
                                       "; " + coupled_failure_advice(true),
                                   t);
    return failed_checks_error(coupling_at_load(Q, f) + "the coupled zones fail the checks (3.3)-(3.4) (margins: " +
                                   margins_text(t.checks) + "): " + coupled_failure_cause(false) +
                                   ", or the discrete zones at this n miss the checks next to a zone end (8(r)); a "
                                   "larger n (--n, or none: the ladder's) may answer it; " +
                                   coupled_failure_advice(false),
                               t);
}

[[noreturn]] void not_converged(std::ostringstream& msg, const std::optional<failed_checks_error>& lagging) {
    // Without a failed check on the way a fault of this n, as always (numerical_error: no rung is tried after it).
    // With one, the cause is still the alternation: the margins are of an iterate that is no solution, so they are no
    // reason and settle nothing over the rungs (8(q) "A failure the levels settle" reads converged points' margins
    // only); the refusal says so, and a rung above is tried (8(q), "An alternation that converges at no level").
    if (!lagging) {
        msg << "; docs/formulation.md 8(e)); another n (--n, or none: the ladder's) may converge, and "
            << alternation_failure_advice();
        throw numerical_error(msg.str());
    }
    msg << ", its iterates failing the checks (3.3)-(3.4) on the way, margins: " << margins_text(lagging->checks())
        << "; docs/formulation.md 8(e), 8(q)); " << alternation_failure_advice()
        << ", and another n (--n, or none: the ladder's) may converge";
    throw alternation_error(msg.str());
}

// The zone ends of a point (the second zone's are 2 outside five zones).
std::vector<double> ends_of(const tangential_solution& s) { return {s.start(), s.c0(), s.start2(), s.end2()}; }

// The pressure's kinks at the zone ends of `s` carried explicitly (docs/formulation.md 8(l) step 0, 8(o)):
// p_q^0 = beta_D sqrt(1 - r^2) H[q/sqrt(1 - r^2)] from a stick zone's part q of p1 = sign (f p S + q), q =
// sqrt(1 - t^2) psi(t) on the zone (as tangential_solver::traction adds it), for the braked three zones (slip sigma on
// both sides, S = 1) and the driven three zones (S the blend of 8(g)), whose int p H and W (dissimilar_zones) take p_q^0
// (load_between; W's Cauchy part of p_q^0 H by Tricomi's identity beside the series' closed form, 8(o)). On the blended
// zone the blend's own (1 +- t)^(3/2) kinks join q too (8(r)): its part 2 f p (Theta - Theta_3) leaves the smoother
// Theta_3 on the right side; without it the entry converged at order 1 (8(r)). Rough rollers carry them on three zones
// (braked and driven) with the layer terms K2[p_q^0] on the normal right side and (K2 - K1)[p_q^0] in G (8(o), "Rough
// rollers"; pressure_kinks::add_layers). Null elsewhere, where the old right side beta_D p1 stays: gross sliding (q = 0,
// nothing to carry), rough rollers' five zones (measured in 8(o): free rolling of the rough pair cost 2.6 to 3.3 times
// the CPU with the kinks, and its levels' changes at n = 64, 128 were larger, not smaller) and smooth rollers' five
// zones, which are on the exact weight (weighted_kinks_of; 8(x)'s plateau on the square-root weight, kept for the
// driven pair's thin second zone until session 25, is gone: 8(z), "The driven five zones on the weight").
// The source of a step's kinks: the iterate whose point s gives q (its stick zones' psi) and whose pressure p the
// blends' kinks read (the same iterate as beta_D p1^(k-1), 8(l) step 0), with beta_D and f.
struct step_source {
    const tangential_solution& s;
    const normal_solution& normal;
    double beta_d, f;
};

// A stick zone whose q the kinks carry: strictly inside (-1, 1), with its series.
bool carries_q(const tangential_solution& z) {
    return z.c0() > z.start() && z.start() > -1.0 && z.c0() < 1.0 && !z.psi_b.empty();
}

// The blend's kinks 2 f p (Theta - Theta_3) of the stick zone [start, start + 2 rho] at t, with the sign of its rise
// (8(r)), p the source's pressure.
double blend_part(const step_source& from, double start, double rho, double rise, double t) {
    return rise * 2.0 * from.f * from.normal.pressure(start + rho * (t + 1.0)) * blend_kinks(t);
}

std::shared_ptr<const pressure_kinks> kinks_of(const step_source& from, const gauss_chebyshev& rule, const kernel& k1,
                                               const kernel& k2) {
    const tangential_solution& s = from.s;
    const double beta_d = from.beta_d;
    const bool smooth = k1.empty() && k2.empty();
    // Five zones: smooth rollers' on the exact weight (weighted_kinks_of), rough rollers' without kinks (below).
    if (s.layout.stick_zones() == 2) return nullptr;
    const auto layered = [&](std::shared_ptr<pressure_kinks> k) {
        if (!smooth) k->add_layers(k2, k1);
        return k;
    };
    if (s.layout.stick_zones() != 1 || !carries_q(s)) return nullptr;
    auto k = std::make_shared<pressure_kinks>();
    // The blended zone's right side 2 sign f p Theta (8(g)) has Theta's (1 +- t)^(3/2) kinks, which p's U-series
    // cannot carry and the entry condition weighs by (1 + t)^(-3/2) (order 1 at the entry): its part
    // 2 f p (Theta - Theta_3) joins q here, leaving the smoother blend Theta_3 on the right side (8(r)).
    k->add_zone(rule, beta_d, s.sign, s.start(), s.c0(), s.psi_b,
                s.layout.opposite() ? std::function<double(double)>([&from, start = s.start(), rho = 0.5 * (s.c0() - s.start())](
                                          double t) { return blend_part(from, start, rho, 1.0, t); })
                                    : std::function<double(double)>{});
    return layered(std::move(k));
}
// Plan C (docs/formulation.md 8(w)): the braked three zones of smooth rollers (one slip direction sigma at both edges,
// a + b = 1) take k_E = sigma beta_D f into the normal operator on the weight w_N, and carry p_q, the exact
// (H + k_E)^-1 of -beta_D q, from the source's stick zone (on its own weight: Jacobi from 8(v), else the square root).
// Null elsewhere (the old path of kinks_of). `rules_of`: the previous step's kinks, whose zone recurrences are reused;
// `rules`: the solve's Gauss-Jacobi rules, shared with the tangential solvers' Jacobi zones.
std::shared_ptr<pressure_kinks> weighted_kinks_of(const step_source& from, int n, bool smooth,
                                                  const pressure_kinks* rules_of, jacobi_rule_set& rules) {
    const tangential_solution& s = from.s;
    const double beta_d = from.beta_d, f = from.f;
    if (!smooth || s.layout.layers_neglected()) return nullptr;
    // 8(x), 8(z): five zones (slip-, stick, slip+, stick, slip-: the edges slip one way, sigma_E = -sign, p1 = sign (f p S
    // + q), S = -1 at both edges) on the exact weight w_k of (H + k) with 8(x)'s continuous k = sign beta_D f S_3 (S_3 the
    // smoothed S, k = k_E = sigma_E beta_D f at both edges), p_q summed over both stick zones, each from its q on the
    // square-root weight with the blend's kinks 2 f p (Theta - Theta_3) in it (8(r)): (D1) is solved whole, nothing on
    // its right side (no plateau, no remainder: 8(z), "Wired"). All five zones of smooth rollers, the driven pair's
    // thin second stick zone too (8(z), "The driven five zones on the weight", session 25).
    if (s.layout.stick_zones() == 2) {
        const tangential_solution &zone1 = s.zone_system(0), &zone2 = s.zone_system(1);
        // Each zone's q on the square-root weight (its U-series below), as the five zones' systems solve it.
        for (const tangential_solution* z : {&zone1, &zone2})
            if (!carries_q(*z) || z->weight_a > 0.0) return nullptr;
        auto k = std::make_shared<pressure_kinks>();
        k->set_weight(-s.sign * beta_d * f);
        std::array<std::function<double(double)>, 2> psi;
        int i = 0;
        for (const auto& [z, rise] : {std::pair<const tangential_solution*, double>{&zone1, 1.0}, {&zone2, -1.0}}) {
            const std::vector<double> c = z->psi_b;
            const double start = z->start(), rho = 0.5 * (z->c0() - z->start());
            psi[i++] = [c, &from, start, rho, rise](double t) {
                return u_series(c, t) + blend_part(from, start, rho, rise, t);
            };
        }
        k->set_variable(n, beta_d, s.sign, f, {zone1.start(), zone1.c0(), zone2.start(), zone2.c0()}, psi);
        return k;
    }
    if (s.layout.stick_zones() != 1 || s.layout.opposite() || !carries_q(s)) return nullptr;
    auto k = std::make_shared<pressure_kinks>();
    k->set_weight(s.sign * beta_d * f);
    if (s.weight_a > 0.0) {
        const std::vector<double> c = s.psi_b;
        const double a = s.weight_a, b = s.weight_b;
        k->add_weighted_zone(
            n, beta_d, s.sign, s.start(), s.c0(), a, [c, a, b](double t) { return jacobi_series(c, a, b, t); }, rules_of,
            &rules);
    } else {
        const std::vector<double> c = s.psi_b;
        k->add_weighted_zone(
            n, beta_d, s.sign, s.start(), s.c0(), 0.5, [c](double t) { return u_series(c, t); }, rules_of, &rules);
    }
    return k;
}
}  // namespace

namespace {
// 8(e), "The ends' rounding floor": the steps whose ends' changes must all lie within their floor at the step limit, so
// that the stop reads noise that persists, not a slow contraction passing through the floor.
constexpr std::size_t ends_floor_run = 5;

// 8(m), "Full coupling next to sliding": the gap below which the load's rounding eps f moves a braked stick zone's
// ends by a quarter of its half-width or more (eps rho/(2 (1 - |Q|/f)) against rho/4).
constexpr double braked_rounding_gap = 2.0 * DBL_EPSILON;

// The zone ends' largest change over the last three of the level's own steps is no smaller than over the three before:
// no contraction over two of the cycles seen near sliding (period three).
bool ends_cycle(const std::vector<double>& changes, std::size_t own_from) {
    if (changes.size() < own_from + 6) return false;
    const auto last = changes.end();
    return *std::max_element(last - 3, last) >= *std::max_element(last - 6, last - 3);
}

bool ends_within_floor(const std::vector<double>& changes, const std::vector<double>& floors, std::size_t own_from) {
    if (changes.size() < own_from + ends_floor_run) return false;
    for (std::size_t j = changes.size() - ends_floor_run; j < changes.size(); ++j)
        if (!(changes[j] <= floors[j])) return false;
    return true;
}
}  // namespace

// No fallback to another path where the alternation on the weight fails (8(x), "The fallback"): a level on another path
// than its rung's other levels would make their estimate compare two discretisations.
const tangential_solution& full_coupling::solve(const normal_solution& johnson, dissimilar_zones& johnson_zones,
                                                const tangential_solution& johnson_point, bool checked,
                                                const full_coupling* coarser) {
    const double Q = johnson_point.Q;
    current_.reset();
    previous_.reset();
    summary_ = coupling_summary{};
    summary_.lambda_johnson = johnson.lambda;
    did_not_converge_ = false;
    // The source of beta_D p1^(k) for normal solve k + 1: at k = 0 Johnson's point (its zones workspace
    // outlives this solve: the contact's) or the coarser level's converged iterate (8(e), "The start from
    // the coarser level": the same load, its p1 a function of r evaluated at this level's points), then the
    // current iterate.
    const iterate* start = coarser != nullptr && coarser->current_ && coarser->current_->s.Q == Q
                               ? coarser->current_.get()
                               : nullptr;
    dissimilar_zones* source_zones = start ? start->zones.get() : &johnson_zones;
    tangential_solution source = start ? start->s : johnson_point;
    double lambda = start ? start->normal.lambda : johnson.lambda, offset = start ? start->normal.offset : 0.0;
    if (start) summary_.start_level = start->normal.rule.n;
    // Newton's Jacobian in the zone ends: the coarser level's last one where it starts this alternation (the same
    // load, the same four unknowns, its ends this level's first step's start), else differenced afresh.
    jacobian_ = newton_jacobian{};
    if (start) jacobian_.J = coarser->jacobian_.J;
    double previous_change = 0.0;
    // Per step, the ends' rounding floor: the two iterates' Newton resolutions summed (8(e), "The ends' rounding floor").
    std::vector<double> end_floors;
    std::optional<failed_checks_error> lagging;  // a step's failed checks while its kinks lag (below)
    bool jacobi_on = false;                   // 8(v): once on, for the rest of the alternation
    int switched_at = 0;                      // the step that switched it on (0: none)
    // The Gauss-Jacobi rules of this solve (n and 4 n nodes, 8(v) and 8(w)): built once, read by every step's weighted
    // kinks and tangential solver (the same n and exponent), instead of once by each.
    const auto jacobi_rules = std::make_shared<jacobi_rule_set>();
    for (int k = 1; k <= coupling_max_iterations; ++k) {
        if (checkpoint_) checkpoint_();
        const double beta = beta_d_;
        std::function<double(double)> coupled = [source_zones, source, beta](double r) {
            return beta * source_zones->traction(source, r);
        };
        // 8(l) step 0: the kinks of p^(k) from q of p1^(k-1), the same iterate as beta_D p1^(k-1).
        const normal_solution& source_normal = current_ ? current_->normal : start ? start->normal : johnson;
        const step_source from{source, source_normal, beta, f_};
        std::shared_ptr<pressure_kinks> weighted =
            weighted_kinks_of(from, johnson.rule.n, k1_.empty() && k2_.empty(),
                              current_ ? current_->normal.kinks.get() : nullptr, *jacobi_rules);
        // The braked three zones (8(v), 8(w)) also put their stick zone on its Jacobi weight; five zones (8(x)) not.
        const bool braked = weighted && source.layout.stick_zones() == 1;
        const auto solve_step = [&](std::shared_ptr<const pressure_kinks> kinks) {
            auto it = std::make_unique<iterate>(iterate{
                weighted ? normal_solver_.solve_weighted(
                               coupled, [&source_normal](double r) { return source_normal.pressure(r); },
                               ends_of(source), weighted)
                         : normal_solver_.solve(k2_, coupled, ends_of(source), &sweeps_, kinks),
                nullptr, nullptr, {}});
            it->normal.how = johnson.how;
            // Rough rollers (8(o)): G = -L1[p] = (2/pi) lambda (r + e) + beta_D p1 + (K2 - K1)[p], whose part of
            // phi's series the tangential solver tabulates itself (convolution_table) and whose part of p_q^0 is the
            // kinks' own table.
            if (kinks && kinks->layered())
                it->normal.tangential_term = [coupled, kinks](double r) {
                    return coupled(r) + kinks->layer_difference(r);
                };
            it->tangential = std::make_unique<tangential_solver>(it->normal, k1_, k2_, f_, false);
            it->tangential->share_rules(jacobi_rules);
            if (current_ && current_->tangential) it->tangential->share_jacobi(*current_->tangential);
            // 8(v), adopted with 8(w): the braked three zones of smooth rollers (the weighted pressure's case) take the
            // local -k q into the operator on the Jacobi weight; G's k q of the source comes off their right side.
            // From the step whose source is this level's and whose ends moved by at most settled_for_jacobi, then kept.
            if (braked && !jacobi_on && current_ && !summary_.end_changes.empty() &&
                summary_.end_changes.back() <= settled_for_jacobi) {
                jacobi_on = true;
                switched_at = k;
            }
            if (braked && jacobi_on)
                it->tangential->couple_locally([source](double r) { return stick_traction(source, r); }, source.start(),
                                               source.c0());
            it->zones = std::make_unique<dissimilar_zones>(*it->tangential, k1_, beta_d_);
            it->s = step(*it->zones, source, Q, f_, jacobian_, braked, checked);
            return it;
        };
        std::unique_ptr<iterate> next;
        try {
            next = solve_step(weighted ? nullptr : kinks_of(from, johnson.rule, k1_, k2_));
        } catch (const std::exception&) {
            if (lagging) throw resolution_error(lagging->what());  // the first failure seen, as the old program refused
            throw;
        }
        // The checks of a reported point. With p_q^0 the step's pressure has its kinks at the source's zone
        // ends, not at the step's own: until the ends settle, the checks next to them see that lag (measured on the
        // five zones, whose margins are 1e-8 f: 8(o)), so they are acted on at the converged iterate, where the two sets
        // of ends agree to the alternation's tolerance; a failure on the way is the refusal if the alternation
        // stops otherwise. Without p_q^0 (rough rollers), at once, as before.
        if (checked && !next->s.checks.hold()) {
            if (!next->normal.kinks) throw failed_checks(next->s, Q, f_);
            if (!lagging) lagging = failed_checks(next->s, Q, f_);
        }

        // Iterate, then test: the changes of lambda, e, xi and the zone ends over this step.
        const double value_change =
            std::max({std::fabs(next->normal.lambda - lambda), std::fabs(next->normal.offset - offset),
                      std::fabs(next->s.xi - source.xi)});
        // At gross sliding (|Q| = f) there are no zone ends: start = c0 = r*, the least point of the
        // slip velocity (dissimilar_zones::gross_sliding), is found by golden section only to about
        // sqrt(eps) of a flat minimum (1e-8), so it is no test of the alternation; xi = -min v is.
        double end_change = 0.0;
        if (std::fabs(Q) != f_) {
            const std::vector<double> a = ends_of(next->s), b = ends_of(source);
            for (std::size_t i = 0; i < a.size(); ++i) end_change = std::max(end_change, std::fabs(a[i] - b[i]));
        }
        if (!(std::isfinite(value_change) && std::isfinite(end_change)) && lagging)
            throw resolution_error(lagging->what());
        if (!(std::isfinite(value_change) && std::isfinite(end_change)))
            throw numerical_error(coupling_at_load(Q, f_) + "the alternation gives a non-finite value at step " +
                                  std::to_string(k));
        // The values' rounding floor over this step (coupling_value_floor): changes within it need not fall (below).
        const double value_floor = coupling_value_floor(next->normal.lambda, next->normal.offset, next->s.xi, f_,
                                                        next->normal.rcond, next->s.rcond);
        // The ends' rounding floor over this step: each iterate's ends are its Newton root within the resolution it
        // reports (its rounding where that lies above zone_end_resolution: 8(e), "The root before the last step"),
        // so two iterates' ends differ by up to the sum as noise. Read only at the step limit (below).
        end_floors.push_back(next->s.ends_resolution + source.ends_resolution);
        summary_.changes.push_back(value_change);
        summary_.end_changes.push_back(end_change);
        summary_.newton_residuals = jacobian_.residuals;
        summary_.newton_jacobians = jacobian_.differenced;
        // The switching step's change is the two operators' difference, not a step of either map (8(e), "The stop
        // from the contraction"): no ratio is read across it.
        if (k > 2 && previous_change > 0.0 && (switched_at == 0 || k >= switched_at + 2))
            summary_.contraction = std::max(summary_.contraction, value_change / previous_change);

        // The iterate before the current one is no longer a source: cut its reference (its G is
        // never asked again; asking would be a bug, so it throws) and release it.
        if (current_)
            current_->normal.tangential_term = [](double) -> double {
                throw numerical_error("full coupling: a released iterate's G was asked for");
            };
        previous_ = std::move(current_);
        current_ = std::move(next);
        source_zones = current_->zones.get();
        source = current_->s;
        lambda = current_->normal.lambda;
        offset = current_->normal.offset;
        summary_.iterations = k;

        // The stop (8(e), "The stop from the contraction"): each group within its tolerance, by its last change or
        // by the contraction's bound on its distance to the fixed point; from a coarser start the first change is the
        // levels' difference, not a step of this level's map, so no ratio is read from it.
        // Likewise from the step that switches the stick zone onto its Jacobi weight (8(v)): the changes before and
        // at it are of the square-root map, whose fixed point is not this one's, so the history restarts after it.
        const std::size_t own_from = switched_at > 0 ? static_cast<std::size_t>(switched_at) : start ? 1 : 0;
        // A reported point stopped by the bound whose checks fail goes on: with p_q^0 its kinks lag its ends by the
        // last change (up to (1 - kappa)/kappa tolerances), and the plain rule's smaller lag is what the checks were
        // measured at (8(o)); so the bound never refuses where the plain rule would answer.
        const bool values_plain = value_change <= coupling_value_tolerance;
        const bool plain = values_plain && end_change <= coupling_end_tolerance;
        // A reported point (checked) whose iterate fails the checks (3.3)-(3.4): no stop but the plain rule's, and a
        // refusal where it stops.
        const bool fails_checks = checked && !current_->s.checks.hold();
        const bool contraction_stop = stop_ == coupling_stop::contraction && !fails_checks;
        const bool values_settled =
            values_plain || (contraction_stop && coupling_settled(summary_.changes, own_from, coupling_value_tolerance));
        const bool settled =
            plain || (values_settled && contraction_stop &&
                      coupling_settled(summary_.end_changes, own_from, coupling_end_tolerance));
        // From a coarser level, the first change is the two levels' difference, not the alternation's: at
        // least two steps, so that the point's G never refers to the coarser level's iterate.
        // Nor does a braked zone still on the square-root weight stop: its fixed point is not the Jacobi weight's, and
        // the next step switches (its ends moved by less than settled_for_jacobi).
        const bool may_stop = !(start && k == 1) && !(braked && !jacobi_on);
        const auto stop_here = [&]() -> const tangential_solution& {
            if (fails_checks) throw failed_checks(current_->s, Q, f_);
            summary_.offset = offset;
            summary_.peak_pressure_change =
                peak_of(current_->normal).p / peak_of(johnson).p * std::sqrt(johnson.lambda / current_->normal.lambda) -
                1.0;
            return current_->s;
        };
        if (settled && may_stop) return stop_here();
        // 8(e), "The ends' rounding floor": at the step limit, where the alternation would otherwise refuse, the values
        // settled and the ends' last changes all within their rounding floor (the iterates' Newton noise, which need
        // not fall below 1e-10: free rolling of the pair at f = 1e-4, n = 1000, changes 1.1e-10 .. 7.3e-10 over 40
        // steps against a floor of 7.9e-9) stop at the floor. Only there: every point that stops within the steps
        // stops where and as it did. The level's ends then lie within (kappa d + rho)/(1 - kappa) of the fixed point
        // (8(e), "The stop from the contraction", with one step's noise rho = the floor; kappa 1/2 where the changes
        // within the floor give no ratio: coupling_fixed_point_distance), which replaces their Newton resolution
        // where larger: the estimates read it (newton_floor_excess, 8(q) "The estimates' floor of the zone ends").
        // Ratios of 1 or more read above the floor give no bound: refused, as before.
        if (k == coupling_max_iterations && may_stop && values_settled && !fails_checks &&
            ends_within_floor(summary_.end_changes, end_floors, own_from)) {
            const double band = *std::max_element(end_floors.end() - ends_floor_run, end_floors.end());
            const double distance =
                coupling_fixed_point_distance(summary_.end_changes, own_from, band, current_->s.ends_resolution);
            if (std::isfinite(distance)) {
                current_->s.ends_resolution = std::max(current_->s.ends_resolution, distance);
                return stop_here();
            }
        }
        // 8(m), "Full coupling next to sliding": braked within 2 eps of sliding the load's rounding (eps f) moves the
        // thin stick zone's ends by up to eps rho/(2 (1 - |Q|/f)), a quarter of its half-width or more, drawn anew at every
        // step. Where the ends' changes over the last three steps are no smaller than over the three before (one ulp at
        // f = 0.05: c0 cycling by 6e-7 with period three, at every level, 40 steps each: 60 s CPU to the refusal below),
        // the alternation cannot settle them: refused at once. Only in that band, where points that settle (one ulp at
        // f = 0.3: changes falling from the first steps) stop as before.
        const double gap = 1.0 - std::fabs(Q) / f_;
        if (Q * beta_d_ < 0.0 && gap > 0.0 && gap < braked_rounding_gap && end_change > coupling_end_tolerance &&
            ends_cycle(summary_.end_changes, own_from)) {
            did_not_converge_ = true;
            std::ostringstream msg;
            msg.precision(2);
            msg << coupling_at_load(Q, f_) << "braked within rounding of sliding (1 - |Q|/f = " << gap
                << "), the zone ends change by " << end_change << " at step " << k
                << " and no less than three steps before: the load's rounding moves the thin stick zone's ends by up "
                   "to a quarter of its width, which the alternation cannot settle (docs/formulation.md 8(m)); "
                << alternation_failure_advice();
            throw beyond_method_error(msg.str());
        }
        // Growing changes after the first steps: the alternation does not contract here (changes
        // below the tolerance or the rounding floor are rounding, which need not fall; only the ends are then
        // unsettled).
        if (k > 3 && (switched_at == 0 || k > switched_at + 2) &&
            value_change > std::max(coupling_value_tolerance, value_floor) && value_change > previous_change &&
            previous_change > summary_.changes[k - 3]) {
            did_not_converge_ = true;
            std::ostringstream msg;
            msg.precision(3);
            msg << coupling_at_load(Q, f_) << "the alternation does not contract (changes " << summary_.changes[k - 3] << ", "
                << previous_change << ", " << value_change;
            not_converged(msg, lagging);
        }
        previous_change = value_change;
    }
    did_not_converge_ = true;
    std::ostringstream msg;
    msg.precision(3);
    msg << coupling_at_load(Q, f_) << "the alternation does not converge in " << coupling_max_iterations
        << " steps (last changes " << previous_change << " in lambda, e, xi against " << coupling_value_tolerance
        << ", " << summary_.end_changes.back() << " in the zone ends against " << coupling_end_tolerance;
    // Their Newton rounding where it lies above the tolerance (8(e), "The ends' rounding floor"): not the stop's reason.
    if (end_floors.back() > coupling_end_tolerance) msg << " and their rounding " << end_floors.back();
    not_converged(msg, lagging);
}

}  // namespace roughroll
