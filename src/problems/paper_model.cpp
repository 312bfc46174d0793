// SPDX-License-Identifier: GPL-3.0-or-later
// The paper's problem as a point_model (point_model.hpp): the stick zone [-1, c0] of (4.4)-(4.5), and
// zone_solver's general search where it fails its checks (options.zones, docs/formulation.md section 7),
// on the two-parameter collocation (with Richardson's rule for 'extrapolated') or on the one-parameter
// limit's Glauert system (7(g)); and make_point_model, which chooses the model once.
#include <algorithm>
#include <cmath>
#include <exception>
#include <optional>
#include <sstream>
#include <string>

#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"
#include "roughroll/numerics/quadrature.hpp"
#include "roughroll/problems/one_parameter.hpp"
#include "roughroll/problems/point_model.hpp"
#include "roughroll/problems/zone_checks.hpp"
#include "roughroll/problems/zone_solver.hpp"

namespace roughroll {

normal_solution level_normal(const model_input& in) {
    normal_solution normal =
        solve_normal(kernel::normal(in.surfaces), in.options.nodes(), level_of(in.options.how), in.cache);
    normal.how = in.options.how;  // a smooth scene under 'extrapolated' is exact at one level
    return normal;
}

tangential_solution point_model::at_stick_end(double, bool, bool) {
    throw input_error("a curve swept in c0 (--sweep, Python sweep=True) is the paper's single zone only");
}

namespace {

// The paper's zone and the general search on one solver.
class zone_model : public point_model {
public:
    using point_model::point_model;
    estimate_structure structure() const override { return estimate_structure::paper; }

    // The single zone at Q of this level, cached: the levels of an estimate and the coarse level of an
    // extrapolation are solved once per Q. `checked`: with the checks (3.3)-(3.4) (a point reported), or
    // without (a level). `guess`, `slope`: a c0 near the root (the level below's) and dQ/dc0 there.
    const tangential_solution& single(double Q, bool checked, std::optional<double> guess = std::nullopt,
                                      std::optional<double> slope = std::nullopt) {
        checkpoint();
        if (!last_ || !(last_->Q == Q) || (checked && !last_checked_)) {
            last_ = solve(Q, guess, checked, slope);
            last_checked_ = checked || checks_always_;
        }
        return *last_;
    }
    // Why the general search runs, for the line of its numerical fault (general_search_fault): zones = "general"
    // asks for it; the paper's zone fails its checks (zones = "auto"); the paper's zone failed numerically; or the
    // point's zones are the search's (a level of its estimate, the coarse level of its extrapolation).
    struct search_cause {
        enum { asked, checks_failed, paper_faulted, zones_searched } kind;
        const traction_checks* checks = nullptr;  // checks_failed: the paper's zone's
    };
    // zone_solver's general search at Q (section 7), from `ends` (the coarse level's zone) when given. A numerical
    // fault on the way (a GSL status, a singular system, a root search without convergence) is a numerical_error in
    // the user's terms (general_search_fault, `why`), the search's own line nested in it: every caller's.
    tangential_solution general(double Q, const std::vector<double>& ends, search_cause why) {
        return worded(Q, why, [&] {
            checkpoint();
            return search(Q).solve(Q, true, guided_ ? ends : std::vector<double>{});
        });
    }
    // The same search, empty where no zone of its structure carries Q (zone_solver::find).
    std::optional<tangential_solution> find_general(double Q, const std::vector<double>& ends, search_cause why) {
        return worded(Q, why, [&] {
            checkpoint();
            return search(Q).find(Q, true, guided_ ? ends : std::vector<double>{});
        });
    }
    // The general search at s's load from s's zone (a level of s's estimate, the coarse level of its extrapolation).
    tangential_solution general_like(const tangential_solution& s) {
        return general(s.Q, s.layout.stick_ends(), {search_cause::zones_searched});
    }
    tangential_solution like(const tangential_solution& s, method, int) override {
        return s.layout.general() ? general_like(s) : single(s.Q, false);
    }
    double traction(const tangential_solution& d, double r) override { return problem().traction(d, r); }
    double slip_velocity(const tangential_solution& d, double r) override { return problem().slip_velocity(d, r); }
    std::vector<double> slip_velocity(const tangential_solution& d, const std::vector<double>& r) override {
        return problem().slip_velocity(d, r);
    }
    tangential_solution at_stick_end(double c0, bool checked, bool near) override {
        checkpoint();  // as every level's solve (contact::set_checkpoint)
        return problem().at_stick_end(c0, checked, near);
    }

protected:
    virtual tangential_problem& problem() = 0;  // the derived model's solver
    tangential_solution solve(double Q, std::optional<double> guess, bool checked, std::optional<double> slope) {
        return problem().solve(Q, guess, checked || checks_always_, slope);
    }
    // The search of Q's zones, its faults in its own words (general, find_general word them): one per model, but
    // for the one-parameter limit of dissimilar rollers, one per sign of Q (8(s)).
    virtual zone_solver& search(double) { return *zones_; }
    // The paper's single zone s where it holds (or options.zones says "single"); else the general
    // search's answer where it holds its checks (or options.zones says "general"); else s, its checks
    // failed. `ends`: the coarse level's zone.
    tangential_solution zones_for(double Q, tangential_solution s, const std::vector<double>& ends) {
        if (options_.zones == zone_search::general) return general(Q, ends, {search_cause::asked});
        if (options_.zones == zone_search::single || s.checks.hold()) return s;
        // A structure the general search does not cover (no zone of it carries Q: an empty find, or a load the
        // search refuses; or its answer fails the checks too): the single zone, its checks failed. A numerical fault
        // of the search is not that statement: general's numerical_error.
        std::optional<tangential_solution> g;
        try {
            g = find_general(Q, ends, {search_cause::checks_failed, &s.checks});
        } catch (const resolution_error&) {
        }
        return g && g->checks.hold() ? *g : s;
    }

