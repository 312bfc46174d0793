// Results as the user reads them: one creep point as JSON or text, a creep curve as CSV.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "roughroll/contact.hpp"

namespace roughroll {

struct point_report {
    std::string label;
    const normal_solution& normal;
    const tangential_solution& solution;
    double seconds;  // wall time of the normal and tangential solves
};

nlohmann::json to_json(const point_report& r);
void write_summary(std::ostream& out, const point_report& r);

// Header Q,Q_over_f,c0,xi,xi_over_f,xi_carter,c0_carter,checks_hold; digits to round-trip.
void write_curve_csv(std::ostream& out, const std::vector<curve_point>& curve);

}  // namespace roughroll
