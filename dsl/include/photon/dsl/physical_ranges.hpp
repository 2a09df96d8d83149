// SPDX-License-Identifier: MIT
#pragma once
// Values POV-Ray takes but photon's physical materials and lights cannot: POV-Ray renders a
// `transmit 100` (light amplified on its way through), a negative colour (light taken away) or a
// `phong_size 0`, as arithmetic on colours; photon's surfaces conserve energy and its lights only
// emit. Each function here returns the nearest value photon can render and, when it had to change
// the value, the words of the warning that says what photon uses instead (build.hpp reports it at
// the value's place).

#include <algorithm>
#include <string>

#include "description.hpp"
#include "value.hpp"

namespace photon::dsl {

template <class T>
struct Clamped {
    T value;
    std::string message;  ///< empty when the value was kept
};

inline std::string rgb_text(const Vector3& c) {
    return "<" + format_number(c.x) + ", " + format_number(c.y) + ", " + format_number(c.z) + ">";
}

/// A pigment colour with rgb >= 0, filter and transmit >= 0 and filter + transmit <= 1 (both
/// scaled down together when their sum is over 1, keeping their ratio).
[[nodiscard]] inline Clamped<Color> physical_pigment(const Color& c) {
    Clamped<Color> out{c, {}};
    Color& p = out.value;
    if (c.rgb.x < 0 || c.rgb.y < 0 || c.rgb.z < 0) {
        p.rgb = glm::max(c.rgb, Vector3(0.0));
        out.message = "negative colour rgb " + rgb_text(c.rgb) +
                      " (POV-Ray subtracts light there): photon's reflectances are >= 0 and it uses rgb " +
                      rgb_text(p.rgb);
    }
    p.filter = std::max(0.0, c.filter);
    p.transmit = std::max(0.0, c.transmit);
    if (p.filter + p.transmit > 1 + 1e-9) {
        const double sum = p.filter + p.transmit;
        p.filter /= sum;
        p.transmit /= sum;
    }
    if (p.filter != c.filter || p.transmit != c.transmit) {
        if (!out.message.empty()) out.message += "; ";
        out.message += "filter " + format_number(c.filter) + " and transmit " + format_number(c.transmit) +
                       " (POV-Ray lets more light through than arrives when they sum over 1): photon's "
                       "surfaces conserve energy and it uses filter " +
                       format_number(p.filter) + " and transmit " + format_number(p.transmit);
    }
    return out;
}

/// A light's intensity with every channel >= 0; zero when no channel is positive (the caller
/// leaves such a light out).
[[nodiscard]] inline Clamped<Vector3> physical_light(const Vector3& intensity, const Vector3& colour) {
    Clamped<Vector3> out{glm::max(intensity, Vector3(0.0)), {}};
    if (out.value == intensity) return out;
    out.message = "negative light colour rgb " + rgb_text(colour) +
                  " (POV-Ray's light takes light away there): photon's lights only emit, " +
                  (out.value == Vector3(0.0) ? std::string("so photon leaves this light out")
                                             : "so photon reads the negative channels as 0");
    return out;
}

/// A Phong exponent > 0. With `phong 0` there is no highlight and the size changes nothing, so
/// it is replaced without a message.
[[nodiscard]] inline Clamped<double> physical_phong_size(double phong, double phong_size) {
    if (phong_size > 0) return {phong_size, {}};
    if (phong == 0) return {1.0, {}};
    return {1.0, "`phong_size " + format_number(phong_size) +
                     "` (POV-Ray's highlight is then phong * cos^" + format_number(phong_size) +
                     ", spread over the whole hemisphere): photon's highlight needs a positive size and uses "
                     "phong_size 1"};
}

}  // namespace photon::dsl
