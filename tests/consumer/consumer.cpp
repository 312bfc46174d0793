// SPDX-License-Identifier: GPL-3.0-or-later
// A program outside roughroll, built against an installed copy by tests/install_consumer.sh
// (with find_package(roughroll) and with pkg-config), on the public headers alone: roughroll.hpp
// and the roughness layer's (the install holds no others, tests/installed_headers.sh). It parses a
// scene (which links toml++ through the library), solves the smooth scene's creep point and a rough
// one (the smooth one by the contact's closed-form path), and exits 1 unless the smooth xi is Carter's
// and the rough point satisfies the paper's checks with an error estimate that bounds its distance
// from the default method's point.
#include <cmath>
#include <iostream>
#include <optional>
#include <string>

#include "roughroll/roughroll.hpp"  // nlohmann/json.hpp included, must compile here
#include "roughroll/io/micro_geometry_input.hpp"
#include "roughroll/io/profile_csv.hpp"
#include "roughroll/io/roughness_output.hpp"
#include "roughroll/layer/piecewise_averages.hpp"

int main() {
    using namespace roughroll;
    const scene smooth = parse_scene("friction = 0.3\nQ = 0.15\n[solver]\nmethod = \"product\"\nn = 32\n", "consumer");
    const double Q = load_of(smooth, std::nullopt);
    contact plain(smooth.surfaces, smooth.friction, smooth.solver);
    const double xi = plain.point(Q).xi;
    const double expected = carter(Q, smooth.friction).xi;  // (2f/pi)(1 - sqrt(1 - Q/f))
    std::cout << "smooth: xi " << shortest(xi) << ", Carter " << shortest(expected) << "\n";
    if (!(std::fabs(xi - expected) <= 1e-12)) {
        std::cerr << "consumer: smooth xi differs from Carter's by " << shortest(xi - expected) << "\n";
        return 1;
    }

    scene rough = smooth;
    rough.surfaces.cylinder1.tangential = {1.0, 0.5};
    rough.surfaces.cylinder1.normal = {1.0, 0.5};
    contact c(rough.surfaces, rough.friction, rough.solver);
    const tangential_solution s = c.point(Q);
    std::cout << "rough:  xi " << shortest(s.xi) << ", c0 " << shortest(s.c0()) << "\n";
    if (!s.checks.hold() || !(s.xi > expected)) {  // roughness raises the creep (README)
        std::cerr << "consumer: the rough point fails its checks or is not above Carter's creep\n";
        return 1;
    }
    // Its estimate at n = 32 bounds its distance from the default method's point (extrapolated, n = 128).
    const std::optional<error_estimate> e = c.estimate(s);
    const double fine = contact(rough.surfaces, rough.friction, solver_options{}).point(Q).xi;
    std::cout << "rough:  xi error estimate " << (e ? shortest(e->xi) : std::string("none")) << ", xi at the default n "
              << shortest(fine) << "\n";
    if (!e || !(std::fabs(s.xi - fine) <= e->xi)) {
        std::cerr << "consumer: the rough point has no error estimate, or its xi is further from the default's\n";
        return 1;
    }
    return 0;
}
