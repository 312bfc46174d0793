// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/contact.hpp"

#include <algorithm>
#include <cmath>

#include <sstream>

#include "roughroll/numerics/collocation.hpp"
#include "roughroll/numerics/error_bound.hpp"
#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"
#include "roughroll/problems/dissimilar_zones.hpp"

namespace roughroll {

namespace {
kernel widest_kernel(const roughness& r) {
    const double rate = std::max(kernel::normal(r).max_rate(), kernel::tangential(r).max_rate());
    return kernel(std::vector<exponential_term>{{1.0, rate}});
}
}  // namespace

contact::contact(const roughness& surfaces, double f, const solver_options& options, const dissimilar& materials,
                 normal_cache* cache)
    : surfaces_(surfaces), options_(options), f_(f), materials_(materials) {
    if (!(std::isfinite(f) && f > 0.0)) throw input_error("friction coefficient f must be positive and finite");
    check_dissimilar(materials, options);
    const int n = options.nodes();
    if (options.how == method::one_parameter) {
        limit_ = std::make_unique<one_parameter_solver>(surfaces, f, n);
        limit_zones_ = std::make_unique<one_parameter_zones>(*limit_);
        return;
    }
    const bool extrapolate = options.how == method::extrapolated &&
                             !(kernel::normal(surfaces).empty() && kernel::tangential(surfaces).empty());
    if (extrapolate) {
        // Richardson's rule holds only where the error already falls like n^-4.
        check_extrapolation_range(widest_kernel(surfaces), n, "these kernels");
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
    zones_ = std::make_unique<zone_solver>(*tangential_);
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
    const auto guess = coarse ? std::optional<zone_guess>({coarse->start, coarse->c0}) : std::nullopt;
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
                reported_ ? quarter : levels_[1]->level_point(Q, false, quarter.c0, quarter.load_slope);
            start = half.c0;
            start_slope = half.load_slope;
            if (quarter.c0 > -1.0 && quarter.c0 < 1.0) quarter_c0 = quarter.c0;
            if (!reported_) start = predicted_start(quarter_c0, half.c0);
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
        zones_for(Q, tangential_->solve(Q, predicted_start(quarter_c0, coarse.c0), true, coarse.load_slope), &coarse);
    // Both levels on the same path: the coarse level's zones by the general search too.
    if (s.general) coarse = companion_->general_point(Q, zone_guess{s.start, s.c0});
    last_fine_ = s;
    if (s.general) {
        // The general path is not extrapolated: its zone ends do not yet converge at a clean
        // n^-4 at the default n (docs/formulation.md 7(e)). Level n, estimated against n/2.
        last_coarse_ = coarse;
        // Refused where the fast path's extrapolation is: a creep at the edge of the double range.
        if (!std::isfinite(richardson(s.xi, coarse.xi)))
            throw numerical_error("extrapolation: the creep is not finite (roughness parameters too large?)");
        return s;
    }
    s.c0 = richardson(s.c0, coarse.c0);
    s.xi = richardson(s.xi, coarse.xi);
    if (!(std::isfinite(s.c0) && std::isfinite(s.xi)))
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

double contact::kernel_strength() const {
    return std::max(kernel::tangential(surfaces_).strength(), kernel::normal(surfaces_).strength());
}

tangential_solution contact::distribution(const tangential_solution& s) {
    if (!reported_ || dissimilar_) return s;  // a dissimilar point is level n itself
    if (!last_fine_ || last_fine_->Q != s.Q)
        last_fine_ = s.general ? general_point(s.Q, zone_guess{s.start, s.c0}) : tangential_->solve(s.Q);
    return *last_fine_;
}

std::optional<error_estimate> contact::estimate(const tangential_solution& s) {
    // The levels' differences measure how a solution of the discrete equations moves with n; where
    // (3.3)-(3.4) fail, the answer is not the model's solution at any n, and they bound nothing.
    // They are still solved: where they do not converge the point is refused, as any other.
    std::optional<error_estimate> e = levels_estimate(s);
    if (!s.checks.hold()) return std::nullopt;
    return e;
}

std::optional<error_estimate> contact::levels_estimate(const tangential_solution& s) {
    if (reported_ && s.general && !dissimilar_) {
        // A point of the general path is level n itself, not extrapolated: the difference from
        // n/2 (on the same path), with the rounding floor of every estimate.
        if (!last_coarse_ || last_coarse_->Q != s.Q)
            last_coarse_ = companion_->general_point(s.Q, zone_guess{s.start, s.c0});
        // The floors of every estimate; c0's near gross sliding, where the zone shrinks to a
        // point, is the one validation/test_honest_estimates.cpp needs (5e-12 at Q/f = 1 - 1e-15).
        const rounding_floors floor = floors_at(nodes(), s, s, normal().lambda, f_, kernel_strength());
        return error_estimate{std::fabs(reported_->lambda - normal_->lambda) + floor.lambda,
                              std::fabs(s.c0 - last_coarse_->c0) + floor.c0,
                              std::fabs(s.xi - last_coarse_->xi) + floor.xi,
                              0.0,
                              "n/2 (general zone search: level n, not extrapolated)",
                              false};
    }
    // Three levels of the level method on the structure of s (for dissimilar rollers the reported
    // values are level n's; for the paper's problem those of its distributions).
    if (!build_levels()) return std::nullopt;
    const tangential_solution own = distribution(s);
    std::array<tangential_solution, 3> at{};
    for (int i = 0; i < 3; ++i) at[i] = levels_[i] ? structure_level(*levels_[i], s, own, false) : own;
    return estimate_from(s, own, at, false);
}

bool contact::build_levels() {
    if (levels_built_) return levels_[0] != nullptr || levels_[1] != nullptr;
    levels_built_ = true;
    // A plain contact at m nodes (the level method), or null when m is outside the nodes
    // supported or the kernels are beyond its resolution.
    const method how = level_method();
    auto plain = [&](int m) -> contact* {
        if (m < min_nodes || m > max_nodes) return nullptr;
        if (m == nodes() / 2 && companion_) return companion_.get();
        for (const auto& c : owned_levels_)
            if (c->nodes() == m) return c.get();
        try {
            owned_levels_.push_back(std::make_unique<contact>(surfaces_, f_, solver_options{m, how}, materials_));
            owned_levels_.back()->set_checkpoint(checkpoint_);
            return owned_levels_.back().get();
        } catch (const resolution_error&) {
            return nullptr;
        }
    };
    const int n = nodes();
    // Three levels n_0, 2 n_0, 4 n_0 containing n: n/4, n/2, n, else n/2, n, 2n (for
    // extrapolated, Richardson's value from the middle levels), else n, 2n, 4n. First the
    // first of them whose coarsest level is in the asymptotic range (the one-parameter limit
    // has no kernel to resolve: its ratio alone decides), then the first that can be solved.
    const int coarsest[] = {n / 4, n / 2, n};
    const int count = companion_ ? 2 : 3;
    for (bool require_range : {true, false}) {
        for (int i = 0; i < count; ++i) {
            const int m = coarsest[i];
            if (m < min_nodes || (n << i) > max_nodes) continue;
            if (require_range && how != method::one_parameter && !in_asymptotic_range(widest_kernel(surfaces_), m, how))
                continue;
            std::array<contact*, 3> at{};
            bool ok = true;
            for (int k = 0; k < 3 && ok; ++k) {
                if (k == 2 - i) continue;  // this contact's own level
                at[k] = plain(k < 2 - i ? n >> (2 - i - k) : n << (k - 2 + i));
                ok = at[k] != nullptr;
            }
            if (ok) {
                levels_ = at;
                return true;
            }
        }
    }
    return false;
}

void contact::make_finer(int m) {
    if (finer_) return;
    finer_ = std::make_unique<contact>(surfaces_, f_, solver_options{m, level_method()}, materials_);
    finer_->set_checkpoint(checkpoint_);
}

tangential_solution contact::structure_level(contact& level, const tangential_solution& s,
                                             const tangential_solution& own, bool swept) {
    if (swept) return level.level_at_stick_end(own.c0, false, sweeping_near_);
    // A point of the general path is compared with the general path's answers at the levels.
    if (!dissimilar_)
        return s.general ? level.general_point(s.Q, zone_guess{s.start, s.c0}) : level.level_point(s.Q, false);
    if (coupled_) {
        // Full coupling (8(e)): the level's own alternation from its own Johnson's point (a Johnson's
        // point against a coupled n would measure the coupling, not the discretisation). A level that
        // cannot be coupled leaves no honest estimate (the point itself was).
        try {
            return level.coupled_level_point(s.Q, level.johnson_level_point(s.Q, s), false);
        } catch (const numerical_error& why) {
            throw resolution_error(no_honest_estimate(options_.how, nodes(), estimate_structure::full_coupling) +
                                   "level " + std::to_string(level.nodes()) + ": " + why.what());
        }
    }
    if (s.five) {
        // Five zones (8(j)): the level from this level's ends (Newton), else its own search.
        const std::vector<double> ends{s.start, s.c0, s.start2, s.end2};
        const five_zone_solution* v = level.five_level_point(last_five_load_, &ends);
        if (v == nullptr)
            throw resolution_error(no_honest_estimate(options_.how, nodes(), estimate_structure::dissimilar) +
                                   "level " + std::to_string(level.nodes()) +
                                   " finds no five zones at Q = " + shortest(s.Q) + " from level n's zones; " +
                                   (nodes() < max_nodes
                                        ? "another n (at most " + std::to_string(max_nodes) + ") may find them"
                                        : "n is at its largest, so the load is beyond the method's reach"));
        return five_zone_point(*v);
    }
    return level.dissimilar_level_point(s.Q, zone_guess{s.start, s.c0}, s.opposite);
}

error_estimate contact::estimate_from(const tangential_solution& s, const tangential_solution& own,
                                      const std::array<tangential_solution, 3>& at, bool swept) {
    int self = 0;
    while (levels_[self] != nullptr) ++self;
    const estimate_structure structure = !dissimilar_ ? estimate_structure::paper
                                         : coupled_   ? estimate_structure::full_coupling
                                                      : estimate_structure::dissimilar;
    const double lambda = normal().lambda, strength = kernel_strength();
    const int finest_n = levels_[2] ? levels_[2]->nodes() : nodes();
    const rounding_floors floor = floors_at(finest_n, s, own, lambda, f_, strength);
    // The structure's table: P_H/P2, xi, then the paper's c0 (or Q on a curve swept in c0), or the
    // ends of dissimilar rollers' stick zones, which carry Newton's resolution too (dissimilar_zones.hpp).
    using q = estimated_quantity;
    using sol = tangential_solution;
    using est = error_estimate;
    std::vector<q> table;
    if (!dissimilar_) {
        const bool x = reported_ != nullptr;  // Richardson's values, all three
        table = {{"P_H/P2", nullptr, floor.lambda, floor.lambda, x, true, &est::lambda},
                 {"xi", &sol::xi, floor.xi, floor.xi, x, true, &est::xi},
                 swept ? q{"Q", &sol::Q, floor.Q, floor.Q, x, true, &est::Q}
                       : q{"c0", &sol::c0, floor.c0, floor.c0, x, true, &est::c0}};
    } else {
        const double ends = zone_ends_floor(finest_n, floor.c0, s, lambda, f_, strength);
        const double finer_ends = zone_ends_floor(2 * nodes(), floor.c0, s, lambda, f_, strength);
        // Level n is reported, not extrapolated; P_H/P2 as reported (Richardson's for 'extrapolated',
        // level n's at full coupling: contact::normal), with no second chance.
        table = {
            {"P_H/P2", nullptr, floor.lambda, floor.lambda, reported_ != nullptr && !coupled_, false, &est::lambda},
            {"xi", &sol::xi, floor.xi, floor.xi, false, true, &est::xi},
            {"c0", &sol::c0, ends, finer_ends, false, true, &est::c0},
            {"the stick zone's start", &sol::start, ends, finer_ends, false, true, &est::start}};
        // Five zones: the second stick zone's ends, their bounds folded into c0's and the start's
        // (each reported bound the larger of the two zones', formulation 7 "What c0 means").
        if (s.five) {
            table.push_back({"the second stick zone's end", &sol::end2, ends, finer_ends, false, true, &est::c0});
            table.push_back(
                {"the second stick zone's start", &sol::start2, ends, finer_ends, false, true, &est::start});
        }
    }
    std::array<estimate_level, 3> levels;
    for (int i = 0; i < 3; ++i)
        levels[i] = {at[i], levels_[i] ? levels_[i]->normal_level().lambda : normal_level().lambda};
    // Level 2n on the structure of s, where n is the finest level. A search that finds no zone
    // there leaves no fourth level; for the paper's single zone a numerical fault is one.
    const auto finer = [&]() -> std::optional<estimate_level> {
        const int m = 2 * nodes();
        if (levels_[2] != nullptr || m > max_nodes) return std::nullopt;
        try {
            make_finer(m);
            tangential_solution t = structure_level(*finer_, s, own, swept);
            return estimate_level{std::move(t), finer_->normal_level().lambda};
        } catch (const resolution_error&) {
            return std::nullopt;
        } catch (const numerical_error&) {
            if (!s.general && !dissimilar_) throw;
            return std::nullopt;
        } catch (const error&) {
            if (!dissimilar_) throw;
            return std::nullopt;
        }
    };
    const estimate_point point{
        options_.how,       nodes(),           self, structure, reported_ != nullptr && !dissimilar_, own.checks.hold(),
        swept ? "c0" : "Q", swept ? s.c0 : s.Q};
    return estimate_from_levels(table, levels, finer, point);
}

tangential_solution contact::level_at_stick_end(double c0, bool checked, bool near) {
    // A sweep's consecutive c0 give nearby systems: refined on the previous factorisation
    // (dense_system::solve_near, docs/formulation.md "Swept points refined on the previous
    // factorisation"), the same solution to rounding.
    return limit_ ? limit_->at_stick_end(c0, checked) : tangential_->at_stick_end(c0, checked, near);
}

void check_sweepable(const dissimilar& materials) {
    if (materials.beta_d != 0.0)
        throw input_error(
            "a curve swept in c0 is the paper's single zone, never the answer for beta_d != 0 "
            "(docs/formulation.md 8(g)); solve at given loads instead");
}

contact::swept_point contact::at_stick_end(double c0) {
    check_sweepable(materials_);
    try {
        return swept_at(c0);
    } catch (const resolution_error&) {
        // A refusal is decided on fresh factorisations, as for the point alone: the refined
        // route agrees with them only to rounding, and a refusal line quotes Q(c0) to the digit.
        sweeping_near_ = false;
        try {
            swept_point p = swept_at(c0);
            sweeping_near_ = true;
            return p;
        } catch (...) {
            sweeping_near_ = true;
            throw;
        }
    }
}

contact::swept_point contact::swept_at(double c0) {
    tangential_solution s = level_at_stick_end(c0, true, sweeping_near_);
    const tangential_solution own = s;
    std::optional<tangential_solution> coarse;  // level n/2 at c0: the companion, often an estimate level too
    if (reported_) {
        // Richardson's rule on Q(c0) and xi(c0) at the same c0.
        coarse = companion_->level_at_stick_end(c0, false, sweeping_near_);
        // Q = 0 and f at c0 = 1 and -1 are exact on every level: kept exact (Carter's columns).
        if (c0 != 1.0 && c0 != -1.0) s.Q = richardson(s.Q, coarse->Q);
        s.xi = richardson(s.xi, coarse->xi);
        if (!(std::isfinite(s.Q) && std::isfinite(s.xi)))
            throw numerical_error("extrapolation: Q(c0) or the creep is not finite (roughness parameters too large?)");
    }
    // A load outside [0, f] is no point of this curve (docs/robustness.md, "Curves with refused
    // points"): the sweep's slip zone carries q = +f p (sign +1), so |q| <= f p of (3.3) gives
    // |Q| <= f int p = f, and Q(c0) rises from 0 at full stick (c0 = 1) to f (c0 = -1); a negative
    // Q is the mirror case, whose slip zone is at the other edge. Outside [0, f] the inequalities
    // fail: n does not resolve the layers, or the single stick zone is not the solution there
    // (docs/formulation.md 7(c), leading slip: Q(c0) > f near c0 = -1). The ends c0 = +-1 are exact.
    refuse_load_outside(s, std::nullopt);
    if (!build_levels()) return {s, std::nullopt};
    std::array<tangential_solution, 3> at{};
    for (int i = 0; i < 3; ++i)
        at[i] = !levels_[i]                                ? own
                : coarse && levels_[i] == companion_.get() ? *coarse  // solved above: not again
                                                           : levels_[i]->level_at_stick_end(c0, false, sweeping_near_);
    const error_estimate e = estimate_from(s, own, at, true);
    // The same for the load's error interval: Q +- e.Q reaching beyond [0, f] cannot be told from
    // full stick or gross sliding (and may be no physical point at all).
    refuse_load_outside(s, e.Q);
    if (!s.checks.hold()) return {s, std::nullopt};  // as estimate(): no bound for such a point
    return {s, e};
}

void contact::refuse_load_outside(const tangential_solution& s, std::optional<double> error) const {
    if (s.c0 == 1.0 || s.c0 == -1.0) return;  // Q = 0 and Q = f exactly (full stick, gross sliding)
    const double d = error.value_or(0.0);
    if (s.Q - d >= 0.0 && s.Q + d <= f_) return;
    std::ostringstream msg;
    msg.precision(3);
    msg << "Q(c0) = " << shortest(s.Q);
    if (error)
        msg << " +- " << *error << " (its error estimate) reaches";
    else
        msg << " lies";
    msg << " outside [0, f] = [0, " << shortest(f_) << "] at c0 = " << shortest(s.c0) << " for method '"
        << to_string(options_.how) << "' at n = " << nodes() << ": "
        << (error ? std::string("the load is not resolved there; ") +
                        (nodes() < max_nodes ? "increase n, or the scene is beyond the method's reach"
                                             : "n is at its largest, so the scene is beyond the method's reach")
                  : std::string("no physical point (|Q| <= f needs (3.3)-(3.4)): n does not resolve the layers, or the "
                                "single stick zone is not the solution there; ") +
                        (nodes() < max_nodes ? "increase n, or solve at given loads" : "solve at given loads"));
    throw resolution_error(msg.str());
}

const tangential_solution& contact::dissimilar_level_point(double Q, std::optional<zone_guess> guess, bool opposite) {
    checkpoint();
    if (!last_dissimilar_ || !(last_dissimilar_->Q == Q)) last_dissimilar_ = dissimilar_->solve(Q, guess, opposite);
    return *last_dissimilar_;
}

const coupling_summary* contact::coupling() const { return coupled_load_ ? &coupled_->summary() : nullptr; }

dissimilar_zones& contact::zones_of_point() { return coupled_load_ ? coupled_->zones() : *dissimilar_; }

tangential_solution contact::dissimilar_point(double Q) {
    // Edge zones far below what the search finds (|beta_D| small against f): refused before any solve.
    check_edge_zones_resolvable(materials_.beta_d, f_, Q, nodes());
    const tangential_solution johnson = johnson_point(Q);
    if (!coupled_) return johnson;
    return coupled_level_point(Q, johnson, true);
}

tangential_solution contact::johnson_level_point(double Q, const tangential_solution& near) {
    if (!near.five) return dissimilar_level_point(Q, zone_guess{near.start, near.c0}, near.opposite);
    const std::vector<double> ends{near.start, near.c0, near.start2, near.end2};
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
                guess = zone_guess{t.start, t.c0};
                opposite = t.opposite;
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
        // on steel at n = 32, 8(j) 4a), a resolution_error (a curve's row is refused, not the curve).
        if (!s.checks.hold())
            throw resolution_error("dissimilar rollers at Q/f = " + shortest(Q / f_) +
                                   ": the five zones (slip, stick, reversed slip, stick, slip) fail the checks "
                                   "(3.3)-(3.4) (margins: stick " +
                                   shortest(s.checks.stick_margin) + ", slip " + shortest(s.checks.slip_margin) +
                                   "): a zone is below the collocation's resolution "
                                   "at n = " +
                                   std::to_string(nodes()) + " (docs/formulation.md 8(j)); " +
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
    if (dissimilar_ && d.opposite) {
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
