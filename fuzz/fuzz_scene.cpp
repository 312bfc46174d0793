// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target on the scene reader: roughroll::parse_scene on arbitrary bytes, then
// roughroll::load_of on every scene it accepts, without and with an override Q.
//
// An input_error is the expected answer to bad input and ends the run quietly. Anything
// else is a finding: another exception (libFuzzer reports it as a crash through
// std::terminate), a crash, a sanitizer report, a hang, or a broken promise of scene.hpp,
// checked below and reported by abort():
//   - parse_scene's message is one line starting with "fuzz:";
//   - an accepted scene has f finite and > 0, T and A finite and >= 0, n = 0 or within
//     [min_nodes, max_nodes], and a Q, when given, finite with |Q| <= f;
//   - load_of returns the override (or the scene's Q) exactly when it is finite and
//     |Q| <= f, and throws input_error with a one-line message otherwise.
//
// Build and run: scripts/fuzz [SECONDS] (see docs/robustness.md).
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

#include "roughroll/base/error.hpp"
#include "roughroll/numerics/quadrature.hpp"
#include "roughroll/io/scene.hpp"
#include "roughroll/base/text.hpp"

namespace {

[[noreturn]] void broken(const char* promise, const std::string& detail) {
    std::fprintf(stderr, "fuzz_scene: broken promise: %s: %s\n", promise, detail.c_str());
    std::abort();
}

// One line of valid UTF-8 with no control character (text.hpp's one_line changes nothing in
// it), and short: a long key or value is echoed cut (issue 11).
bool one_line(const std::string& message) { return roughroll::one_line(message) == message && message.size() <= 1000; }

bool finite_non_negative(double x) { return std::isfinite(x) && x >= 0.0; }

void check_scene(const roughroll::scene& s) {
    if (!(s.friction >= roughroll::min_friction && s.friction <= roughroll::max_friction))
        broken("f in [min_friction, max_friction]", std::to_string(s.friction));
    if (s.Q && !(std::isfinite(*s.Q) && std::fabs(*s.Q) <= s.friction))
        broken("scene Q finite and |Q| <= f", std::to_string(*s.Q));
    const roughroll::roughness_term terms[] = {s.surfaces.cylinder1.tangential, s.surfaces.cylinder1.normal,
                                               s.surfaces.cylinder2.tangential, s.surfaces.cylinder2.normal};
    for (const roughroll::roughness_term& term : terms)
        if (!finite_non_negative(term.T) || !finite_non_negative(term.A))
            broken("T and A finite and >= 0", std::to_string(term.T) + ", " + std::to_string(term.A));
    const int n = s.solver.n;
    if (n != 0 && (n < roughroll::min_nodes || n > roughroll::max_nodes)) broken("n in range", std::to_string(n));
    // The underflow rule: no value of an accepted scene is a subnormal.
    if (s.Q && *s.Q != 0.0 && std::fabs(*s.Q) < DBL_MIN) broken("Q not subnormal", std::to_string(*s.Q));
    if (!s.physical) return;
    // A physical scene: every derived quantity finite where it is made, or an input_error
    // naming keys; the width search's trials (a_H / 6.5e5 to R/10) included.
    const roughroll::physical_scene& p = *s.physical;
    const double a_H = roughroll::hertz_half_width(p, p.P2);
    if (!(std::isfinite(a_H) && a_H >= DBL_MIN)) broken("a_H normal and finite", std::to_string(a_H));
    for (const double x : {1.0 / 6.5e5, 1e-3, 1.0, 1e3, 0.1 * p.radius() / a_H}) {
        try {
            const roughroll::roughness r = roughroll::roughness_at(p, x * a_H);
            for (const roughroll::roughness_term& term :
                 {r.cylinder1.tangential, r.cylinder1.normal, r.cylinder2.tangential, r.cylinder2.normal})
                if (!finite_non_negative(term.T) || !finite_non_negative(term.A))
                    broken("T and A at a trial width finite and >= 0",
                           std::to_string(term.T) + ", " + std::to_string(term.A));
        } catch (const roughroll::input_error& e) {
            if (!one_line(e.what())) broken("one-line message", e.what());
        }
    }
}

// load_of(s, override) against its contract.
void check_load(const roughroll::scene& s, std::optional<double> override) {
    const std::optional<double> Q = override ? override : s.Q;
    const bool solvable = Q && std::isfinite(*Q) && std::fabs(*Q) <= s.friction;
    try {
        const double load = roughroll::load_of(s, override);
        if (!solvable) broken("load_of refuses a bad Q", "returned " + std::to_string(load));
        if (std::memcmp(&load, &*Q, sizeof load) != 0) broken("load_of returns Q as given", std::to_string(load));
    } catch (const roughroll::input_error& e) {
        if (solvable) broken("load_of accepts |Q| <= f", e.what());
        if (!one_line(e.what())) broken("one-line message", e.what());
    }
}

// The overrides tried on each scene: the limits and their neighbours, the non-finite
// values, and one double taken from the input's last bytes (any bit pattern).
void check_loads(const roughroll::scene& s, const std::uint8_t* data, std::size_t size) {
    const double f = s.friction;
    const double inf = std::numeric_limits<double>::infinity();
    const double specials[] = {0.0,
                               -0.0,
                               f,
                               -f,
                               0.5 * f,
                               std::nextafter(f, inf),
                               -std::nextafter(f, inf),
                               std::nextafter(f, 0.0),
                               inf,
                               -inf,
                               std::numeric_limits<double>::quiet_NaN(),
                               std::numeric_limits<double>::denorm_min(),
                               std::numeric_limits<double>::max()};
    check_load(s, std::nullopt);
    for (const double Q : specials) check_load(s, Q);
    if (size >= sizeof(double)) {
        double Q;
        std::memcpy(&Q, data + size - sizeof Q, sizeof Q);
        check_load(s, Q);
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    roughroll::scene s;
    try {
        s = roughroll::parse_scene(text, "fuzz");
    } catch (const roughroll::input_error& e) {
        const std::string message = e.what();
        if (message.rfind("fuzz:", 0) != 0) broken("message starts with the source", message);
        if (!one_line(message)) broken("one-line message", message);
        return 0;
    }
    check_scene(s);
    check_loads(s, data, size);
    return 0;
}