    std::unique_ptr<zone_solver> zones_;  // on the derived model's solver
    bool checks_always_ = false;          // the solver checks every point it solves
    bool guided_ = true;                  // a coarse level's zone starts the search (general's `ends`)

private:
    // `search`'s numerical_error as general_search_fault's line, the search's own nested in it.
    template <class F>
    auto worded(double Q, search_cause why, F search) -> decltype(search()) {
        try {
            return search();
        } catch (const numerical_error&) {
            std::throw_with_nested(numerical_error(general_search_fault(Q, why)));
        }
    }
    // The line of a numerical fault of the general search (a zone system singular at a trial start, a root search of
    // a zone end without convergence): what failed in the scene's terms and what the user can change.
    std::string general_search_fault(double Q, search_cause why) const {
        std::string line = "at Q/f = " + shortest(Q / f_) + " ";
        switch (why.kind) {
            case search_cause::asked:
                line += "the search for a stick zone between two slip zones (zones = \"general\") ";
                break;
            case search_cause::checks_failed:
                line += "the paper's stick zone from the leading edge fails the checks (3.3)-(3.4) (margins: " +
                        margins_text(*why.checks) + "), and the search for a stick zone between two slip zones ";
                break;
            case search_cause::paper_faulted:
                line += "the paper's stick zone from the leading edge and the search for a stick zone between two slip "
                        "zones both ";
                break;
            case search_cause::zones_searched:
                line += "the search for a stick zone between two slip zones ";
                break;
        }
        line += "failed numerically at n = " + std::to_string(nodes()) +
                " (a zone's system or the root search of its ends, docs/formulation.md 7(e)); another n may get "
                "through";
        if (why.kind == search_cause::paper_faulted) return line;  // zones = "single" would meet the paper's fault
        return line + ", and zones = \"single\" (solver.zones, --zones) reports the paper's zone" +
               (why.kind == search_cause::checks_failed ? " with its failed checks" : "");
    }

    std::optional<tangential_solution> last_;  // single's cache
    bool last_checked_ = false;
};

// The collocation of (4.4) (tangential_solver); for 'extrapolated', Richardson's rule on the companion
// level n/2 (product integration): P_H/P2 by contact, c0 and xi here.
class collocation_model final : public zone_model {
public:
    explicit collocation_model(const model_input& in)
        : zone_model(in),
          levels_(*this, in.cache),
          companion_(extrapolates(in.surfaces, in.options) ? &levels_.at(in.options.nodes() / 2) : nullptr),
          normal_(level_normal(in)),
          tangential_(normal_, kernel::tangential(in.surfaces), kernel::normal(in.surfaces), in.f) {
        zones_ = std::make_unique<zone_solver>(tangential_.zone_operator());
    }
    point_model& level(int m) override { return levels_.at(m); }
    const normal_solution& normal() const override { return normal_; }
    tangential_solver* tangential() override { return &tangential_; }
    tangential_solution point(double Q, const std::function<std::vector<int>()>& below) override;
    tangential_solution distribution(const tangential_solution& s) override {
        // For 'extrapolated' the level-n solution at the same Q, whose c0 and xi are level n's (within the
        // error estimate of the extrapolated ones).
        if (!companion_) return s;
        if (!last_fine_ || last_fine_->Q != s.Q)
            last_fine_ = s.layout.general() ? general_like(s) : tangential_.solve(s.Q);
        return *last_fine_;
    }

private:
    tangential_problem& problem() override { return tangential_; }

