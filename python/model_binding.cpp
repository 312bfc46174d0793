// SPDX-License-Identifier: GPL-3.0-or-later
// The pieces of the model a reader of the paper meets on the way to a creep point, for the
// notebooks and for anyone checking a step by hand:
//   kernel(terms, z):       K*(z) = sum T exp(-A |z|) sgn z, (3.23)-(3.24) with E1, E2 (kernel.hpp);
//                           T may be negative here, so that the printed sign (E2) can be shown.
//   normal_problem(terms):  (3.19)-(3.20) discretised by (4.2)-(4.3), (4.6)-(4.7) for the normal
//                           kernel of those terms: P_H/P2, gamma_0n, phi at the nodes, p(r) (4.1).
//   carter(Q, f):           Carter's closed form, (1 + c0)/2 = sqrt(1 - Q/f), xi = (2f/pi)(1 - sqrt(1 - Q/f)).
//   roughness_spec:         k, t, alpha of (2.11)-(2.15) from a micro-geometry, as `roughroll roughness --json`.
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "binding.hpp"
#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"
#include "roughroll/io/micro_geometry_input.hpp"
#include "roughroll/io/roughness_output.hpp"
#include "roughroll/layer/roughness_parameters.hpp"
#include "roughroll/model/carter.hpp"
#include "roughroll/model/kernel.hpp"
#include "roughroll/problems/normal_problem.hpp"
#include "roughroll/problems/tangential_problem.hpp"

namespace py = pybind11;

namespace roughroll::python {

namespace {

// Terms (T, A): T finite (any sign: a difference of kernels, or a printed sign), A finite, >= 0.
kernel kernel_of(const std::vector<std::pair<double, double>>& terms) {
    std::vector<exponential_term> list;
    for (const auto& [T, A] : terms) {
        if (!std::isfinite(T)) throw input_error("a kernel term's T must be finite (got " + shortest(T) + ")");
        if (!(std::isfinite(A) && A >= 0.0))
            throw input_error("a kernel term's A must be finite and >= 0 (got " + shortest(A) + ")");
        if (T != 0.0) list.push_back({T, A});  // T = 0 removes a term, as in a scene
    }
    return kernel(std::move(list));
}

}  // namespace

void bind_model(py::module_& m) {
    m.def(
        "kernel",
        [](const std::vector<std::pair<double, double>>& terms, const std::vector<double>& z) {
            const kernel k = kernel_of(terms);
            std::vector<double> out;
            out.reserve(z.size());
            for (const double x : z) {
                if (!std::isfinite(x)) throw input_error("z must be finite (got " + shortest(x) + ")");
                out.push_back(x == 0.0 ? 0.0 : k(x));  // the jump at 0: its value is never used
            }
            return out;
        },
        py::arg("terms"), py::arg("z"));

    m.def(
        "normal_problem",
        [](const std::vector<std::pair<double, double>>& terms, int n, const std::string& method_name,
           const std::vector<double>& r) {
            const method how = method_from_string(method_name);
            if (how != method::paper && how != method::product)
                throw input_error("the normal problem alone is solved by 'paper' or 'product' (got '" + method_name +
                                  "')");
            for (const double x : r)
                if (!(x >= -1.0 && x <= 1.0)) throw input_error("r must lie in [-1, 1] (got " + shortest(x) + ")");
            const kernel k2 = kernel_of(terms);
            normal_solution s = [&] {
                py::gil_scoped_release release;
                return solve_normal(k2, n, how);
            }();
            py::dict d;
            d["hertz_load_ratio"] = s.lambda;
            d["gamma"] = s.gamma;
            d["rcond"] = s.rcond;
            d["n"] = s.rule.n;
            d["method"] = to_string(s.how);
            d["nodes"] = s.rule.nodes;
            d["weights"] = s.rule.weights;
            d["collocation"] = s.rule.collocation;
            d["phi"] = s.phi;
            std::vector<double> p;
            p.reserve(r.size());
            for (const double x : r) p.push_back(s.pressure(x));
            d["p"] = std::move(p);
            return d;
        },
        py::arg("terms"), py::arg("n"), py::arg("method"), py::arg("r"));

    m.def(
        "carter",
        [](double Q, double f) {
            if (!(std::isfinite(f) && f > 0.0))
                throw input_error("friction coefficient f must be positive and finite (got " + shortest(f) + ")");
            load_magnitude(Q, f);  // finite, |Q| <= f: the scene's checks
            const carter_point p = carter(Q, f);
            return std::make_pair(p.c0, p.xi);
        },
        py::arg("Q"), py::arg("f"));

    m.def(
        "roughness_spec",
        [](const std::string& text, const std::string& source, const std::string& base_dir) {
            py::gil_scoped_release release;
            const micro_geometry g = parse_roughness_spec(text, source, base_dir);
            return to_json(source, g, compute_roughness_parameters(g)).dump();
        },
        py::arg("text"), py::arg("source"), py::arg("base_dir"));
    m.def(
        "read_roughness_spec",
        [](const std::string& path) {
            py::gil_scoped_release release;
            const micro_geometry g = read_roughness_spec(path);
            return to_json(path, g, compute_roughness_parameters(g)).dump();
        },
        py::arg("path"));
}

}  // namespace roughroll::python
