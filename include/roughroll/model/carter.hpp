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

}  // namespace roughroll
