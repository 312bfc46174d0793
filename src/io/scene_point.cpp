// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/io/scene_point.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <utility>

#include "roughroll/base/error.hpp"
#include "roughroll/numerics/quadrature.hpp"
#include "roughroll/problems/contact_internals.hpp"
#include "roughroll/problems/creep_curve.hpp"
#include "roughroll/problems/load_ratio.hpp"
#include "roughroll/problems/level_ladder.hpp"

namespace roughroll {

void override_solver(scene& s, std::optional<int> n, const std::optional<std::string>& method_name,
                     const std::optional<std::string>& zones_name, std::optional<double> tolerance) {
    if (n && tolerance)
        throw input_error("n and tolerance: give one (n fixes the nodes; the tolerance lets the ladder choose n)");
    if (n) {
        check_node_count(*n);  // 0 would otherwise mean the method's default
        s.solver.n = *n;
        s.solver.tolerance.reset();
    }
    if (tolerance) {
        check_tolerance(*tolerance, "tolerance");
        s.solver.tolerance = *tolerance;
        s.solver.n = 0;  // the ladder chooses n (over the scene's solver.n)
    }
    if (method_name) s.solver.how = method_from_string(*method_name);
    if (zones_name) s.solver.zones = zone_search_from_string(*zones_name);
}

bool width_follows_tangential_load(const scene& s) {
    return s.physical && s.physical->width == width_rule::given_load && s.materials.beta_d != 0.0 &&
           s.materials.coupling == coupling_level::full;
}

namespace {
bool same_roughness(const roughness& x, const roughness& y) {
    const auto term = [](const roughness_term& u, const roughness_term& v) { return u.T == v.T && u.A == v.A; };
    const auto cylinder = [&term](const cylinder_roughness& u, const cylinder_roughness& v) {
        return term(u.tangential, v.tangential) && term(u.normal, v.normal);
    };
    return cylinder(x.cylinder1, y.cylinder1) && cylinder(x.cylinder2, y.cylinder2);
}

// The width of a physical scene at full coupling, which follows the load Q (docs/formulation.md 8(e); 2(j) "The coupled
// width on a ladder"): the root of lambda_n(x) = x^2 with lambda_n the coupled point's P_H/P2 at Q, polished by secant
// steps from the root of the cheap level, Johnson's P_H/P2 (the pressure alone, normal problems only) plus `shift`, to
// find_width's step rule (1e-12 in x, as from Johnson's root: the same root, the start alone is better).
// The coupled points are solved through `levels` (a ladder's store, or one of their own), so that the contact built at
// the width found takes the last one's levels and point (the root the polish returns is the last width it solved at):
// none solved again. `shift`: the coupled P_H/P2 less Johnson's at the rung below's width (0: none known), which moves
// the cheap root from Johnson's (1e-3 away at beta_D f ~ 1e-2) to within the coupling's own level change of the coupled
// root (4e-9 relative at n = 256 on the rough pair), so that the polish needs fewer coupled points.
// `shift_found`: the same difference at the width found (nothing where it is not a width the search solved at).
contact_width coupled_width(scene& s, normal_cache* cache, double Q, const std::function<void()>& checkpoint,
                            const std::shared_ptr<level_store>& levels, double shift,
                            std::optional<double>* shift_found = nullptr) {
    const auto pressure_alone = [&s, cache](const roughness& r) { return load_ratio(r, s.solver, cache); };
    std::optional<std::pair<roughness, double>> last;  // the last coupled point's roughness and P_H/P2
    const contact_width w = find_width(
        *s.physical,
        [&](const roughness& r) {
            last.reset();
            contact c = contact_internals::with_levels(r, s.friction, s.solver, s.materials, cache, levels);
            c.set_checkpoint(checkpoint);
            c.point(Q);
            last = std::make_pair(r, c.normal().lambda);
            return last->second;
        },
        [&pressure_alone, shift](const roughness& r) { return pressure_alone(r) + shift; }, true);
    s.surfaces = roughness_at(*s.physical, w.a);
    if (shift_found) {
        shift_found->reset();
        if (last && same_roughness(last->first, s.surfaces))
            *shift_found = last->second - pressure_alone(s.surfaces);
    }
    return w;
}
}  // namespace

std::optional<contact_width> settle_width(scene& s, normal_cache* cache, std::optional<double> Q,
                                          const std::function<void()>& checkpoint) {
    if (!s.physical) return std::nullopt;
    // lambda = P_H/P2 at a trial width, as the scene's method reports it (the normal problem alone),
    // searched on the method's cheap level n/2 first and polished at the scene's method; the
    // trials share their product-integration workspaces (collocation.hpp).
    normal_cache own;
    normal_cache* shared = cache ? cache : &own;
    const auto pressure_alone = [&s, shared](const roughness& r) { return load_ratio(r, s.solver, shared); };
    contact_width w;
    if (width_follows_tangential_load(s)) {
        if (!Q) throw input_error("the width of a physical scene at full coupling follows the tangential load: give Q");
        // Full coupling: lambda of the coupled point at Q (docs/formulation.md 8(e)); Johnson's
        // level (the pressure alone) is the cheap level whose root starts the secant polish.
        if (!smooth(*s.physical)) return coupled_width(s, shared, *Q, checkpoint, std::make_shared<level_store>(), 0.0);
        const double load = *Q;
        w = find_width(
            *s.physical,
            [&s, shared, load, &checkpoint](const roughness& r) {
                return coupled_load_ratio(r, s.friction, s.solver, s.materials, load, shared, checkpoint);
            },
            pressure_alone, true);
    } else {
        w = find_width(*s.physical, pressure_alone,
                       [&s, shared](const roughness& r) { return coarse_load_ratio(r, s.solver, shared); });
    }
    s.surfaces = roughness_at(*s.physical, w.a);
    return w;
}

namespace {
// The relative step of the width's finite difference (docs/formulation.md 2(j) "The width's error"): far above the
// quantities' noise (zone ends ~1e-9 against changes ~1e-7 at this step), far below the widths' curvature scale.
constexpr double width_step = 1e-6;

// The width's error in the estimate of a physical scene whose roughness follows the width (docs/formulation.md 2(j)
// "The width's error"): the levels of the estimate are all solved at level n's width x = a/a_H, while x itself is
// the root of lambda_n(x) = x^2 and carries lambda_n's error e_lambda as dx = e_lambda / |2x - lambda'(x)|. Each
// quantity's sensitivity to x is a forward difference at level n, one point at x (1 + width_step), and each
// estimate gains |dq/dx| dx; P_H/P2 = x^2 itself is off by 2x dx. None where T, A do not depend on the width
// (smooth rollers, the paper's Hertz width). At full coupling the printed p(0) and measured values (offset e, Johnson's
// P_H/P2: error_estimate::coupling, 8(e)) gain the same term, read at the moved point.
contact::estimate_term width_error(const scene& s, const contact_width& w, const std::function<void()>& checkpoint) {
    if (!s.physical || smooth(*s.physical) || s.physical->width == width_rule::hertz) return {};
    // The contact at the moved width, built once: a curve's rows share its normal problem (and a ladder's repeated
    // estimates of one rung their point).
    auto held = std::make_shared<std::unique_ptr<contact>>();
    return [s, w, checkpoint, held](const tangential_solution& t, const normal_solution& p,
                                    const coupling_summary* alternation, error_estimate& e, bool swept) {
        const double x = w.a / w.a_hertz, step = width_step * x;
        if (!*held) {
            *held = std::make_unique<contact>(roughness_at(*s.physical, (x + step) * w.a_hertz), s.friction, s.solver,
                                              s.materials);
            (*held)->set_checkpoint(checkpoint);
        }
        contact& moved = **held;
        // A point swept in c0 (contact::at_stick_end) is moved at its c0, which is given, not solved: its Q and xi
        // follow the width there (reported as the sweep reports them, Richardson's where the method extrapolates).
        const tangential_solution m =
            swept ? contact_internals::reported_at_stick_end(moved, t.c0()) : moved.point(t.Q);
        const double slope = (moved.normal().lambda - p.lambda) / step - 2.0 * x;  // F'(x), F = lambda_n(x) - x^2
        const double dx = e.lambda / std::fabs(slope);
        const double k = dx / step;  // per unit change over the step
        e.lambda = std::max(e.lambda, 2.0 * x * dx);
        e.xi += k * std::fabs(m.xi - t.xi);
        if (swept) {
            e.Q += k * std::fabs(m.Q - t.Q);
            return;  // c0 exact, the paper's zone from r = -1, and no peak printed (estimate_from)
        }
        e.c0 += k * std::max(std::fabs(m.c0() - t.c0()), std::fabs(m.end2() - t.end2()));
        if (e.start != 0.0) e.start += k * std::max(std::fabs(m.start() - t.start()), std::fabs(m.start2() - t.start2()));
        if (e.peak) {
            const pressure_peak at = peak_of(p), near = peak_of(moved.normal());
            e.peak->r += k * std::fabs(near.r - at.r);
            e.peak->p += k * std::fabs(near.p - at.p);
            e.peak->centre += k * std::fabs(near.centre - at.centre);
        }
        // NaN (no estimate: gamma_0n, the peak's change at full coupling) stays NaN.
        if (e.coupling && alternation && moved.coupling()) {
            e.coupling->offset += k * std::fabs(moved.normal().offset - p.offset);
            e.coupling->lambda_johnson += k * std::fabs(moved.coupling()->lambda_johnson - alternation->lambda_johnson);
        }
    };
}

void watch_width(contact& c, const scene& s, const std::optional<contact_width>& w,
                 const std::function<void()>& checkpoint) {
    if (w) c.set_estimate_term(width_error(s, *w, checkpoint));
}
}  // namespace

std::optional<si_point> si_of(const scene& s, const std::optional<contact_width>& w, const tangential_solution& t) {
    if (!s.physical || !w) return std::nullopt;
    return to_si(*s.physical, *w, t.Q, t.f, t.c0(), t.xi);
}

point_report scene_point::report() const {
    const coupling_summary* coupled = solved.coupling();
    return {settled.label,
            solved.normal(),
            solution,
            seconds,
            estimate,
            si_of(settled, width, solution),
            coupled ? std::optional<coupling_summary>(*coupled) : std::nullopt};
}

std::optional<std::string> beyond_every_n(const scene& s, double Q) {
    if (s.solver.n != 0) return std::nullopt;  // an explicit n: no ladder
    // The rule does not depend on the width (smooth rollers alone, and the edge zones' bound of beta_D, f, Q and n),
    // so the scene's contact as given answers it, before a physical scene's width search solves at the load (for
    // full coupling's free rolling beyond every n, minutes of a search that fails).
    try {
        return contact(s.surfaces, s.friction, s.solver, s.materials)
            .beyond_every_n(Q, ladder_rungs(s.solver.how).back(), s.solver.tolerance.value_or(default_tolerance));
    } catch (const resolution_error&) {
        return std::nullopt;  // a contact that cannot be built: the ladder refuses it as before
    }
}

namespace {
// Full coupling of a smooth pair (settled_contact): the dimensionless contact does not depend on the width, which
// follows from the point's lambda alone (a = a_H sqrt(lambda), docs/formulation.md 8(e) "The width of a physical
// scene"; contact_width.cpp).
bool width_from_point(const scene& s) { return width_follows_tangential_load(s) && smooth(*s.physical); }

// That width from c's last point (its coupled pressure's lambda: c.point(Q) solved, nothing solved here); the scene's
// surfaces at it, as settled_contact sets them.
contact_width width_of_point(scene& s, const contact& c) {
    const contact_width w = find_width(*s.physical, [&c](const roughness&) { return c.normal().lambda; }, {}, true);
    s.surfaces = roughness_at(*s.physical, w.a);
    return w;
}

// Hertz's width a_H checked against the radius, as find_width checks it before any solve (lambda = 1: a = a_H), where
// the width itself is left to the answer (scene_rungs::after_point); its input_error if a_H > R/10.
void check_hertz_width(const scene& s) {
    static_cast<void>(find_width(*s.physical, [](const roughness&) { return 1.0; }, {}, true));
}

// The contact of a scene whose width is settled first, at the load Q (the scene is modified in place).
// `shift`, `shift_found`: a rough pair's at full coupling (coupled_width), from and for the rung below and above.
contact settled_contact(scene& s, std::optional<contact_width>& width, double Q,
                        const std::function<void()>& checkpoint, std::shared_ptr<level_store> levels = nullptr,
                        double shift = 0.0, std::optional<double>* shift_found = nullptr) {
    normal_cache cache;
    if (width_follows_tangential_load(s) && smooth(*s.physical)) {
        // Full coupling of a smooth pair: the dimensionless contact does not depend on the width
        // (no layer; find_width takes a = a_H sqrt(lambda) from one coupled point), so the contact
        // whose point gives lambda is the contact at the width found, its coupled point at Q kept.
        contact c = contact_internals::with_levels(s.surfaces, s.friction, s.solver, s.materials, &cache, levels);
        c.set_checkpoint(checkpoint);
        width = find_width(
            *s.physical,
            [&c, Q](const roughness&) {
                c.point(Q);
                return c.normal().lambda;
            },
            {}, true);
        s.surfaces = roughness_at(*s.physical, width->a);
        return c;
    }
    if (width_follows_tangential_load(s)) {
        // A rough pair: the contact at the width found takes the search's last coupled point, through the same store.
        if (!levels) levels = std::make_shared<level_store>();
        width = coupled_width(s, &cache, Q, checkpoint, levels, shift, shift_found);
    } else {
        width = settle_width(s, &cache, Q, checkpoint);
    }
    contact c = contact_internals::with_levels(s.surfaces, s.friction, s.solver, s.materials, &cache, levels);
    c.set_checkpoint(checkpoint);
    watch_width(c, s, width, checkpoint);
    return c;
}

// The scene at each rung of the ladder: settled at the rung's n (a physical scene's width follows
// P_H/P2 at that n). The first rung is the scene as given (solver.n = 0: the method's default), so
// that its point is today's. `Q`: the load of a point, or of a row whose width follows the load
// (settled_contact, as without the ladder); none for the rows of a curve whose width does not
// (settle_width alone, as curve_of without the ladder). `checkpoint`: as solve_point's.
// `after_point`: a smooth pair's width at full coupling is left to the rung that answers (answered), so that building
// a rung solves nothing: the ladder's rule (a') of docs/formulation.md 8(q) then reads the top rung's levels before its
// point (settled_contact would solve that point to find the width first), and a rung whose point fails is not solved
// twice (once to build it for level_ladder::point's beyond_every_n, once again in the climb). The numbers are the
// same: the width is the answer's lambda's, as settled_contact finds it from the same point.
struct scene_rungs {
    scene given;
    std::optional<double> Q;
    std::function<void()> checkpoint;
    std::map<int, std::pair<scene, std::optional<contact_width>>> settled;
    bool after_point = false;
    // A rough pair at full coupling: the coupled P_H/P2 less Johnson's at the last rung's width (coupled_width).
    std::optional<double> coupling_shift{};

