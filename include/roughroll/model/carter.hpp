// SPDX-License-Identifier: GPL-3.0-or-later
// Carter's closed form for smooth cylinders (the T = 0 limit of (3.19)-(3.22)):
//   lambda = P_H/P2 = 1,  p(r) = (2/pi) sqrt(1 - r^2),
//   (1 + c0)/2 = sqrt(1 - Q/f),  xi = (2 f/pi) (1 - sqrt(1 - Q/f)),
// for 0 <= Q <= f; the mirror case Q < 0 changes the sign of xi.
#pragma once

namespace roughroll {

struct carter_point {
    double c0;
    double xi;
};

carter_point carter(double Q, double f);  // requires f > 0, |Q| <= f

// The same curve by its stick end c0 in [-1, 1] (Q >= 0): Q = f (1 - rho^2), xi = (2 f/pi)(1 - rho).
struct carter_stick_end {
    double Q;
    double xi;
};
carter_stick_end carter_at_stick_end(double c0, double f);

}  // namespace roughroll
