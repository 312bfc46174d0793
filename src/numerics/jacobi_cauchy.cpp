// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/numerics/jacobi_cauchy.hpp"

#include <cmath>
#include <string>

#include <gsl/gsl_math.h>
#include <gsl/gsl_sf_gamma.h>
#include <gsl/gsl_sf_hyperg.h>

#include "roughroll/base/error.hpp"

namespace roughroll {

namespace {
double hyperg_2F1(double a, double b, double c, double y) {
    gsl_sf_result r;
    gsl_check(gsl_sf_hyperg_2F1_e(a, b, c, y, &r), "the Cauchy transform of a Jacobi weight (2F1)");
    return r.val;
}

// GSL's special functions through their _e forms, so that a failure is a numerical_error, not a NaN.
double checked(int (*fn)(double, gsl_sf_result*), double x, const char* what) {
    gsl_sf_result r;
    gsl_check(fn(x, &r), what);
    return r.val;
}
double gamma_of(double x) { return checked(gsl_sf_gamma_e, x, "the Cauchy transform of a Jacobi weight (Gamma)"); }
double lngamma_of(double x) { return checked(gsl_sf_lngamma_e, x, "the Cauchy transform of a Jacobi weight (ln Gamma)"); }

// x >= 0 inside, x <= -1 outside: the forms whose 2F1 argument lies in [0, 1/2] resp. (0, 1) (8(y)).
double cauchy_oriented(double a, double b, double x) {
    if (x < -1.0) {
        // int w/(tau - x) = 2^(a+b+1) B(a+1, b+1)/(1 - x) 2F1(1, a+1; a+b+2; 2/(1 - x)) (tau = 1 - 2u: the Euler integral).
        // Next to the end (y = 2/(1 - x) > 1/2) GSL's 2F1 loses digits as y -> 1 (1.4e-10 at x = -1 - 1e-6, measured
        // against mpmath): there the connection formula in d = 1 - y (DLMF 15.8.4; c - a - b = b not an integer),
        //   2F1(1, a+1; a+b+2; y) = (a+b+1)/b 2F1(1, a+1; 1-b; d) + Gamma(a+b+2) Gamma(-b)/Gamma(a+1) d^b (1-d)^-(a+b+1),
        // whose series has d <= 1/2.
        const double y = 2.0 / (1.0 - x), d = (-1.0 - x) / (1.0 - x);
        const double F = y <= 0.5 ? hyperg_2F1(1.0, a + 1.0, a + b + 2.0, y)
                                  : (a + b + 1.0) / b * hyperg_2F1(1.0, a + 1.0, 1.0 - b, d) +
                                        gamma_of(a + b + 2.0) * gamma_of(-b) / gamma_of(a + 1.0) *
                                            std::pow(d, b) * std::pow(1.0 - d, -(a + b + 1.0));
        return M_1_PI * std::exp((a + b + 1.0) * M_LN2 + lngamma_of(a + 1.0) + lngamma_of(b + 1.0) - lngamma_of(a + b + 2.0)) / (1.0 - x) * F;
    }
    // Inside: cot(pi a) w(x) - 2^(a+b) Gamma(a) Gamma(1+b)/(pi Gamma(a+b+1)) 2F1(1, -a-b; 1-a; (1-x)/2) (8(y)).
    const double w = std::pow(1.0 - x, a) * std::pow(1.0 + x, b);
    const double scale = std::exp((a + b) * M_LN2 + lngamma_of(a) + lngamma_of(1.0 + b) - lngamma_of(a + b + 1.0));
    return w / std::tan(M_PI * a) - M_1_PI * scale * hyperg_2F1(1.0, -a - b, 1.0 - a, 0.5 * (1.0 - x));
}
}  // namespace

double jacobi_weight_cauchy(double a, double b, double x) {
    gsl_guard();
    if (!(a > 0.0 && a < 1.0 && b > 0.0 && b < 1.0) || !std::isfinite(x) || std::fabs(x) == 1.0)
        throw numerical_error("the Cauchy transform of the Jacobi weight with exponents " + std::to_string(a) + ", " +
                              std::to_string(b) + " at " + std::to_string(x) + " is not defined here");
    // tau -> -tau swaps the exponents and the sign: C_0^(a,b)(x) = -C_0^(b,a)(-x).
    const bool mirrored = x > 1.0 || (x < 0.0 && x > -1.0);
    return mirrored ? -cauchy_oriented(b, a, -x) : cauchy_oriented(a, b, x);
}

jacobi_cauchy_collocation::jacobi_cauchy_collocation(int n, double a, double b)
    : rule(n, a, b), collocation(gauss_jacobi(n + 1, -a, -b).nodes), barycentric(n) {
    // Gauss-Jacobi nodes' barycentric weights (-1)^k sqrt((1 - t_k^2) W_k) (Wang, Huybrechs and Vandewalle, Math.
    // Comp. 83, 2014), nodes ascending; a common factor cancels in the barycentric formula.
    for (int k = 0; k < n; ++k)
        barycentric[k] = (k % 2 ? -1.0 : 1.0) * std::sqrt((1.0 - rule.nodes[k]) * (1.0 + rule.nodes[k]) * rule.weights[k]);
}

std::vector<double> jacobi_cauchy_collocation::lagrange(double x) const {
    const int n = rule.n;
    std::vector<double> l(n);
    double sum = 0.0;
    for (int k = 0; k < n; ++k) {
        const double d = x - rule.nodes[k];
        if (d == 0.0) throw numerical_error("Jacobi collocation: a collocation point falls on a node; another n avoids it");
        l[k] = barycentric[k] / d;
        sum += l[k];
    }
    for (int k = 0; k < n; ++k) l[k] /= sum;
    return l;
}

void jacobi_cauchy_collocation::add_to(gsl_matrix* m, const std::vector<double>& k_at_points) const {
    const int n = rule.n;
    const double* W = rule.weights.data();
    const double* t = rule.nodes.data();
    for (int i = 0; i <= n; ++i) {
        const double x = collocation[i];
        double sum = 0.0;
        for (int k = 0; k < n; ++k) sum += W[k] / (t[k] - x);
        // psi(x) [C_0(x) - k w(x)] + (1/pi) sum W_k (psi_k - psi(x))/(t_k - x), psi(x) = sum_k l_k(x) psi_k.
        const double D = jacobi_weight_cauchy(rule.a, rule.b, x) - k_at_points[i] * jacobi_weight(rule.a, rule.b, x) -
                         M_1_PI * sum;
        const std::vector<double> l = lagrange(x);
        double* row = gsl_matrix_ptr(m, i, 0);
        for (int k = 0; k < n; ++k) row[k] += M_1_PI * W[k] / (t[k] - x) + l[k] * D;
    }
}

}  // namespace roughroll
