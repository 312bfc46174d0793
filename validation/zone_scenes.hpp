// SPDX-License-Identifier: GPL-3.0-or-later
// Scenes where the paper's single stick zone fails its checks (docs/formulation.md 7(c)):
// unequal kernels with both cylinders rough, K1* far above K2* near the edge, so G'(-1) < 0.
// Found by a scan of random scenes, not tuned; shared by the zone-search validations.
#pragma once

#include "roughroll/model/roughness.hpp"

namespace roughroll::zone_scenes {

// Fails from moderate loads on.
inline roughness tangential_dominates_a() {
    roughness r;
    r.cylinder1.tangential = {3.5613, 1.65266};
    r.cylinder2.tangential = {3.33641, 6.08721};
    r.cylinder1.normal = {0.112749, 1.75668};
    r.cylinder2.normal = {0.0338885, 1.17053};
    return r;
}

// Fails only near gross sliding (from Q/f ~ 1 - 1e-3 on).
inline roughness tangential_dominates_b() {
    roughness r;
    r.cylinder1.tangential = {5.71149, 0.39556};
    r.cylinder2.tangential = {1.0744, 0.625575};
    r.cylinder1.normal = {0.2749, 4.27018};
    r.cylinder2.normal = {0.0939665, 0.917649};
    return r;
}

}  // namespace roughroll::zone_scenes
