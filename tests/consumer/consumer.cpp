// SPDX-License-Identifier: GPL-3.0-or-later
// A program outside roughroll, built against an installed copy by tests/install_consumer.sh
// (with find_package(roughroll) and with pkg-config), on the public headers alone: roughroll.hpp
// and the roughness layer's (the install holds no others, tests/installed_headers.sh). It parses a
// scene (which links toml++ through the library), solves the smooth scene's creep point and a rough
// one (the smooth one by the contact's closed-form path), and exits 1 unless the smooth xi is Carter's
// and the rough point satisfies the paper's checks with an error estimate that bounds its distance
// from the default method's point; then calls every member contact.hpp declares on the rough contact.
#include <cmath>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "roughroll/roughroll.hpp"  // nlohmann/json.hpp included, must compile here
#include "roughroll/io/micro_geometry_input.hpp"
#include "roughroll/io/profile_csv.hpp"
#include "roughroll/io/roughness_output.hpp"
#include "roughroll/layer/piecewise_averages.hpp"

namespace {
bool fails(const std::string& what) {
    std::cerr << "consumer: " << what << "\n";
    return false;
}

// Every member contact.hpp declares, called from the install tree alone (issue 24 review S8: contact::tangential()
// returned a type no installed header defined; normal_solution's rule is the installed gauss_chebyshev.hpp's):
// `c` the rough contact at n = 32 and s its point at Q.
bool every_member(roughroll::contact& c, const roughroll::tangential_solution& s, double Q, double f) {
    using namespace roughroll;
    const normal_solution& normal = c.normal();
    if (normal.rule.n != 32 || normal.rule.nodes.size() != 32 || normal.phi.size() != 32)
        return fails("the normal solution's rule is not the contact's n = 32");
    const pressure_peak peak = peak_of(normal);
    if (!(peak.p > 0.0 && peak.p < 2.0 / std::acos(-1.0)))
        return fails("the rough pressure's peak is not below Hertz's 2/pi");  // the layer flattens it (README)
    if (c.coupling() != nullptr || c.friction() != f || c.materials().beta_d != 0.0)
        return fails("the contact's coupling, friction or materials are not the scene's");
    const tangential_solution d = c.distribution(s);
    const std::vector<double> grid{-0.5, 0.0, 0.5};
    const std::vector<contact::distribution_row> rows = c.distributions(d, grid);
    const std::vector<double> v = c.slip_velocity(d, grid);
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const contact::distribution_row& row = rows[i];
        if (row.p1 != c.traction(d, row.r) || row.v != c.slip_velocity(d, row.r) || row.v != v[i] ||
            !(std::fabs(row.p1) <= f * row.p * (1.0 + 1e-12)))
            return fails("the distributions disagree with traction() and slip_velocity(), or |p1| > f p, at r = " +
                         shortest(row.r));
    }
    int levels = 0;
    c.set_checkpoint([&levels] { ++levels; });
    const contact::swept_point swept = c.at_stick_end(s.c0());
    if (levels == 0 || !(std::fabs(swept.solution.Q - Q) <= 1e-8))
        return fails("the point swept at the stick end c0 did not call the checkpoint (" + std::to_string(levels) +
                     " levels) or has another load (" + shortest(swept.solution.Q - Q) + " from the point's)");
    if (!(std::fabs(c.continued_point(Q, s).xi - s.xi) <= 1e-10))
        return fails("the point continued from s has another creep");
    if (c.beyond_every_n(Q, max_nodes, 1e-4))
        return fails("the ladder's rule refuses a load the contact answers");
    std::cout << "rough:  every member of contact.hpp called (peak pressure " << shortest(peak.p) << ", " << levels
              << " levels solved for the swept point)\n";
    return true;
}
}  // namespace

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
    return every_member(c, s, Q, rough.friction) ? 0 : 1;
}
