// Photon grid build, step 4: one invocation per bucket sorts the bucket's slots ascending (Shell
// sort with Ciura's gaps: buckets hold a handful to a few thousand photons, already nearly in
// order), so the grid — and every sum a gather forms over it — is the same on every run.
// Every step keeps the range a permutation: should lavapipe's shared loop-iteration limit (see
// docs/photon-mapping.md) cut a huge bucket's sort short, no photon is lost, only the order.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "photon/grid_build_bindings.glsl"
#include "common/termination_counters.glsl"

layout(local_size_x = kGridGroupSize) in;

const uint kGaps[8] = uint[8](701u, 301u, 132u, 57u, 23u, 10u, 4u, 1u);

// A bucket's slots almost always lie in one segment of the sorted slots (buckets hold a few
// photons, segments millions): its reference and mask stay in registers instead of being read
// from the segment table at every access of the sort. A bucket across two segments goes
// through the table. In the one-segment form (kSingleSegment, segmented.glsl) SORTED_SLOT is a
// direct index already, and the constant leaves only it (lavapipe runs both sides of a branch).
UintSegment bucketSegment;
uint bucketMask;
bool bucketInOneSegment;

uint slotAt(uint k) { return kSingleSegment || !bucketInOneSegment ? SORTED_SLOT(k) : bucketSegment.items[k & bucketMask]; }

void setSlot(uint k, uint value) {
    if (kSingleSegment || !bucketInOneSegment) SORTED_SLOT(k) = value;
    else bucketSegment.items[k & bucketMask] = value;
}

void sortBucket() {
    uint bucket = itemIndex();
    if (bucket > params.tableMask) return;
    uint begin = cellStart[bucket];
    uint end = cellStart[bucket + 1u];
    uint n = end - begin;
    if (n < 2u) return;
    uint shift = sortedSlotTable.segmentShift;
    bucketMask = sortedSlotTable.segmentMask;
    bucketInOneSegment = (begin >> shift) == ((end - 1u) >> shift);
    bucketSegment = UintSegment(sortedSlotTable.segments[begin >> shift]);
    uint passes = 0u;    // passes and insertions done, against those due: fewer when a loop was cut
    uint rows = 0u;
    uint rowsDue = 0u;
    for (uint g = 0u; g < 8u; ++g) {
        passes += 1u;
        uint gap = kGaps[g];
        rowsDue += max(n, gap) - gap;
        for (uint i = gap; i < n; ++i) {
            rows += 1u;
            uint value = slotAt(begin + i);
            uint j = i;
            while (j >= gap && slotAt(begin + j - gap) > value) {
                setSlot(begin + j, slotAt(begin + j - gap));
                j -= gap;
            }
            setSlot(begin + j, value);
        }
    }
    noteLoopCut(passes, 8u);
    noteLoopCut(rows, rowsDue);
}

void main() {
    sortBucket();
    countTerminations(kTerminationGridCells);  // rays and gathers this invocation's bounds cut short
}
