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
    if (dissimilar_) return dissimilar_estimate(s);
    if (reported_ && s.general) {
        // A point of the general path is level n itself, not extrapolated: the difference from
        // n/2 (on the same path), with the rounding floor of every estimate.
        if (!last_coarse_ || last_coarse_->Q != s.Q)
            last_coarse_ = companion_->general_point(s.Q, zone_guess{s.start, s.c0});
        // The floors of every estimate; c0's near gross sliding, where the zone shrinks to a
        // point, is the one validation/test_honest_estimates.cpp needs (5e-12 at Q/f = 1 - 1e-15).
        const rounding_floors floor = floors_at(nodes(), s, s);
        return error_estimate{std::fabs(reported_->lambda - normal_->lambda) + floor.lambda,
                              std::fabs(s.c0 - last_coarse_->c0) + floor.c0,
                              std::fabs(s.xi - last_coarse_->xi) + floor.xi,
                              0.0,
                              "n/2 (general zone search: level n, not extrapolated)",
                              false};
    }
    if (!build_levels()) return std::nullopt;
    const tangential_solution own = distribution(s);
    std::array<tangential_solution, 3> at{};
    // A point of the general path is compared with the general path's answers at the levels.
    for (int i = 0; i < 3; ++i)
        at[i] = !levels_[i] ? own
                : s.general ? levels_[i]->general_point(s.Q, zone_guess{s.start, s.c0})
                            : levels_[i]->level_point(s.Q, false);
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

std::optional<tangential_solution> contact::above_finest(const tangential_solution& s, const tangential_solution& own,
                                                         bool swept) {
    const int m = 2 * nodes();
    if (levels_[2] != nullptr || m > max_nodes) return std::nullopt;  // n must be the finest level
    try {
        make_finer(m);
        if (swept) return finer_->level_at_stick_end(own.c0, false, sweeping_near_);
        // On the zone path of s, as the other levels (estimate()).
        return s.general ? finer_->general_point(s.Q, zone_guess{s.start, s.c0}) : finer_->level_point(s.Q, false);
    } catch (const resolution_error&) {
        return std::nullopt;
    } catch (const numerical_error&) {  // the general search finds no zone at 2n: no fourth level
        if (!s.general) throw;
        return std::nullopt;
    }
}

contact::rounding_floors contact::floors_at(int n, const tangential_solution& s, const tangential_solution& own) const {
    const double lambda = normal().lambda;
    // The size of the terms of (4.4)-(4.5): the pressure's scale P_H/P2 (through G) and the
    // kernels' strength sum |T| (a near-constant kernel T exp(-A |z|), A << 1, multiplies
    // int q = O(f) by T, and those terms cancel to xi: a tangential layer T = 100, A = 1e-3
    // loses 1e-13 absolute in xi = 3e-8 at n = 128).
    const double strength = std::max(kernel::tangential(surfaces_).strength(), kernel::normal(surfaces_).strength());
    const double size = std::max({1.0, std::fabs(lambda), strength});          // for xi
    const double n_eps = rounding_floor(n, std::max(1.0, std::fabs(lambda)));  // for c0 and Q
    // c0: Q(c0) of (4.5) rounds to about n eps f K (an O(f) sum whose terms grow with G of
    // (3.25)); near gross sliding Q = f (1 - rho^2) (Carter), so c0 = 2 rho - 1 moves by
    // min(n eps K/rho, 2 sqrt(n eps K)), K = max(1, P_H/P2). On the paper's single zone the
    // special loads Q = 0 and |Q| = f are solved without a system (c0 = 1, -1 exactly); the
    // general search's zone at |Q| = f (the least G) is computed.
    const bool special = !s.general && (s.Q == 0.0 || std::fabs(s.Q) == f_);
    double c0_floor = special ? 0.0 : std::min(n_eps / own.rho(), 2.0 * std::sqrt(n_eps));
    double xi_floor = rounding_floor(n, std::fabs(own.xi) + f_ * size);
    if (own.general && !own.psi_b.empty() && own.rho() > 0.0) {
        // A zone of the general search (docs/formulation.md 7(d), 7(e)): xi, b_0 and psi(-1) are
        // read off (4.4), whose terms of size |xi| + f K they cancel (stick_system_floor). The
        // ends solve the load in the gap form rho (pi/2) b_0 = |Q| - f and the entry condition
        // psi(-1)/|b_0| = 0, both relative to b_0, which near gross sliding vanishes like
        // f G'' rho^2/2: the ends move by rho times the floor over |b_0| (the residuals of 7(d)
        // have slopes 2 and 3 in gamma and log rho, which the factor 1 covers).
        const double system = stick_system_floor(n, std::fabs(own.xi) + f_ * size);
        xi_floor = std::max(xi_floor, system);
        c0_floor = std::max(c0_floor, own.rho() * system / std::fabs(own.psi_b[0]));
    }
    return {rounding_floor(n, lambda), c0_floor, xi_floor, f_ * n_eps};
}

