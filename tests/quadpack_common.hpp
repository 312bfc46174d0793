// SPDX-License-Identifier: GPL-3.0-or-later
// What the tests' QUADPACK references share (tests/jacobi_quadpack.hpp, tests/hilbert_on_pieces.hpp): a
// std::function integrand behind GSL's function pointer, and an adaptive workspace allocated and freed in one place.
// Header-only, for tests.
#pragma once

#include <cstddef>
#include <functional>
#include <new>

#include <gsl/gsl_integration.h>

namespace quadpack_common {

using integrand = std::function<double(double)>;

inline double call(double x, void* p) { return (*static_cast<const integrand*>(p))(x); }

// GSL reads the integrand through a non-const pointer and never writes it.
inline gsl_function function_of(const integrand& g) { return gsl_function{&call, const_cast<integrand*>(&g)}; }

// QUADPACK's adaptive workspace of `limit` subintervals (the limit every call on it passes).
struct interval_workspace {
    explicit interval_workspace(std::size_t size) : limit(size), w(gsl_integration_workspace_alloc(size)) {
        if (w == nullptr) throw std::bad_alloc();
    }
    ~interval_workspace() { gsl_integration_workspace_free(w); }
    interval_workspace(const interval_workspace&) = delete;
    interval_workspace& operator=(const interval_workspace&) = delete;
    const std::size_t limit;
    gsl_integration_workspace* const w;
};

}  // namespace quadpack_common
