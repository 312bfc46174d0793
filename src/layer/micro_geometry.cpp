// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/layer/micro_geometry.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <functional>
#include <limits>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_interp.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_poly.h>

#include "roughroll/base/error.hpp"
#include "roughroll/base/gsl_handles.hpp"
#include "roughroll/base/text.hpp"

namespace roughroll {

const char* to_string(profile_kind kind) {
    switch (kind) {
        case profile_kind::flat: return "flat";
        case profile_kind::sine: return "sine";
        case profile_kind::sawtooth: return "sawtooth";
        case profile_kind::measured: return "measured";
    }
    return "?";
}

const char* to_string(micro_shape_kind kind) {
    switch (kind) {
        case micro_shape_kind::sine: return "sine";
    }
    return "?";
}

const char* to_string(decay_kind kind) {
    switch (kind) {
        case decay_kind::linear: return "linear";
        case decay_kind::quadratic: return "quadratic";
        case decay_kind::cosine: return "cosine";
    }
    return "?";
}

const char* to_string(normal_factor kind) {
    switch (kind) {
        case normal_factor::derived: return "derived";
        case normal_factor::printed: return "printed";
    }
    return "?";
}

// docs/formulation.md, E11: H_1 = 0 of (2.5) couples V_1 to W_2 through C_1122 = lambda0, and
// R_2 of (2.3) couples them back through C_2211 = lambda0; eliminating V_1 leaves
// (lambda0/(lambda0 + 2mu0))^2 in (2.12). The paper prints lambda0 + mu0 in its place.
double normal_factor_ratio(normal_factor kind, double lambda0, double mu0) {
    const double stiff = lambda0 + 2.0 * mu0;
    switch (kind) {
        case normal_factor::derived: return lambda0 / stiff;
        case normal_factor::printed: return (lambda0 + mu0) / stiff;
    }
    return std::numeric_limits<double>::quiet_NaN();
}

// The decays of (2.6)-(2.8) in u = (H - x2)/H: each has dhat(1) = d(0) = 1, dhat(0) = d(H) = 0
// and dhat_u > 0 (d' < 0) on (0, 1).
double decay_value_from_top(decay_kind kind, double u) {
    switch (kind) {
        case decay_kind::linear: return u;
        case decay_kind::quadratic: return u * u;
        case decay_kind::cosine: return std::sin(M_PI_2 * u);
    }
    return std::numeric_limits<double>::quiet_NaN();
}

double decay_slope_from_top(decay_kind kind, double u) {
    switch (kind) {
        case decay_kind::linear: return 1.0;
        case decay_kind::quadratic: return 2.0 * u;
        case decay_kind::cosine: return M_PI_2 * std::cos(M_PI_2 * u);
    }
    return std::numeric_limits<double>::quiet_NaN();
}

double decay_value(decay_kind kind, double x2, double H) { return decay_value_from_top(kind, (H - x2) / H); }

double decay_slope(decay_kind kind, double x2, double H) { return -decay_slope_from_top(kind, (H - x2) / H) / H; }

// h = l sin(2 pi x1/l): the scale l makes h a length, and cancels in (2.11)-(2.14) anyway.
double micro_shape_slope(micro_shape_kind kind, double x1, double l) {
    switch (kind) {
        case micro_shape_kind::sine: return 2.0 * M_PI * std::cos(2.0 * M_PI * x1 / l);
    }
    return std::numeric_limits<double>::quiet_NaN();
}

// The periodic spline of a measured profile: the knots with the closing point (l, h0(0))
// appended, as gsl_interp_cspline_periodic requires (first and last values equal).
struct profile_function::spline {
    std::vector<double> x;
    std::vector<double> y;
    std::vector<double> slope;  // h0' at every knot, once: piece() and the extremes use them
    interp_ptr interp;
    interp_accel_ptr accel;
};

namespace {

std::unique_ptr<profile_function::spline> build_spline(const profile_samples& s, double l) {
    const std::size_t n = s.x1.size();
    if (n < 3 || s.h0.size() != n) {
        throw input_error(
            one_line(s.source + ": a measured profile needs at least 3 samples (got " + std::to_string(n) + ")"));
    }
    auto sp = std::make_unique<profile_function::spline>();
    sp->x = s.x1;
    sp->y = s.h0;
    sp->x.push_back(l);
    sp->y.push_back(s.h0.front());
    for (std::size_t i = 0; i + 1 < sp->x.size(); ++i) {
        if (!(sp->x[i] < sp->x[i + 1]) || !std::isfinite(sp->y[i])) {
            throw input_error(
                one_line(s.source + ": the samples must be finite with x1 strictly increasing in [0, l)"));
        }
    }
    sp->interp = make_interp(gsl_interp_cspline_periodic, sp->x.size());
    gsl_check(gsl_interp_init(sp->interp.get(), sp->x.data(), sp->y.data(), sp->x.size()),
              s.source + ": periodic spline of the profile");
    sp->accel = make_interp_accel();
    sp->slope.resize(sp->x.size());
    for (std::size_t i = 0; i < sp->x.size(); ++i) {
        const int status = gsl_interp_eval_deriv_e(sp->interp.get(), sp->x.data(), sp->y.data(), sp->x[i],
                                                   sp->accel.get(), &sp->slope[i]);
        if (status != GSL_SUCCESS)
            gsl_check(status, s.source + ": the slope of the spline at x1 = " + shortest(sp->x[i]));
    }
    return sp;
}

}  // namespace

profile_function::profile_function(const profile& p, double l) : kind_(p.kind), delta_(p.delta), l_(l) {
    gsl_guard();
    if (!(std::isfinite(l) && l > 0.0))
        throw input_error("the period l must be finite and > 0 (got " + shortest(l) + ")");
    breaks_ = {0.0, l};
    if (kind_ == profile_kind::measured) {
        spline_ = build_spline(p.measured, l);
        breaks_ = spline_->x;
    }
}

profile_function::~profile_function() = default;
profile_function::profile_function(profile_function&&) noexcept = default;
profile_function& profile_function::operator=(profile_function&&) noexcept = default;

double profile_function::operator()(double x1) const {
    // Periodicity: reduce to [0, l). fmod keeps the sign of x1, hence the correction.
    double x = std::fmod(x1, l_);
    if (x < 0.0) x += l_;
    switch (kind_) {
        case profile_kind::flat: return 0.0;
        case profile_kind::sine: return 0.5 * delta_ * (1.0 - std::cos(2.0 * M_PI * x / l_));
        case profile_kind::sawtooth: return delta_ * x / l_;
        case profile_kind::measured: {
            double y = 0.0;
            gsl_check(gsl_interp_eval_e(spline_->interp.get(), spline_->x.data(), spline_->y.data(), x,
                                        spline_->accel.get(), &y),
                      "evaluating the measured profile at x1 = " + shortest(x));
            return y;
        }
    }
    return std::numeric_limits<double>::quiet_NaN();
}

profile_function::cubic profile_function::piece(std::size_t i) const {
    if (kind_ != profile_kind::measured || i + 1 >= spline_->x.size())
        throw numerical_error("profile_function::piece(" + std::to_string(i) + ") of a " + to_string(kind_) +
                              " profile: only the knot intervals of a measured profile are cubics");
    const spline& sp = *spline_;
    const double w = sp.x[i + 1] - sp.x[i];
    const double y0 = sp.y[i], y1 = sp.y[i + 1];
    const double m0 = sp.slope[i] * w, m1 = sp.slope[i + 1] * w;
    // Hermite: p(0) = y0, p(1) = y1, p'(0) = m0, p'(1) = m1.
    return {sp.x[i], w, {y0, m0, 3.0 * (y1 - y0) - 2.0 * m0 - m1, 2.0 * (y0 - y1) + m0 + m1}};
}

namespace {

// The extreme of a measured profile's spline that `better` prefers (std::less: the minimum,
// std::greater: the maximum): on each cubic piece, among its ends and the roots of its
// derivative p'(t) = c1 + 2 c2 t + 3 c3 t^2 inside (0, 1).
template <class Better>
profile_function::extreme spline_extreme(const profile_function& h0, Better better) {
    const std::size_t pieces = h0.breakpoints().size() - 1;
    profile_function::extreme best{h0.piece(0).c[0], 0.0};
    const auto consider = [&](const profile_function::cubic& p, double t) {
        const double v = p(t);
        if (better(v, best.value)) best = {v, p.x0 + t * p.width};
    };
    for (std::size_t i = 0; i < pieces; ++i) {
        const profile_function::cubic p = h0.piece(i);
        // Knots so close that a slope overflows give a piece with non-finite coefficients: the
        // extreme is then not finite (the conditions report it), never a silently skipped piece.
        for (const double c : p.c)
            if (!std::isfinite(c)) return {std::numeric_limits<double>::quiet_NaN(), p.x0};
        consider(p, 0.0);
        double r[2];
        const int roots = gsl_poly_solve_quadratic(3.0 * p.c[3], 2.0 * p.c[2], p.c[1], &r[0], &r[1]);
        for (int k = 0; k < roots; ++k)
            if (r[k] > 0.0 && r[k] < 1.0) consider(p, r[k]);
    }
    return best;
}

}  // namespace

profile_function::extreme profile_function::minimum() const {
    switch (kind_) {
        case profile_kind::flat: return {0.0, 0.0};
        case profile_kind::sine: return {0.0, 0.0};
        case profile_kind::sawtooth: return {0.0, 0.0};
        case profile_kind::measured: break;
    }
    return spline_extreme(*this, std::less<double>());
}

profile_function::extreme profile_function::maximum() const {
    switch (kind_) {
        case profile_kind::flat: return {0.0, 0.0};
        case profile_kind::sine: return {delta_, 0.5 * l_};
        case profile_kind::sawtooth: return {delta_, l_};
        case profile_kind::measured: break;
    }
    return spline_extreme(*this, std::greater<double>());
}

std::vector<std::string> decay_violations(const std::function<double(double)>& d,
                                          const std::function<double(double)>& d_slope, double H,
                                          const std::string& name) {
    std::vector<std::string> out;
    const std::string who = "decay '" + name + "': ";
    const double tolerance = 1e-12;
    const double d0 = d(0.0), dH = d(H);
    if (!(std::fabs(d0 - 1.0) <= tolerance))
        out.push_back(who + "d(0) = " + shortest(d0) + ", not 1 (the paper's d(0) = 1)");
    if (!(std::fabs(dH) <= tolerance)) out.push_back(who + "d(H) = " + shortest(dH) + ", not 0 (the paper's d(H) = 0)");
    const int points = 1000;
    for (int i = 1; i <= points; ++i) {
        const double x2 = H * i / (points + 1.0);
        const double slope = d_slope(x2);
        if (!(slope < 0.0)) {
            out.push_back(who + "d'(" + shortest(x2) + ") = " + shortest(slope) +
                          " is not negative (the paper's d' < 0 on (0, H))");
            break;  // one message per condition
        }
    }
    return out;
}

namespace {

void layer_violations(const layer& m, std::vector<std::string>& out) {
    const auto positive = [&out](const char* name, double x) {
        if (!(std::isfinite(x) && x > 0.0))
            out.push_back(std::string(name) + " must be finite and > 0 (got " + shortest(x) + ")");
    };
    if (!(std::isfinite(m.lambda0) && m.lambda0 >= 0.0))
        out.push_back("lambda0 must be finite and >= 0 (got " + shortest(m.lambda0) + ")");
    positive("mu0", m.mu0);
    positive("H", m.H);
    positive("l", m.l);
    if (!out.empty()) return;
    std::string range = layer_range_violation(m);
    if (!range.empty()) out.push_back(std::move(range));
}

// 0 <= h0 < H on every sample of a measured profile, naming its line.
void sample_violations(const profile_samples& s, double H, std::vector<std::string>& out) {
    for (std::size_t i = 0; i < s.h0.size(); ++i) {
        const double h = s.h0[i];
        if (h >= 0.0 && h < H) continue;  // the message only for a violation (profiles of 1e6 samples)
        const std::string where = s.source + ":" + (i < s.lines.size() ? std::to_string(s.lines[i]) : "?") + ": ";
        if (!(h >= 0.0)) {
            out.push_back(one_line(where + "h0 = " + shortest(h) +
                                   " is below 0 (the paper's 0 <= h0 < H; h0 is measured from the deepest valley: "
                                   "shift a zero-mean profile by its minimum)"));
            return;
        }
        if (!(h < H)) {
            out.push_back(one_line(where + "h0 = " + shortest(h) + " is not below H = " + shortest(H) +
                                   " (the paper's 0 <= h0 < H)"));
            return;
        }
    }
}

void profile_violations(const micro_geometry& g, std::vector<std::string>& out) {
    const profile& p = g.bottom;
    const double H = g.material.H;
    if (p.kind == profile_kind::sine || p.kind == profile_kind::sawtooth) {
        if (!(std::isfinite(p.delta) && p.delta >= 0.0)) {
            out.push_back("delta must be finite and >= 0 (got " + shortest(p.delta) + ")");
        } else if (!(p.delta < H)) {
            out.push_back("delta = " + shortest(p.delta) + " is not below H = " + shortest(H) + ": the " +
                          to_string(p.kind) +
                          " profile's peak h0 = delta would reach the top of the layer "
                          "(the paper's 0 <= h0 < H)");
        }
        return;
    }
    if (p.kind != profile_kind::measured) return;
    const std::size_t before = out.size();
    sample_violations(p.measured, H, out);
    if (out.size() != before) return;  // the samples first: a spline through bad samples says nothing new
    const profile_function h0(p, g.material.l);
    const profile_function::extreme low = h0.minimum(), high = h0.maximum();
    const auto between = [&p](double x) {
        const std::vector<double>& x1 = p.measured.x1;
        const std::size_t i = static_cast<std::size_t>(std::upper_bound(x1.begin(), x1.end(), x) - x1.begin());
        const auto line = [&p](std::size_t j) {
            return j < p.measured.lines.size() ? std::to_string(p.measured.lines[j]) : std::string("?");
        };
        return i < x1.size() ? " between lines " + line(i - 1) + " and " + line(i)
                             : " between line " + line(x1.size() - 1) + " and line " + line(0) +
                                   " one period on (the last piece of the periodic spline wraps round to x1 = 0)";
    };
    const std::string who = p.measured.source + ": the periodic spline through the samples ";
    if (!std::isfinite(low.value) || !std::isfinite(high.value)) {
        // Knots so close that the spline's slopes overflow double precision.
        out.push_back(one_line(who + "is not finite (samples too close together for double precision?)"));
        return;
    }
    // A dip of a rounding's size next to a sample of 0 (about 1e-37 m for a smooth profile
    // sampled at h0 = 0) is not an overshoot.
    if (!(low.value >= -1e-12 * H)) {
        out.push_back(one_line(who + "overshoots to h0 = " + shortest(low.value) + " at x1 = " + shortest(low.x1) +
                               between(low.x1) + ", below 0 (the paper's 0 <= h0 < H); sample more densely there"));
    }
    if (!(high.value < H)) {
        out.push_back(one_line(who + "overshoots to h0 = " + shortest(high.value) + " at x1 = " + shortest(high.x1) +
                               between(high.x1) + ", not below H = " + shortest(H) +
                               " (the paper's 0 <= h0 < H); sample more densely there"));
    }
}

}  // namespace

std::string layer_range_violation(const layer& m) {
    if (!(std::isfinite(m.lambda0) && m.lambda0 >= 0.0 && std::isfinite(m.mu0) && m.mu0 > 0.0 && std::isfinite(m.H) &&
          m.H > 0.0))
        return "";  // condition_violations names the invalid value
    // k is mu0/H to (lambda0 + 2 mu0)/H and t mu0 H to (lambda0 + 2 mu0) H, times factors of
    // order 1 of the shapes: both must fit in double precision, with a margin of 1e3.
    const double stiff = m.lambda0 + 2.0 * m.mu0, margin = 1e3;
    const bool k_fits = stiff / m.H <= DBL_MAX / margin && m.mu0 / m.H >= DBL_MIN * margin;
    const bool t_fits = stiff * m.H <= DBL_MAX / margin && m.mu0 * m.H >= DBL_MIN * margin;
    if (k_fits && t_fits) return "";
    return "H = " + shortest(m.H) + " m with mu0 = " + shortest(m.mu0) + " Pa, lambda0 = " + shortest(m.lambda0) +
           " Pa puts " +
           (k_fits ? "t (mu0 H to (lambda0 + 2 mu0) H = " + shortest(m.mu0 * m.H) + " to " + shortest(stiff * m.H) +
                         " Pa m)"
                   : "k (mu0/H to (lambda0 + 2 mu0)/H = " + shortest(m.mu0 / m.H) + " to " + shortest(stiff / m.H) +
                         " Pa/m)") +
           " outside the range of double precision (1e3 DBL_MIN to DBL_MAX/1e3)";
}

std::vector<std::string> condition_violations(const micro_geometry& g) {
    std::vector<std::string> out;
    layer_violations(g.material, out);
    if (!out.empty()) return out;  // the other checks need a valid H and l
    profile_violations(g, out);
    const double H = g.material.H;
    const decay_kind kind = g.decay;
    const std::vector<std::string> decay =
        decay_violations([kind, H](double x2) { return decay_value(kind, x2, H); },
                         [kind, H](double x2) { return decay_slope(kind, x2, H); }, H, to_string(kind));
    out.insert(out.end(), decay.begin(), decay.end());
    return out;
}

void check_conditions(const micro_geometry& g) {
    const std::vector<std::string> problems = condition_violations(g);
    if (!problems.empty()) throw input_error(one_line(problems.front()));
}

}  // namespace roughroll
