// SPDX-License-Identifier: GPL-3.0-or-later
// roughroll's public interface in one include: what a program on the library needs for the
// rolling contact of a scene (README.md, "A program on the library").
//
//   read_scene, parse_scene, load_of     a scene file (TOML) or text, checked (io/scene.hpp)
//   solve_point, curve_of                a creep point with its error estimate and SI units,
//                                        a creep curve, as `roughroll point` / `curve` report
//                                        them (io/scene_point.hpp)
//   contact                              one scene's contact: its normal solution, points, their
//                                        error estimates, tractions (problems/contact.hpp)
//   tangential_solution, zone_layout,    a point with its stick and slip zones, the normal solution
//   normal_solution, error_estimate,     with its pressure, the estimate per quantity, what full
//   coupling_summary                     coupling measured (problems/*_solution.hpp, zone_layout.hpp,
//                                        error_estimate.hpp, coupling_summary.hpp)
//   creep_curve, swept_curve, curve_loads  a contact's creep curve, row by row (problems/creep_curve.hpp)
//   si_point, contact_width              a physical scene's results in SI units (model/physical_scene.hpp)
//   si_estimate, estimate_si             their error estimates, from the dimensionless ones (io/si_estimate.hpp)
//   carter, carter_at_stick_end          Carter's closed form for smooth cylinders (model/carter.hpp)
//   roughness, dissimilar                the rollers' roughness T, A (3.26) and Dundurs' pair (model/)
//   solver_options, method               the method, n, zone search and tolerance (numerics/method.hpp)
//   to_json, write_summary, version      the program's JSON and text reports (io/output.hpp)
//   error, input_error,                  the typed errors, each with a one-line message
//   resolution_error, numerical_error    (base/error.hpp)
//   shortest                             the shortest text that reads back as a double (base/text.hpp)
//
// Link roughroll::roughroll (CMake) or `pkg-config --cflags --libs roughroll`. These headers and the
// roughness layer's (a micro-geometry and its parameters: layer/, io/roughness_output.hpp,
// io/micro_geometry_input.hpp, io/profile_csv.hpp) are the ones installed (CMakeLists.txt,
// ROUGHROLL_PUBLIC_HEADERS); the solvers' and numerics' stay in the source tree.
#pragma once

#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"
#include "roughroll/io/output.hpp"
#include "roughroll/io/scene.hpp"
#include "roughroll/io/scene_point.hpp"
#include "roughroll/io/si_estimate.hpp"
#include "roughroll/model/carter.hpp"
#include "roughroll/model/dissimilar.hpp"
#include "roughroll/model/physical_scene.hpp"
#include "roughroll/model/roughness.hpp"
#include "roughroll/numerics/method.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/coupling_summary.hpp"
#include "roughroll/problems/creep_curve.hpp"
#include "roughroll/problems/error_estimate.hpp"
#include "roughroll/problems/normal_solution.hpp"
#include "roughroll/problems/tangential_solution.hpp"
#include "roughroll/problems/zone_layout.hpp"
