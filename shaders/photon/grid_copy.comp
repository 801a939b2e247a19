// Photon grid build, step 5: copies the photon records into bucket order.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "photon/grid_build_bindings.glsl"

layout(local_size_x = kGridGroupSize) in;

void main() {
    uint i = itemIndex();
    if (i >= cellStart[params.tableMask + 1u]) return;
    uint slot = SORTED_SLOT(i);
    GRID_PHOTON(i) = PHOTON(slot);
}
