// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target on the profile CSV reader: roughroll::parse_profile_csv on arbitrary bytes,
// then, on every profile it accepts, the condition checks and the periodic spline.
//
// An input_error is the expected answer to bad input and ends the run quietly. Anything else
// is a finding: another exception, a crash, a sanitizer report, a hang, or a broken promise of
// profile_csv.hpp, checked below and reported by abort():
//   - the message is one line starting with "fuzz:";
//   - an accepted profile has at least min_profile_samples samples, one line number each,
//     x1 starting at 0, strictly increasing and below l, every value finite;
//   - condition_violations on it (H = 1) returns one-line messages and does not throw, and
//     the spline's minimum and maximum bracket every sample (or are not finite, and then
//     condition_violations says so).
//
// Build and run: scripts/fuzz [SECONDS] (see docs/robustness.md).
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "roughroll/base/error.hpp"
#include "roughroll/layer/micro_geometry.hpp"
#include "roughroll/io/profile_csv.hpp"
#include "roughroll/base/text.hpp"

namespace {

[[noreturn]] void broken(const char* promise, const std::string& detail) {
    std::fprintf(stderr, "fuzz_profile: broken promise: %s: %s\n", promise, detail.c_str());
    std::abort();
}

// One line of valid UTF-8 with no control character (text.hpp's one_line changes nothing in
// it), and short: a long field is echoed cut (issue 11).
bool one_line(const std::string& message) { return roughroll::one_line(message) == message && message.size() <= 1000; }

constexpr double period = 4.0;

void check_samples(const roughroll::profile_samples& s) {
    const std::size_t n = s.x1.size();
    if (n < static_cast<std::size_t>(roughroll::min_profile_samples) || s.h0.size() != n || s.lines.size() != n)
        broken("at least min_profile_samples samples, a line each", std::to_string(n));
    if (s.x1.front() != 0.0) broken("x1 starts at 0", std::to_string(s.x1.front()));
    for (std::size_t i = 0; i < n; ++i) {
        if (!std::isfinite(s.x1[i]) || !std::isfinite(s.h0[i])) broken("finite samples", std::to_string(i));
        // The underflow rule (text.hpp): no sample is a subnormal.
        for (const double v : {s.x1[i], s.h0[i]})
            if (v != 0.0 && std::fabs(v) < DBL_MIN) broken("no subnormal sample", std::to_string(i));
        if (!(s.x1[i] < period)) broken("x1 below l", std::to_string(s.x1[i]));
        if (i > 0 && !(s.x1[i] > s.x1[i - 1])) broken("x1 strictly increasing", std::to_string(i));
    }
}

void check_conditions(const roughroll::profile_samples& s) {
    roughroll::micro_geometry g;
    g.material = {1.0, 1.0, 1.0, period};
    g.bottom.kind = roughroll::profile_kind::measured;
    g.bottom.measured = s;
    try {
        const auto violations = roughroll::condition_violations(g);
        for (const std::string& m : violations)
            if (!one_line(m)) broken("one-line violation", m);
        const roughroll::profile_function h0(g.bottom, period);
        const auto low = h0.minimum(), high = h0.maximum();
        if (!std::isfinite(low.value) || !std::isfinite(high.value)) {
            if (violations.empty()) broken("a non-finite spline is a violation", "");
            return;
        }
        for (const double h : s.h0)
            if (low.value > h || high.value < h) broken("extremes bracket the samples", std::to_string(h));
    } catch (const roughroll::numerical_error&) {
        // A spline GSL cannot build (e.g. knots too close for double precision) is reported, not a crash.
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    roughroll::profile_samples s;
    try {
        s = roughroll::parse_profile_csv(text, "fuzz", period);
    } catch (const roughroll::input_error& e) {
        const std::string message = e.what();
        if (message.rfind("fuzz:", 0) != 0) broken("message starts with the source", message);
        if (!one_line(message)) broken("one-line message", message);
        return 0;
    }
    check_samples(s);
    check_conditions(s);
    return 0;
}
