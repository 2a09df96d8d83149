// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's animation options (+K, Initial_Frame, Final_Frame, Initial_Clock, Final_Clock) turned
// into the values of the scene's identifiers clock, clock_on, frame_number, ... for one frame, by
// POV-Ray 3.7's own rules, so that an animation scene reads as it does in POV-Ray's frame. Many
// of POV-Ray's sample scenes index arrays by frame_number and only read under their .ini file.

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>

#include "parser/parse_options.hpp"

namespace photon::dsl {

/// What a command line asks for (each field empty when not given).
struct AnimationRequest {
    std::optional<double> clock;                  ///< +K / Clock=: a still image at this clock
    std::optional<double> initial_frame, final_frame;  ///< +KFI / +KFF (Initial_Frame, Final_Frame)
    double initial_clock = 0, final_clock = 1;    ///< +KI / +KF (POV-Ray's defaults 0 and 1)
    std::optional<double> frame;                  ///< the frame to read; the first one when empty
};

/// The identifiers' values for the frame `r` asks for. A still image (no frame range, or POV-Ray's
/// still ranges 1..1 and 0..0 without --frame) has clock = the +K value (0 without it), clock_on
/// set only by +K, and frame_number, initial_frame, final_frame, initial_clock, final_clock and
/// clock_delta all 0, as POV-Ray 3.7 declares them. An animation's frame N has frame_number N and
/// clock = initial_clock + (N - initial_frame) * clock_delta, clock_delta = (final_clock -
/// initial_clock) / (final_frame - initial_frame), 0 for a one-frame range (where POV-Ray divides
/// by zero). A frame alone reads as the one frame of the range N..N. Throws std::invalid_argument
/// for a frame outside the range, a clock with a frame range, or a value that is not a whole number.
[[nodiscard]] inline AnimationClock animation_clock(const AnimationRequest& r) {
    const auto whole = [](double v, const char* what) {
        if (!(v == double(long(v))) || v < 0)
            throw std::invalid_argument(std::string(what) + " must be a whole number >= 0");
        return v;
    };
    AnimationClock a;
    const bool range = r.initial_frame || r.final_frame;
    if (r.clock && (range || r.frame))
        throw std::invalid_argument("the clock of an animation frame comes from its frame and clock range, not --clock");
    const double first = range ? whole(r.initial_frame.value_or(1), "the initial frame") : 0;
    const double last = range ? std::max(whole(r.final_frame.value_or(1), "the final frame"), first) : 0;
    const bool still = !r.frame && (!range || (first == last && (first == 0 || first == 1)));
    if (still) {
        a.clock = r.clock.value_or(0.0);
        a.clock_on = r.clock.has_value();
        return a;
    }
    const double frame = whole(r.frame.value_or(first), "the frame");
    a.initial_frame = range ? first : frame;
    a.final_frame = range ? last : frame;
    if (frame < a.initial_frame || frame > a.final_frame)
        throw std::invalid_argument("frame " + std::to_string(long(frame)) + " is outside the frames " +
                                    std::to_string(long(a.initial_frame)) + " to " + std::to_string(long(a.final_frame)));
    a.initial_clock = r.initial_clock;
    a.final_clock = r.final_clock;
    a.clock_delta = a.final_frame > a.initial_frame
                        ? (r.final_clock - r.initial_clock) / (a.final_frame - a.initial_frame)
                        : 0.0;
    a.frame_number = frame;
    a.clock = r.initial_clock + a.clock_delta * (frame - a.initial_frame);
    a.clock_on = true;
    return a;
}

}  // namespace photon::dsl
