// glTF primitive modes that describe triangles: TRIANGLES (4, the default), TRIANGLE_STRIP (5)
// and TRIANGLE_FAN (6), all turned into triangle lists. POINTS, LINES, LINE_LOOP and LINE_STRIP
// (0..3) have no surface to render and are skipped with a warning.
#pragma once

#include <cstdint>
#include <vector>

namespace vkp {

// True for -1 (mode absent: TRIANGLES), 4, 5 and 6.
bool isTriangleMode(int mode);

// Triangles a primitive of `mode` with `vertices` vertices (or indices) draws: vertices / 3
// (whole triangles) for TRIANGLES, vertices - 2 for strips and fans (0 below 3 vertices).
uint64_t triangleCountOfMode(int mode, uint64_t vertices);

// The triangle list of a strip or fan, with the winding the glTF 2.0 specification gives
// (section 3.7.2.1, "Topology types"): strip triangle i is {v_i, v_(i+1+i%2), v_(i+2-i%2)} (odd
// triangles swap their last two vertices, so every triangle keeps the first's facing); fan
// triangle i is {v_(i+1), v_(i+2), v_0}. TRIANGLES (or -1) returns `indices` as they are.
std::vector<uint32_t> triangleListIndices(int mode, const std::vector<uint32_t>& indices);

}  // namespace vkp
