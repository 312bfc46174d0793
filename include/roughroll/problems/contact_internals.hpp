// SPDX-License-Identifier: GPL-3.0-or-later
// The library's own access to the solvers behind a contact (contact.hpp): its tests reach the
// two-parameter tangential solver of a level through it, and a ladder builds its rungs by it (with_levels).
// Not installed: the public contact's traction(), slip_velocity() and distributions() serve every method,
// and the solver's header (tangential_problem.hpp) brings the numerics with it.
#pragma once

#include <memory>
#include <vector>

#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/level_store.hpp"
#include "roughroll/problems/point_estimate.hpp"
#include "roughroll/problems/tangential_solver.hpp"

namespace roughroll {

class dissimilar_zones;

struct contact_internals {
    // The two-parameter tangential solver of c's level; for method::one_parameter there is none:
    // throws input_error (contact::traction and contact::slip_velocity serve every method).
    static tangential_solver& tangential(contact& c);
    // The contact's constructor with a ladder's store (level_ladder.hpp, level_store.hpp): its model and levels
    // are the store's where another rung made them and their numbers are the same; nullptr: every level made here.
    static contact with_levels(const roughness& surfaces, double f, const solver_options& options,
                               const dissimilar& materials, normal_cache* cache, std::shared_ptr<level_store> levels);
    // The levels of c's estimate at Q solved before c's point, kept for c.point(Q) (point_model::levels_before; the
    // ladder's rule (a'), docs/formulation.md 8(q)); empty where c's model solves none first.
    static std::vector<estimate_level> levels_before(contact& c, double Q);
    // c's point at the stick zone's end c0 as contact::at_stick_end reports it (Richardson's Q and xi where the method
    // extrapolates), without its estimate or the load's check: the swept point's width error (io/scene_point.cpp).
    static tangential_solution reported_at_stick_end(contact& c, double c0);
    // Johnson's zones workspace of c's level (dissimilar rollers, either coupling level); null for any other model.
    static const dissimilar_zones* johnson_zones(contact& c);
};

inline tangential_solver& tangential_of(contact& c) { return contact_internals::tangential(c); }

}  // namespace roughroll