    std::unique_ptr<contact> operator()(int n, const std::shared_ptr<level_store>& levels) {
        scene at = given;
        if (n != at.solver.nodes()) at.solver.n = n;
        std::optional<contact_width> width;
        std::unique_ptr<contact> c;
        if (Q && after_point && width_from_point(at)) {
            check_hertz_width(at);  // before any solve; the answer's own width is checked by answered()
            c = std::make_unique<contact>(
                contact_internals::with_levels(at.surfaces, at.friction, at.solver, at.materials, nullptr, levels));
            c->set_checkpoint(checkpoint);
        } else if (Q) {
            // A rough pair at full coupling: each rung's width search starts from the rung below's coupling shift.
            std::optional<double> shift_found;
            c = std::make_unique<contact>(
                settled_contact(at, width, *Q, checkpoint, levels, coupling_shift.value_or(0.0), &shift_found));
            if (shift_found) coupling_shift = shift_found;
        } else {
            width = settle_width(at);
            c = std::make_unique<contact>(
                contact_internals::with_levels(at.surfaces, at.friction, at.solver, at.materials, nullptr, levels));
            c->set_checkpoint(checkpoint);
            watch_width(*c, at, width, checkpoint);
        }
        settled.insert_or_assign(n, std::make_pair(std::move(at), width));
        return c;
    }