error_estimate contact::estimate_from(const tangential_solution& s, const tangential_solution& own,
                                      const std::array<tangential_solution, 3>& at, bool swept) {
    int self = 0;
    while (levels_[self] != nullptr) ++self;
    const bool extrapolated = reported_ != nullptr;
    const reported_value which{self, extrapolated};
    const int order = level_method() == method::product ? 4 : 2;
    const int finest_n = levels_[2] ? levels_[2]->nodes() : nodes();
    auto lambda_at = [&](int i) { return levels_[i] ? levels_[i]->normal_level().lambda : normal_level().lambda; };
    const rounding_floors floor = floors_at(finest_n, s, own);
    struct quantity {
        const char* name;
        three_levels v;
        double floor;
        double* out;
    };
    error_estimate e{0.0, 0.0, 0.0, 0.0, "", false};
    std::vector<quantity> qs{{"P_H/P2", {lambda_at(0), lambda_at(1), lambda_at(2)}, floor.lambda, &e.lambda},
                             {"xi", {at[0].xi, at[1].xi, at[2].xi}, floor.xi, &e.xi}};
    if (swept)
        qs.push_back({"Q", {at[0].Q, at[1].Q, at[2].Q}, floor.Q, &e.Q});
    else
        qs.push_back({"c0", {at[0].c0, at[1].c0, at[2].c0}, floor.c0, &e.c0});
    const int coarsest_n = levels_[0] ? levels_[0]->nodes() : nodes();
    bool second_chance = false, confirmed = false;
    // Three levels that look converged can still be pre-asymptotic (docs/performance.md, "How the
    // error estimates are made", the fourth level): where they show less than the method's order,
    // and always for the one-parameter limit, whose c0 error changes with c0's place among the nodes
    // and can pass near zero at one level, level 2n confirms: the estimate is also bounded from
    // n/2, n, 2n, and the point is refused where those do not converge visibly.
    const bool always_confirm = options_.how == method::one_parameter;
    // An observed order far above the method's (ratio beyond 2^(p+2)) is no sign of the asymptotic
    // range either: a coarsest level far off, or a middle level that lies near the limit by chance
    // (paper at n = 16 near gross sliding: ratio 50 over 4, 8, 16, then a sign change and 6 times
    // the estimate at 32).
    const double too_fast = std::ldexp(1.0, order + 2);
    for (const quantity& q : qs) {
        error_bound b = bound_error(q.v, order, which, q.floor);
        three_levels used = q.v;
        int used_coarsest_n = coarsest_n;
        const bool rounding = std::fabs(q.v.finest - q.v.middle) <= q.floor;  // the ratio then means nothing
        const bool confirm =
            b.resolved && (always_confirm || !b.asymptotic || (std::fabs(b.ratio) > too_fast && !rounding));
        if ((!b.resolved && own.checks.hold()) || confirm) {
            // One level finer, n/2, n, 2n (error_bound.hpp). Where the first three gave no estimate
            // (a second chance, where n/4 is still pre-asymptotic for this quantity): only for a
            // solution whose inequalities (3.3)-(3.4) hold, and only where the finer levels show at
            // least order p - 1, since three pre-asymptotic levels of a very stiff layer can look
            // convergent by chance. Where they gave one (a confirmation): the larger of the two.
            if (const std::optional<tangential_solution> above = above_finest(s, own, swept)) {
                const int i = static_cast<int>(&q - qs.data());
                const double v = i == 0   ? finer_->normal_level().lambda
                                 : i == 1 ? above->xi
                                 : swept  ? above->Q
                                          : above->c0;
                const three_levels finer{q.v.middle, q.v.finest, v};
                error_bound fb = confirm ? confirm_error(finer, order, extrapolated, q.floor)
                                         : bound_error(finer, order, reported_value{1, extrapolated}, q.floor);
                if (confirm) {
                    if (fb.resolved) {
                        fb.value = std::max(fb.value, b.value);
                        fb.asymptotic = fb.asymptotic && b.asymptotic;
                    }
                    confirmed = true;
                } else {
                    if (!(fb.ratio >= std::ldexp(1.0, order - 1))) fb.resolved = false;
                    second_chance = second_chance || fb.resolved;
                }
                b = fb;
                used = finer;
                used_coarsest_n = 2 * coarsest_n;
            }
        }
        if (!b.resolved) {
            std::ostringstream msg;
            msg.precision(3);
            msg << "no honest error estimate for method '" << to_string(options_.how) << "' at n = " << nodes() << ": "
                << q.name << " does not converge visibly over n = " << used_coarsest_n << ", " << 2 * used_coarsest_n
                << ", " << 4 * used_coarsest_n << " (differences " << used.middle - used.coarsest << ", "
                << used.finest - used.middle << ")";
            if (!swept)
                msg << " at Q = " << s.Q;
            else
                msg << " at c0 = " << s.c0;
            msg << (nodes() < max_nodes ? "; increase n, or the scene is beyond the method's reach"
                                        : "; the scene is beyond the method's reach at the largest n");
            throw resolution_error(msg.str());
        }
        *q.out = std::max(*q.out, b.value);
        e.bounded = e.bounded || !b.asymptotic;
    }
    static const char* const names[] = {"n/4", "n/2", "n", "2n", "4n"};
    const int first = 2 - self;  // index of the coarsest level's name
    e.against = std::string(extrapolated ? "level n"
                            : self == 2  ? "n/2"
                                         : "2n") +
                " (levels " + names[first] + ", " + names[first + 1] + ", " + names[first + 2] +
                (second_chance ? "; n/2, n, 2n where n/4 fell short" : "") +
                (confirmed ? "; confirmed on n/2, n, 2n" : "") + (e.bounded ? "; observed order below " : "; order ") +
                std::to_string(order) + (e.bounded ? ": bounded)" : " observed)");
    return e;
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

std::optional<error_estimate> contact::dissimilar_estimate(const tangential_solution& s) {
    // Three levels of the level method (n/4, n/2, n where they fit), the rule of error_bound.hpp
    // for xi, c0 and the start (the reported values are level n's), and for P_H/P2 as reported
    // (Richardson's for 'extrapolated'). No estimate where the levels do not converge visibly.
    if (!build_levels()) return std::nullopt;
    int self = 0;
    while (levels_[self] != nullptr) ++self;
    std::array<tangential_solution, 3> at{};
    for (int i = 0; i < 3; ++i) {
        if (!levels_[i]) {
            at[i] = s;
        } else if (coupled_) {
            // Full coupling (8(e)): each level's own alternation from its own Johnson's point. A level
            // that cannot be coupled leaves no honest estimate (the point itself was).
            try {
                at[i] = levels_[i]->coupled_level_point(s.Q, levels_[i]->johnson_level_point(s.Q, s), false);
            } catch (const numerical_error& why) {
                throw resolution_error("no honest error estimate for method '" + to_string(options_.how) + "' at n = " +
                                       std::to_string(nodes()) + " (dissimilar rollers, full coupling): level " +
                                       std::to_string(levels_[i]->nodes()) + ": " + why.what());
            }
        } else if (s.five) {
            // Five zones (8(j)): each level from this level's ends (Newton), else its own search.
            const std::vector<double> ends{s.start, s.c0, s.start2, s.end2};
            const five_zone_solution* v = levels_[i]->five_level_point(last_five_load_, &ends);
            if (v == nullptr)
                throw resolution_error(
                    "no honest error estimate for method '" + to_string(options_.how) + "' at n = " +
                    std::to_string(nodes()) + " (dissimilar rollers): level " + std::to_string(levels_[i]->nodes()) +
                    " finds no five zones at Q = " + shortest(s.Q) + " from level n's zones; " +
                    (nodes() < max_nodes ? "another n (at most " + std::to_string(max_nodes) + ") may find them"
                                         : "n is at its largest, so the load is beyond the method's reach"));
            at[i] = five_zone_point(*v);
        } else {
            at[i] = levels_[i]->dissimilar_level_point(s.Q, zone_guess{s.start, s.c0}, s.opposite);
        }
    }
    const int order = level_method() == method::product ? 4 : 2;
    const int finest_n = levels_[2] ? levels_[2]->nodes() : nodes();
    const rounding_floors floor = floors_at(finest_n, s, s);
    auto lambda_at = [&](int i) { return levels_[i] ? levels_[i]->normal_level().lambda : normal_level().lambda; };
    // The levels' own n: a refusal names them, since n and 2 n can share one set (n/2, n, 2 n
    // when n/4 is below the asymptotic range, n/4, n/2, n at 2 n).
    auto level_nodes = [&](int i) { return levels_[i] ? levels_[i]->nodes() : nodes(); };
    error_estimate e{0.0, 0.0, 0.0, 0.0, "", false};
    struct quantity {
        const char* name;
        three_levels v;
        double floor;
        bool extrapolated;
        double* out;
    };
    // Each level's ends are Newton's within zone_end_resolution, so the difference of two levels
    // carries up to twice that: below it, a difference is that noise, not a ratio (free rolling of
    // data/aluminium-on-steel.toml at n = 512 had been refused on -1.6e-13, -1.08e-11). Near gross
    // sliding the entry condition's rounding moves the ends by rho/|b_0| times it (formulation 8(m),
    // entry_ends_floor; the braked pair at Q = -0.049999 had been refused on -5.3e-11, -4.1e-10), at
    // the finest level used: m = finest_n, or 2n for the second chance below.
    const double terms = std::fabs(s.xi) + std::fabs(s.forcing) * std::max(1.0, std::fabs(normal().lambda)) +
                         f_ * std::max({1.0, std::fabs(normal().lambda), kernel::tangential(surfaces_).strength(),
                                        kernel::normal(surfaces_).strength()});
    const auto ends_floor_at = [&](int m) {
        return floor.c0 + 2.0 * zone_end_resolution +
               (s.psi_b.empty() ? 0.0 : entry_ends_floor(m, terms, s.rho(), s.psi_b[0]));
    };
    const double ends_floor = ends_floor_at(finest_n);
    const quantity qs[] = {
        // (At full coupling P_H/P2 is level n's, not extrapolated: contact::normal.)
        {"P_H/P2",
         {lambda_at(0), lambda_at(1), lambda_at(2)},
         floor.lambda,
         reported_ != nullptr && !coupled_,
         &e.lambda},
        {"xi", {at[0].xi, at[1].xi, at[2].xi}, floor.xi, false, &e.xi},
        // The ends carry Newton's resolution too (dissimilar_zones.hpp).
        {"c0", {at[0].c0, at[1].c0, at[2].c0}, ends_floor, false, &e.c0},
        {"the stick zone's start", {at[0].start, at[1].start, at[2].start}, ends_floor, false, &e.start},
        // Five zones: the second stick zone's ends, their bounds folded into c0's and the start's
        // (each reported bound the larger of the two zones', formulation 7 "What c0 means").
        {"the second stick zone's end", {at[0].end2, at[1].end2, at[2].end2}, ends_floor, false, &e.c0},
        {"the second stick zone's start", {at[0].start2, at[1].start2, at[2].start2}, ends_floor, false, &e.start}};
    // The second chance of estimate_from, one level finer (n/2, n, 2n), where n is the finest level
    // and the solution's checks hold: an n/4 that oscillates (the second stick zone's end of the
    // rough pair of data/aluminium-on-steel-rough.toml at n = 64 over 16, 32, 64) must not refuse an
    // n whose finer levels converge. Only where the finer levels show at least order p - 1.
    std::optional<tangential_solution> above;
    bool above_tried = false;
    auto finer_level = [&]() -> const tangential_solution* {
        if (above_tried) return above ? &*above : nullptr;
        above_tried = true;
        const int m = 2 * nodes();
        if (self != 2 || m > max_nodes || !s.checks.hold()) return nullptr;
        try {
            make_finer(m);
            if (coupled_) {
                // Full coupling: the finer level's own alternation, as the levels below (a Johnson's
                // point at 2n against a coupled n would measure the coupling, not the discretisation).
                above = finer_->coupled_level_point(s.Q, finer_->johnson_level_point(s.Q, s), false);
            } else if (s.five) {
                const std::vector<double> ends{s.start, s.c0, s.start2, s.end2};
                if (const five_zone_solution* v = finer_->five_level_point(last_five_load_, &ends))
                    above = five_zone_point(*v);
            } else {
                above = finer_->dissimilar_level_point(s.Q, zone_guess{s.start, s.c0}, s.opposite);
            }
        } catch (const error&) {  // no finer level: the refusal below stands
            above.reset();
        }
        return above ? &*above : nullptr;
    };
    for (std::size_t k = 0; k < (s.five ? 6u : 4u); ++k) {  // the second zone's ends for five zones only
        const quantity& q = qs[k];
        if (coupled_) {
            // Full coupling (8(e)): the zone ends converge at order 1 or less, erratically, and the
            // errors change sign between levels (the exponents at the edges and zone ends shift with
            // the coupling; P_H/P2 and xi at order 2 against gross sliding's closed form), so no
            // asymptotic rule holds. The bound is twice the larger of the last two level changes, plus
            // the rounding floor: measured against n = 512 and the closed form
            // (FullCoupling.EstimatesBoundTheError, .GrossSlidingAgainstTheClosedForm); bound_error's
            // rule under-reported there (a stick start's error 2.7e-4 estimated at 1.2e-4).
            const double d1 = q.v.middle - q.v.coarsest, d2 = q.v.finest - q.v.middle;
            const double bound = 2.0 * std::max(std::fabs(d1), std::fabs(d2)) + q.floor;
            if (!std::isfinite(bound))
                throw resolution_error("no honest error estimate for method '" + to_string(options_.how) + "' at n = " +
                                       std::to_string(nodes()) + " (dissimilar rollers, full coupling): " + q.name +
                                       " is not finite on its levels");
            *q.out = std::max(*q.out, bound);
            e.bounded = true;
            continue;
        }
        error_bound b = bound_error(q.v, order, reported_value{self, q.extrapolated}, q.floor);
        three_levels used = q.v;
        int used_coarsest = level_nodes(0);
        if (!b.resolved && k > 0) {  // P_H/P2 (k = 0) is the normal problem's: estimate_from's rule
            if (const tangential_solution* a = finer_level()) {
                const double values[] = {0.0, a->xi, a->c0, a->start, a->end2, a->start2};
                used = {q.v.middle, q.v.finest, values[k]};
                used_coarsest = level_nodes(1);
                b = bound_error(used, order, reported_value{1, false}, k >= 2 ? ends_floor_at(2 * nodes()) : q.floor);
                if (!(b.ratio >= std::ldexp(1.0, order - 1))) b.resolved = false;
            }
        }
        if (!b.resolved) {
            std::ostringstream msg;
            msg.precision(3);
            msg << "no honest error estimate for method '" << to_string(options_.how) << "' at n = " << nodes()
                << " (dissimilar rollers): " << q.name
                << " does not converge visibly over the levels n = " << used_coarsest << ", " << 2 * used_coarsest
                << ", " << 4 * used_coarsest << " (differences " << used.middle - used.coarsest << ", "
                << used.finest - used.middle << ") at Q = " << s.Q << "; ";
            // A larger n helps only where its levels fit below max_nodes (the finest is n, or 2n above).
            if (nodes() < max_nodes)
                msg << "a larger n (at most " << max_nodes << ") may converge";
            else
                msg << "n is at its largest, so the load is beyond the method's reach";
            throw resolution_error(msg.str());
        }
        *q.out = std::max(*q.out, b.value);
        e.bounded = e.bounded || !b.asymptotic;
    }
    static const char* const names[] = {"n/4", "n/2", "n", "2n", "4n"};
    const int first = 2 - self;
    if (coupled_) {
        e.against = std::string("levels ") + names[first] + ", " + names[first + 1] + ", " + names[first + 2] +
                    " (dissimilar rollers, full coupling: level n, twice the larger of the last two level changes)";
        return e;
    }
    e.against = std::string(self == 2 ? "n/2" : "2n") + " (dissimilar rollers: level n, not extrapolated; levels " +
                names[first] + ", " + names[first + 1] + ", " + names[first + 2] +
                (above ? "; n/2, n, 2n where n/4 fell short" : "") +
                (e.bounded ? "; observed order below " : "; order ") + std::to_string(order) +
                (e.bounded ? ": bounded)" : " observed)");
    return e;
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
