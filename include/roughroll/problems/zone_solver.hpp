// The tangential problem with the zone structure found, not assumed (docs/formulation.md,
// section 7). The complementarity form of (3.2)-(3.4), for Q >= 0 (Q < 0 is the mirror):
//   stick zone:  v = xi - L1[p1] = 0,          |p1| <= f p                     (3.2), (3.3)
//   slip zone:   p1 = f p sgn v,               v != 0                          (3.4), (3.15)
//   int p1 = Q                                                                 (3.13)
// The structures solved, at the order of the product-integration scheme (4.4):
//   - the paper's: stick [-1, c0], slip (c0, 1]: tangential_solver, the fast path;
//   - slip [-1, s), stick [s, c0], slip (c0, 1], both slip zones in the direction of Q: the
//     structure when the paper's zone would carry |p1| > f p at its leading end (G'(-1) < 0,
//     section 7(c)). On the stick zone p1 = f p + q with q = psi(t) sqrt(1 - t^2) and
//       L1[q](r) = xi + f G(r),  r = s + rho (t + 1),  rho = (c0 - s)/2,  rho int q = Q - f,
//     (tangential_solver::solve_on_zone), plus the entry condition of 7(b), psi(t = -1) = 0:
//     the traction reaches the bound f p smoothly where material enters the stick zone;
//   - gross sliding |Q| = f: slip everywhere, stick only at the point r* where G is least,
//     xi = -f min G (7(d)).
// (s, c0) solve the two conditions Q(s, c0) = |Q|, psi_{s,c0}(-1) = 0 by nested Brent
// searches. Other structures (slip against Q, several stick zones) are detected by the
// checks of (3.3)-(3.4) and reported, not solved.
#pragma once

#include <string>
#include <vector>

#include "roughroll/problems/tangential_problem.hpp"

namespace roughroll {

// One zone of the contact in r = x1/a.
struct zone {
    double from, to;
    bool stick;
    int direction;  // slip: +1 or -1, the sign of p1 there (the slip velocity's sign, (3.4)); stick: 0
};

struct zone_solution {
    tangential_solution single;  // psi_b, xi, Q, f, sign, checks; single.c0 = end of the stick zone
    double start = -1.0;         // start of the stick zone: -1 in the paper's structure
    std::vector<zone> zones;     // from r = -1 to 1
    bool general = false;        // found by the general search (false: the paper's structure held)

    bool papers_structure() const { return start == -1.0; }
};

class zone_solver {
public:
    // The tangential solver supplies G, the system (4.4) on any stick zone and the fast path;
    // it must outlive this workspace. k1 and f: the solver's own K1* and friction coefficient
    // (the slip velocity off the stick zone needs the kernel).
    zone_solver(tangential_solver& single, const kernel& k1, double f);

    // The solution of the complementarity problem for the load Q, |Q| <= f. `force_general`
    // runs the general search even where the single zone's checks hold (it then returns the
    // single zone, found by the same conditions).
    zone_solution solve(double Q, bool force_general = false);

    // p1(r) and v(r) (0 on the stick zone) of a solution of this solver.
    double traction(const zone_solution& s, double r);
    double slip_velocity(const zone_solution& s, double r);
    traction_checks check(const zone_solution& s);

    // psi(t = -1) of the stick zone [start, c0] at load |Q| = Q(start, c0): the entry condition.
    double entry_coefficient(const tangential_solution& s) const;

private:
    zone_solution general(double magnitude);
    zone_solution gross_sliding();
    double stick_end(double start, double magnitude);  // c0 with Q(start, c0) = magnitude
    std::vector<zone> zones_of(double start, double c0, double sign) const;

    tangential_solver& single_;
    kernel k1_;
    double f_;
};

}  // namespace roughroll
