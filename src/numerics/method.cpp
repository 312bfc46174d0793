// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/numerics/method.hpp"

#include <cmath>
#include <ostream>

#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"

namespace roughroll {

std::string to_string(method m) {
    switch (m) {
        case method::paper: return "paper";
        case method::product: return "product";
        case method::extrapolated: return "extrapolated";
        case method::one_parameter: return "one-parameter";
    }
    return "unknown";
}

int default_nodes(method m) {
    switch (m) {
        case method::paper: return 200;
        case method::product: return 96;
        case method::extrapolated: return 128;
        case method::one_parameter: return 128;
    }
    return 0;
}

method method_from_string(const std::string& name) {
    if (name == "paper") return method::paper;
    if (name == "product") return method::product;
    if (name == "extrapolated") return method::extrapolated;
    if (name == "one-parameter") return method::one_parameter;
    throw input_error("unknown method '" + name + "' (known: paper, product, extrapolated, one-parameter)");
}

std::string to_string(zone_search z) {
    switch (z) {
        case zone_search::automatic: return "auto";
        case zone_search::single: return "single";
        case zone_search::general: return "general";
    }
    return "unknown";
}

zone_search zone_search_from_string(const std::string& name) {
    if (name == "auto") return zone_search::automatic;
    if (name == "single") return zone_search::single;
    if (name == "general") return zone_search::general;
    throw input_error("unknown zone search '" + name + "' (known: auto, single, general)");
}

void check_tolerance(double tolerance, const std::string& name) {
    if (!(std::isfinite(tolerance) && tolerance > 0.0 && tolerance < 1.0))
        throw input_error(name + " must be a relative accuracy in (0, 1), e.g. 1e-6 (got " + shortest(tolerance) + ")");
}

method level_of(method m) { return m == method::extrapolated ? method::product : m; }

std::ostream& operator<<(std::ostream& os, method m) { return os << to_string(m); }

}  // namespace roughroll