    // Rung n's scene and width, c its contact after its point answered (where the width was left to it, from c's point).
    std::pair<scene, std::optional<contact_width>>& answered(int n, const contact& c) {
        auto& rung = settled.at(n);
        if (!rung.second && Q && after_point && width_from_point(rung.first)) rung.second = width_of_point(rung.first, c);
        return rung;
    }
};

// A point or row of the ladder that no rung answers, refused before the first rung settles its width (beyond_every_n).
void refuse_beyond_every_n(const scene& s, double Q) {
    if (const std::optional<std::string> why = beyond_every_n(s, Q)) throw resolution_error(*why);
}

level_ladder ladder_of(const scene& s, scene_rungs& rungs) {
    return level_ladder(s.solver, s.surfaces,
                        [&rungs](int n, const std::shared_ptr<level_store>& levels) { return rungs(n, levels); });
}
}  // namespace

scene_point solve_point(scene s, const std::optional<load_given>& load, const std::function<void()>& checkpoint) {
    const double Q = load_of(s, load);
    const auto start = std::chrono::steady_clock::now();
    const auto since_start = [&start] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    if (s.solver.n == 0) {  // the ladder chooses n (problems/level_ladder.hpp)
        scene_rungs rungs{s, Q, checkpoint, {}, true};
        level_ladder ladder = ladder_of(s, rungs);
        refuse_beyond_every_n(s, Q);
        level_ladder::answer a = ladder.point(Q);
        std::unique_ptr<contact> c = ladder.release(a.n);
        auto& [settled, width] = rungs.answered(a.n, *c);
        const double seconds = since_start();
        return {std::move(settled), width, std::move(*c), std::move(a.solution), seconds, std::move(a.estimate)};
    }
    std::optional<contact_width> width;
    contact c = settled_contact(s, width, Q, checkpoint);
    try {
        const tangential_solution solution = c.point(Q);
        const double seconds = since_start();
        std::optional<error_estimate> estimate = c.estimate(solution);
        return {std::move(s), width, std::move(c), solution, seconds, estimate};
    } catch (const unadvised_refusal& e) {  // its line names no change (base/error.hpp): with n given, n
        throw advised_at_given_n(e, s.solver.n);
    }
}

scene_curve curve_of(scene s, const std::optional<std::vector<double>>& loads, int points, bool sweep,
                     const std::function<void()>& before_row, const std::function<void()>& checkpoint) {
    const std::vector<double> Qs = loads ? *loads : curve_loads(points, s.friction, s.materials.beta_d);
    const bool climbs = s.solver.n == 0;  // the ladder chooses each row's n (problems/level_ladder.hpp)
    if (!width_follows_tangential_load(s)) {
        std::vector<curve_point> rows;
        std::vector<contact_width> widths;
        std::vector<int> nodes;
        if (climbs) {
            // Each rung settles its own width (at no load: the width does not follow it).
            scene_rungs rungs{s, std::nullopt, checkpoint, {}};
            level_ladder ladder = ladder_of(s, rungs);
            rows = ladder_curve(ladder, Qs, points, sweep, nodes, before_row);
            const int first = ladder.rungs().front();
            for (std::size_t i = 0; i < rows.size(); ++i)
                if (const auto& width = rungs.settled.at(nodes[i] != 0 ? nodes[i] : first).second)
                    widths.push_back(*width);
            s = std::move(rungs.settled.at(first).first);
        } else {
            const std::optional<contact_width> width = settle_width(s);
            contact c(s.surfaces, s.friction, s.solver, s.materials);
            c.set_checkpoint(checkpoint);
            watch_width(c, s, width, checkpoint);
            rows = sweep ? swept_curve(c, points, before_row, {}, s.solver.n)
                         : creep_curve(c, Qs, before_row, {}, s.solver.n);
            if (width) widths.assign(rows.size(), *width);
            for (const curve_point& row : rows) nodes.push_back(row.is_refused() ? 0 : s.solver.nodes());
        }
        return {std::move(s), std::move(rows), std::move(widths), std::move(nodes)};
    }
    // The width follows the load: Johnson's width (the pressure alone) for refused rows, then
    // each row at its own width (with the ladder, a ladder per row: each rung its width at the row's load).
    if (sweep) check_sweepable(s.materials);
    scene johnson = s;
    johnson.materials.coupling = coupling_level::johnson;
    const contact_width johnson_width = *settle_width(johnson);
    scene_curve out{s, {}, {}, {}};
    for (const double Q : Qs) {
        if (before_row) before_row();
        scene at = s;
        normal_cache cache;
        try {
            if (climbs) {
                scene_rungs rungs{s, Q, checkpoint, {}};
                level_ladder ladder = ladder_of(s, rungs);
                refuse_beyond_every_n(s, Q);  // as solve_point: before the width's solves
                std::vector<int> used;
                std::vector<curve_point> row = ladder_curve(ladder, {Q}, 1, false, used);
                auto& [settled, width] = rungs.settled.at(used.front() != 0 ? used.front() : ladder.rungs().front());
                out.rows.push_back(std::move(row.front()));
                out.widths.push_back(*width);
                out.nodes.push_back(used.front());
                if (used.front() != 0) out.settled = std::move(settled);
                continue;
            }
            const contact_width w = *settle_width(at, &cache, Q, checkpoint);
            contact c(at.surfaces, at.friction, at.solver, at.materials, &cache);
            c.set_checkpoint(checkpoint);
            watch_width(c, at, w, checkpoint);
            std::vector<curve_point> row = creep_curve(c, {Q}, {}, {}, at.solver.n);
            out.nodes.push_back(row.front().is_refused() ? 0 : at.solver.nodes());
            out.rows.push_back(std::move(row.front()));
            out.widths.push_back(w);
            out.settled = std::move(at);
        } catch (const resolution_error& e) {
            // The width's search at a given n may meet the same refusal as the row (no three zones at this n): advised
            // as solve_point's (the ladder's rows reach here advised).
            const unadvised_refusal* unadvised = climbs ? nullptr : dynamic_cast<const unadvised_refusal*>(&e);
            out.rows.push_back(unadvised ? refused_load(Q, s.friction, advised_at_given_n(*unadvised, s.solver.n))
                                         : refused_load(Q, s.friction, e));
            out.widths.push_back(johnson_width);
            out.nodes.push_back(0);
        }
    }
    return out;
}

}  // namespace roughroll
