// GLSL-only bindings shared by the photon-grid build kernels (host/photon/photon_grid.h):
// counting sort of the selected photons by the hash of their cell.
#ifndef VKP_GRID_BUILD_GLSL
#define VKP_GRID_BUILD_GLSL

#include "shared/kernels/grid_build.glsl"
#include "shared/photon.glsl"
#include "shared/photon_grid.glsl"

#include "common/item_index.glsl"
#include "common/segmented_arrays.glsl"

// The input, the sorted slots and the output are segmented arrays (segmented.glsl): a map of any size.
SEGMENTED_ARRAY(kGridSlotBinding, Photons, photonTable);  // fixed slots
// tableSize + 1 entries: counts per bucket, then (scanned) the first sorted index of each bucket;
// the last entry ends as the number of photons in the grid.
layout(std430, set = 0, binding = kGridCellStartBinding) buffer CellStart { uint cellStart[]; };
layout(std430, set = 0, binding = kGridCursorBinding) buffer Cursor { uint cursor[]; };            // scatter positions
SEGMENTED_ARRAY(kGridSortedSlotBinding, SortedSlots, sortedSlotTable);  // slot per sorted photon
SEGMENTED_ARRAY(kGridPhotonBinding, GridPhotons, gridPhotonTable);
#define PHOTON(i) PHOTON_AT(photonTable, i)
#define SORTED_SLOT(i) UINT_AT(sortedSlotTable, i)
#define GRID_PHOTON(i) PHOTON_AT(gridPhotonTable, i)

layout(push_constant) uniform Push { PhotonGridParams params; };

// The bucket of slot `slot`, or ~0u when the map does not keep that photon.
uint bucketOfSlot(uint slot) {
    GpuPhoton p = PHOTON(slot);
    if (!photonSelected(photonFlags(p), params.requiredFlags, params.rejectedFlags)) return ~0u;
    return gridHash(gridCell(p.position, params.invCellSize), params.tableMask);
}

#endif
