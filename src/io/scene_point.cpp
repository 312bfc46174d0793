#include "roughroll/io/scene_point.hpp"

#include <chrono>
#include <utility>

#include "roughroll/numerics/quadrature.hpp"

namespace roughroll {

void override_solver(scene& s, std::optional<int> n, const std::optional<std::string>& method_name,
                     const std::optional<std::string>& zones_name) {
    if (n) {
        check_node_count(*n);  // 0 would otherwise mean the method's default
        s.solver.n = *n;
    }
    if (method_name) s.solver.how = method_from_string(*method_name);
    if (zones_name) s.solver.zones = zone_search_from_string(*zones_name);
}

std::optional<contact_width> settle_width(scene& s, normal_cache* cache) {
    if (!s.physical) return std::nullopt;
    // lambda = P_H/P2 at a trial width, as the scene's method reports it (the normal problem alone),
    // searched on the method's cheap level n/2 first and polished at the scene's method; the
    // trials share their product-integration workspaces (collocation.hpp).
    normal_cache own;
    normal_cache* shared = cache ? cache : &own;
    const contact_width w = find_width(
        *s.physical, [&s, shared](const roughness& r) { return load_ratio(r, s.solver, shared); },
        [&s, shared](const roughness& r) { return coarse_load_ratio(r, s.solver, shared); });
    s.surfaces = roughness_at(*s.physical, w.a);
    return w;
}

std::optional<si_point> si_of(const scene& s, const std::optional<contact_width>& w, const tangential_solution& t) {
    if (!s.physical || !w) return std::nullopt;
    return to_si(*s.physical, *w, t.Q, t.f, t.c0, t.xi);
}

point_report scene_point::report() const {
    const coupling_summary* coupled = solved.coupling();
    return {settled.label, solved.normal(), solution, seconds, estimate, si_of(settled, width, solution),
            coupled ? std::optional<coupling_summary>(*coupled) : std::nullopt};
}

namespace {
// The contact of a scene whose width is settled first (the scene is modified in place).
contact settled_contact(scene& s, std::optional<contact_width>& width) {
    normal_cache cache;
    width = settle_width(s, &cache);
    return contact(s.surfaces, s.friction, s.solver, s.materials, &cache);
}
}  // namespace

scene_point solve_point(scene s, std::optional<double> Q_option) {
    const double Q = load_of(s, Q_option);
    const auto start = std::chrono::steady_clock::now();
    std::optional<contact_width> width;
    contact c = settled_contact(s, width);
    const tangential_solution solution = c.point(Q);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::optional<error_estimate> estimate = c.estimate(solution);
    return {std::move(s), width, std::move(c), solution, seconds, estimate};
}

}  // namespace roughroll
