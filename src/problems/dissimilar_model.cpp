// SPDX-License-Identifier: GPL-3.0-or-later
// Dissimilar rollers (beta_D != 0, docs/formulation.md section 8) as point_models (point_model.hpp):
// Johnson's level (three zones of either kind, five zones, or the edge layers neglected, 8(g)-8(n)),
// and full coupling (8(e)), the alternation from Johnson's point of the same level. Every point is
// reported at level n (not extrapolated) and estimated on three levels of the same model.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"
#include "roughroll/problems/coupling_summary.hpp"
#include "roughroll/problems/dissimilar_zones.hpp"
#include "roughroll/problems/edge_layers.hpp"
#include "roughroll/problems/full_coupling.hpp"
#include "roughroll/problems/no_slip_coupled.hpp"
#include "roughroll/problems/point_model.hpp"
#include "roughroll/problems/unresolvable_zones.hpp"
#include "roughroll/problems/zone_checks.hpp"
#include "roughroll/problems/zone_newton.hpp"

namespace roughroll {

namespace {

// Free rolling of smooth dissimilar rollers at Johnson's level (docs/formulation.md 8(n)): the largest
// relative estimate of the layers-neglected point, as the ladder compares them: the bound of its xi
// relative to the no-slip creep, and the bounds of the main stick zone's ends (relative to the
// half-width); none for any other pair or level.
std::optional<double> layers_relative_bound(const dissimilar& materials, const roughness& surfaces, double f) {
    if (materials.coupling == coupling_level::full || kernel::layered(surfaces)) return std::nullopt;
    const neglected_layers layers = no_slip_layers(materials.beta_d, f);
    // The estimate the route reports (its xi the no-slip creep with the layers' shift; P_H/P2 Hertz's 1), as the
    // ladder compares it (edge_layers.hpp).
    return neglected_layers_relative(layers, no_slip_creep(materials.beta_d) + layers.xi_shift, 1.0);
}

// `relative` rounded up to two significant digits: the tolerance a refusal names.
std::string tolerance_up(double relative) { return significant(rounded_up(relative, 2), 2); }

// The advice of a refusal of such a point: the tolerance (two digits, rounded up) at which its layers
// would be neglected, and which of the route's estimates sets it; empty where the bound is no use
// (half of xi or more).
std::string layers_tolerance_advice(double relative, double beta_d, double f) {
    if (!(relative < 0.5)) return {};
    const std::string up = tolerance_up(relative);
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
// The crossing below which layer_change_lower_bound(t_c top^2) exceeds `tolerance` (< 0.3): where the rule refuses.
double unresolved_crossing(int top, double tolerance) {
    const double root_x = std::log(0.3 / tolerance) / 0.57;
    return std::min(root_x * root_x, layer_change_measured_to) / (static_cast<double>(top) * top);
}

// " (below about F at this tolerance)", F the friction `reach` below which the rule refuses no longer, rounded down to
// two digits so that the advice never names an f the rule refuses; empty where it is not known.
std::string reach_advice(std::optional<double> reach, const char* at) {
    if (!(reach && *reach > 0.0)) return {};
    const double unit = std::pow(10.0, std::floor(std::log10(*reach)) - 1.0);
    return std::string(" (below about ") + significant(std::floor(*reach / unit) * unit, 2) + " at " + at + ")";
}

// The advice of the quick refusal of rough rollers' free rolling (docs/formulation.md 8(n), "Rough rollers: beyond
// every n"): no route neglects their layers, so only a smaller f answers; `reach` the f below which the rule refuses
// no longer (the five zones resolved enough at the top rung, by the measured law), empty where it is not known.
std::string rough_layers_advice(std::optional<double> reach) {
    return "the edge layers of these rough rollers are resolved, and their free rolling may be answered by its five "
           "zones, only at a smaller friction f" +
           reach_advice(reach, "this tolerance") +
           "; no route neglects the layers of rough rollers (smooth rollers have one, 8(n))";
}

// The largest |Q/f| at which the law's tenth was compared with the leading slip zone's changes (8(n), "Beyond every
// n", item 7): the rule is asked at 0 < |Q/f| <= this only.
constexpr double loaded_law_measured_to = 0.5;

// Johnson's zones (dissimilar_zones) on the uncoupled pressure of a level: Johnson's level itself
// (uncoupled_model) and the start of full coupling's alternation (coupled_model).
class johnson_model : public point_model {
public:
    explicit johnson_model(const model_input& in)
        : point_model(in),
          normal_(level_normal(in)),
          tangential_(normal_, kernel::tangential(in.surfaces), kernel::normal(in.surfaces), in.f),
          zones_(tangential_, kernel::tangential(in.surfaces), in.materials.beta_d),
          layers_(layers_relative_bound(in.materials, in.surfaces, in.f)) {}

    const normal_solution& normal() const override { return normal_; }
    tangential_solver* tangential() override { return &tangential_; }
    const dissimilar_zones* johnson_zones() const override { return &zones_; }
    estimate_structure structure() const override { return estimate_structure::dissimilar; }
    double traction(const tangential_solution& d, double r) override { return zones_of_point().traction(d, r); }
    double slip_velocity(const tangential_solution& d, double r) override {
        return zones_of_point().slip_velocity(d, r);
    }
    std::vector<double> slip_velocity(const tangential_solution& d, const std::vector<double>& r) override {
        if (d.layout.opposite() || d.layout.layers_neglected()) return point_model::slip_velocity(d, r);
        return solver_of_point().slip_velocity(d, r);  // the collocation's sweep
    }

    // Johnson's point of this level from the zone ends of s (Newton).
    tangential_solution like(const tangential_solution& s, method how, int n) override {
        if (s.layout.stick_zones() != 2) return three(s.Q, s.layout.stick_ends(), s.layout.opposite());
        // Five zones (8(j)): the level from the point's ends (Newton), else its own search.
        const std::vector<double> ends = s.layout.stick_ends();
        rounding_limits met;
        if (std::optional<tangential_solution> t = five(s.Q, &ends, met)) return *t;
        if (met.met()) throw rounding_limit_error(met.refusal());
        throw resolution_error(no_honest_estimate(how, n, structure()) + "level " + std::to_string(nodes()) +
                               " finds no five zones at Q = " + shortest(s.Q) + " from level n's zones; " +
                               (n < max_nodes ? "another n (at most " + std::to_string(max_nodes) + ") may find them"
                                              : "n is at its largest, so the load is beyond the method's reach"));
    }

    std::optional<std::string> beyond_every_n(double Q, int top, double tolerance) const override {
        // Stick zones below the rounding (near complete slip) or at the leading edge (driven, next to sliding): no n
        // resolves them (8(f) "Below the rounding", 8(m) "Driven, next to sliding").
        if (std::optional<std::string> why = unresolvable(Q)) return why;
        // Free rolling of rough rollers: their own crossing decides (8(n), "Rough rollers: beyond every n"), before
        // item 11's estimate, which is the smooth pair's and 4.5 times too thick for them.
        if (Q == 0.0 && kernel::layered(surfaces_))
            if (std::optional<std::string> why = layers_beyond(Q, top, tolerance)) return why;
        // A leading slip zone thinner than the largest rung resolves (8(j) item 11): refused before any solve.
        if (!layers_negligible(Q)) {
            try {
                check_edge_zones(Q, top);
            } catch (const resolution_error& why) {
                return std::string(why.what());
            }
        }
        return layers_beyond(Q, top, tolerance);
    }

protected:
    // Free rolling whose layers the tolerance does not neglect (smooth rollers at Johnson's level) or cannot (rough
    // rollers, every level): the estimate at n is at least the change of 1 + s1 from n/2 (numerics/error_bound.hpp),
    // which the ladder compares with tolerance (1 + s1); no rung n <= top meets it where the top one does not.
    std::optional<std::string> layers_beyond(double Q, int top, double tolerance) const {
        // The law was measured on product integration.
        if (level_of(options_.how) != method::product) return std::nullopt;
        const std::optional<double> crossing = unresolved_layers(Q, tolerance);
        if (!crossing) return std::nullopt;
        const double x = *crossing * top * top;
        const double change = layer_change_lower_bound(x);
        if (!(change > tolerance)) return std::nullopt;
        std::ostringstream msg;
        msg.precision(2);
        const bool loaded = Q != 0.0;  // item 7: the leading slip zone of three zones (or five) at a load
        msg << "no n up to " << top << " meets the tolerance " << shortest(tolerance) << " (relative) for "
            << (loaded ? "Q/f = " + shortest(Q / f_) + " on" : std::string("free rolling of")) << " these rollers at f = "
            << shortest(f_) << ": " << (loaded ? "its slip zone at the leading edge, " : "its edge layers, ");
        if (*crossing > 0.0)
            msg << "about " << *crossing << " of the half-width,";
        else
            msg << "below the smallest double,";
        msg << (loaded ? " is" : " are") << " too thin (at n = " << top << " the "
            << (loaded ? "leading slip zone" : "five zones' leading layer") << " still changes by more than " << change
            << " of itself from n = " << top / 2 << ", docs/formulation.md 8(n))";
        const std::string advice =
            kernel::layered(surfaces_) ? rough_layers_advice(rough_reach(unresolved_crossing(top, tolerance)))
            : loaded                   ? loaded_advice(*crossing, unresolved_crossing(top, tolerance), change)
                                       : edge_zones_advice(Q);
        if (!advice.empty()) msg << "; " << advice;
        return msg.str();
    }
    // The advice of the rule's refusal at 0 < |Q/f| <= 1/2 (8(n) item 7): the leading slip zone estimated `zone` thick,
    // `edge` the thickness from which the top rung resolves it by the law; `change` the law's tenth there. No route
    // neglects that zone (8(n), "Not covered"), so a smaller f at the same Q/f (t(kappa) = 2 exp(-pi f kappa/|beta_D|),
    // kappa fixed by Q/f: the zone reaches `edge` at f log(2/edge)/log(2/zone)), a tolerance above the law's tenth (where
    // the ladder tries, and may answer), or free rolling (its layers neglected, 8(n)).
    std::string loaded_advice(double zone, double edge, double change) const {
        std::optional<double> reach;
        if (zone > 0.0 && edge > 0.0 && edge < 2.0) reach = f_ * std::log(2.0 / edge) / std::log(2.0 / zone);
        return "a smaller friction f resolves that zone" + reach_advice(reach, "this Q/f and tolerance") +
               "; at a tolerance above " + tolerance_up(change) +
               " (solver.tolerance, --tolerance) the ladder tries this point; free rolling (Q = 0) is answered with its "
               "edge layers neglected, a load at this f by no route that neglects the leading zone";
    }
    // Rough rollers: the friction at which the crossing falls to `crossing` (the rule's edge), where known.
    virtual std::optional<double> rough_reach(double crossing) const {
        // Johnson's level: below x0 the crossing is t_c = x0 exp(-(pi/|beta_D|)(f - g(x0))) (johnson_layers_crossing),
        // g(x0) of the no-slip solution, which does not depend on f: the f of a crossing c is g(x0) + (|beta_D|/pi)
        // log(x0/c).
        const layers_crossing& here = rough_crossing();
        if (!(crossing > 0.0 && crossing < here.x0)) return std::nullopt;
        return here.friction_at(crossing);
    }
    // Johnson's level, free rolling of rough rollers: the crossing of this level's no-slip solution, made once.
    const layers_crossing& rough_crossing() const {
        if (!rough_crossing_)
            rough_crossing_ = johnson_layers_crossing(normal_, kernel::tangential(surfaces_),
                                                      kernel::normal(surfaces_), materials_.beta_d, f_);
        return *rough_crossing_;
    }

    // `solve()`, its refusal (resolution_error) followed by what answers the load instead, where something does.
    template <class F>
    auto advised(double Q, F&& solve) const -> decltype(solve()) {
        try {
            return solve();
        } catch (const resolution_error& why) {
            const std::string advice = edge_zones_advice(Q);
            if (advice.empty()) throw;
            throw resolution_error(std::string(why.what()) + "; " + advice);
        }
    }
    // Stick zones no n resolves at this load (unresolvable_zones.hpp), or its refusal's line.
    std::optional<std::string> unresolvable(double Q) const {
        return unresolvable_zones(materials_, kernel::layered(surfaces_), f_, Q);
    }
    // unresolvable (at every n), then check_edge_zones_resolvable at n, advised: before any solve of a point.
    void check_edge_zones(double Q, int n) const {
        if (std::optional<std::string> why = unresolvable(Q)) throw resolution_error(*why);
        advised(Q, [&] {
            check_edge_zones_resolvable(materials_.beta_d, f_, Q, n, options_.tolerance.value_or(default_tolerance));
        });
    }
    // The crossing t_c of the edge layers whose resolution beyond_every_n bounds (free rolling of smooth rollers),
    // where the point needs them resolved: at Johnson's level where the tolerance does not neglect them.
    virtual std::optional<double> unresolved_layers(double Q, double tolerance) const {
        // Rough rollers: no layers-neglected route, so always resolved, at their own crossing (8(n), "Rough rollers").
        if (Q == 0.0 && kernel::layered(surfaces_)) return rough_crossing().crossing;
        // A load on smooth rollers at Johnson's level: the leading slip zone, about 0.54 t(kappa) (8(j) item 11) thick,
        // has no route that neglects it, and its changes obey the law on the scale t(kappa) (8(n) item 7, measured at
        // 0 < |Q/f| <= 1/2).
        if (Q != 0.0) {
            if (materials_.beta_d == 0.0 || materials_.coupling == coupling_level::full || kernel::layered(surfaces_) ||
                !(std::fabs(Q) <= loaded_law_measured_to * f_))
                return std::nullopt;
            return leading_zone_estimate(materials_.beta_d, f_, Q);
        }
        const std::optional<double> bound = layers_bound(Q);
        if (!bound || *bound <= tolerance) return std::nullopt;
        return no_slip_layers(materials_.beta_d, f_).crossing;
    }
    // At Johnson's level: free rolling of smooth rollers, the tolerance at which its layers would be neglected.
    virtual std::string edge_zones_advice(double Q) const {
        const std::optional<double> bound = layers_bound(Q);
        return bound ? layers_tolerance_advice(*bound, materials_.beta_d, f_) : std::string();
    }
    // The zones and solver a solution of this model is evaluated with (full coupling's after its point).
    virtual dissimilar_zones& zones_of_point() { return zones_; }
    virtual tangential_solver& solver_of_point() { return tangential_; }

    // Johnson's point at Q of this level: the estimate's levels `below` first, coarsest first, each from
    // the zone of the level below (Newton), so that only the coarsest scans the starts of the stick zone.
    // `previous`: a curve's previous row (contact::continued_point), whose zones start the coarsest level.
    tangential_solution johnson_point(double Q, const std::vector<johnson_model*>& below,
                                      const tangential_solution* previous = nullptr);

    // The edge layers' bound on xi relative to the no-slip creep for free rolling of smooth rollers at
    // Johnson's level (8(n)); empty for any other load, pair or level.
    std::optional<double> layers_bound(double Q) const { return Q == 0.0 ? layers_ : std::nullopt; }
    // Layers that move xi, and the zone ends, by less than the tolerance: the no-slip solution with them
    // neglected answers.
    bool layers_negligible(double Q) const {
        const std::optional<double> relative = layers_bound(Q);
        return relative && *relative <= options_.tolerance.value_or(default_tolerance);
    }

    normal_solution normal_;
    tangential_solver tangential_;
    dissimilar_zones zones_;

private:
    // Three zones at Q on this level (dissimilar_zones::solve), cached per Q.
    const tangential_solution& three(double Q, const std::vector<double>& ends, bool opposite) {
        checkpoint();
        if (!last_three_ || !(last_three_->Q == Q)) last_three_ = zones_.solve(Q, ends, opposite);
        return *last_three_;
    }
    // Five zones (docs/formulation.md 8(j)) at Q on this level, from `ends` (s1, c1, s2, c2: the coarser level's)
    // when given, as the point at the load asked (Newton's differs by its residual, 1e-17 at Q = 0; full
    // coupling's alternation solves at Q); empty when none are found (the rounding limits met on the way noted in
    // `met`). Cached per Q.
    std::optional<tangential_solution> five(double Q, const std::vector<double>* ends, rounding_limits& met) {
        checkpoint();
        if (!(last_five_ && last_five_load_ == Q)) {
            std::optional<tangential_solution> v;
            try {
                // From the coarser level's ends first (Newton, as the three-zone levels); on a curve the previous
                // row's five zones continued in the load next (a start only: the root is the same to Newton's
                // tolerance, validation/test_dissimilar_curve.cpp); then the search's own (zone_start.hpp, 8(j) 4a).
                std::vector<five_zone_start> first;
                if (ends) first.push_back(five_zone_start::at_ends(*ends));
                if (last_five_) first.push_back(five_zone_start::continuing(*last_five_));
                v = zones_.five_zones(Q, std::move(first), &met);
            } catch (const numerical_error&) {
                v.reset();  // no five zones found on this level
            }
            if (!v) return std::nullopt;
            last_five_ = v;
            last_five_load_ = Q;
        }
        tangential_solution s = *last_five_;
        s.Q = Q;
        return s;
    }
    // The point of five zones at Q, the levels `below` first (each from the ends of the one below it);
    // empty where none are found (the rounding limits met on the way noted in `met`), or at |Q| >= f, where none are
    // searched.
    std::optional<tangential_solution> five_point(double Q, const std::vector<johnson_model*>& below,
                                                  rounding_limits& met);
    // The point of five zones at Q by Newton alone on every level, the coarsest from `ends` (a curve's previous
    // row, continued in the load), each other from the level below; empty where Newton does not converge on a
    // level or the checks of this level's zones fail, with no level's cache touched: the point's own search
    // then answers. Kept as each level's five zones at Q where it answers (the estimate's levels reuse them). A
    // Newton stopped at the ends' rounding limit is noted in `met`.
    std::optional<tangential_solution> five_continued(double Q, const std::vector<johnson_model*>& below,
                                                      std::vector<double> ends, rounding_limits& met);

    // Whether this level holds five zones at Q whose checks (3.3)-(3.4) hold (its point's, or a level's of an
    // estimate, cached by five or five_continued).
    bool five_hold(double Q) const { return last_five_ && last_five_load_ == Q && last_five_->checks.hold(); }

    std::optional<double> layers_;
    mutable std::optional<layers_crossing> rough_crossing_;  // rough_crossing's, once asked
    std::optional<tangential_solution> last_three_;
    std::optional<tangential_solution> last_five_;
    double last_five_load_ = 0.0;  // the load it was asked for
};

tangential_solution johnson_model::johnson_point(double Q, const std::vector<johnson_model*>& below,
                                                 const tangential_solution* previous) {
    std::vector<double> guess;  // the ends of a zone near the one sought, Newton's start (empty: none)
    bool opposite = false;
    // The ends' rounding limit met by a route below (zone_newton.hpp): the refusal where no route answers.
    rounding_limits met;
    // A curve's previous row as the coarsest level's start (zone_start.hpp: a layout already solved, continued in
    // the load; 8(j) 10): its five zones by Newton from their ends, its three zones as the zone search's guess
    // (zone_solver: Newton, the scan where Newton fails or lands on a zone failing the checks). Rows of gross
    // sliding or of the edge layers neglected (8(n)) give no start.
    if (previous && std::fabs(previous->Q) < f_ && std::fabs(Q) < f_ && !previous->layout.layers_neglected()) {
        if (previous->layout.stick_zones() == 2) {
            if (std::optional<tangential_solution> s = five_continued(Q, below, previous->layout.stick_ends(), met))
                return *s;
        } else if (previous->layout.stick_zones() == 1 && previous->start() > -1.0) {
            guess = previous->layout.stick_ends();
            opposite = previous->layout.opposite();
        }
    }
    // Where the finest level below holds five zones at Q whose checks hold (a coarser rung of the ladder answered this
    // load with them: its levels are this rung's, 8(q) "The rungs share their levels"), this level's five zones from
    // them first, and three zones only where these are not found or fail their checks. The three zones' search
    // (zone_solver: Newton from the coarser level's three zones, which fail the checks there, then the scan of every
    // start, for both structures) was a fifth of the driven point (docs/performance.md, session 23); where its zones hold
    // their checks at a level whose five zones hold theirs too, the discretisation has both structures' roots, and
    // either is a point of the model at this n (the transitions of 8(j) 4a, where the two meet).
    if (!below.empty() && below.back()->five_hold(Q)) {
        rounding_limits tried;  // a route that does not answer here is the search below's, with its own notes
        try {
            if (std::optional<tangential_solution> s = five_point(Q, below, tried)) return *s;
        } catch (const resolution_error&) {  // five zones failing the checks at this n: the three zones' search next
        }
    }
    for (johnson_model* level : below) {
        try {
            const tangential_solution& t = level->three(Q, guess, opposite);
            guess = t.layout.stick_ends();
            opposite = t.layout.opposite();
        } catch (const resolution_error&) {  // no three zones on this level: the next searches without a guess
            guess.clear();
        } catch (const numerical_error&) {
            guess.clear();
        }
    }
    // Free rolling, no three zones, or three zones that fail (3.3)-(3.4) (resolution_error), or a
    // numerical fault of their search: five zones (|Q| < f; on the braked side, Q/sgn(beta_D) < 0,
    // until the slip+ zone closes, 8(j) 4a). Where none are found either, the first error stands: a fault
    // aborts; a structure not found at this n is a refusal (a curve's refused row, docs/robustness.md),
    // saying so, or the ends' rounding limit where a route met it. Each `throw;` is inside the handler of the error it
    // rethrows (outside one it terminates).
    try {
        tangential_solution s = three(Q, guess, opposite);
        require_checks(s);  // a point reported holds (3.3)-(3.4); a level of its estimate need not
        return s;
    } catch (const rounding_limit_error&) {  // its line says what to change; not "another n"
        if (std::optional<tangential_solution> s = five_point(Q, below, met)) return *s;
        throw;
    } catch (const resolution_error& why) {
        if (std::optional<tangential_solution> s = five_point(Q, below, met)) return *s;
        if (met.met()) throw rounding_limit_error(met.refusal());
        if (!(std::fabs(Q) < f_)) throw;
        throw resolution_error(std::string(why.what()) +
                               "; no five zones (slip, stick, reversed slip, stick, slip) are found at n = " +
                               std::to_string(nodes()) +
                               " either (their search starts from the coarser levels' zones): " +
                               (nodes() < max_nodes
                                    ? "a larger n (at most " + std::to_string(max_nodes) + ") may find them"
                                    : std::string("n is at its largest, so the load is beyond the method's reach")));
    } catch (const numerical_error&) {
        if (std::optional<tangential_solution> s = five_point(Q, below, met)) return *s;
        throw;
    }
}

std::optional<tangential_solution> johnson_model::five_continued(double Q, const std::vector<johnson_model*>& below,
                                                                 std::vector<double> ends, rounding_limits& met) {
    std::vector<johnson_model*> levels = below;
    levels.push_back(this);
    std::vector<tangential_solution> found;
    for (johnson_model* level : levels) {
        level->checkpoint();
        std::optional<tangential_solution> v;
        try {
            v = level->zones_.five_zones(Q, ends, std::nullopt, &met);  // Newton from the ends, empty where it fails
        } catch (const numerical_error&) {
        }
        if (!v) return std::nullopt;
        ends = v->layout.stick_ends();
        found.push_back(std::move(*v));
    }
    tangential_solution s = found.back();
    s.Q = Q;  // as five_point: the load asked for
    // A root whose checks fail is another structure's (the transitions of 8(j) 4a): the point's search decides.
    if (!s.checks.hold()) return std::nullopt;
    for (std::size_t i = 0; i < levels.size(); ++i) {
        levels[i]->last_five_ = std::move(found[i]);
        levels[i]->last_five_load_ = Q;
    }
    return s;
}

std::optional<tangential_solution> johnson_model::five_point(double Q, const std::vector<johnson_model*>& below,
                                                             rounding_limits& met) {
    if (!(std::fabs(Q) < f_)) return std::nullopt;
    std::vector<double> ends;
    for (johnson_model* level : below) {
        const std::optional<tangential_solution> v = level->five(Q, ends.empty() ? nullptr : &ends, met);
        ends = v ? v->layout.stick_ends() : std::vector<double>{};
    }
    std::optional<tangential_solution> s = five(Q, ends.empty() ? nullptr : &ends, met);
    if (!s) return std::nullopt;
    // Failing checks on a converged root: zones thinner than n resolves (f = 0.3 for aluminium
    // on steel at n = 32, 8(j) 4a), or Newton from under-resolved coarser ends landing on another
    // root (f = 0.425..0.5 at n = 1000, 8(n) "Beyond every n"); a resolution_error either way (a
    // curve's row is refused, not the curve).
    if (!s->checks.hold())
        throw resolution_error("dissimilar rollers at Q/f = " + shortest(Q / f_) +
                               ": the five zones (slip, stick, reversed slip, stick, slip) fail the checks "
                               "(3.3)-(3.4) (margins: " + margins_text(s->checks) +
                               "): a zone is below the collocation's resolution at n = " + std::to_string(nodes()) +
                               ", or the search from the coarser levels' zones found other five zones than the "
                               "physical ones (docs/formulation.md 8(j), 8(n)); " +
                               (nodes() < max_nodes
                                    ? "a larger n (at most " + std::to_string(max_nodes) + ") may resolve it"
                                    : "n is at its largest, so this load is beyond the method's reach"));
    return s;
}

// Johnson's level (8(g)-8(n)); its levels are Johnson's levels.
class uncoupled_model final : public johnson_model {
public:
    explicit uncoupled_model(const model_input& in) : johnson_model(in), levels_(*this, in.cache) {}
    point_model& level(int m) override { return levels_.at(m); }
    tangential_solution point(double Q, const std::function<std::vector<int>()>& below) override {
        return solved(Q, below, nullptr);
    }
    tangential_solution continued(double Q, const tangential_solution& previous,
                                  const std::function<std::vector<int>()>& below) override {
        return solved(Q, below, &previous);
    }

private:
    tangential_solution solved(double Q, const std::function<std::vector<int>()>& below,
                               const tangential_solution* previous) {
        if (layers_negligible(Q)) return zones_.layers_neglected_point();
        // Free rolling of smooth rollers whose layers are too thin for n but too thick for the tolerance
        // (docs/formulation.md 8(n)): any refusal names the tolerance at which they would be neglected.
        // Edge zones far below what the search finds (|beta_D| small against f): refused before any solve.
        check_edge_zones(Q, nodes());
        return advised(Q, [&] { return johnson_point(Q, levels_.at<johnson_model>(below()), previous); });
    }

    model_levels<uncoupled_model> levels_;
};

// Full coupling (docs/formulation.md 8(e)): the alternation from Johnson's point on this level, cached per Q;
// its levels are full coupling's, each from its own Johnson's point.
class coupled_model final : public johnson_model {
public:
    explicit coupled_model(const model_input& in)
        : johnson_model(in),
          johnson_layers_(
              layers_relative_bound(dissimilar{in.materials.beta_d, coupling_level::johnson}, in.surfaces, in.f)),
          levels_(*this, in.cache),
          coupling_(kernel::tangential(in.surfaces), kernel::normal(in.surfaces), in.options.nodes(),
                    level_of(in.options.how), in.f, in.materials.beta_d) {
        // Smooth rollers (johnson_layers_ is empty for rough ones): the no-slip limit's route and its bound (8(t)).
        if (johnson_layers_) {
            const neglected_layers l = coupled_no_slip_layers(in.materials.beta_d, in.f);
            const no_slip_coupled_solution limit = no_slip_coupled(in.materials.beta_d, kernel{}, kernel{}, 0);
            no_slip_relative_ = neglected_layers_relative(l, limit.xi, limit.load_ratio);  // as the ladder sees it
        }
    }

    // After a point the coupled pressure of that point (not extrapolated); before, Johnson's.
    const normal_solution& normal() const override {
        if (no_slip_) return no_slip_->normal;
        return load_ ? coupling_.normal() : normal_;
    }
    const coupling_summary* coupling() const override {
        if (no_slip_) return &no_slip_->summary;
        return load_ ? &coupling_.summary() : nullptr;
    }
    estimate_structure structure() const override { return estimate_structure::full_coupling; }
    void set_checkpoint(std::function<void()> hook) override {
        coupling_.set_checkpoint(hook);
        point_model::set_checkpoint(std::move(hook));
    }

    point_model& level(int m) override { return levels_.at(m); }
    tangential_solution point(double Q, const std::function<std::vector<int>()>& below) override {
        no_slip_.reset();
        if (no_slip_negligible(Q)) return no_slip_point();
        // The levels levels_before solved at this Q are used once (the ladder's rule (a'), 8(q)): the same work,
        // in the same order, as solving them here.
        std::optional<levels_solved> solved;
        if (before_ && before_->Q == Q) solved = std::move(before_);
        before_.reset();
        if (!solved) solved = solve_levels(Q, below);
        try {
            return coupled(Q, solved->johnson, true, solved->start);
        } catch (const alternation_error& e) {
            // The estimate's levels' alternations did not converge either: the ladder reads it over two rungs (8(q),
            // "An alternation that converges at no level").
            throw alternation_error(e.what(), solved->none_converged);
        }
    }
    std::vector<estimate_level> levels_before(double Q, const std::function<std::vector<int>()>& below) override {
        no_slip_.reset();
        before_.reset();
        if (no_slip_negligible(Q)) return {};
        before_ = solve_levels(Q, below);
        std::vector<estimate_level> levels;
        for (coupled_model* level : levels_.at(below())) {
            if (!(level->load_ && *level->load_ == Q)) return {};  // failed: the estimate asks it again
            levels.push_back({level->point_, level->normal().lambda});
        }
        return levels;
    }
    std::optional<std::string> beyond_every_n(double Q, int top, double tolerance) const override {
        if (no_slip_negligible(Q)) return std::nullopt;  // answered by the no-slip limit, no rung solved
        return johnson_model::beyond_every_n(Q, top, tolerance);
    }
    double traction(const tangential_solution& d, double r) override {
        if (no_slip_ && d.layout.layers_neglected())
            return coupled_no_slip_traction(no_slip_->limit, f_, no_slip_->normal.pressure(r), r);
        return johnson_model::traction(d, r);
    }
    tangential_solution like(const tangential_solution& s, method how, int n) override {
        no_slip_.reset();
        // The level's own alternation from its own Johnson's point (a Johnson's point against a coupled n
        // would measure the coupling, not the discretisation). A level that cannot be coupled leaves no
        // honest estimate (the point itself was).
        try {
            return coupled(s.Q, johnson_model::like(s, how, n), false);
        } catch (const numerical_error& why) {
            throw resolution_error(no_honest_estimate(how, n, estimate_structure::full_coupling) + "level " +
                                   std::to_string(nodes()) + ": " + why.what());
        }
    }

protected:
    // Free rolling of smooth rollers: no layers-neglected route, so always resolved, at the full level's crossing
    // (8(p) "The edges"; 8(n) "Beyond every n", at full coupling, where the leading layer's changes lie above
    // Johnson's law).
    std::optional<double> unresolved_layers(double Q, double) const override {
        // Rough rollers: the crossing of the no-slip limit with their layers (8(t), item 1; no route neglects them).
        if (Q == 0.0 && kernel::layered(surfaces_)) return rough_limit().crossing(f_);
        if (!(Q == 0.0 && johnson_layers_)) return std::nullopt;
        return coupled_layers_crossing(materials_.beta_d, f_);
    }
    // The f at which the limit's crossing falls to `crossing` (it falls as f grows: atan f, 8(t) item 1), by bisection
    // on (0, f]; the rule refuses f, so its crossing is below `crossing`.
    std::optional<double> rough_reach(double crossing) const override {
        const no_slip_coupled_solution& limit = rough_limit();
        double lo = 0.0, hi = f_;
        if (!(limit.crossing(hi) < crossing)) return std::nullopt;
        for (int i = 0; i < 60 && hi - lo > 1e-6 * hi; ++i) {
            const double mid = 0.5 * (lo + hi);
            (mid > 0.0 && limit.crossing(mid) < crossing ? hi : lo) = mid;
        }
        return lo;
    }
    // The no-slip limit at full coupling with the scene's layers (8(t)): n = 64 puts its lambda and xi within 3e-9 of
    // the extrapolated ones (8(t)'s table), phi(-1), which sets the crossing, likewise. Made once.
    const no_slip_coupled_solution& rough_limit() const {
        if (!rough_limit_)
            rough_limit_ = no_slip_coupled(materials_.beta_d, kernel::tangential(surfaces_), kernel::normal(surfaces_), 64);
        return *rough_limit_;
    }
    // Free rolling of smooth rollers: the no-slip limit at the tolerance its bound meets (8(t)), or Johnson's level
    // with its edge layers neglected (8(n)), at the tolerance it names where the default does not neglect them.
    std::string edge_zones_advice(double Q) const override {
        if (!(Q == 0.0 && johnson_layers_)) return {};
        if (no_slip_relative_ && *no_slip_relative_ < 0.5)
            return "a tolerance of " + tolerance_up(*no_slip_relative_) +
                   " or more (solver.tolerance, --tolerance; n not given) answers this free rolling with its edge "
                   "layers neglected (the no-slip limit at full coupling, docs/formulation.md 8(t)); coupling = "
                   "\"johnson\" answers it with the pressure uncoupled (8(n))";
        if (*johnson_layers_ <= options_.tolerance.value_or(default_tolerance))
            return "coupling = \"johnson\" answers this free rolling with its edge layers neglected and the pressure "
                   "uncoupled (docs/formulation.md 8(n))";
        const std::string advice = layers_tolerance_advice(*johnson_layers_, materials_.beta_d, f_);
        return advice.empty() ? advice : "with coupling = \"johnson\", " + advice;
    }

    dissimilar_zones& zones_of_point() override { return load_ ? coupling_.zones() : zones_; }
    tangential_solver& solver_of_point() override { return load_ ? coupling_.tangential() : tangential_; }

private:
    // Johnson's point of this level at Q and the estimate's levels below it, coarsest first, each alternation from the
    // one below (8(e), "The start from the coarser level"); a level that fails leaves the next to Johnson's point (and
    // its refusal to the estimate, which asks it again). `start`: the finest level's alternation, this level's start.
    struct levels_solved {
        double Q;
        tangential_solution johnson;
        const full_coupling* start;
        bool none_converged;  // every level's alternation stopped without converging (full_coupling::did_not_converge)
    };
    levels_solved solve_levels(double Q, const std::function<std::vector<int>()>& below) {
        check_edge_zones(Q, nodes());
        const std::vector<int> ms = below();
        tangential_solution johnson = johnson_point(Q, levels_.at<johnson_model>(ms));
        const std::vector<coupled_model*> levels = levels_.at(ms);
        const full_coupling* start = levels.empty() ? nullptr : finest_solved_below(Q, levels.front()->nodes());
        bool none_converged = !levels.empty();
        for (coupled_model* level : levels) {
            bool alternated = false;  // the failure, if any, is the level's alternation's (not Johnson's point's)
            try {
                const tangential_solution& from = level->johnson_model::like(johnson, options_.how, nodes());
                alternated = true;
                level->coupled(Q, from, false, start);
                start = &level->coupling_;
                none_converged = false;
            } catch (const numerical_error&) {
                start = nullptr;
                none_converged = none_converged && alternated && level->coupling_.did_not_converge();
            } catch (const resolution_error&) {
                start = nullptr;
                none_converged = none_converged && alternated && level->coupling_.did_not_converge();
            }
        }
        return {Q, std::move(johnson), start, none_converged};
    }

    // The start of this chain's coarsest level `coarsest` where it is not solved at Q yet: the converged alternation at
    // Q of the finest other level of the ladder below this one (docs/formulation.md 8(q), "The top rung's levels from the
    // finest coupled rung"; its p1 is a function of r, read at any n, 8(e) "The start from the coarser level"), else
    // none (Johnson's point). Rung 1000's levels 250, 500 double no rung: from their own Johnson's five zones the
    // alternation loses them where the chain 32 .. 256 follows them (free rolling of the pair at f = 0.3).
    const full_coupling* finest_solved_below(double Q, int coarsest) {
        if (levels_.at(coarsest).load_ == std::optional<double>(Q)) return nullptr;  // solved: kept, as before
        const coupled_model* finest = nullptr;
        for (point_model* m : stored_alike()) {
            const auto* c = dynamic_cast<const coupled_model*>(m);
            if (c && c->nodes() < nodes() && c->load_ == std::optional<double>(Q) && !c->no_slip_ &&
                (!finest || c->nodes() > finest->nodes()))
                finest = c;
        }
        return finest ? &finest->coupling_ : nullptr;
    }

    // Free rolling of smooth rollers whose edge layers the tolerance neglects at full coupling (8(t)): every
    // relative bound of the no-slip limit's route within it.
    bool no_slip_negligible(double Q) const {
        return Q == 0.0 && no_slip_relative_ && *no_slip_relative_ <= options_.tolerance.value_or(default_tolerance);
    }
    // That route's point: the closed form of 8(p) (no_slip_coupled at n = 0, exact for smooth rollers), its pressure at
    // this level's nodes, reported as stick on [-1, 1] with the layers neglected.
    tangential_solution no_slip_point() {
        checkpoint();
        no_slip_coupled_solution limit = no_slip_coupled(materials_.beta_d, kernel{}, kernel{}, 0);
        normal_solution normal = no_slip_normal(limit, nodes(), options_.how);
        coupling_summary summary;
        summary.offset = limit.offset;
        summary.lambda_johnson = normal_.lambda;
        // 8(p), "The width and the peak": the peak at the centre, (2/pi) lambda cosh(pi eps), against Hertz's 2/pi,
        // at the same P2: (p_max/p_max,J) sqrt(lambda_J/lambda) - 1 (coupling_summary.hpp).
        summary.peak_pressure_change = std::sqrt(limit.load_ratio / normal_.lambda) * std::cosh(M_PI * limit.epsilon) - 1.0;
        tangential_solution s = coupled_no_slip_point(limit, f_, normal, tangential_.rounding(0.0));
        no_slip_ = no_slip_route{std::move(limit), std::move(normal), std::move(summary)};
        return s;
    }

    // The coupled point at Q from Johnson's point `johnson` of this level; `checked` as
    // full_coupling::solve (the cache keeps a checked point for an unchecked call).
    const tangential_solution& coupled(double Q, const tangential_solution& johnson, bool checked,
                                       const full_coupling* start = nullptr) {
        checkpoint();
        if (load_ && *load_ == Q && (checked_ || !checked)) return point_;
        load_.reset();  // Johnson's pressure and zones until the alternation has converged
        point_ = coupling_.solve(normal_, zones_, johnson, checked, start);
        load_ = Q;
        checked_ = checked;
        return point_;
    }

    std::optional<double> johnson_layers_;  // layers_relative_bound at Johnson's level, for the advice
    std::optional<double> no_slip_relative_;  // the no-slip limit's largest relative bound (smooth rollers), 8(t)
    mutable std::optional<no_slip_coupled_solution> rough_limit_;  // rough_limit's, once asked
    struct no_slip_route {
        no_slip_coupled_solution limit;
        normal_solution normal;
        coupling_summary summary;
    };
    std::optional<no_slip_route> no_slip_;  // the last point's, where that route answered it
    std::optional<levels_solved> before_;   // levels_before's, for the next point at its Q
    model_levels<coupled_model> levels_;
    full_coupling coupling_;
    std::optional<double> load_;  // the load of the last coupled point; empty: none solved
    tangential_solution point_;
    bool checked_ = false;
};

}  // namespace

std::unique_ptr<point_model> make_dissimilar_model(const model_input& in) {
    if (in.materials.coupling == coupling_level::full) return std::make_unique<coupled_model>(in);
    return std::make_unique<uncoupled_model>(in);
}

}  // namespace roughroll
