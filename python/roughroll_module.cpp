// SPDX-License-Identifier: GPL-3.0-or-later
// The module roughroll._roughroll and the bridge from roughroll's typed errors
// (base/error.hpp) to the Python exceptions of roughroll._errors:
//   input_error -> InputError (a ValueError), resolution_error -> ResolutionError,
//   numerical_error -> NumericalError (an ArithmeticError), any other roughroll::error -> Error;
// each with the one-line message the command line prints after "roughroll: error: ".
// std::bad_alloc becomes MemoryError (pybind11's own translation).
#include <exception>

#include <pybind11/pybind11.h>

#include "binding.hpp"
#include "roughroll/base/error.hpp"
#include "roughroll/numerics/quadrature.hpp"

namespace py = pybind11;

namespace {

void raise(const char* name, const roughroll::error& e) {
    // Looked up at each error (a sys.modules hit): no Python object outlives the interpreter here.
    const py::object type = py::module_::import("roughroll._errors").attr(name);
    PyErr_SetString(type.ptr(), e.what());
}

}  // namespace

PYBIND11_MODULE(_roughroll, m) {
    m.doc() = "roughroll's C++ library (Pauk & Wozniak's two-parameter rolling contact); use the package roughroll.";
    roughroll::gsl_guard();  // GSL's aborting error handler off before any solve
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const roughroll::input_error& e) {
            raise("InputError", e);
        } catch (const roughroll::resolution_error& e) {
            raise("ResolutionError", e);
        } catch (const roughroll::numerical_error& e) {
            raise("NumericalError", e);
        } catch (const roughroll::error& e) {
            raise("Error", e);
        }
    });
    m.attr("__version__") = ROUGHROLL_VERSION;
    m.attr("min_nodes") = roughroll::min_nodes;
    m.attr("max_nodes") = roughroll::max_nodes;
    roughroll::python::bind_scene(m);
    roughroll::python::bind_batch(m);
    roughroll::python::bind_model(m);
}