    model_levels<collocation_model> levels_;
    collocation_model* companion_;  // 'extrapolated': level n/2
    normal_solution normal_;
    tangential_solver tangential_;
    std::optional<tangential_solution> last_fine_;  // level n of the last extrapolated point
};

tangential_solution collocation_model::point(double Q, const std::function<std::vector<int>()>& below) {
    // Each level's root search starts from the root of the level below: n/4 (the estimate's
    // coarsest level, solved here anyway) from Carter's c0, n/2 from n/4's root, n from n/2's,
    // with a Newton step on the slope of the level below.
    std::optional<double> start, slope, quarter_c0;
    // Level n starts from its own c0 as the levels n/4 and n/2 predict it, c0_n = c0_{n/2} +
    // (c0_{n/2} - c0_{n/4})/2^p where the error falls as n^-p (Richardson's rule, (4.6)): within
    // ~1e-10 instead of the ~1e-8 of c0_{n/2}, so that the Newton step on the slope of n/2 lands
    // within the search's 1e-15 and level n costs two solves, not three. Only the start: the
    // secant from it converges to the same root either way (stick_end_for_load).
    const auto predicted = [&](double half) -> std::optional<double> {
        if (!quarter_c0 || !(half > -1.0 && half < 1.0)) return half;
        const double c0 = half + (half - *quarter_c0) / std::ldexp(1.0, order_of(options_.how));
        return c0 > -1.0 && c0 < 1.0 ? c0 : half;
    };
    const std::vector<collocation_model*> levels = levels_.at(below());
    if (levels.size() == 2) {  // n/4 and n/2
        try {
            const tangential_solution& quarter = levels[0]->single(Q, false);
            if (quarter.c0() > -1.0 && quarter.c0() < 1.0) quarter_c0 = quarter.c0();
            start = quarter.c0();
            slope = quarter.load_slope;
            if (!companion_) {  // else the companion is n/2, solved below
                const tangential_solution& half = levels[1]->single(Q, false, start, slope);
                start = predicted(half.c0());
                slope = half.load_slope;
            }
        } catch (const error&) {  // the estimate will say why; the search goes without a start
            start = slope = std::nullopt;
        }
    }
    if (!companion_) return zones_for(Q, single(Q, true, start, slope), {});
    tangential_solution coarse = companion_->single(Q, false, start, slope);
    tangential_solution s = zones_for(Q, tangential_.solve(Q, predicted(coarse.c0()), true, coarse.load_slope),
                                      coarse.layout.stick_ends());
    // Both levels on the same path: the coarse level's zones by the general search too.
    last_fine_ = s;
    // The general path is not extrapolated: its zone ends do not yet converge at a clean n^-4 at the default n
    // (docs/formulation.md 7(e)). Level n, estimated against n/2, refused where the fast path's extrapolation is:
    // a creep at the edge of the double range.
    const bool general = s.layout.general();
    if (general) coarse = companion_->general_like(s);
    const double c0 = general ? s.c0() : richardson(s.c0(), coarse.c0()), xi = richardson(s.xi, coarse.xi);
    if (!(std::isfinite(c0) && std::isfinite(xi)))
        throw numerical_error("extrapolation: the creep is not finite (roughness parameters too large?)");
    if (general) return s;
    s.layout = one_stick_zone(s.start(), c0, s.layout.route, s.sign < 0.0 ? -1 : 1);  // the paper's zone, extrapolated
    s.xi = xi;
    return s;
}

// The one-parameter limit (one_parameter_solver): no levels below, no extrapolation. For dissimilar
// rollers (Johnson's level, docs/formulation.md 8(s)) one search per sign of Q, each with its forcing
// sgn(Q) beta_D, and a point whose checks fail refused: its structure (slip against Q at an edge) is not built.
class limit_model final : public zone_model {
public:
    explicit limit_model(const model_input& in)
        : zone_model(in), levels_(*this, in.cache), limit_(in.surfaces, in.f, in.options.nodes(), in.materials.beta_d) {
        zones_ = std::make_unique<zone_solver>(limit_.zone_operator(limit_.forcing_at(1.0)));
        if (in.materials.beta_d != 0.0)
            braked_ = std::make_unique<zone_solver>(limit_.zone_operator(limit_.forcing_at(-1.0)));
        checks_always_ = true;
        // Required, not only cheap: its levels are shared by a ladder's rungs (shareable), so a level's answer must not
        // depend on which rung's levels below started its search.
        guided_ = false;
    }
    point_model& level(int m) override { return levels_.at(m); }
    // No level starts another's search (point ignores `below`, like() searches afresh) and single()'s cache
    // holds what a solve gives: a ladder's rungs share these levels (level_store).
    bool shareable() const override { return true; }
    const normal_solution& normal() const override { return limit_.normal(); }
    tangential_solver* tangential() override { return nullptr; }
    tangential_solution point(double Q, const std::function<std::vector<int>()>&) override {
        tangential_solution s = limit_point(Q);
        if (limit_.beta_d() == 0.0 || s.checks.hold()) return s;
        // Dissimilar rollers: refused, with the search's zone where there is one (its margins, not the paper zone's).
        std::optional<tangential_solution> searched;
        if (s.layout.general()) {
            searched = s;
        } else if (options_.zones != zone_search::single) {
            // Empty where no zone of the structure carries Q: its refusal is the one below. A numerical fault of
            // the search is not that statement: find_general's numerical_error.
            searched = find_general(Q, {}, {search_cause::checks_failed, &s.checks});
        }
        refuse_dissimilar(searched.value_or(s));
    }

private:
    zone_solver& search(double Q) override { return *(Q < 0.0 && braked_ ? braked_ : zones_); }  // sgn(Q) beta_D
    tangential_solution limit_point(double Q) {
        if (options_.zones == zone_search::single) return zones_for(Q, single(Q, true), {});
        // The one-parameter paper's zone can be singular where the general zone is not (its
        // c0 tends to -1 near gross sliding when eps2 > eps1, docs/formulation.md 7(g)). A fault of the general
        // search is worded for the user, by general here and by zones_for (the same search again would meet it again).
        std::optional<tangential_solution> paper;
        try {
            paper = single(Q, true);
        } catch (const numerical_error&) {
            return general(Q, {}, {search_cause::paper_faulted});
        }
        return zones_for(Q, *std::move(paper), {});
    }
    // A point of dissimilar rollers whose checks fail (8(s)): a zone between slips with Q whose stick margin alone
    // fails, by less than entry_floor, is the entry's discretisation (7(h): -6.9e-8, -5.7e-9, +1.2e-9 at n = 64, 128,
    // 256 measured), which a larger n resolves; anything else is a structure with slip against Q, not built.
    [[noreturn]] void refuse_dissimilar(const tangential_solution& s) const {
        constexpr double entry_floor = 1e-6;
        const bool discretisation =
            s.layout.general() && s.checks.slip_margin >= 0.0 && s.checks.stick_margin > -entry_floor;
        std::ostringstream msg;  // the user's beta_d and load exactly (shortest), the computed margins to 3 digits
        msg << "method 'one-parameter' with beta_d = " << shortest(limit_.beta_d())
            << " at Q/f = " << shortest(s.Q / limit_.friction()) << ": the stick zone fails (3.3)-(3.4) (margins: "
            << margins_text(s.checks) << "); "
            << (discretisation ? "the entry's discretisation (docs/formulation.md 7(h)): " +
                                     (options_.nodes() < max_nodes
                                          ? "set n = " + std::to_string(std::min(2 * options_.nodes(), max_nodes))
                                          : std::string("n is at its largest; use method 'product'"))
                               : std::string("the zones have slip against Q (free rolling: in both directions), which "
                                             "the limit does not build (docs/formulation.md 8(s)): use method 'product' "
                                             "or 'extrapolated'"));
        if (!discretisation) throw beyond_method_error(msg.str());
        throw resolution_error(msg.str());
    }
    tangential_problem& problem() override { return limit_; }

    model_levels<limit_model> levels_;
    one_parameter_solver limit_;
    std::unique_ptr<zone_solver> braked_;  // Q < 0 with beta_D != 0: the forcing -beta_D (8(s))
};

}  // namespace

std::unique_ptr<point_model> make_point_model(const roughness& surfaces, double f, const solver_options& options,
                                              const dissimilar& materials, normal_cache* cache) {
    const model_input in{surfaces, f, options, materials, cache};
    if (options.how == method::one_parameter)  // Johnson's level for dissimilar rollers (8(s))
        return std::make_unique<limit_model>(in);
    if (materials.beta_d != 0.0) return make_dissimilar_model(in);
    return std::make_unique<collocation_model>(in);
}

}  // namespace roughroll
