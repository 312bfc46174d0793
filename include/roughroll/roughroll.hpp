// SPDX-License-Identifier: GPL-3.0-or-later
// roughroll's public interface in one include: what a program on the library needs for the
// rolling contact of a scene (README.md, "A program on the library").
//
//   read_scene, parse_scene, load_of     a scene file (TOML) or text, checked (io/scene.hpp)
//   solve_point, curve_of                a creep point with its error estimate and SI units,
//                                        a creep curve, as `roughroll point` / `curve` report
//                                        them (io/scene_point.hpp)
//   contact, tangential_solution,        one scene's contact: its normal solution, points, the
//   normal_solution, error_estimate      stick and slip zones, tractions (problems/contact.hpp)
//   creep_curve, swept_curve, curve_loads  a contact's creep curve, row by row (problems/creep_curve.hpp)
//   si_point, contact_width              a physical scene's results in SI units (model/physical_scene.hpp)
//   carter, carter_at_stick_end          Carter's closed form for smooth cylinders (model/carter.hpp)
//   to_json, write_summary, version      the program's JSON and text reports (io/output.hpp)
//   error, input_error,                  the typed errors, each with a one-line message
//   resolution_error, numerical_error    (base/error.hpp)
//   shortest                             the shortest text that reads back as a double (base/text.hpp)
//
// Link roughroll::roughroll (CMake) or `pkg-config --cflags --libs roughroll`. The layers'
// own headers stay available for finer use (roughness parameters: layer/, io/roughness_output.hpp).
#pragma once

#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"
#include "roughroll/io/output.hpp"
#include "roughroll/io/scene.hpp"
#include "roughroll/io/scene_point.hpp"
#include "roughroll/model/carter.hpp"
#include "roughroll/model/physical_scene.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/creep_curve.hpp"
