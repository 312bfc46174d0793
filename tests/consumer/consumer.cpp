// SPDX-License-Identifier: GPL-3.0-or-later
// A program outside roughroll, built against an installed copy by tests/install_consumer.sh
// (with find_package(roughroll) and with pkg-config). It parses a scene (which links toml++
// through the library), solves the smooth scene's creep point with the numerical scheme itself
// (not Carter's closed-form path) and a rough one, and exits 1 unless the smooth xi is
// Carter's and the rough point satisfies the paper's checks.
#include <cmath>
#include <iostream>
#include <optional>

#include "roughroll/model/carter.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/io/output.hpp"  // every public header, nlohmann/json.hpp included, must compile here
#include "roughroll/io/scene.hpp"

int main() {
    using namespace roughroll;
    const scene smooth = parse_scene("friction = 0.3\nQ = 0.15\n[solver]\nmethod = \"product\"\nn = 32\n", "consumer");
    const double Q = load_of(smooth, std::nullopt);
    const normal_solution normal = normal_solver(smooth.solver.nodes(), smooth.solver.how).solve(kernel{});
    tangential_solver solver(normal, kernel{}, kernel{}, smooth.friction, /*closed_form=*/false);
    const double xi = solver.solve(Q).xi;
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
    return 0;
}
