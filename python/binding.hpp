// SPDX-License-Identifier: GPL-3.0-or-later
// The extension roughroll._roughroll (pybind11), one file per idea:
//   roughroll_module.cpp  the module and the translation of roughroll's errors into Python's
//   scene_binding.cpp     scenes, a point (the program's JSON), creep curves, tractions
//   batch.cpp             many points on several threads, the GIL released
//   model_binding.cpp     the pieces a reader of the paper meets: kernels (3.23)-(3.24), the
//                         normal problem (3.19)-(3.20), Carter's closed form, roughness specs
// The Python package roughroll (python/roughroll/) checks argument types and builds scene
// text from dicts; what reaches C++ is typed, and every value check is the library's own.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include <pybind11/pybind11.h>

#include "roughroll/io/scene.hpp"

namespace roughroll::python {

void bind_scene(pybind11::module_& m);
void bind_batch(pybind11::module_& m);
void bind_model(pybind11::module_& m);

// The Python keywords n=, method=, zones=: the command line's --n, --method, --zones.
struct solver_keywords {
    std::optional<int> n;
    std::optional<std::string> method;
    std::optional<std::string> zones;
    std::optional<double> friction;   // over the scene's friction, as --friction
    std::optional<double> tolerance;  // the ladder's, as --tolerance (over solver.n and solver.tolerance)
};

// The Python keywords Q=, Q_over_f=, P1=: the command line's --Q, --Q-over-f, --P1, at most one
// (an input_error naming them otherwise); nothing when none is given (the scene's load).
std::optional<load_given> load_keywords(std::optional<double> Q, std::optional<double> Q_over_f,
                                        std::optional<double> P1);

// One point of a scene as `roughroll point SCENE --json` prints it (compact), with the
// solver keywords over the scene's [solver] table. Runs without the GIL.
// `checkpoint`: called before each level's solve (contact::set_checkpoint); check_signals for a
// point solved on the interpreter's thread, nothing for a batch's workers (which watch for Ctrl-C
// themselves, batch.cpp).
std::string point_json(scene s, const std::optional<load_given>& load, const solver_keywords& k,
                       const std::function<void()>& checkpoint = {});
// Ctrl-C during a solve that runs without the GIL: the signal handler only sets a flag that
// PyErr_CheckSignals reads (with the GIL); a KeyboardInterrupt (error_already_set) ends the solve.
void check_signals();

}  // namespace roughroll::python
