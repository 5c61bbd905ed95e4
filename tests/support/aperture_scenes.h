// The validation suite's small-aperture scenes as Radiance text (validation/cases_daylight.cpp
// builds the same ones): black, so only the sky through the opening lights the sensors.
#pragma once

namespace candela::test_support {

// An infinite black roof 3 m up with a 1 × 1.5 m opening centred over the origin.
inline constexpr const char* kRoofOpening =
    "void plastic black 0 0 5 0 0 0 0 0\n"
    "black polygon r1 0 0 12 -1e4 -1e4 3  1e4 -1e4 3  1e4 -0.75 3  -1e4 -0.75 3\n"
    "black polygon r2 0 0 12 -1e4 0.75 3  1e4 0.75 3  1e4 1e4 3  -1e4 1e4 3\n"
    "black polygon r3 0 0 12 -1e4 -0.75 3  -0.5 -0.75 3  -0.5 0.75 3  -1e4 0.75 3\n"
    "black polygon r4 0 0 12 0.5 -0.75 3  1e4 -0.75 3  1e4 0.75 3  0.5 0.75 3\n";

// An infinite black wall x = 0 with a 2 × 1 m window (y −1..1, z 1..2) and a black ceiling
// 2 m up over the room (x > 0).
inline constexpr const char* kSideWindow =
    "void plastic black 0 0 5 0 0 0 0 0\n"
    "black polygon w1 0 0 12 0 -1e4 -1e4  0 1e4 -1e4  0 1e4 1  0 -1e4 1\n"
    "black polygon w2 0 0 12 0 -1e4 2  0 1e4 2  0 1e4 1e4  0 -1e4 1e4\n"
    "black polygon w3 0 0 12 0 -1e4 1  0 -1 1  0 -1 2  0 -1e4 2\n"
    "black polygon w4 0 0 12 0 1 1  0 1e4 1  0 1e4 2  0 1 2\n"
    "black polygon ceiling 0 0 12 0 -1e4 2  1e4 -1e4 2  1e4 1e4 2  0 1e4 2\n";

}  // namespace candela::test_support
