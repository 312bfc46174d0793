// SPDX-License-Identifier: GPL-3.0-or-later
// contact's points of a creep curve swept in c0 (contact::at_stick_end, contact.hpp): Q(c0) of (4.5)
// without a root search, Richardson's rule at the same c0, its estimate, and the refusal of a load
// outside [0, f]; and which scenes take a swept curve (check_sweepable).
#include <cmath>
#include <sstream>

#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"
#include "roughroll/numerics/collocation.hpp"
#include "roughroll/problems/contact.hpp"

#include "contact_impl.hpp"

namespace roughroll {

void check_sweepable(const dissimilar& materials) {
    if (materials.beta_d != 0.0 && materials.coupling == coupling_level::full)
        throw input_error(
            "a swept curve (--sweep, Python sweep=True) of dissimilar rollers is continued in the load at Johnson's "
            "level only: at coupling = \"full\" each row's alternation starts from its own Johnson's point "
            "(docs/formulation.md 8(e)); solve the curve without --sweep (Python sweep=False: --points loads from -f to "
            "f, the same rows), or set coupling = \"johnson\"");
}

contact::swept_point contact::impl::at_stick_end(double c0) {
    if (materials_.beta_d != 0.0)
        throw input_error(
            "a point at a stick zone's end c0 is not defined for beta_d != 0: c0 ends the paper's stick zone from the "
            "leading edge, which dissimilar rollers never have (docs/formulation.md 8(g)); a swept curve (--sweep) "
            "continues their curve in the load instead");
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

contact::swept_point contact::impl::swept_at(double c0) {
    std::optional<tangential_solution> coarse;  // level n/2 at c0: the companion, often an estimate level too
    tangential_solution own;
    tangential_solution s = reported_at(c0, own, coarse);
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
        at[i] = !levels_[i]                          ? own
                : coarse && levels_[i] == companion_ ? *coarse  // solved above: not again
                                                     : levels_[i]->at_stick_end(c0, false, sweeping_near_);
    const error_estimate e = estimate_from(s, own, at, true);
    // The same for the load's error interval: Q +- e.Q reaching beyond [0, f] cannot be told from
    // full stick or gross sliding (and may be no physical point at all).
    refuse_load_outside(s, e.Q);
    if (!s.checks.hold()) return {s, std::nullopt};  // as estimate(): no bound for such a point
    return {s, e};
}

tangential_solution contact::impl::reported_at(double c0, tangential_solution& own,
                                               std::optional<tangential_solution>& coarse) {
    tangential_solution s = model_->at_stick_end(c0, true, sweeping_near_);
    own = s;
    if (reported_) {
        // Richardson's rule on Q(c0) and xi(c0) at the same c0.
        coarse = companion_->at_stick_end(c0, false, sweeping_near_);
        // Q = 0 and f at c0 = 1 and -1 are exact on every level: kept exact (Carter's columns).
        if (c0 != 1.0 && c0 != -1.0) s.Q = richardson(s.Q, coarse->Q);
        s.xi = richardson(s.xi, coarse->xi);
        if (!(std::isfinite(s.Q) && std::isfinite(s.xi)))
            throw numerical_error("extrapolation: Q(c0) or the creep is not finite (roughness parameters too large?)");
    }
    return s;
}

void contact::impl::refuse_load_outside(const tangential_solution& s, std::optional<double> error) const {
    if (s.c0() == 1.0 || s.c0() == -1.0) return;  // Q = 0 and Q = f exactly (full stick, gross sliding)
    const double d = error.value_or(0.0);
    if (s.Q - d >= 0.0 && s.Q + d <= f_) return;
    std::ostringstream msg;
    msg.precision(3);
    msg << "Q(c0) = " << shortest(s.Q);
    if (error)
        msg << " +- " << *error << " (its error estimate) reaches";
    else
        msg << " lies";
    msg << " outside [0, f] = [0, " << shortest(f_) << "] at c0 = " << shortest(s.c0()) << " for method '"
        << to_string(options_.how) << "' at n = " << nodes() << ": "
        << (error ? std::string("the load is not resolved there; ") +
                        (nodes() < max_nodes ? "increase n, or the scene is beyond the method's reach"
                                             : "n is at its largest, so the scene is beyond the method's reach")
                  : std::string("no physical point (|Q| <= f needs (3.3)-(3.4)): n does not resolve the layers, or the "
                                "single stick zone is not the solution there; ") +
                        (nodes() < max_nodes ? "increase n, or solve at given loads" : "solve at given loads"));
    throw resolution_error(msg.str());
}

}  // namespace roughroll
