// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/contact.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>

#include "roughroll/numerics/collocation.hpp"
#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"
#include "roughroll/problems/dissimilar_zones.hpp"
#include "roughroll/problems/edge_layers.hpp"

namespace roughroll {

namespace {
// Free rolling of smooth dissimilar rollers at Johnson's level (docs/formulation.md 8(n)): the largest
// relative estimate of the layers-neglected point, as the ladder compares them: the bound of its xi
// relative to the no-slip creep, and the bounds of the main stick zone's ends (relative to the
// half-width); none for any other pair or level.
std::optional<double> layers_relative_bound(const dissimilar& materials, const roughness& surfaces, double f) {
    if (materials.beta_d == 0.0 || materials.coupling == coupling_level::full || !kernel::normal(surfaces).empty() ||
        !kernel::tangential(surfaces).empty())
        return std::nullopt;
    const neglected_layers layers = no_slip_layers(materials.beta_d, f);
    return std::max({layers.xi_bound / std::fabs(no_slip_creep(materials.beta_d)), layers.leading_bound,
                     layers.trailing_bound});
}
}  // namespace

contact::contact(const roughness& surfaces, double f, const solver_options& options, const dissimilar& materials,
                 normal_cache* cache)
    : surfaces_(surfaces), options_(options), f_(f), materials_(materials) {
    if (!(std::isfinite(f) && f > 0.0)) throw input_error("friction coefficient f must be positive and finite");
    check_dissimilar(materials, options);
    free_rolling_layers_ = layers_relative_bound(materials, surfaces, f);
    const int n = options.nodes();
    if (options.how == method::one_parameter) {
        limit_ = std::make_unique<one_parameter_solver>(surfaces, f, n);
        limit_zones_ = std::make_unique<zone_solver>(limit_->zone_operator());
        return;
    }
    const bool extrapolate = options.how == method::extrapolated &&
                             !(kernel::normal(surfaces).empty() && kernel::tangential(surfaces).empty());
    if (extrapolate) {
        // Richardson's rule holds only where the error already falls like n^-4.
        check_extrapolation_range(widest_kernel(), n, "these kernels");
        companion_ = std::make_unique<contact>(surfaces, f, solver_options{n / 2, method::product, options.zones},
                                               materials, cache);
    }
    normal_ =
        std::make_unique<normal_solution>(solve_normal(kernel::normal(surfaces), n, level_of(options.how), cache));
    normal_->how = options.how;  // a smooth scene under 'extrapolated' is exact at one level
    if (extrapolate) {
        reported_ = std::make_unique<normal_solution>(*normal_);
        reported_->lambda = richardson(normal_->lambda, companion_->normal().lambda);
    }
    tangential_ =
        std::make_unique<tangential_solver>(*normal_, kernel::tangential(surfaces), kernel::normal(surfaces), f);
    zones_ = std::make_unique<zone_solver>(tangential_->zone_operator());
    if (materials.beta_d != 0.0)
        dissimilar_ = std::make_unique<dissimilar_zones>(*tangential_, kernel::tangential(surfaces), materials.beta_d);
    if (materials.beta_d != 0.0 && materials.coupling == coupling_level::full)
        coupled_ = std::make_unique<full_coupling>(kernel::tangential(surfaces), kernel::normal(surfaces), n,
                                                   level_of(options.how), f, materials.beta_d);
}

void contact::set_checkpoint(std::function<void()> hook) {
    checkpoint_ = std::move(hook);
    for (contact* c : {companion_.get(), finer_.get()})
        if (c) c->set_checkpoint(checkpoint_);
    for (const auto& c : owned_levels_) c->set_checkpoint(checkpoint_);
    if (coupled_) coupled_->set_checkpoint(checkpoint_);
}

const normal_solution& contact::normal_level() const {
    if (coupled_load_) return coupled_->normal();
    return limit_ ? limit_->normal() : *normal_;
}

const normal_solution& contact::normal() const {
    if (limit_) return limit_->normal();
    if (coupled_load_) return coupled_->normal();  // level n, not extrapolated (docs/formulation.md 8(e))
    return reported_ ? *reported_ : *normal_;
}

tangential_solver& contact::tangential() {
    if (!tangential_)
        throw input_error(
            "method 'one-parameter' has no two-parameter tangential solver: use contact::traction and "
            "contact::slip_velocity");
    return *tangential_;
}

tangential_solution contact::general_point(double Q, std::optional<zone_guess> guess) {
    checkpoint();
    if (limit_zones_) return limit_zones_->solve(Q, true);
    return zones_->solve(Q, true, guess);
}

tangential_solution contact::zones_for(double Q, tangential_solution s, const tangential_solution* coarse) {
    const auto guess = coarse ? std::optional<zone_guess>({coarse->start(), coarse->c0()}) : std::nullopt;
    if (options_.zones == zone_search::general) return general_point(Q, guess);
    if (options_.zones == zone_search::single || s.checks.hold()) return s;
    // A structure the general search does not cover (no root, or its answer fails the checks
    // too): the single zone, its checks failed.
    try {
        tangential_solution g = general_point(Q, guess);
        return g.checks.hold() ? g : s;
    } catch (const resolution_error&) {  // no zone of the general structure (zone_solver.hpp)
        return s;
    } catch (const numerical_error&) {
        return s;
    }
}

tangential_solution contact::point(double Q) {
    if (dissimilar_) return dissimilar_point(Q);
    // Each level's root search starts from the root of the level below: n/4 (the estimate's
    // coarsest level, solved here anyway) from Carter's c0, n/2 from n/4's root, n from n/2's,
    // with a Newton step on the slope of the level below.
    std::optional<double> start, start_slope, quarter_c0;
    // Level n starts from its own c0 as the levels n/4 and n/2 predict it, c0_n = c0_{n/2} +
    // (c0_{n/2} - c0_{n/4})/2^p where the error falls as n^-p (Richardson's rule, (4.6)): within
    // ~1e-10 instead of the ~1e-8 of c0_{n/2}, so that the Newton step on the slope of n/2 lands
    // within the search's 1e-15 and level n costs two solves, not three. Only the start: the
    // secant from it converges to the same root either way (stick_end_for_load).
    const auto predicted_start = [this](std::optional<double> quarter, double half) -> std::optional<double> {
        if (!quarter || !(half > -1.0 && half < 1.0)) return half;
        const double predicted = half + (half - *quarter) / std::ldexp(1.0, level_method() == method::product ? 4 : 2);
        return predicted > -1.0 && predicted < 1.0 ? predicted : half;
    };
    // (Not for the one-parameter limit: its search is cheap, and contact::point is its solve.)
    const bool below = !limit_ && build_levels() && levels_[0] && levels_[1] && !levels_[2];
    if (below) {
        try {
            const tangential_solution& quarter = levels_[0]->level_point(Q, false);
            const tangential_solution& half =
                reported_ ? quarter : levels_[1]->level_point(Q, false, quarter.c0(), quarter.load_slope);
            start = half.c0();
            start_slope = half.load_slope;
            if (quarter.c0() > -1.0 && quarter.c0() < 1.0) quarter_c0 = quarter.c0();
            if (!reported_) start = predicted_start(quarter_c0, half.c0());
        } catch (const error&) {  // the estimate will say why; the search goes without a start
        }
    }
    if (!reported_) {
        if (limit_ && options_.zones != zone_search::single) {
            // The one-parameter paper's zone can be singular where the general zone is not (its
            // c0 tends to -1 near gross sliding when eps2 > eps1, docs/formulation.md 7(g)).
            try {
                return zones_for(Q, level_point(Q, true, start, start_slope), nullptr);
            } catch (const numerical_error&) {
                return general_point(Q);
            }
        }
        return zones_for(Q, level_point(Q, true, start, start_slope), nullptr);
    }
    tangential_solution coarse = companion_->level_point(Q, false, start, start_slope);
    tangential_solution s =
        zones_for(Q, tangential_->solve(Q, predicted_start(quarter_c0, coarse.c0()), true, coarse.load_slope), &coarse);
    // Both levels on the same path: the coarse level's zones by the general search too.
    if (s.layout.general()) coarse = companion_->general_point(Q, zone_guess{s.start(), s.c0()});
    last_fine_ = s;
    if (s.layout.general()) {
        // The general path is not extrapolated: its zone ends do not yet converge at a clean
        // n^-4 at the default n (docs/formulation.md 7(e)). Level n, estimated against n/2.
        last_coarse_ = coarse;
        // Refused where the fast path's extrapolation is: a creep at the edge of the double range.
        if (!std::isfinite(richardson(s.xi, coarse.xi)))
            throw numerical_error("extrapolation: the creep is not finite (roughness parameters too large?)");
        return s;
    }
    s.layout = one_stick_zone(s.start(), richardson(s.c0(), coarse.c0()), s.layout.route,
                              s.sign < 0.0 ? -1 : 1);  // the paper's zone, extrapolated
    s.xi = richardson(s.xi, coarse.xi);
    if (!(std::isfinite(s.c0()) && std::isfinite(s.xi)))
        throw numerical_error("extrapolation: the creep is not finite (roughness parameters too large?)");
    return s;
}

const tangential_solution& contact::level_point(double Q, bool checked, std::optional<double> guess,
                                                std::optional<double> slope) {
    checkpoint();
    if (!last_level_point_ || !(last_level_point_->Q == Q) || (checked && !last_level_point_checked_)) {
        last_level_point_ = limit_ ? limit_->solve(Q, guess) : tangential_->solve(Q, guess, checked, slope);
        last_level_point_checked_ = checked || limit_;
    }
    return *last_level_point_;
}

method contact::level_method() const { return level_of(options_.how); }

kernel contact::widest_kernel() const {
    const double rate = std::max(kernel::normal(surfaces_).max_rate(), kernel::tangential(surfaces_).max_rate());
    return kernel(std::vector<exponential_term>{{1.0, rate}});
}

tangential_solution contact::distribution(const tangential_solution& s) {
    if (!reported_ || dissimilar_) return s;  // a dissimilar point is level n itself
    if (!last_fine_ || last_fine_->Q != s.Q)
        last_fine_ = s.layout.general() ? general_point(s.Q, zone_guess{s.start(), s.c0()}) : tangential_->solve(s.Q);
    return *last_fine_;
}

const tangential_solution& contact::dissimilar_level_point(double Q, std::optional<zone_guess> guess, bool opposite) {
    checkpoint();
    if (!last_dissimilar_ || !(last_dissimilar_->Q == Q)) last_dissimilar_ = dissimilar_->solve(Q, guess, opposite);
    return *last_dissimilar_;
}

const coupling_summary* contact::coupling() const { return coupled_load_ ? &coupled_->summary() : nullptr; }

dissimilar_zones& contact::zones_of_point() { return coupled_load_ ? coupled_->zones() : *dissimilar_; }

namespace {
// The advice of a refusal of such a point: the tolerance (two digits, rounded up) at which its layers
// would be neglected, and which of the route's estimates sets it; empty where the bound is no use
// (half of xi or more).
std::string layers_tolerance_advice(double relative, double beta_d, double f) {
    if (!(relative < 0.5)) return {};
    const double unit = std::pow(10.0, std::floor(std::log10(relative)) - 1.0);
    const std::string up = significant(std::ceil(relative / unit) * unit, 2);
    const neglected_layers layers = no_slip_layers(beta_d, f);
    const bool ends =
        std::max(layers.leading_bound, layers.trailing_bound) * std::fabs(no_slip_creep(beta_d)) > layers.xi_bound;
    return std::string("a tolerance of ") + up +
           " or more (solver.tolerance, --tolerance; n not given) answers this free rolling with its edge layers "
           "neglected (docs/formulation.md 8(n)" +
           (ends ? ": the creep within a smaller one, the zone ends set it" : "") + ")";
}

// The relative change of the five zones' leading layer 1 + s1 between levels n/2 and n, bounded below
// (docs/formulation.md 8(n), "Beyond every n"): at Q = 0 the layers scale with t_c and sit at the
// main zone's ends, where the collocation's nodes are spaced as 1/n^2, so the change is a function of
// x = t_c n^2 alone, measured 3 exp(-0.57 sqrt(x)) to within 10 % for x from 36 to 555 (and larger
// below 36); a tenth of it, and nothing beyond the measured range.
constexpr double layer_change_measured_to = 555.0;
double layer_change_lower_bound(double x) {
    return x <= layer_change_measured_to ? 0.3 * std::exp(-0.57 * std::sqrt(x)) : 0.0;
}
}  // namespace

std::optional<std::string> contact::beyond_every_n(double Q, int top, double tolerance) const {
    // Free rolling of smooth rollers at Johnson's level whose layers the tolerance does not neglect:
    // the estimate at n is at least the change of 1 + s1 from n/2 (numerics/error_bound.hpp), which
    // the ladder compares with tolerance (1 + s1); no rung n <= top meets it where the top one does not.
    if (!dissimilar_) return std::nullopt;  // beta_D = 0: the paper's problem, no edge layers
    const std::optional<double> bound = layers_bound(Q);
    if (!bound || *bound <= tolerance) return std::nullopt;
    if (level_method() != method::product) return std::nullopt;  // the law was measured on product integration
    const double crossing = no_slip_layers(materials_.beta_d, f_).crossing;
    const double x = crossing * top * top;
    const double change = layer_change_lower_bound(x);
    if (!(change > tolerance)) return std::nullopt;
    std::ostringstream msg;
    msg.precision(2);
    msg << "no n up to " << top << " meets the tolerance " << shortest(tolerance)
        << " (relative) for free rolling of these rollers at f = " << shortest(f_) << ": its edge layers, about "
        << crossing << " of the half-width, are too thin (at n = " << top
        << " the five zones' leading layer still changes by more than " << change
        << " of itself from n = " << top / 2 << ", docs/formulation.md 8(n))";
    const std::string advice = layers_tolerance_advice(*bound, materials_.beta_d, f_);
    if (!advice.empty()) msg << "; " << advice;
    return msg.str();
}

bool contact::layers_negligible(double Q) const {
    // Layers that move xi, and the zone ends, by less than the tolerance: the no-slip solution with them
    // neglected answers.
    const std::optional<double> relative = layers_bound(Q);
    return relative && *relative <= options_.tolerance.value_or(default_tolerance);
}

tangential_solution contact::dissimilar_point(double Q) {
    if (layers_negligible(Q)) return dissimilar_->layers_neglected_point();
    try {
        // Edge zones far below what the search finds (|beta_D| small against f): refused before any solve.
        check_edge_zones_resolvable(materials_.beta_d, f_, Q, nodes());
        const tangential_solution johnson = johnson_point(Q);
        if (!coupled_) return johnson;
        return coupled_level_point(Q, johnson, true);
    } catch (const resolution_error& why) {
        // Free rolling of smooth rollers whose layers are too thin for n but too thick for the tolerance
        // (docs/formulation.md 8(n)): the tolerance at which they would be neglected.
        const std::optional<double> bound = layers_bound(Q);
        const std::string advice = bound ? layers_tolerance_advice(*bound, materials_.beta_d, f_) : std::string();
        if (advice.empty()) throw;
        throw resolution_error(std::string(why.what()) + "; " + advice);
    }
}

tangential_solution contact::johnson_level_point(double Q, const tangential_solution& near) {
    if (near.layout.stick_zones() != 2)
        return dissimilar_level_point(Q, zone_guess{near.start(), near.c0()}, near.layout.opposite());
    const std::vector<double> ends{near.start(), near.c0(), near.start2(), near.end2()};
    const five_zone_solution* v = five_level_point(Q, &ends);
    if (v == nullptr)
        throw resolution_error("dissimilar rollers at n = " + std::to_string(nodes()) +
                               ": no five zones at Q = " + shortest(Q) +
                               " from the neighbouring level's zones (the five zones change "
                               "between levels); another n may find them");
    tangential_solution t = five_zone_point(*v);
    t.Q = Q;
    return t;
}

const tangential_solution& contact::coupled_level_point(double Q, const tangential_solution& johnson, bool checked) {
    checkpoint();
    if (coupled_load_ && *coupled_load_ == Q && (coupled_checked_ || !checked)) return coupled_point_;
    coupled_load_.reset();  // Johnson's pressure and zones until the alternation has converged
    coupled_point_ = coupled_->solve(*normal_, *dissimilar_, johnson, checked);
    coupled_load_ = Q;
    coupled_checked_ = checked;
    return coupled_point_;
}

tangential_solution contact::johnson_point(double Q) {
    // The estimate's levels below this one first, coarsest first, each from the zone of the level
    // below (Newton), so that only the coarsest scans the starts of the stick zone.
    std::optional<zone_guess> guess;
    bool opposite = false;
    if (build_levels()) {
        for (contact* level : levels_) {
            if (level == nullptr) break;
            try {
                const tangential_solution& t = level->dissimilar_level_point(Q, guess, opposite);
                guess = zone_guess{t.start(), t.c0()};
                opposite = t.layout.opposite();
            } catch (const resolution_error&) {  // no three zones on this level: the next searches without a guess
                guess.reset();
            } catch (const numerical_error&) {
                guess.reset();
            }
        }
    }
    // Free rolling, no three zones, or three zones that fail (3.3)-(3.4) (resolution_error), or a
    // numerical fault of their search: five zones (|Q| < f; on the braked side, Q/sgn(beta_D) < 0,
    // until the slip+ zone closes, 8(j) 4a). Where none are found either, the first error stands:
    // a fault aborts; a structure not found at this n is a refusal (a curve's refused row,
    // docs/robustness.md), saying so.
    const auto five_or = [&](const error& why) -> tangential_solution {
        if (!(std::fabs(Q) < f_)) throw;
        std::vector<double> ends;
        if (build_levels())
            for (contact* level : levels_) {
                if (level == nullptr) break;
                const five_zone_solution* v = level->five_level_point(Q, ends.empty() ? nullptr : &ends);
                ends = v ? std::vector<double>{v->s1, v->c1, v->s2, v->c2} : std::vector<double>{};
            }
        const five_zone_solution* v = five_level_point(Q, ends.empty() ? nullptr : &ends);
        if (v == nullptr) {
            if (dynamic_cast<const resolution_error*>(&why) == nullptr) throw;
            throw resolution_error(std::string(why.what()) +
                                   "; no five zones (slip, stick, reversed slip, stick, "
                                   "slip) are found at n = " +
                                   std::to_string(nodes()) +
                                   " either (their search starts from the coarser levels' zones): another n may "
                                   "find them, except on the driven side closer than Q/f = 0.998 to gross sliding, "
                                   "which no n reaches yet (docs/robustness.md)");
        }
        tangential_solution s = five_zone_point(*v);
        s.Q = Q;  // the load asked for; Newton's solved load differs by its residual (1e-17 at Q = 0)
        // Failing checks on a converged root: zones thinner than n resolves (f = 0.3 for aluminium
        // on steel at n = 32, 8(j) 4a), or Newton from under-resolved coarser ends landing on another
        // root (f = 0.425..0.5 at n = 1000, 8(n) "Beyond every n"); a resolution_error either way (a
        // curve's row is refused, not the curve).
        if (!s.checks.hold())
            throw resolution_error("dissimilar rollers at Q/f = " + shortest(Q / f_) +
                                   ": the five zones (slip, stick, reversed slip, stick, slip) fail the checks "
                                   "(3.3)-(3.4) (margins: stick " +
                                   shortest(s.checks.stick_margin) + ", slip " + shortest(s.checks.slip_margin) +
                                   "): a zone is below the collocation's resolution "
                                   "at n = " +
                                   std::to_string(nodes()) +
                                   ", or the search from the coarser levels' zones found other five zones than the "
                                   "physical ones (docs/formulation.md 8(j), 8(n)); " +
                                   (nodes() < max_nodes
                                        ? "a larger n (at most " + std::to_string(max_nodes) + ") may resolve it"
                                        : "n is at its largest, so this load is beyond the method's reach"));
        return s;
    };
    try {
        tangential_solution s = dissimilar_level_point(Q, guess, opposite);
        require_checks(s);  // a point reported holds (3.3)-(3.4); a level of its estimate need not
        return s;
    } catch (const resolution_error& why) {
        return five_or(why);
    } catch (const numerical_error& why) {
        return five_or(why);
    }
}

const five_zone_solution* contact::five_level_point(double Q, const std::vector<double>* ends) {
    checkpoint();
    if (last_five_ && last_five_load_ == Q) return &*last_five_;
    std::optional<five_zone_solution> v;
    try {
        // From the coarser level's ends first (Newton, as the three-zone levels), else from the
        // three zones of 8(j) item 4 and the continuation in Q (dissimilar_zones::five_zones).
        // On a curve, the previous row's five zones continued in the load come next (a start only:
        // the root is the same to Newton's tolerance, validation/test_dissimilar_curve.cpp).
        if (ends) v = dissimilar_->five_zones(Q, *ends);
        if (!v && last_five_) v = dissimilar_->five_zones_from(Q, *last_five_);
        if (!v) v = dissimilar_->five_zones(Q);
    } catch (const numerical_error&) {
        v.reset();  // no five zones found on this level
    }
    if (!v) return nullptr;
    last_five_ = v;
    last_five_load_ = Q;
    return &*last_five_;
}

double contact::traction(const tangential_solution& d, double r) {
    if (dissimilar_) return zones_of_point().traction(d, r);  // either structure of 8(g)
    return limit_ ? limit_->traction(d, r) : tangential_->traction(d, r);
}

double contact::slip_velocity(const tangential_solution& d, double r) {
    if (dissimilar_) return zones_of_point().slip_velocity(d, r);
    return limit_ ? limit_->slip_velocity(d, r) : tangential_->slip_velocity(d, r);
}

std::vector<double> contact::slip_velocity(const tangential_solution& d, const std::vector<double>& r) {
    if (dissimilar_ && (d.layout.opposite() || d.layout.layers_neglected())) {
        std::vector<double> v(r.size());
        for (std::size_t i = 0; i < r.size(); ++i) v[i] = zones_of_point().slip_velocity(d, r[i]);
        return v;
    }
    if (!limit_) return (coupled_load_ ? coupled_->tangential() : *tangential_).slip_velocity(d, r);
    std::vector<double> v(r.size());
    for (std::size_t i = 0; i < r.size(); ++i) v[i] = limit_->slip_velocity(d, r[i]);
    return v;
}

std::vector<contact::distribution_row> contact::distributions(const tangential_solution& d,
                                                              const std::vector<double>& grid) {
    const std::vector<double> velocity = slip_velocity(d, grid);
    std::vector<distribution_row> rows(grid.size());
    for (std::size_t i = 0; i < grid.size(); ++i) {
        distribution_row& row = rows[i];
        row.r = grid[i];
        row.p = normal().pressure(row.r);
        row.p1 = traction(d, row.r);
        row.stick = d.sticks(row.r);
        row.v = row.stick ? 0.0 : velocity[i];
        if (!std::isfinite(row.p) || !std::isfinite(row.p1) || !std::isfinite(row.v))
            throw numerical_error("non-finite traction at r = " + shortest(row.r));
    }
    return rows;
}

}  // namespace roughroll
